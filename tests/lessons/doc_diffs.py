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
import re
import sys

import doc_blocks

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


def expected(root, m):
    want, kept, total = block(root, m.group(1), m.group(2), m.group(3) or "")
    return want, f"{kept} of {total} hunks of {m.group(1)} -> {m.group(2)}"


if __name__ == "__main__":
    sys.exit(doc_blocks.run("doc_diffs.py", MARK, "[0-9][0-9]_*.md", expected))
