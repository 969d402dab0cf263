#!/usr/bin/env bash
# run_bad.sh SCENE_CHECK_BIN BAD_DIR - every malformed scene must be rejected with the expected message.
#
# Each BAD_DIR/NAME.scene starts with "# expect: SUBSTRING". scene_check must exit with status 2 and
# print exactly one line on stderr that contains SUBSTRING. Cases whose second line is
# "# expect-at: render" fail only when the model is loaded, so they are skipped here.
# Also checked: a scene file that does not exist is reported with its path.
set -u

if [ $# -ne 2 ]; then
    echo "usage: $0 SCENE_CHECK_BIN BAD_DIR" >&2
    exit 2
fi
bin=$1
dir=$2
err=$(mktemp)
trap 'rm -f "$err"' EXIT

passed=0
failed=0
skipped=0

# check NAME WANT ARGS...: run scene_check on ARGS and compare with WANT.
check() {
    local name=$1 want=$2
    shift 2
    "$bin" "$@" >/dev/null 2>"$err"
    local status=$? lines
    lines=$(wc -l <"$err")
    local why=""
    if [ "$status" -ne 2 ]; then
        why="exit status $status, expected 2"
    elif [ "$lines" -ne 1 ]; then
        why="$lines lines on stderr, expected 1"
    elif ! grep -qF -- "$want" "$err"; then
        why="message does not contain '$want'"
    fi
    if [ -z "$why" ]; then
        echo "PASS $name"
        passed=$((passed + 1))
    else
        echo "FAIL $name: $why"
        sed 's/^/    stderr: /' "$err" | head -n 5 | cut -c1-200
        failed=$((failed + 1))
    fi
}

shopt -s nullglob
for scene in "$dir"/*.scene; do
    name=$(basename "$scene")
    first=$(head -n 1 "$scene")
    second=$(sed -n 2p "$scene")
    case $first in
        "# expect: "?*) want=${first#"# expect: "} ;;
        *)
            echo "FAIL $name: first line is not '# expect: SUBSTRING'"
            failed=$((failed + 1))
            continue
            ;;
    esac
    if [ "$second" = "# expect-at: render" ]; then
        echo "SKIP $name (checked when the model is loaded)"
        skipped=$((skipped + 1))
        continue
    fi
    check "$name" "$want" "$scene"
done

missing="$dir/does-not-exist.scene"
check "missing file" "$missing: cannot open scene: No such file or directory" "$missing"

if [ $((passed + failed)) -lt 2 ]; then
    echo "FAIL no cases found in $dir"
    failed=$((failed + 1))
fi
echo "$passed passed, $failed failed ($skipped skipped)"
[ "$failed" -eq 0 ]
