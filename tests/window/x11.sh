# x11.sh - sourced by the window tests: their own Xvfb, and twm on it, torn down on exit.
#   x11_start          Xvfb on a free display; DISPLAY set; returns 1 (message printed) if it fails
#   x11_start_twm      twm on it (iconifying and placing windows need a window manager)
#   x11_stop           kill what x11_start and x11_start_twm started (the caller's EXIT trap)
# Both need x11_tmp, a scratch folder. Callers skip (77) first when Xvfb or twm is missing:
#   x11_missing        prints "skip: ..." and returns 0 when a tool is not installed
# The waits below poll for readiness and stop as soon as it comes: their limits (30 s) are only there
# so a broken X never hangs a test, and sit far above a start-up on a loaded machine (ctest -j).
x11_xvfb_pid="" x11_twm_pid=""

x11_missing() {
  for tool in Xvfb twm; do
    if ! command -v "$tool" >/dev/null 2>&1; then
      echo "skip: $tool is not installed (scripts/install-deps.sh)"
      return 0
    fi
  done
  return 1
}

x11_stop() {
  [ -n "$x11_twm_pid" ] && kill "$x11_twm_pid" 2>/dev/null && wait "$x11_twm_pid" 2>/dev/null
  [ -n "$x11_xvfb_pid" ] && kill "$x11_xvfb_pid" 2>/dev/null && wait "$x11_xvfb_pid" 2>/dev/null
  x11_twm_pid="" x11_xvfb_pid=""
}

# Xvfb picks a free display itself and writes its number once it accepts connections.
x11_start() {
  Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$x11_tmp/display" 2>"$x11_tmp/xvfb.log" &
  x11_xvfb_pid=$!
  for _ in $(seq 600); do
    grep -q '^[0-9]' "$x11_tmp/display" 2>/dev/null && break
    kill -0 "$x11_xvfb_pid" 2>/dev/null || break
    sleep 0.05
  done
  if ! grep -q '^[0-9]' "$x11_tmp/display" 2>/dev/null; then
    echo "FAIL: Xvfb did not start: $(tail -2 "$x11_tmp/xvfb.log")"
    return 1
  fi
  export DISPLAY=":$(head -1 "$x11_tmp/display")"
  unset WAYLAND_DISPLAY
}

# twm's defaults ask the user to place each new window and use fonts Xvfb may lack.
x11_start_twm() {
  cat >"$x11_tmp/twmrc" <<'TWMRC'
RandomPlacement
UsePPosition "on"
TitleFont "fixed"
ResizeFont "fixed"
MenuFont "fixed"
IconFont "fixed"
IconManagerFont "fixed"
TWMRC
  LC_ALL=C twm -f "$x11_tmp/twmrc" >"$x11_tmp/twm.log" 2>&1 &
  x11_twm_pid=$!
  # twm marks the root window once it manages the screen; without xprop, give it a few seconds
  # (a guess: xprop, from x11-utils, which scripts/install-deps.sh installs, is what to rely on).
  if command -v xprop >/dev/null 2>&1; then
    for _ in $(seq 600); do
      xprop -root 2>/dev/null | grep -q _MIT_PRIORITY_COLORS && break
      sleep 0.05
    done
  else
    sleep 3
  fi
  if ! kill -0 "$x11_twm_pid" 2>/dev/null; then
    echo "FAIL: twm did not start: $(tail -2 "$x11_tmp/twm.log")"
    return 1
  fi
}
