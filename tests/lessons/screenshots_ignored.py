#!/usr/bin/env python3
"""screenshots_ignored.py ROOT | --goldens ROOT - what the pages name as pictures holds.

    ROOT            every file a page tells the learner to write with --screenshot (or --heatmap)
                    from the course's folder is one git leaves out (.gitignore), so following the
                    pages never leaves untracked pictures in the learner's `git status`; 77 when
                    ROOT is not a git checkout
    --goldens ROOT  every tests/golden/NAME.png a page names (an exercise's target) exists
Exit 0 when all hold, 1 naming each that does not."""
import pathlib
import re
import subprocess
import sys

WRITES = re.compile(r"--(?:screenshot|heatmap(?:-on-fail)?)[ =]([\w./-]+\.png)")


GOLDEN = re.compile(r"tests/golden/([\w.-]+\.png)")


def goldens(root):
    pages = [root / "README.md"] + sorted((root / "docs").glob("*.md"))
    named = sorted({(page.name, name) for page in pages for name in GOLDEN.findall(page.read_text())
                    if name != "NAME.png"})
    missing = [(page, name) for page, name in named if not (root / "tests/golden" / name).is_file()]
    for page, name in missing:
        print(f"FAIL {page}: names tests/golden/{name}, which does not exist")
    print(f"{len(named) - len(missing)} of {len(named)} goldens the pages name exist")
    return 1 if missing else 0


def main(argv):
    if argv[1] == "--goldens":
        return goldens(pathlib.Path(argv[2]))
    root = pathlib.Path(argv[1])
    if subprocess.run(["git", "-C", str(root), "rev-parse"], capture_output=True).returncode != 0:
        print("skip: not a git checkout")
        return 77
    pages = [root / "README.md"] + sorted((root / "docs").glob("*.md"))
    written = sorted({(page.name, path) for page in pages for path in WRITES.findall(page.read_text())
                      if not path.startswith(("/", "$"))})
    bad = [(page, path) for page, path in written
           if subprocess.run(["git", "-C", str(root), "check-ignore", "-q", "--no-index", path]).returncode != 0]
    for page, path in bad:
        print(f"FAIL {page}: writes '{path}', which git would list as untracked")
    print(f"{len(written) - len(bad)} of {len(written)} pictures the pages write are ignored by git")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
