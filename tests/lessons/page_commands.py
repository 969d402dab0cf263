"""page_commands.py - every command a page shows runs as written.

    page_commands.py --run ROOT BUILD PAGE   run PAGE's commands (a path under ROOT: README.md or
                                             docs/NAME.md); exit 0 when every one did what it says
    page_commands.py --list ROOT             the pages that have commands, one per line (CMake makes
                                             one test of each)

A command is a line of a fenced block tagged `sh`. Each block's lines run in order, in one shell per
line, from a scratch folder laid out like the repository's root (assets, docs, scripts, shaders,
tests and tools linked from ROOT, build/ linked to BUILD), so a page's relative paths mean what they
say and what a command writes stays out of the tree. What each line must do:
  - exit 0, or the status its comment names ("# ... exit 1");
  - print every `key=value` its comment names ("# shaded_pixels=368265");
  - finish within TIME_LIMIT seconds.
A chapter opens a window unless told --headless; the machine running the tests may have no display,
so a chapter line without --headless (nor --help or --gl-info) runs with --headless added. A line
that writes a file or a measurement (--screenshot, --bench) must say --headless itself: without a
display it would exit 2, as a learner's would. A chapter's --bench line without --frames runs 2 frames
after 1 warm-up instead of 10 after 3: the same line, the same counts, a rougher time.
A line is not run only when an HTML comment right above its block says so and why:
    <!-- not run: `PREFIX`: the reason -->
and runs with extra arguments when one says
    <!-- short: `PREFIX` with `ARGS`: the reason -->
(PREFIX: the start of the line; a marker that matches no line fails, so none goes stale). A block
with no tag whose lines look like commands fails too: it must be tagged `sh` (or `text` for output).
"""
import os
import pathlib
import re
import shlex
import subprocess
import sys
import tempfile

TIME_LIMIT = 240  # seconds per line: the slowest runs a chapter at 1,024 lights for 13 frames
LINKED = ("assets", "docs", "scripts", "shaders", "tests", "tools")
BLOCK = re.compile(r"((?:<!--[^\n]*-->\n)*)```(\w*)\n(.*?)```", re.S)
NOT_RUN = re.compile(r"<!-- not run: `([^`]+)`: (\S.*?) -->")
SHORT = re.compile(r"<!-- short: `([^`]+)` with `([^`]+)`: (\S.*?) -->")
LOOKS_LIKE_COMMAND = re.compile(r"^\s*(\./scripts/|build/bin/|cmake |ctest |bash |COURSE_\w+=)", re.M)
CHAPTER = re.compile(r"^build/bin/\d\d_\w+$")


def split_comment(line):
    """The command and its trailing comment (a '#' after whitespace, outside quotes)."""
    quote = None
    for i, c in enumerate(line):
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c == "#" and (i == 0 or line[i - 1].isspace()):
            return line[:i].rstrip(), line[i + 1:].strip()
    return line.rstrip(), ""


def joined_lines(body):
    """(index of the first line, the line) with continuation lines (ending in a backslash) joined."""
    lines, start, pending = [], 0, ""
    for k, line in enumerate(body.splitlines()):
        if not pending:
            start = k
        if line.endswith("\\"):
            pending += line[:-1] + " "
            continue
        lines.append((start, pending + line))
        pending = ""
    return lines


def blocks(page_text):
    """(line number, markers text, tag, body) of each fenced block."""
    for m in BLOCK.finditer(page_text):
        yield page_text[:m.start(2)].count("\n") + 1, m.group(1), m.group(2), m.group(3)


def program_of(command):
    """The program a command line runs, after any VAR=value prefixes."""
    words = shlex.split(command)
    while words and re.match(r"^\w+=", words[0]):
        words.pop(0)
    return words[0] if words else ""


