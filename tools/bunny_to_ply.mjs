// bunny_to_ply.mjs - convert the Stanford bunny from the npm package `bunny` to ASCII PLY.
//
//   node tools/bunny_to_ply.mjs PATH_TO/node_modules/bunny OUT.ply
//
// The package holds `positions` (x y z arrays) and `cells` (triangles as vertex indices).
// The output is normalised for the course scenes: centred on x = z = 0, standing on y = 0,
// exactly 1 unit tall. Only positions and faces are written; the mesh loader computes
// smooth per-vertex normals itself. Numbers are printed with a fixed precision so the
// file is reproducible byte for byte.

import { createRequire } from "node:module";
import { writeFileSync } from "node:fs";
import { resolve } from "node:path";

function fail(message) {
    process.stderr.write(`bunny_to_ply: ${message}\n`);
    process.exit(1);
}

function bounds(positions) {
    const lo = [Infinity, Infinity, Infinity];
    const hi = [-Infinity, -Infinity, -Infinity];
    for (const p of positions) {
        for (let i = 0; i < 3; i++) {
            lo[i] = Math.min(lo[i], p[i]);
            hi[i] = Math.max(hi[i], p[i]);
        }
    }
    return { lo, hi };
}

// Six times the signed volume: positive when the triangles wind counter-clockwise seen from outside.
function signedVolume6(positions, cells) {
    let sum = 0;
    for (const [a, b, c] of cells) {
        const p = positions[a], q = positions[b], r = positions[c];
        sum += p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
               p[2] * (q[0] * r[1] - q[1] * r[0]);
    }
    return sum;
}

function formatNumber(x) {
    const s = x.toFixed(6);
    return s === "-0.000000" ? "0.000000" : s;
}

const args = process.argv.slice(2);
if (args.length !== 2 || args[0] === "--help" || args[0] === "-h") {
    process.stdout.write("usage: node tools/bunny_to_ply.mjs PATH_TO/node_modules/bunny OUT.ply\n");
    process.exit(args.length === 1 && (args[0] === "--help" || args[0] === "-h") ? 0 : 2);
}

const require = createRequire(import.meta.url);
let bunny;
try {
    bunny = require(resolve(args[0]));
} catch (err) {
    fail(`cannot load the bunny package from ${args[0]}: ${err.message}`);
}
const { positions, cells } = bunny;
if (!Array.isArray(positions) || !Array.isArray(cells) || positions.length === 0) {
    fail("the package has no `positions`/`cells` arrays");
}

const { lo, hi } = bounds(positions);
const height = hi[1] - lo[1];
if (!(height > 0)) {
    fail("the mesh has no height");
}
const scale = 1 / height;
const cx = 0.5 * (lo[0] + hi[0]);
const cz = 0.5 * (lo[2] + hi[2]);
const moved = positions.map(p => [(p[0] - cx) * scale, (p[1] - lo[1]) * scale, (p[2] - cz) * scale]);

// Keep the winding counter-clockwise from outside, whatever the source uses, so culling works.
const flip = signedVolume6(moved, cells) < 0;
const faces = cells.filter(c => c.length === 3 && c[0] !== c[1] && c[1] !== c[2] && c[0] !== c[2])
                   .map(c => (flip ? [c[0], c[2], c[1]] : c));

const lines = [
    "ply",
    "format ascii 1.0",
    "comment Stanford bunny (Stanford 3D scanning repository), from the npm package bunny",
    "comment normalised: centred on x = z = 0, standing on y = 0, height 1",
    `element vertex ${moved.length}`,
    "property float x",
    "property float y",
    "property float z",
    `element face ${faces.length}`,
    "property list uchar int vertex_indices",
    "end_header",
];
for (const p of moved) {
    lines.push(p.map(formatNumber).join(" "));
}
for (const f of faces) {
    lines.push(`3 ${f[0]} ${f[1]} ${f[2]}`);
}
try {
    writeFileSync(args[1], lines.join("\n") + "\n");
} catch (err) {
    fail(`cannot write ${args[1]}: ${err.message}`);
}
process.stdout.write(`bunny_to_ply: ${moved.length} vertices, ${faces.length} triangles -> ${args[1]}` +
                     `${flip ? " (winding flipped)" : ""}\n`);
