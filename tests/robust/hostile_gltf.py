#!/usr/bin/python3
"""hostile_gltf.py PROGRAM [--chapter] [--open-log LIB] [--sanitized] | --write-seeds FOLDER - glTF files written as an attacker
would, each refused cleanly, within bounds, and without opening anything outside the model's folder.

Each case writes its files into a fresh folder `model/` beside a folder `outside/` that holds a
secret file, then runs PROGRAM on a one-line scene `model PATH`: scene_check, or with --chapter a
chapter drawing one small headless frame of it (exit 77 there, no GL context, skips). A case passes
when the run
    - exits 2 with one line on stderr holding the expected reason (no signal, no hang: 60 s);
    - peaks at most 512 MB resident (model_file.h: MODEL_MAX_MB_DEFAULT; not checked with
      --sanitized, whose shadow memory is counted too), and its time is printed;
    - with --open-log LIB (tests/robust/open_log.c, preloaded): opened no path that resolves into
      `outside/` (the log must hold the model file itself, or the interposer saw nothing).
`good` is the control: the same triangle without the attack loads (exit 0), opening its own files.
The categories are docs/scene-format.md's "Files from elsewhere"; the fuzz corpus holds the small
ones too (tests/fuzz/corpus_model/hostile_*).
"""
import base64
import json
import os
import struct
import subprocess
import sys
import tempfile
import time
import zlib

MEMORY_MB = 512
HANG_S = 60
TRIANGLE = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)  # 36 bytes


def data_uri(data):
    return "data:application/octet-stream;base64," + base64.b64encode(data).decode()


def triangle(uri=None):
    """A valid one-triangle glTF: its buffer a data URI unless `uri` names a file."""
    return {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "buffers": [{"byteLength": 36, "uri": uri or data_uri(TRIANGLE)}],
    }