def plan_line(command, comment, markers):
    """What to run for one line and what it must do: (run or None, why not, expected status, keys)."""
    for prefix, reason in markers["not_run"]:
        if command.startswith(prefix):
            markers["used"].add(prefix)
            return None, reason, 0, []
    args = command
    for prefix, extra, _ in markers["short"]:
        if command.startswith(prefix):
            markers["used"].add(prefix)
            args += " " + extra
    words = shlex.split(command)
    if program_of(command) == "build/bin/bench" and "--quick" not in args.split():
        return None, "FAIL: the benchmark's sweep takes minutes: give the block a short variant (--quick)", 0, []
    if CHAPTER.match(program_of(command)) and not {"--headless", "--help", "--gl-info"} & set(words):
        if {"--screenshot", "--bench"} & set(words):
            return None, "FAIL: writes a file or a measurement without --headless (exit 2 without a display)", 0, []
        args += " --headless"
    if CHAPTER.match(program_of(command)) and "--bench" in words and "--frames" not in words:
        args += " --frames 2 --warmup 1"  # the same line and counts; the page's 10 frames only time it better
    status = re.search(r"\bexit (\d+)\b", comment)
    keys = re.findall(r"\b(\w+=[\w.]+)", comment.replace(",", ""))
    return args, None, int(status.group(1)) if status else 0, keys


def scratch_root(root, build):
    where = pathlib.Path(tempfile.mkdtemp(prefix="page-commands-"))
    for name in LINKED:
        (where / name).symlink_to(root / name)
    (where / "build").symlink_to(build)
    (where / "out").mkdir()
    return where


def run_line(where, args, status, keys):
    try:
        p = subprocess.run(["bash", "-c", args], cwd=where, capture_output=True, text=True, timeout=TIME_LIMIT)
    except subprocess.TimeoutExpired:
        return f"did not finish in {TIME_LIMIT} s"
    if p.returncode == 77:
        return "skip"
    if p.returncode != status:
        tail = (p.stderr.strip() or p.stdout.strip()).splitlines()[-2:]
        return f"exit {p.returncode}, expected {status}: {' | '.join(tail)}"
    printed = set((p.stdout + p.stderr).split())
    missing = [k for k in keys if k not in printed]
    return f"printed none of {missing}" if missing else None


def markers_of(text):
    return {"not_run": NOT_RUN.findall(text), "short": SHORT.findall(text), "used": set()}


def run_page(root, build, page):
    text = (root / page).read_text()
    where = scratch_root(root, build)
    fails = ran = skipped = 0
    for line_no, marks, tag, body in blocks(text):
        if tag == "" and LOOKS_LIKE_COMMAND.search(body):
            print(f"FAIL {page}:{line_no}: a block of commands without a tag: tag it sh (or text for output)")
            fails += 1
        if tag != "sh":
            continue
        markers = markers_of(marks)
        for k, raw in joined_lines(body):
            command, comment = split_comment(raw)
            if not command:
                continue
            where_line = f"{page}:{line_no + 1 + k}"
            args, why_not, status, keys = plan_line(command, comment, markers)
            if args is None:
                if why_not.startswith("FAIL"):
                    print(f"FAIL {where_line}: {command}: {why_not[6:]}")
                    fails += 1
                else:
                    print(f"not run {where_line}: {command} ({why_not})")
                continue
            result = run_line(where, args, status, keys)
            ran += 1
            if result == "skip":
                print(f"skip {where_line}: {args}: no GL context")
                skipped += 1
            elif result:
                print(f"FAIL {where_line}: {args}: {result}")
                fails += 1
            else:
                print(f"ok   {where_line}: {args}")
        for prefix in {p for p, _ in markers["not_run"]} | {p for p, _, _ in markers["short"]}:
            if prefix not in markers["used"]:
                print(f"FAIL {page}:{line_no}: a marker names `{prefix}`, which no line of the block starts with")
                fails += 1
    subprocess.run(["rm", "-rf", str(where)])
    print(f"{page}: {ran} command(s) run, {fails} failure(s)")
    if fails == 0 and ran > 0 and skipped == ran:
        return 77
    return 1 if fails else 0


def pages_with_commands(root):
    pages = [root / "README.md"] + sorted((root / "docs").glob("*.md"))
    return [p.relative_to(root) for p in pages if re.search(r"```sh\n|" + LOOKS_LIKE_COMMAND.pattern, p.read_text(), re.M)]


def main(argv):
    if len(argv) == 3 and argv[1] == "--list":
        for page in pages_with_commands(pathlib.Path(argv[2])):
            print(page)
        return 0
    if len(argv) == 5 and argv[1] == "--run":
        os.environ.pop("DISPLAY", None)  # as on a machine without one, whatever the tests run under
        return run_page(pathlib.Path(argv[2]).resolve(), pathlib.Path(argv[3]).resolve(), argv[4])
    print(__doc__.split("\n\n")[1], file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
