#!/usr/bin/env python3
"""importance_tiers.py IMAGE.png COUNTS - chapter 14's --view importance against what its page says:
the discs of each tier's colour (shaders/shadow_debug.frag: red tier 0, yellow 1, cyan 2, blue 3),
counted as 4-connected regions of at least MIN_PIXELS pixels within 2/255 of the colour, must be
COUNTS, "t0/t1/t2/t3" (the --bench line's tier_lights=, and docs/14_shadows.md's caption). Render the
view large enough that the discs (12 pixels across at any size) do not touch. Exit 0 pass, 1 fail,
2 bad input. Needs only the standard library."""
import sys

from msaa_edges import load

# The centres' colours, 8-bit: shadow_debug.frag's tier_color() times 255.
TIER_COLOURS = [(255, 38, 26), (255, 230, 26), (0, 217, 230), (38, 64, 255)]
MIN_PIXELS = 20  # a disc's centre (radius 0.7 of 6 pixels) has about 50; stray scene pixels far fewer


def near(c, want):
    return all(abs(a - b) <= 2 for a, b in zip(c, want))


def regions(w, h, rows, colour):
    """The sizes of the 4-connected regions of pixels near `colour`."""
    seen, sizes = set(), []
    for y in range(h):
        for x in range(w):
            if (x, y) in seen or not near(rows[y][x], colour):
                continue
            stack, size = [(x, y)], 0
            seen.add((x, y))
            while stack:
                px, py = stack.pop()
                size += 1
                for nx, ny in ((px + 1, py), (px - 1, py), (px, py + 1), (px, py - 1)):
                    if 0 <= nx < w and 0 <= ny < h and (nx, ny) not in seen and near(rows[ny][nx], colour):
                        seen.add((nx, ny))
                        stack.append((nx, ny))
            sizes.append(size)
    return sizes


def main(argv):
    if len(argv) != 3 or len(argv[2].split('/')) != 4:
        print(__doc__)
        return 2
    want = [int(n) for n in argv[2].split('/')]
    w, h, rows = load(argv[1])
    got = [sum(s >= MIN_PIXELS for s in regions(w, h, rows, c)) for c in TIER_COLOURS]
    ok = got == want
    print(f"importance_tiers: discs per tier {'/'.join(map(str, got))}, expected {argv[2]} -> "
          f"{'PASS' if ok else 'FAIL'}")
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main(sys.argv))
