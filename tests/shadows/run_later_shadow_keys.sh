#!/usr/bin/env bash
# run_later_shadow_keys.sh IMGDIFF OUTDIR CHAPTER KEY [ARGS...] - chapter 14's shadows in a later
# chapter (15 to 19, --shadows N), driven headless by a --script (the window's events, frame by frame):
#   1. with --shadows 80, KEY turns them off: the picture is the chapter's own without --shadows, byte
#      for byte, drawn by the programs built without SHADOWS (off costs nothing); KEY again: the
#      shadowed picture again, by the SHADOWS programs
#   2. without --shadows, KEY changes nothing and says, in one line, to start with --shadows N
# Skips (77) without a GL context; never passes without checking.
set -u
imgdiff=$1 outdir=$2 chapter=$3 key=$4
shift 4
args=(--headless --size 160x120 "$@")
name=$(basename "$chapter")
mkdir -p "$outdir"
out="$outdir/${name}_shadow_keys"
rm -f "$out".*
fail=0
say() { echo "$1"; case $1 in FAIL*) fail=1 ;; esac; }
same() { # same EXPECTED ACTUAL WHAT: byte for byte
  if "$imgdiff" --quiet --tolerance 0 --max-fraction 0 "$1" "$2" >"$out.diff" 2>&1; then say "ok   $3"
  else say "FAIL $3: $(tail -1 "$out.diff") ($2)"; fi
}
cat >"$out.script" <<SCRIPT
0 screenshot $out.on.png
1 key $key
1 screenshot $out.off.png
2 key $key
2 screenshot $out.on-again.png
2 quit
SCRIPT
"$chapter" "${args[@]}" --shadows 80 --script "$out.script" >"$out.stdout" 2>"$out.stderr"
rc=$?
if [ "$rc" -eq 77 ]; then echo "skip: no GL context: $(head -1 "$out.stderr")"; exit 77; fi
[ "$rc" -eq 0 ] || { echo "FAIL $name --shadows 80 --script: exit $rc: $(head -3 "$out.stderr")"; exit 1; }
"$chapter" "${args[@]}" --screenshot "$out.plain.png" 2>/dev/null || say "FAIL $name's picture without --shadows"
"$imgdiff" --quiet --tolerance 0 --max-fraction 0 "$out.plain.png" "$out.on.png" >/dev/null 2>&1 &&
  say "FAIL $name draws the same picture with and without shadows here: the test below proves nothing"
same "$out.plain.png" "$out.off.png" "$key: shadows off, the picture without --shadows"
same "$out.on.png" "$out.on-again.png" "$key again: the shadowed picture again"
grep -q 'shadows: off' "$out.stderr" "$out.stdout" && say "ok   $key says shadows off" ||
  say "FAIL no 'shadows: off' line after $key"
said=$(cat "$out.stderr" "$out.stdout" | grep -o 'lighting programs built with[a-z]* SHADOWS' | tr '\n' '|')
want='lighting programs built with SHADOWS|lighting programs built without SHADOWS|lighting programs built with SHADOWS|'
[ "$said" = "$want" ] && say "ok   the programs switch: with SHADOWS, without after $key, with after $key again" ||
  say "FAIL the programs' switches were '$said', want '$want'"

cat >"$out.none.script" <<SCRIPT
0 key $key
0 screenshot $out.none.png
0 quit
SCRIPT
"$chapter" "${args[@]}" --script "$out.none.script" >"$out.none.stdout" 2>"$out.none.stderr" ||
  say "FAIL $name --script without --shadows: exit $?"
same "$out.plain.png" "$out.none.png" "$key without --shadows: the picture unchanged"
n=$(cat "$out.none.stderr" "$out.none.stdout" | grep -c 'start with --shadows N')
[ "$n" -eq 1 ] && say "ok   $key without --shadows: one line says to start with --shadows N" ||
  say "FAIL $key without --shadows: $n lines saying to start with --shadows N (want 1)"
exit "$fail"
