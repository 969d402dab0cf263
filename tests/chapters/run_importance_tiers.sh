#!/usr/bin/env bash
# run_importance_tiers.sh CHAPTER OUTDIR SCENE PAGE - chapter 14's --view importance says what its
# page's caption says. The caption's counts ("Here N lights have 256-texel tiles and M have 128-texel
# ones") are the plan's (the --bench line's tier_lights=) and the view's, its discs counted by their
# tier's colour (tests/chapters/importance_tiers.py). At 800x600 the discs, 12 pixels across at any
# size, do not touch (at the golden's 320x240 two of them merge).
set -u
chapter=$1 outdir=$2 scene=$3 page=$4
mkdir -p "$outdir"
text=$(tr '\n' ' ' <"$page")
fitted=$(grep -Eo "Here [0-9]+ lights have 256-texel tiles and [0-9]+ have 128-texel ones" <<<"$text")
[ -n "$fitted" ] || { echo "FAIL: no counts in $page's caption of the importance view"; exit 1; }
want="0/0/$(sed -E 's/Here ([0-9]+) .* and ([0-9]+) .*/\1\/\2/' <<<"$fitted")"

out=$("$chapter" --headless --size 800x600 --frames 1 --gl-debug --quiet --scene "$scene" --bench \
      --view importance --screenshot "$outdir/importance.png")
rc=$?
if [ $rc -eq 77 ]; then echo "skip: no GL context"; exit 77; fi
if [ $rc -ne 0 ]; then echo "FAIL: $chapter --view importance exited with $rc"; exit 1; fi
plan=$(grep -o "tier_lights=[0-9/]*" <<<"$out")
[ "$plan" = "tier_lights=$want" ] || { echo "FAIL: the plan has $plan, the caption says $want"; exit 1; }
echo "ok: the plan's tiers are the caption's, $want"
/usr/bin/python3 "$(dirname "$0")/importance_tiers.py" "$outdir/importance.png" "$want"
