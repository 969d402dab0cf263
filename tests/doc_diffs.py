#!/usr/bin/python3
"""doc_diffs.py - the "what changed" block of each chapter page is the real diff of two chapter files.

A page marks its block like this (the pattern picks the essential hunks: those with a changed code
line (not a comment or an #include) that matches it; an empty pattern keeps every hunk; one line of context):

    <!-- what-changed: chapters/05_attenuation_radius.c chapters/06_additive_blending.c GL_ONE|accum -->
    ```diff
    ...hunks of `diff -u`...
    ```
    <!-- /what-changed -->

    doc_diffs.py --check ROOT    exit 1 and name the page when a block is not what the files give
    doc_diffs.py --update ROOT   rewrite every block from the files
"""
import difflib
import pathlib
import re
import sys

MARK = re.compile(r"<!-- what-changed: (\S+) (\S+)(?: (.*?))? -->\n(.*?)<!-- /what-changed -->\n", re.S)


def hunks(old, new):
    """The unified diff of two files (1 line of context), split into hunks (header first)."""
    a = old.read_text().splitlines()
    b = new.read_text().splitlines()
    lines = list(difflib.unified_diff(a, b, str(old.name), str(new.name), n=1, lineterm=""))
    out, cur = [], None
    for line in lines[2:]:
        if line.startswith("@@"):
            cur = [line]
            out.append(cur)
        else:
            cur.append(line)
    return [f"--- {old.name}", f"+++ {new.name}"], out


def is_code_change(line):
    """An added or removed line of code: the banners' prose and the includes are not the lesson."""
    body = line[1:].lstrip()
    return line[:1] in "+-" and not body.startswith(("*", "/*", "//", "#include"))


def block(root, old, new, pattern):
    head, all_hunks = hunks(root / old, root / new)
    rx = re.compile(pattern) if pattern else None
    keep = [h for h in all_hunks if rx is None or any(is_code_change(l) and rx.search(l) for l in h[1:])]
    text = "\n".join(head + [l for h in keep for l in h])
    return f"```diff\n{text}\n```\n", len(keep), len(all_hunks)


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("--check", "--update"):
        print(__doc__.strip().splitlines()[0])
        print("usage: doc_diffs.py --check|--update ROOT", file=sys.stderr)
        return 2
    root = pathlib.Path(sys.argv[2])
    failures = pages = 0
    for page in sorted((root / "docs").glob("[0-9][0-9]_*.md")):
        text = page.read_text()
        def replace(m):
            nonlocal failures, pages
            pages += 1
            want, kept, total = block(root, m.group(1), m.group(2), m.group(3) or "")
            if m.group(4) != want and sys.argv[1] == "--update":
                print(f"updated {page.relative_to(root)}: {kept} of {total} hunks")
            elif m.group(4) != want:
                failures += 1
                print(f"{page.relative_to(root)}: the what-changed block differs from "
                      f"diff -u {m.group(1)} {m.group(2)} (run tests/doc_diffs.py --update .)")
            else:
                print(f"ok   {page.relative_to(root)}: {kept} of {total} hunks of {m.group(1)} -> {m.group(2)}")
            return m.group(0).replace(m.group(4), want)
        updated = MARK.sub(replace, text)
        if sys.argv[1] == "--update" and updated != text:
            page.write_text(updated)
    if pages == 0:
        print("no what-changed block found", file=sys.stderr)
        return 1
    return 1 if failures and sys.argv[1] == "--check" else 0


if __name__ == "__main__":
    sys.exit(main())
