#!/usr/bin/env python3
"""probe_exercise.py ROOT - exercise 2 of docs/19_image_based_light.md, checked: its scene is
assets/scenes/default.scene with only the middle probe's line changed (the copy cannot drift), and
the number of pixels its page says fall back to the constant ambient is what the two goldens hold
(the black pixels of 19_image_based_light_probe_raised.png beyond those of ..._probe.png: --view
probe draws black outside every probe). The goldens themselves are golden.19_image_based_light_*.
Exit 0 when both hold, 1 when not."""
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from msaa_edges import load  # noqa: E402


def black(path):
    w, h, px = load(path)
    return sum(1 for y in range(h) for x in range(w) if px[y][x] == (0, 0, 0))


def main(argv):
    root = pathlib.Path(argv[1])
    scene = [line for line in (root / "tests/scenes/default_probe_raised.scene").read_text().splitlines()]
    base = (root / "assets/scenes/default.scene").read_text().splitlines()
    scene = scene[2:]  # its own two comment lines
    changed = [(a, b) for a, b in zip(base, scene) if a != b]
    if len(scene) != len(base) or changed != [("probe 0.3 1.2 0.2 radius 4.5", "probe 0.3 4 0.2 radius 4.5")]:
        print(f"FAIL: default_probe_raised.scene differs from default.scene in more than the probe: {changed}")
        return 1
    golden = root / "tests/golden"
    more = black(golden / "19_image_based_light_probe_raised.png") - black(golden / "19_image_based_light_probe.png")
    page = (root / "docs/19_image_based_light.md").read_text()
    m = re.search(r"([\d,]+) more pixels are black", page)
    if not m or int(m.group(1).replace(",", "")) != more:
        print(f"FAIL: the goldens have {more:,} more black pixels; exercise 2 says {m.group(1) if m else 'nothing'}")
        return 1
    print(f"ok   the raised probe leaves {more:,} more pixels to the constant ambient, as the page says")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
