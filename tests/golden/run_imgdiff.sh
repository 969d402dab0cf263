#!/usr/bin/env bash
# run_imgdiff.sh - run imgdiff and check its exit status, its verdict, and the files it should (not) write.
#
#   run_imgdiff.sh STATUS [--creates PNG] [--no-file PNG] [--says TEXT] -- IMGDIFF [ARGS...]
#
# STATUS is the expected exit status (0 pass, 1 differ, 2 error). Status 0 and 1 must also print the
# matching "-> PASS" / "-> FAIL" line. --creates names a file that must exist afterwards and be a PNG;
# --no-file names one that must not. Both are removed before the run so an old file proves nothing.
# --says TEXT must appear in the error output (the message has to name what went wrong).
set -u

expected=$1
shift
creates=()
absent=()
says=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    case $1 in
        --creates) creates+=("$2"); shift 2 ;;
        --no-file) absent+=("$2"); shift 2 ;;
        --says) says+=("$2"); shift 2 ;;
        *) echo "run_imgdiff.sh: unknown argument $1" >&2; exit 2 ;;
    esac
done
shift # the "--"

for f in ${creates[@]+"${creates[@]}"} ${absent[@]+"${absent[@]}"}; do
    mkdir -p "$(dirname "$f")"
    rm -f "$f"
done

errors=$(mktemp)
trap 'rm -f "$errors"' EXIT
output=$("$@" 2>"$errors")
status=$?
printf '%s\n' "$output"
cat "$errors" >&2

fail() { echo "run_imgdiff.sh: $*" >&2; exit 1; }

[ "$status" -eq "$expected" ] || fail "exit status $status, expected $expected"
case $expected in
    0) [[ $output == *"-> PASS"* ]] || fail "no PASS line" ;;
    1) [[ $output == *"-> FAIL"* ]] || fail "no FAIL line" ;;
esac
for f in ${creates[@]+"${creates[@]}"}; do
    [ -s "$f" ] || fail "$f was not written"
    [ "$(head -c 4 "$f" | tail -c 3)" = "PNG" ] || fail "$f is not a PNG"
done
for f in ${absent[@]+"${absent[@]}"}; do
    [ ! -e "$f" ] || fail "$f should not have been written"
done
for text in ${says[@]+"${says[@]}"}; do
    grep -qF -- "$text" "$errors" || fail "error output does not mention '$text'"
done
exit 0
