#!/usr/bin/env bash
# run_self_check.sh SRC: run_softpipe.sh never passes a test that did not run on softpipe. A fake
# chapter answers --gl-info with the renderer FAKE_RENDERER names ("driver": whatever GALLIUM_DRIVER
# asks for), FAKE_OSMESA the one its OSMesa back end gets, FAKE_SAMPLES its GL_MAX_SAMPLES and
# FAKE_COMPUTE whether it has compute shaders; it refuses more samples than that (its --samples, or
# FAKE_DEFAULT_SAMPLES) and "--path compute" without compute in the chapters' own words, and exits
# FAKE_EXIT when set. A fake imgdiff leaves a mark, so a skipped test is seen to compare nothing, and
# fails when FAKE_DIFF=fail. No GL needed.
set -u
src=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0

cat >"$tmp/chapter" <<'EOF'
#!/usr/bin/env bash
backend=egl shot="" path="" samples=${FAKE_DEFAULT_SAMPLES:-1} max=${FAKE_SAMPLES:-1}
while [ $# -gt 0 ]; do
  case $1 in
    --headless=osmesa) backend=osmesa ;;
    --gl-info) info=1 ;;
    --screenshot) shot=$2; shift ;;
    --samples) samples=$2; shift ;;
    --path) path=$2; shift ;;
  esac
  shift
done
renderer=${FAKE_RENDERER:-driver}
[ "$backend" = osmesa ] && renderer=${FAKE_OSMESA:-$renderer}
[ "$renderer" = driver ] && renderer=${GALLIUM_DRIVER:-llvmpipe}
if [ -n "${info:-}" ]; then
  [ "$renderer" = crash ] && kill -SEGV $$
  echo "gl: backend=$backend max_width=16384 max_samples=$max"
  echo "gl: renderer=$renderer"
  echo "gl: version=3.3 (Core Profile) Mesa 22.3.6"
  echo "gl: compute=${FAKE_COMPUTE:-no} (compute shaders: core since 4.3)"
  exit 0
fi
if [ "$samples" -gt "$max" ]; then
  echo "chapter: bad --samples '$samples': this context allows at most $max (GL_MAX_SAMPLES $max, ...)" >&2
  exit 2
fi
if [ "$path" = compute ]; then
  echo "--path compute needs compute shaders (OpenGL 4.3), which this context does not have:" \
    "use --path cpu" >&2
  exit 1
fi
[ -n "${FAKE_EXIT:-}" ] && exit "$FAKE_EXIT"
: >"$shot"
EOF
cat >"$tmp/imgdiff" <<'EOF'
#!/usr/bin/env bash
echo compared >>"$(dirname "$0")/compared"
[ "${FAKE_DIFF:-}" = fail ] && { echo "imgdiff: max=108 -> FAIL"; exit 1; }
echo "imgdiff: max=0 -> PASS"
EOF
chmod +x "$tmp/chapter" "$tmp/imgdiff"
: >"$tmp/golden.png"

# expect WHAT RC PATTERN COMPARED -- ARGS...: run_softpipe.sh ARGS exits RC, says PATTERN, and
# compared (yes) or did not (no).
expect() {
  local what=$1 want=$2 pattern=$3 compared=$4
  shift 5
  rm -f "$tmp/compared"
  out=$(env -u GALLIUM_DRIVER bash "$src/tests/softpipe/run_softpipe.sh" "$@" 2>&1)
  rc=$?
  local did=no
  [ -f "$tmp/compared" ] && did=yes
  if [ $rc -ne "$want" ] || ! grep -q -- "$pattern" <<<"$out" || [ $did != "$compared" ]; then
    echo "FAIL: $what: exit $rc (want $want), compared: $did (want $compared), output:"
    sed 's/^/    /' <<<"$out"
    fails=$((fails + 1))
  else
    echo "ok: $what: exit $rc, $(grep -m1 -- "$pattern" <<<"$out")"
  fi
}

golden=(golden "$tmp/imgdiff" "$tmp/out" g "$tmp/golden.png" 1 0.0001 -- "$tmp/chapter" --headless)
agree=(agreement "$tmp/imgdiff" "$tmp/out" a 1 0.0001 -- "$tmp/chapter" --headless -- "$tmp/chapter"
       --headless=osmesa)

expect "softpipe runs the test" 0 "renderer=softpipe" yes -- "${golden[@]}"
FAKE_DIFF=fail expect "a difference on softpipe fails" 1 "max=108 -> FAIL" yes -- "${golden[@]}"
FAKE_EXIT=3 expect "a chapter that fails, fails" 1 "exited with 3" no -- "${golden[@]}"
FAKE_RENDERER=llvmpipe expect "llvmpipe is skipped" 77 "gave renderer 'llvmpipe'" no -- "${golden[@]}"
FAKE_RENDERER=crash expect "no context is skipped" 77 "gave renderer 'none'" no -- "${golden[@]}"
FAKE_OSMESA=llvmpipe expect "one side elsewhere is skipped" 77 "(backend osmesa), not softpipe" no \
  -- "${agree[@]}"
expect "both sides on softpipe" 0 "backend=osmesa renderer=softpipe" yes -- "${agree[@]}"
expect "more samples than the context's is skipped" 77 "GL_MAX_SAMPLES is 1, fewer samples" no \
  -- "${golden[@]}" --samples 4
FAKE_SAMPLES=4 expect "samples the context has run" 0 "renderer=softpipe" yes -- "${golden[@]}" --samples 4
FAKE_DEFAULT_SAMPLES=4 expect "a chapter's default samples count" 77 "GL_MAX_SAMPLES is 1" no \
  -- "${golden[@]}"
FAKE_DEFAULT_SAMPLES=4 expect "--samples 1 on that chapter runs" 0 "renderer=softpipe" yes \
  -- "${golden[@]}" --samples 1
FAKE_SAMPLES=2 expect "2 samples of 4 is skipped too" 77 "GL_MAX_SAMPLES is 2" no \
  -- "${golden[@]}" --samples 4
expect "compute refused is skipped" 77 "has no compute shaders" no -- "${agree[@]}" --path compute
FAKE_COMPUTE=yes expect "a compute refusal where --gl-info has compute fails" 1 "exited with 1" no \
  -- "${agree[@]}" --path compute
COURSE_SOFTPIPE_UNCHECKED="both sides alike" expect "an unchecked test is skipped" 77 \
  "skip: not checked on softpipe: both sides alike" no -- "${golden[@]}"
COURSE_SOFTPIPE_UNCHECKED="x" FAKE_RENDERER=llvmpipe expect "unchecked elsewhere: skipped for the driver" 77 \
  "gave renderer 'llvmpipe'" no -- "${golden[@]}"
COURSE_SOFTPIPE_KNOWN="a driver bug" FAKE_DIFF=fail expect "a known difference says so and compares" 1 \
  "known difference on softpipe .*: a driver bug" yes -- "${golden[@]}"

[ $fails -eq 0 ] && echo "softpipe self-check: all passed"
exit $((fails > 0))
