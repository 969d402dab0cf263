#!/usr/bin/env bash
# run_overdraw_count.sh HEAT_COUNT OUT.png CLAIM -- COMMAND... [-- LIT_ONLY_ARGS...]
# The overdraw view's picture as a claim (tools/heat_count.c reads it back into counts). COMMAND is
# run once with --view overdraw --bench --screenshot OUT.png and, for lit-run, once more as it is
# with --bench (plus LIT_ONLY_ARGS), and `shaded_pixels` (GL_SAMPLES_PASSED) is taken from the
# --bench lines. CLAIM:
#   lit-run    the heat map's total = the lit view's shaded_pixels = the overdraw run's own: the
#              count is of the fragments the lighting pass runs (chapters 06-07: no discard)
#   same-run   the heat map's total = the overdraw run's shaded_pixels (chapters 04-05, whose lit
#              pass discards after running, so its own count is smaller)
#   loop       every covered pixel shows active_lights, and the covered pixels = shaded_pixels
#              (chapter 03: the loop evaluates every light at every covered pixel)
# Exit 77 (no GL context) passes through as a skip.
set -u
heat_count=$1 out=$2 claim=$3
shift 3
[ "$1" = "--" ] && shift
cmd=() lit_only=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do cmd+=("$1"); shift; done
[ $# -gt 0 ] && shift
lit_only=("$@")
mkdir -p "$(dirname "$out")"
rm -f "$out"

field() { # field NAME BENCH_LINE
  sed -n "s/.* $1=\([0-9-]*\).*/\1/p" <<<"$2"
}
bench() { # bench ARGS...: the command's bench line, or exit with its status
  local line rc
  line=$("${cmd[@]}" --bench "$@")
  rc=$?
  if [ $rc -eq 77 ]; then echo "skip: no GL context" >&2; exit 77; fi
  if [ $rc -ne 0 ]; then echo "FAIL: '${cmd[*]} --bench $*' exited with $rc" >&2; exit 1; fi
  grep '^bench:' <<<"$line"
}

overdraw=$(bench --view overdraw --screenshot "$out") || exit $?
shaded=$(field shaded_pixels "$overdraw")
lights=$(field active_lights "$overdraw")
[ -n "$shaded" ] && [ "$shaded" -ge 0 ] || { echo "FAIL: no shaded_pixels in: $overdraw"; exit 1; }
echo "overdraw view: shaded_pixels=$shaded active_lights=$lights"
case $claim in
  lit-run)
    lit=$(bench "${lit_only[@]}") || exit $?
    lit_shaded=$(field shaded_pixels "$lit")
    echo "lit view${lit_only[*]:+ (${lit_only[*]})}: shaded_pixels=$lit_shaded"
    if [ "$lit_shaded" != "$shaded" ]; then
      echo "FAIL: the overdraw view's pass counted $shaded fragments, the lit view's $lit_shaded"
    fi
    "$heat_count" --expect-sum "$lit_shaded" "$out" && [ "$lit_shaded" = "$shaded" ] ;;
  same-run)
    "$heat_count" --expect-sum "$shaded" "$out" ;;
  loop)
    "$heat_count" --expect-each "$lights" --expect-covered "$shaded" "$out" ;;
  *)
    echo "unknown claim '$claim'"; exit 2 ;;
esac
