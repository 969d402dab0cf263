#!/usr/bin/env python3
"""msaa_page_counts.py ROOT - the counts exercise 1 of docs/13_msaa.md states, from the goldens it
names: the pixels of 13_msaa.png that differ from 13_msaa_samples1.png beyond 1/255, the magenta
(edge) pixels of 13_msaa_edges.png, that the first all lie among the second, and how many edge pixels
do not differ. Exit 0 when the page's numbers are the goldens', 1 when not, 2 on bad input."""
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from msaa_edges import load  # noqa: E402


def main(argv):
    if len(argv) != 2:
        print(__doc__)
        return 2
    root = pathlib.Path(argv[1])
    golden = root / "tests" / "golden"
    w, h, msaa = load(golden / "13_msaa.png")
    _, _, one = load(golden / "13_msaa_samples1.png")
    _, _, edges = load(golden / "13_msaa_edges.png")
    cells = [(x, y) for y in range(h) for x in range(w)]
    differ = {p for p in cells if max(abs(a - b) for a, b in zip(msaa[p[1]][p[0]], one[p[1]][p[0]])) > 1}
    magenta = {p for p in cells if edges[p[1]][p[0]] == (255, 0, 255)}
    page = (root / "docs" / "13_msaa.md").read_text()
    m = re.search(r"The ([\d,]+)\s+pixels that differ beyond 1/255 all lie among the ([\d,]+) magenta.*?why do ([\d,]+) edge"
                  r"\s+pixels", page, re.S)
    if not m:
        print("FAIL: exercise 1 of docs/13_msaa.md no longer states its counts")
        return 1
    said = [int(g.replace(",", "")) for g in m.groups()]
    have = [len(differ), len(magenta), len(magenta - differ)]
    print(f"page says differ={said[0]} magenta={said[1]} same={said[2]}; goldens: differ={have[0]} "
          f"magenta={have[1]} same={have[2]}, differing outside the edges: {len(differ - magenta)}")
    return 0 if said == have and not differ - magenta else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
