#!/usr/bin/python3
"""doc_diffs.py - the "what changed" block of each chapter page is the real diff of two chapter files.

A page marks its block like this (the pattern picks the essential hunks: those with a changed code
line (not a comment or an #include) that matches it; an empty pattern keeps every hunk; one line of context).
A block longer than LONG lines shows, inside each hunk, only the changed lines that match the pattern
with CONTEXT lines around them; each stretch left out is one line " ... N lines of the hunk not shown":

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


LONG = 250   # lines: a longer block is cut to the lines around its pattern's matches
CONTEXT = 3  # lines kept on each side of a matching changed line in a cut block


def essential(hunk, rx):
    """The hunk's header, the changed lines that match rx with CONTEXT lines around them, and one line
    for each stretch left out."""
    body = hunk[1:]
    wanted = [i for i, l in enumerate(body) if is_code_change(l) and (rx is None or rx.search(l))]
    show = {j for i in wanted for j in range(i - CONTEXT, i + CONTEXT + 1) if 0 <= j < len(body)}
    out, gap = [hunk[0]], 0
    for i, line in enumerate(body):
        if i in show:
            if gap:
                out.append(f" ... {gap} lines of the hunk not shown")
            out.append(line)
            gap = 0
        else:
            gap += 1
    if gap:
        out.append(f" ... {gap} lines of the hunk not shown")
    return out


def block(root, old, new, pattern):
    head, all_hunks = hunks(root / old, root / new)
    rx = re.compile(pattern) if pattern else None
    keep = [h for h in all_hunks if rx is None or any(is_code_change(l) and rx.search(l) for l in h[1:])]
    if sum(len(h) for h in keep) > LONG:
        keep = [essential(h, rx) for h in keep]
    text = "\n".join(head + [l for h in keep for l in h])
    return f"```diff\n{text}\n```\n", len(keep), len(all_hunks)


MAX_BLOCK = 250  # lines a block may have after the cut: past that it no longer shows the lesson


def expected(root, m):
    want, kept, total = block(root, m.group(1), m.group(2), m.group(3) or "")
    label = f"{kept} of {total} hunks of {m.group(1)} -> {m.group(2)}"
    if want.count("\n") > MAX_BLOCK:
        return None, label, f"{want.count(chr(10))} lines, more than {MAX_BLOCK}: narrow its pattern or pick another base"
    return want, label


if __name__ == "__main__":
    sys.exit(doc_blocks.run("doc_diffs.py", MARK, "[0-9][0-9]_*.md", expected))
