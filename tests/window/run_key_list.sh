#!/usr/bin/env bash
# run_key_list.sh CHAPTER... - F1's key list is never cut: of the chapters given, the one whose list is
# longest (its --help's "window keys" section, in bytes: chapter 19's passed 2,048, the size of the
# buffer that once cut it mid-word, "N  a la") shows it headless with --script at the default size
# (800x600):
#   1. the list the window draws (the script's overlay event prints it, "keys: ...") is --help's,
#      line for line, to the last
#   2. it fits the picture: the overlay draws a long text smaller rather than cut it, and logs when
#      it must cut (a picture too small even at 1x): no such line at 800x600
#   3. ... and at 320x240, where it cannot fit, it says so (never cut silently)
# Skips (77) without a GL context.
set -u
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
longest="" most=0
for bin in "$@"; do
  "$bin" --help | sed -n '/^window keys:/,/^$/p' | sed '/^$/d' >"$tmp/help"
  bytes=$(wc -c <"$tmp/help")
  [ "$bytes" -gt "$most" ] && { most=$bytes; longest=$bin; cp "$tmp/help" "$tmp/want"; }
done
[ -n "$longest" ] || { echo "FAIL: no chapter has a key list"; exit 1; }
echo "     the longest key list: $(basename "$longest"), $most bytes, $(wc -l <"$tmp/want") lines"
fail=0
say() { echo "$1"; case $1 in FAIL*) fail=1 ;; esac; }
show() { # show SIZE...: F1, then the overlay event, after frame 1
  printf '0 key F1\n1 overlay\n1 quit\n' >"$tmp/script"
  "$longest" --headless --paused "$@" --script "$tmp/script" >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  [ $rc -eq 77 ] && { echo "skip: no GL context"; exit 77; }
  [ $rc -eq 0 ] || { say "FAIL $(basename "$longest") $*: exit $rc: $(head -2 "$tmp/err")"; exit 1; }
}

show
sed -n 's/^keys: //p' "$tmp/out" >"$tmp/got"
if cmp -s "$tmp/want" "$tmp/got"; then
  say "ok   1. the window's list is --help's, all $(wc -l <"$tmp/got") lines"
else
  say "FAIL 1. the window's list differs from --help's (first difference below; $(wc -c <"$tmp/got") bytes shown)"
  diff "$tmp/want" "$tmp/got" | head -4
fi
grep -q "do not fit" "$tmp/err" && say "FAIL 2. cut at 800x600: $(grep 'do not fit' "$tmp/err")" ||
  say "ok   2. it fits at 800x600"
show --size 320x240
grep -q "line(s) do not fit in 320x240" "$tmp/err" && say "ok   3. at 320x240 the cut is told: $(grep -o 'overlay: .*' "$tmp/err")" ||
  say "FAIL 3. at 320x240 the list cannot fit, and nothing says so"
exit $fail
