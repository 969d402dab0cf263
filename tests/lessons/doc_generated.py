#!/usr/bin/python3
"""doc_generated.py - the measured figures a page shows are a verbatim copy of one dated run.

scripts/update-docs.sh writes docs/data/ (chapters.md, bench/bench.md), each starting with a stamp
line (date, machine, renderer, commit). A page embeds a section of such a file like this:

    <!-- generated: docs/data/chapters.md#default-800x600 -->
    ...the section's text, exactly...
    <!-- /generated -->

The section is everything under the line "## default-800x600" up to the next "## " line; the name
"stamp" is the file's stamp line.

    doc_generated.py --check ROOT    exit 1 naming each page whose copy differs from its file
    doc_generated.py --update ROOT   rewrite every copy from the files
"""
import re
import sys

import doc_blocks

MARK = re.compile(r"<!-- generated: (\S+?)#(.+?) -->\n(.*?)<!-- /generated -->\n", re.S)


def section(path, name):
    """The named section of a generated file, or None."""
    lines = path.read_text().splitlines()
    if name == "stamp":
        stamps = [l for l in lines if l.startswith("Measured ")]
        return stamps[0] + "\n" if stamps else None
    out, inside = [], False
    for line in lines:
        if line.startswith("## "):
            if inside:
                break
            inside = line[3:].strip() == name
            continue
        if inside:
            out.append(line)
    if not inside and not out:
        return None
    return "\n".join(out).strip("\n") + "\n"


def expected(root, m):
    source = root / m.group(1)
    return (section(source, m.group(2)) if source.exists() else None), f"{m.group(1)}#{m.group(2)}"


if __name__ == "__main__":
    sys.exit(doc_blocks.run("doc_generated.py", MARK, "*.md", expected))
