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
import pathlib
import re
import sys

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


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("--check", "--update"):
        print("usage: doc_generated.py --check|--update ROOT", file=sys.stderr)
        return 2
    root, update = pathlib.Path(sys.argv[2]), sys.argv[1] == "--update"
    failures = blocks = 0
    for page in sorted((root / "docs").glob("*.md")):
        text = page.read_text()

        def replace(m):
            nonlocal failures, blocks
            blocks += 1
            source = root / m.group(1)
            want = section(source, m.group(2)) if source.exists() else None
            where = f"{page.relative_to(root)}: {m.group(1)}#{m.group(2)}"
            if want is None:
                failures += 1
                print(f"FAIL {where}: no such file or section")
                return m.group(0)
            if m.group(3) == want:
                print(f"ok   {where}")
            elif update:
                print(f"updated {where}")
            else:
                failures += 1
                print(f"FAIL {where}: the page's copy differs from the file (scripts/update-docs.sh, "
                      f"or tests/doc_generated.py --update .)")
            return m.group(0).replace(m.group(3), want, 1) if m.group(3) else m.group(0).replace(
                "-->\n", "-->\n" + want, 1)

        updated = MARK.sub(replace, text)
        if update and updated != text:
            page.write_text(updated)
    if blocks == 0:
        print("no generated block found", file=sys.stderr)
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
