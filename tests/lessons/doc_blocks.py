"""doc_blocks.py - what doc_diffs.py and doc_generated.py share: walk the pages, find each marked
block, compare its body with what it should be, and on --update write that instead.

    run(name, mark, pages_glob, expected)
        mark:      a compiled regex whose LAST group is the block's body
        expected:  function(root, match) -> (text or None when it cannot be made, label)
        returns the exit status: 0 all blocks right (or rewritten), 1 a block wrong or none found,
        2 usage
"""
import pathlib
import sys


def run(name, mark, pages_glob, expected):
    if len(sys.argv) != 3 or sys.argv[1] not in ("--check", "--update"):
        print(f"usage: {name} --check|--update ROOT", file=sys.stderr)
        return 2
    root, update = pathlib.Path(sys.argv[2]), sys.argv[1] == "--update"
    counts = {"blocks": 0, "failures": 0}
    for page in sorted((root / "docs").glob(pages_glob)):
        text = page.read_text()

        def replace(m):
            counts["blocks"] += 1
            body = m.group(m.lastindex)
            why = {}
            got = expected(root, m)
            want, label = got[0], got[1]
            if len(got) > 2:
                why["reason"] = got[2]
            where = f"{page.relative_to(root)}: {label}"
            if want is None:
                counts["failures"] += 1
                print(f"FAIL {where}: cannot be made ({why.get('reason', 'no such file or section')})")
                return m.group(0)
            if body == want:
                print(f"ok   {where}")
                return m.group(0)
            if update:
                print(f"updated {where}")
            else:
                counts["failures"] += 1
                print(f"FAIL {where}: the page differs (run tests/{name} --update .)")
            start, end = m.span(m.lastindex)
            whole = m.group(0)
            return whole[: start - m.start()] + want + whole[end - m.start():]

        updated = mark.sub(replace, text)
        if update and updated != text:
            page.write_text(updated)
    if counts["blocks"] == 0:
        print(f"{name}: no marked block found", file=sys.stderr)
        return 1
    return 1 if counts["failures"] else 0
