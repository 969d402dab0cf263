#!/usr/bin/env bash
# run_softpipe.sh KIND ARGS...
# One golden or agreement test on Mesa's softpipe instead of llvmpipe: tests/golden/run_KIND.sh
# (KIND is golden or agreement) with ARGS, its own arguments (IMGDIFF OUTDIR NAME [GOLDEN] TOLERANCE
# MAX_FRACTION -- COMMAND... [-- COMMAND...]), softpipe's bound already in them
# (tests/softpipe/softpipe.cmake), and GALLIUM_DRIVER=softpipe.
#
# A test passes only on softpipe: each command's back end (--headless, --headless=osmesa) is asked
# first with --gl-info, under the same environment, and a renderer other than softpipe, or none,
# exits 77 (skipped, with the renderer it got), never a pass on another driver.
# Softpipe's context is GL 3.3 with GL_MAX_SAMPLES 1: a test whose chapter refuses to run for what
# the context lacks (its own message: "--path compute needs compute shaders (OpenGL 4.3), which this
# context does not have", "bad --samples '4': this context allows at most 1") is skipped with that
# message, and only when --gl-info confirms the lack; any other failure is a failure.
# COURSE_SOFTPIPE_UNCHECKED=REASON skips the test (on softpipe it would pass for nothing), and
# COURSE_SOFTPIPE_KNOWN=REASON prints the known difference the test expects (tests/softpipe/softpipe.cmake).
set -u
export GALLIUM_DRIVER=softpipe
kind=$1
shift
args=("$@")
n=${#args[@]}

# command_of I: the command that starts after the "--" at index I, into cmd.
command_of() {
  local j
  cmd=()
  for ((j = $1 + 1; j < n; j++)); do
    [ "${args[$j]}" = "--" ] && break
    cmd+=("${args[$j]}")
  done
}

for ((i = 0; i < n; i++)); do
  [ "${args[$i]}" = "--" ] || continue
  command_of "$i"
  backend=--headless
  for a in "${cmd[@]}"; do
    case $a in --headless | --headless=*) backend=$a ;; esac
  done
  info=$("${cmd[0]}" "$backend" --gl-info 2>&1)
  renderer=$(sed -n 's/^gl: renderer=//p' <<<"$info")
  got=$(sed -n 's/^gl: backend=\([a-z]*\).*/\1/p' <<<"$info")
  version=$(sed -n 's/^gl: version=//p' <<<"$info")
  case $renderer in
    softpipe*) echo "softpipe: ${cmd[0]##*/} backend=$got renderer=$renderer version=$version" ;;
    *)
      echo "skip: GALLIUM_DRIVER=softpipe gave renderer '${renderer:-none}'" \
        "(backend ${got:-none}), not softpipe"
      exit 77
      ;;
  esac
  [ -z "${first_info:-}" ] && first_info=$info
done

if [ -n "${COURSE_SOFTPIPE_UNCHECKED:-}" ]; then
  echo "skip: not checked on softpipe: $COURSE_SOFTPIPE_UNCHECKED"
  exit 77
fi
[ -n "${COURSE_SOFTPIPE_KNOWN:-}" ] &&
  echo "known difference on softpipe (this test passes only while the pictures differ):" \
    "$COURSE_SOFTPIPE_KNOWN"

log=$(mktemp)
trap 'rm -f "$log"' EXIT
bash "$(dirname "$0")/../golden/run_$kind.sh" "${args[@]}" 2>&1 | tee "$log"
rc=${PIPESTATUS[0]}
[ "$rc" -eq 0 ] && exit 0
if grep -q 'needs compute shaders (OpenGL 4.3), which this context does not have' "$log" &&
  ! grep -q '^gl: compute=yes' <<<"$first_info"; then
  gl=$(sed -n 's/^gl: version=\([0-9.]*\).*/GL \1/p' <<<"$first_info")
  echo "skip: softpipe's context ($gl) has no compute shaders, which this test asks for"
  exit 77
fi
max=$(sed -n 's/^gl: .* max_samples=\([0-9]*\).*/\1/p' <<<"$first_info")
if [ -n "$max" ] && grep -q "this context allows at most $max (GL_MAX_SAMPLES $max" "$log"; then
  echo "skip: softpipe's GL_MAX_SAMPLES is $max, fewer samples than this test asks for"
  exit 77
fi
exit "$rc"