def with_image(uri):
    g = triangle()
    g["images"] = [{"uri": uri}]
    g["textures"] = [{"source": 0}]
    g["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    g["meshes"][0]["primitives"][0]["material"] = 0
    return g


def png(width=1, height=1):
    """A valid RGB PNG of one grey colour."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    rows = b"".join(b"\0" + b"\x80" * (3 * width) for _ in range(height))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def spellings():
    """One image named three ways: one texture."""
    g = with_image("img.png")
    g["images"] += [{"uri": "./img.png"}, {"uri": "sub/../img.png"}]
    g["textures"] += [{"source": 1}, {"source": 2}]
    g["materials"] += [{"pbrMetallicRoughness": {"baseColorTexture": {"index": k}}} for k in (1, 2)]
    g["meshes"][0]["primitives"] = [{"attributes": {"POSITION": 0}, "material": k} for k in range(3)]
    return g


def changed(g, edit):
    edit(g)
    return g


def glb(doc, bin_data=b"", json_length=None, total=None):
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    chunks = struct.pack("<I4s", json_length if json_length is not None else len(text), b"JSON") + text
    if bin_data:
        bin_data += b"\0" * (-len(bin_data) % 4)
        chunks += struct.pack("<I4s", len(bin_data), b"BIN\0") + bin_data
    return struct.pack("<4sII", b"glTF", 2, total if total is not None else 12 + len(chunks)) + chunks


def nested_nodes(depth):
    g = triangle()
    g["nodes"] = [{"children": [i + 1]} for i in range(depth - 1)] + [{"mesh": 0}]
    return g


def many_primitives(count, vertices, d):
    """`count` primitives all reading one accessor of `vertices` points (a file of 12 bytes each)."""
    with open(os.path.join(d, "points.bin"), "wb") as f:
        f.write(b"\0" * (12 * vertices))
    g = triangle("points.bin")
    g["buffers"][0]["byteLength"] = g["bufferViews"][0]["byteLength"] = 12 * vertices
    g["accessors"][0]["count"] = vertices
    g["meshes"][0]["primitives"] = [{"attributes": {"POSITION": 0}} for _ in range(count)]
    return g


def sparse(index):
    g = triangle()
    g["buffers"][0] = {"byteLength": 52, "uri": data_uri(TRIANGLE + struct.pack("<I3f", index, 1, 1, 1))}
    g["bufferViews"] += [{"buffer": 0, "byteOffset": 36, "byteLength": 4},
                         {"buffer": 0, "byteOffset": 40, "byteLength": 12}]
    g["accessors"][0]["sparse"] = {"count": 1, "indices": {"bufferView": 1, "componentType": 5125},
                                   "values": {"bufferView": 2}}
    return g


def skin(joints, matrices, view_bytes):
    g = triangle()
    g["buffers"][0] = {"byteLength": 36 + view_bytes, "uri": data_uri(TRIANGLE + b"\0" * view_bytes)}
    g["bufferViews"].append({"buffer": 0, "byteOffset": 36, "byteLength": view_bytes})
    g["accessors"].append({"bufferView": 1, "componentType": 5126, "count": matrices, "type": "MAT4"})
    g["nodes"] = [{"mesh": 0, "skin": 0}] + [{} for _ in range(joints)]
    g["skins"] = [{"joints": list(range(1, joints + 1)), "inverseBindMatrices": 1}]
    return g


def lights(kind, count=1, spot=True):
    g = triangle()
    light = {"type": kind}
    if kind == "spot" and spot:
        light["spot"] = {}
    g["extensions"] = {"KHR_lights_punctual": {"lights": [light] * count}}
    g["nodes"].append({"extensions": {"KHR_lights_punctual": {"light": 0}}})
    g["scenes"][0]["nodes"].append(1)
    return g


def deep_json(depth):
    text = json.dumps(triangle())
    return text[:-1] + ', "extras": ' + "[" * depth + "]" * depth + "}"


# name -> (what to write: a function of the folder returning the model's file name), expected text
def cases(outside):
    secret = os.path.join(outside, "secret.bin")

    def doc(name, g):
        def write(d):
            with open(os.path.join(d, name), "w") as f:
                f.write(g if isinstance(g, str) else json.dumps(g))
            return name
        return write

    def raw(name, data):
        def write(d):
            with open(os.path.join(d, name), "wb") as f:
                f.write(data)
            return name
        return write

    def linked(name, link, target, g):
        def write(d):
            os.symlink(target, os.path.join(d, link))
            return doc(name, g)(d)
        return write

    def fifo(name, g):
        def write(d):
            os.mkfifo(os.path.join(d, "pipe.bin"))
            return doc(name, g)(d)
        return write

    def with_files(name, g, files):
        def write(d):
            for path, data in files.items():
                os.makedirs(os.path.dirname(os.path.join(d, path)), exist_ok=True)
                with open(os.path.join(d, path), "wb") as f:
                    f.write(data)
            return doc(name, g)(d)
        return write

    def lazy(name, make):
        def write(d):
            return doc(name, make(d))(d)
        return write

    return [
        ("good", doc("good.gltf", triangle()), None),
        ("image_spellings", with_files("a.gltf", spellings(), {"img.png": png(), "sub/x": b""}),
         "ok: 1 textures;"),
        # files outside the model's folder
        ("buffer_parent", doc("a.gltf", triangle("../outside/secret.bin")), "lies outside the model's folder"),
        ("buffer_escaped_parent", doc("a.gltf", triangle("%2e%2e/outside/secret.bin")),
         "lies outside the model's folder"),
        ("buffer_absolute", doc("a.gltf", triangle(secret)), "is not a relative path"),
        ("buffer_file_url", doc("a.gltf", triangle("file://" + secret)), "is not a relative path"),
        ("buffer_symlink", linked("a.gltf", "link.bin", secret, triangle("link.bin")),
         "lies outside the model's folder"),
        ("image_parent", doc("a.gltf", with_image("../outside/secret.png")), "lies outside the model's folder"),
        ("image_symlink", linked("a.gltf", "link.png", os.path.join(outside, "secret.png"),
                                 with_image("link.png")), "lies outside the model's folder"),
        ("buffer_fifo", fifo("a.gltf", triangle("pipe.bin")), "not a regular file"),
        ("buffer_short_file", with_files("a.gltf", triangle("short.bin"), {"short.bin": TRIANGLE[:20]}),
         "buffer 0 says 36 bytes, and its data holds 20"),
        # accessors and views past their bytes
        ("accessor_overrun", doc("a.gltf", changed(triangle(), lambda g: g["accessors"][0].update(count=300000))),
         "end at byte"),
        ("accessor_offset_wrap", doc("a.gltf", changed(triangle(), lambda g: g["accessors"][0].update(
            byteOffset=18446744073709551600))), "'byteOffset' is not a whole number"),
        ("view_offset_wrap", doc("a.gltf", changed(triangle(), lambda g: g["bufferViews"][0].update(
            byteOffset=18446744073709551608))), "'byteOffset' is not a whole number"),
        ("buffer_short_data", doc("a.gltf", changed(triangle(), lambda g: g["buffers"][0].update(byteLength=1000))),
         "says 1000 bytes, and its data holds 36"),
        ("sparse_index", doc("a.gltf", sparse(1000)), "sparse index 0 is 1000"),
        ("sparse_index_in_a_file", with_files("a.gltf", changed(sparse(1000), lambda g: g["buffers"][0].update(
            uri="s.bin")), {"s.bin": TRIANGLE + struct.pack("<I3f", 1000, 1, 1, 1)}), "sparse index 0 is 1000"),
        ("skin_matrices_overrun", doc("a.gltf", skin(2, 2, 64)), "end at byte"),
        ("skin_too_few_matrices", doc("a.gltf", skin(3, 1, 64)), "inverseBindMatrices"),
        ("skin_no_matrices", doc("a.gltf", changed(skin(2, 2, 128), lambda g: g["skins"][0].pop(
            "inverseBindMatrices"))), "has no inverseBindMatrices"),
        # structure: depth, counts, cycles
        ("nested_nodes", doc("a.gltf", nested_nodes(20000)), "nested more than 64 deep"),
        ("index_1e38", doc("a.gltf", changed(triangle(), lambda g: g["scenes"][0].update(nodes=[1e38]))),
         "holds an index that names nothing"),
        ("node_two_parents", doc("a.gltf", changed(triangle(), lambda g: g.update(
            nodes=[{"mesh": 0, "children": [2]}, {"children": [2]}, {}]))), "a child twice"),
        ("node_cycle", doc("a.gltf", changed(triangle(), lambda g: g.update(
            nodes=[{"mesh": 0, "children": [1]}, {"children": [0]}]))), "form a cycle"),
        ("node_loop", doc("a.gltf", changed(triangle(), lambda g: g.update(
            nodes=[{"mesh": 0}, {"children": [2]}, {"children": [1]}]))), "form a cycle"),
        ("nested_json", doc("a.gltf", deep_json(450000)), "nested more than 32 levels deep"),
        ("many_nodes", doc("a.gltf", changed(triangle(), lambda g: g.update(nodes=[{"mesh": 0}] + [{}] * 70000))),
         "'nodes' has more than 65536 entries"),
        ("many_lights", doc("a.gltf", lights("point", 50000)), "'lights' has more than 4096 entries"),
        ("duplicate_key", doc("a.gltf", json.dumps(triangle())[:-1] + ', "scene": 0}'), "the key 'scene' twice"),
        ("json_nul", doc("a.gltf", json.dumps(triangle("a\\u0000../x.bin")).replace("\\\\u", "\\u")), "NUL"),
        ("json_not_utf8", raw("a.gltf", json.dumps(with_image("a.png")).replace('"a.png"', '"a.png", "mimeType": "image/png"')
                                .encode().replace(b"image/png", b"image\xd5png")), "its JSON is not UTF-8"),
        ("image_mime_no_slash", doc("a.gltf", changed(with_image("a.png"), lambda g: g["images"][0].update(
            uri=None, bufferView=0, mimeType="imagexpng") or g["images"][0].pop("uri"))), "mimeType 'imagexpng'"),
        ("json_broken", doc("a.gltf", json.dumps(triangle())[:-20]), "its JSON cannot be read"),
        ("gltf_1", doc("a.gltf", changed(triangle(), lambda g: g["asset"].update(version="1.0"))),
         "not a glTF 2.0 file"),
        # .glb containers
        ("glb_json_chunk_length", raw("a.glb", glb(triangle(), json_length=0xFFFFFFFF)), "a bad .glb chunk"),
        ("glb_header_length", raw("a.glb", glb(triangle(), total=1 << 30)), "a bad .glb header"),
        # lights the course does not read
        ("light_area", doc("a.gltf", lights("area")), "is of type 'area'"),
        ("light_spot_no_cone", doc("a.gltf", lights("spot", spot=False)), "has no 'spot' object"),
        # memory: counts within the vertex limit, the import over the budget
        ("memory_budget", lazy("a.gltf", lambda d: many_primitives(50, 79998, d)), "more than the budget of 512 MB"),
        ("vertex_limit", lazy("a.gltf", lambda d: many_primitives(60, 79998, d)),
         "more than the limits of 4000000"),
    ]


def write_seeds(folder):
    """Each case's model, when it is one file of at most 8 KB, as a fuzz seed (its format byte first:
    4 .gltf, 5 .glb; tests/fuzz/fuzz_model.c)."""
    with tempfile.TemporaryDirectory() as root:
        outside = os.path.join(root, "outside")
        os.mkdir(outside)
        for index, (name, write, _) in enumerate(cases(outside)):
            folder_in = os.path.join(root, str(index))
            os.mkdir(folder_in)
            model = write(folder_in)
            if len(os.listdir(folder_in)) != 1 or os.path.getsize(os.path.join(folder_in, model)) > 8192:
                continue
            with open(os.path.join(folder_in, model), "rb") as f:
                data = f.read()
            with open(os.path.join(folder, "hostile_" + name + os.path.splitext(model)[1]), "wb") as f:
                f.write(bytes([5 if model.endswith(".glb") else 4]) + data)


def main(argv):
    if argv[1] == "--write-seeds":
        write_seeds(argv[2])
        return 0
    scene_check = argv[1]
    open_log = argv[argv.index("--open-log") + 1] if "--open-log" in argv else None
    sanitized = "--sanitized" in argv
    chapter = "--chapter" in argv
    failures = 0
    with tempfile.TemporaryDirectory() as root:
        outside = os.path.join(root, "outside")
        os.mkdir(outside)
        for name in ("secret.bin", "secret.png"):
            with open(os.path.join(outside, name), "wb") as f:
                f.write(b"\x89PNG\r\n\x1a\n" + b"s" * 64)
        print(f"{'case':<24} {'exit':>4} {'ms':>7} {'MB':>6}  result")
        for index, (name, write, want) in enumerate(cases(outside)):
            folder = os.path.join(root, f"model{index}")
            os.mkdir(folder)
            model = os.path.join(folder, write(folder))
            scene = os.path.join(root, f"{index}.scene")
            with open(scene, "w") as f:
                f.write(f"model {model}\n")
            env = dict(os.environ, CHAPTER="1" if chapter else "0")
            log = os.path.join(root, f"{index}.opens")
            if open_log:
                env.update(LD_PRELOAD=open_log, OPEN_LOG=log)
            rc, err, seconds, rss = run_with_rusage(scene_check, scene, env)
            if chapter and want is None and rc == 77:
                print("skip: the chapter has no GL context (exit 77)")
                return 77
            why = judge(rc, err, want, rss, sanitized, chapter)
            if not why and open_log:
                why = judge_opens(log, model, outside)
            failures += bool(why)
            print(f"{name:<24} {rc if rc is not None else 'hang':>4} {seconds * 1000:7.0f} {rss / 1024:6.0f}  "
                  f"{'ok' if not why else 'FAIL: ' + why}")
            if why:
                print("    stderr: " + err.strip()[:400])
    print(f"{'all' if not failures else failures} {'passed' if not failures else 'failed'}")
    return 1 if failures else 0


def run_with_rusage(program, scene, env):
    """The run, its wall time and its own peak resident size (kB), from wait4. `program` is
    scene_check, or a chapter (CHAPTER=1 in env: one small headless frame of the scene)."""
    start = time.monotonic()
    command = [program, scene]
    if env.get("CHAPTER") == "1":
        command = [program, "--headless", "--frames", "1", "--size", "64x48", "--scene", scene]
    p = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env)
    deadline = start + HANG_S
    err = b""
    os.set_blocking(p.stdout.fileno(), False)
    while True:
        chunk = p.stdout.read()
        if chunk:
            err += chunk
        pid, status, usage = os.wait4(p.pid, os.WNOHANG)
        if pid:
            chunk = p.stdout.read()
            err += chunk or b""
            p.returncode = os.waitstatus_to_exitcode(status)
            return p.returncode, err.decode(errors="replace"), time.monotonic() - start, usage.ru_maxrss
        if time.monotonic() > deadline:
            p.kill()
            os.wait4(p.pid, 0)
            return None, err.decode(errors="replace"), time.monotonic() - start, 0
        time.sleep(0.01)


def judge(rc, err, want, rss, sanitized, chapter):
    """Why the run fails its case, or "". A chapter prints no counts: a good file must load."""
    if rc is None:
        return f"no answer in {HANG_S} s (a hang)"
    if want is None or want.startswith("ok: "):
        if rc != 0:
            return f"exit {rc}, expected 0 (a good file must load)"
        return "" if want is None or chapter or want[4:] in err else f"output lacks '{want[4:]}'"
    lines = [line for line in err.splitlines() if line.strip() and not line.startswith("wrote ")]
    if rc != 2:
        return f"exit {rc}, expected 2" + (" (a signal)" if rc < 0 else "")
    if len(lines) != 1 or "cannot load model" not in lines[0]:
        return f"{len(lines)} lines on stderr, expected one 'cannot load model' line"
    if want not in lines[0]:
        return f"message lacks '{want}'"
    if not sanitized and rss > MEMORY_MB * 1024:
        return f"peaked at {rss // 1024} MB, more than {MEMORY_MB}"
    return ""


def judge_opens(log, model, outside):
    try:
        with open(log) as f:
            opened = [line.rstrip("\n") for line in f]
    except FileNotFoundError:
        opened = []
    if model not in opened:
        return "the open log lacks the model file: the interposer saw nothing"
    inside = os.path.realpath(outside) + os.sep
    for path in opened:
        if os.path.realpath(path).startswith(inside):
            return f"opened '{path}', outside the model's folder"
    return ""


if __name__ == "__main__":
    sys.exit(main(sys.argv))
