#!/usr/bin/env bash
# run_cli.sh BINARY SOURCE_DIR: the shared command line's promises, checked on one chapter binary:
# --help, exit codes, and one clear line on stderr for every mistake.
set -u
bin=$1 src=$2
name=$(basename "$bin")
pass=0 fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# expect CODE STDERR_SUBSTRING -- ARGS...   (run with no DISPLAY unless the args say otherwise)
expect() {
  local code=$1 want=$2
  shift 3
  env -u DISPLAY -u WAYLAND_DISPLAY "$bin" "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  local lines
  lines=$(grep -c . "$tmp/err")
  if [ "$rc" -eq 77 ] && [ "$code" -ne 77 ] && grep -q "no GL" "$tmp/err"; then
    echo "skip $*: no GL context"; exit 77
  fi
  if [ "$rc" -ne "$code" ]; then
    fail=$((fail + 1)); echo "FAIL [$*]: exit $rc, expected $code; stderr: $(head -3 "$tmp/err")"
  elif [ -n "$want" ] && ! grep -qF -- "$want" "$tmp/err"; then
    fail=$((fail + 1)); echo "FAIL [$*]: stderr lacks '$want': $(head -3 "$tmp/err")"
  elif [ "$code" -eq 2 ] && [ "$lines" -ne 1 ]; then
    fail=$((fail + 1)); echo "FAIL [$*]: expected one line on stderr, got $lines"
  else
    pass=$((pass + 1)); echo "ok   [$*] -> $rc"
  fi
}

expect 0 "" -- --help
grep -q "^usage: $name" "$tmp/out" || { fail=$((fail + 1)); echo "FAIL --help does not start with usage"; }
expect 2 "unknown option '--bogus'" -- --bogus
expect 2 "unexpected argument 'stray'" -- stray
expect 2 "bad --size '0x0'" -- --headless --size 0x0
expect 2 "bad --size '100000x100000'" -- --headless --size 100000x100000
expect 2 "bad --size 'banana'" -- --headless --size banana
expect 2 "bad --frames '-1'" -- --headless --frames -1
expect 2 "bad --frames '0'" -- --headless --frames 0
expect 2 "bad --cutoff '-1'" -- --headless --cutoff -1
expect 2 "bad --cutoff 'nan'" -- --headless --cutoff nan
expect 2 "bad --lights 'many'" -- --headless --lights many
expect 2 "unknown headless backend 'vulkan'" -- --headless=vulkan
expect 2 "--size needs a value" -- --size
expect 2 "cannot open scene" -- --headless --scene "$tmp/missing.scene"
grep -qF "$tmp/missing.scene" "$tmp/err" || { fail=$((fail + 1)); echo "FAIL missing scene message does not name the path"; }
expect 2 "run with --headless" -- --frames 1
# One pixel over the largest width this context allows (it asks the context: llvmpipe 16384,
# NVIDIA 32768).
max=$(env -u DISPLAY "$bin" --headless --gl-info 2>/dev/null | sed -n 's/.*max_width=\([0-9]*\).*/\1/p')
[ -n "$max" ] || { echo "skip: --gl-info found no GL context"; exit 77; }
# The context is the newest core version the driver gives, never below the course's 3.3.
ctx=$(env -u DISPLAY "$bin" --headless --gl-info 2>/dev/null | sed -n 's/^gl: context=\([0-9]*\)\.\([0-9]*\) core.*/\1\2/p')
if [ -n "$ctx" ] && [ "$ctx" -ge 33 ]; then pass=$((pass + 1)); echo "ok   [--gl-info] context ${ctx:0:1}.${ctx:1}"
else fail=$((fail + 1)); echo "FAIL [--gl-info] context '$ctx' (want a core version >= 3.3)"; fi
# Compute shaders are offered exactly where the context is 4.3 or newer (the loader's own flag).
compute=$(env -u DISPLAY "$bin" --headless --gl-info 2>/dev/null | sed -n 's/^gl: compute=\([a-z]*\).*/\1/p')
want=no; [ -n "$ctx" ] && [ "$ctx" -ge 43 ] && want=yes
if [ "$compute" = "$want" ]; then pass=$((pass + 1)); echo "ok   [--gl-info] compute=$compute for ${ctx:0:1}.${ctx:1}"
else fail=$((fail + 1)); echo "FAIL [--gl-info] compute='$compute', expected $want for context $ctx"; fi
expect 2 "larger than this GL allows" -- --headless --size "$((max + 1))x16" --scene "$src/assets/scenes/default.scene"
# The screenshot's format follows its extension; an unknown one is refused before any rendering.
expect 2 "unknown image format" -- --headless --size 32x24 --screenshot "$tmp/shot.gif"
for ext in bmp tga jpg; do
  expect 0 "wrote $tmp/shot.$ext" -- --headless --size 32x24 --screenshot "$tmp/shot.$ext"
done
magic=$(head -c 2 "$tmp/shot.bmp")
[ "$magic" = "BM" ] && pass=$((pass + 1)) || { fail=$((fail + 1)); echo "FAIL shot.bmp is not a BMP"; }
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
