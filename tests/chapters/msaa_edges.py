#!/usr/bin/env python3
"""msaa_edges.py ONE.png MSAA.png EDGES.png - chapter 13's claims about one flat quad on a background:
the edge mask (EDGES.png, --view edges: edge pixels magenta) lies on the quad's silhouette only, never
inside it; and MSAA anti-aliases: an edge pixel of MSAA.png differs from the 1-sample picture ONE.png
and lies between the two sides (within the range of ONE.png's 3x3 neighbourhood), while every other
pixel is ONE.png's to 1/255. Exit 0 pass, 1 fail, 2 bad input. Needs only the standard library."""
import struct
import sys
import zlib


def load(path):
    """An 8-bit RGB or RGBA PNG, not interlaced, as (width, height, rows of (r, g, b))."""
    data = open(path, 'rb').read()
    pos, idat, width, height, channels = 8, b'', 0, 0, 0
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b'IHDR':
            width, height, depth, colour = struct.unpack('>IIBB', chunk[:10])
            channels = {2: 3, 6: 4}[colour]
        elif kind == b'IDAT':
            idat += chunk
    raw, stride, rows, prev, i = zlib.decompress(idat), width * channels, [], bytearray(width * channels), 0
    for _ in range(height):
        kind, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b, c = prev[x], (prev[x - channels] if x >= channels else 0)
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        prev = line
    return width, height, rows


def main(argv):
    if len(argv) != 4:
        print(__doc__)
        return 2
    w, h, one = load(argv[1])
    _, _, msaa = load(argv[2])
    _, _, edges = load(argv[3])
    magenta = (255, 0, 255)
    edge_count = inside = not_between = differs = other_off = 0
    for y in range(1, h - 1):
        for x in range(1, w - 1):
            around = [one[y + dy][x + dx] for dy in (-1, 0, 1) for dx in (-1, 0, 1)]
            if edges[y][x] != magenta:
                other_off += max(abs(a - b) for a, b in zip(msaa[y][x], one[y][x])) > 1
                continue
            edge_count += 1
            if all(c == one[y][x] for c in around):
                inside += 1  # no colour change in the 1-sample picture around it: inside a surface
            for k in range(3):
                if not min(c[k] for c in around) - 1 <= msaa[y][x][k] <= max(c[k] for c in around) + 1:
                    not_between += 1
                    break
            differs += max(abs(a - b) for a, b in zip(msaa[y][x], one[y][x])) > 1
    ok = edge_count >= 100 and inside == 0 and not_between == 0 and differs * 2 >= edge_count and \
        other_off <= 0.0001 * w * h
    print(f"msaa_edges: edge_pixels={edge_count} inside_surface={inside} not_between_sides={not_between} "
          f"differ_from_1_sample={differs} other_pixels_off={other_off} -> {'PASS' if ok else 'FAIL'}")
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main(sys.argv))
