#!/usr/bin/env bash
# run_ssao_keys.sh IMGDIFF OUTDIR CHAPTER [ARGS...] - the occlusion's keys (T / Y radius, J / L
# directions, B / N blur) in chapter 17 or 19, driven headless by a --script: after each key sequence
# the picture is, byte for byte, the one the matching option draws from the start, and differs from
# the default one. Skips (77) without a GL context; never passes without checking.
set -u
imgdiff=$1 outdir=$2 chapter=$3
shift 3
args=(--headless --size 160x120 --view ao-blurred "$@")
name=$(basename "$chapter")
mkdir -p "$outdir"
out="$outdir/${name}_ssao_keys"
rm -f "$out".*
fail=0
say() { echo "$1"; case $1 in FAIL*) fail=1 ;; esac; }
# case: the keys, pressed one a frame | the option that should draw the same
cases=("Y|--ao-radius 1" "T|--ao-radius 0.25" "L|--ao-samples 32" "J J|--ao-samples 4" "B B|--ao-blur 0"
       "N|--ao-blur 3")
"$chapter" "${args[@]}" --screenshot "$out.default.png" >/dev/null 2>"$out.default.stderr"
rc=$?
if [ "$rc" -eq 77 ]; then echo "skip: no GL context: $(head -1 "$out.default.stderr")"; exit 77; fi
[ "$rc" -eq 0 ] || { echo "FAIL $name: exit $rc: $(head -3 "$out.default.stderr")"; exit 1; }
for i in "${!cases[@]}"; do
  keys=${cases[$i]%%|*} option=${cases[$i]#*|}
  script="$out.$i.script" frame=0
  : >"$script"
  for k in $keys; do echo "$frame key $k" >>"$script"; frame=$((frame + 1)); done
  printf '%d screenshot %s\n%d quit\n' "$frame" "$out.$i.keys.png" "$frame" >>"$script"
  read -r -a opt <<<"$option"
  "$chapter" "${args[@]}" --script "$script" >/dev/null 2>"$out.$i.stderr" || say "FAIL $name keys '$keys': exit $?"
  "$chapter" "${args[@]}" "${opt[@]}" --screenshot "$out.$i.option.png" >/dev/null 2>&1 || say "FAIL $name $option"
  if "$imgdiff" --quiet --tolerance 0 --max-fraction 0 "$out.$i.option.png" "$out.$i.keys.png" >/dev/null 2>&1; then
    say "ok   keys '$keys' draw what $option draws"
  else
    say "FAIL keys '$keys' do not draw what $option draws ($out.$i.keys.png)"
  fi
  "$imgdiff" --quiet --tolerance 0 --max-fraction 0 "$out.default.png" "$out.$i.keys.png" >/dev/null 2>&1 &&
    say "FAIL keys '$keys' left the default picture: the check above proves nothing"
  grep -q 'ambient occlusion: radius' "$out.$i.stderr" || say "FAIL keys '$keys': no line says the new settings"
done
exit "$fail"
