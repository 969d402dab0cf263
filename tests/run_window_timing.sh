#!/usr/bin/env bash
# run_window_timing.sh XVFB_RUN BINARY: the frame time a window shows is the frame time --bench
# measures (same chapter, renderer, scene and size; the animation paused), within 20 %, for the
# deferred renderer and for forward, at 640x480 (longer frames, less relative noise). The window's
# figure is its title, logged with --verbose.
set -u
xvfb=$1 bin=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
for renderer in deferred forward; do
  args=(--size 640x480 --paused --renderer "$renderer")
  "$xvfb" -a -s "-screen 0 1280x1024x24" "$bin" "${args[@]}" --frames 200 --verbose >"$tmp/win" 2>&1
  rc=$?
  if [ $rc -eq 77 ] || grep -q "cannot open display\|DISPLAY" "$tmp/win"; then echo "skip: no display"; exit 77; fi
  window=$(grep "window:" "$tmp/win" | tail -n 1 | sed -n 's/.* | \([0-9.]*\) ms (.*/\1/p')
  bench=$("$bin" --headless "${args[@]}" --bench --frames 30 | sed -n 's/.*median_ms=\([0-9.]*\).*/\1/p')
  if [ -z "$window" ] || [ -z "$bench" ]; then
    echo "FAIL $renderer: no figure (window '$window', bench '$bench', exit $rc)"; tail -3 "$tmp/win"; fail=1
    continue
  fi
  if awk -v w="$window" -v b="$bench" 'BEGIN { d = w - b; if (d < 0) d = -d; exit !(d <= 0.2 * b) }'; then
    echo "ok   $renderer: window $window ms, --bench median $bench ms"
  else
    echo "FAIL $renderer: window $window ms against --bench median $bench ms (more than 20 % apart)"; fail=1
  fi
done
exit $fail
