#!/usr/bin/env bash
# run_minimise.sh IMGDIFF OUTDIR GOLDEN_DIR BINARY...
# A window minimised and restored (--minimise-cycle 3) must draw nothing while minimised, leak no
# GL object, and end on the same picture as tests/golden/NAME.png.
#
# Iconifying is a request to a window manager: on a bare X server nothing happens, so this script
# runs its own Xvfb with twm on it. It checks, in order:
#   1. --minimise-cycle's command-line errors (no display needed);
#   2. without a window manager the run skips (exit 77, "no window manager: cannot minimise")
#      instead of passing without having minimised anything;
#   3. with twm, each BINARY minimises and restores its window 3 times and its screenshot matches
#      the golden (tolerance 1/255 on 99.99 % of pixels, as every window test).
# Exit 77 (skip) when Xvfb or twm is not installed or there is no GL context.
set -u
imgdiff=$1 outdir=$2 golden_dir=$3
shift 3
fail=0
tmp=$(mktemp -d)
x11_tmp=$tmp
. "$(dirname "$0")/x11.sh"
trap 'x11_stop; rm -rf "$tmp"' EXIT

# 1. Command line: rejected with one line wherever it cannot work.
# usage CODE STDERR_SUBSTRING ARGS...
usage() {
  local code=$1 want=$2
  shift 2
  env -u DISPLAY -u WAYLAND_DISPLAY "$1" "${@:2}" >/dev/null 2>"$tmp/err"
  local rc=$? lines
  lines=$(grep -c . "$tmp/err")
  if [ "$rc" -ne "$code" ] || ! grep -qF -- "$want" "$tmp/err" || [ "$lines" -ne 1 ]; then
    echo "FAIL [${*:2}]: exit $rc ($lines line(s)), expected $code and '$want': $(head -2 "$tmp/err")"
    fail=1
  else
    echo "ok   [${*:2}] -> $rc"
  fi
}
usage 2 "--minimise-cycle minimises the window: not with --headless" "$1" --headless --minimise-cycle 3
usage 2 "--minimise-cycle stops the frames it would time: not with --bench" "$1" --bench --minimise-cycle 3
usage 2 "bad --minimise-cycle 'x'" "$1" --minimise-cycle x
usage 2 "bad --minimise-cycle '-1'" "$1" --minimise-cycle -1
[ "$fail" -eq 0 ] || exit 1

x11_missing && exit 77
x11_start || exit 1

# 2. No window manager yet: glfwIconifyWindow does nothing, and the run must say so and skip.
"$1" --size 320x240 --frames 2 --paused --minimise-cycle 1 >/dev/null 2>"$tmp/err"
rc=$?
if [ "$rc" -eq 77 ] && ! grep -q "no window manager" "$tmp/err"; then
  echo "skip: no GL context"
  exit 77
fi
if [ "$rc" -ne 77 ] || ! grep -qxF "no window manager: cannot minimise" "$tmp/err"; then
  echo "FAIL: without a window manager: exit $rc, expected 77 and 'no window manager: cannot minimise':" \
       "$(head -2 "$tmp/err")"
  exit 1
fi
echo "ok   no window manager -> 77"

x11_start_twm || exit 1

# 3. Minimise and restore three times, then the usual frames and the screenshot.
mkdir -p "$outdir"
for bin in "$@"; do
  name=$(basename "$bin")
  actual="$outdir/window.minimise.$name.png"
  rm -f "$actual" "$outdir/window.minimise.$name.diff.png"
  "$bin" --size 320x240 --frames 3 --paused --gl-debug --minimise-cycle 3 --screenshot "$actual" \
    2>"$tmp/err"
  rc=$?
  if [ "$rc" -ne 0 ]; then
    # Even a 77 is a failure here: a window manager is running, so the window must minimise.
    echo "FAIL [$name]: exit $rc: $(grep -v '^warning: \|^wrote ' "$tmp/err" | head -3)"
    fail=1
    continue
  fi
  if ! "$imgdiff" --tolerance 1 --max-fraction 0.0001 --heatmap-on-fail "$outdir/window.minimise.$name.diff.png" \
       "$golden_dir/$name.png" "$actual"; then
    echo "FAIL [$name]: picture after minimising differs from $golden_dir/$name.png (actual: $actual)"
    fail=1
    continue
  fi
  echo "ok   $name minimised and restored 3 times, picture equal to the golden"
done
exit "$fail"
