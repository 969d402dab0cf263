#!/usr/bin/env bash
# run_hard_sizes.sh IMGDIFF OUTDIR BINARY SCENE: case 12, extreme framebuffer sizes on one chapter.
# 1x1, and the largest width and height this GL allows as thin strips (on llvmpipe 16384x8 and
# 8x16384; the limit is asked from the context with --gl-info): a full 16384x16384 frame needs
# about 12 GiB and minutes on llvmpipe (docs/hard-cases.md). Each run has --gl-debug (a GL error
# fails it) and must write a PNG of the requested size that loads. One more pixel is rejected by
# tests/robust/run_cli.sh (cli.*).
set -u
imgdiff=$1 out=$2 bin=$3 scene=$4
mkdir -p "$out"
fail=0
limits=$("$bin" --headless --gl-info 2>/dev/null | head -n 1)
max_w=$(sed -n 's/.*max_width=\([0-9]*\).*/\1/p' <<<"$limits")
max_h=$(sed -n 's/.*max_height=\([0-9]*\).*/\1/p' <<<"$limits")
if [ -z "$max_w" ] || [ -z "$max_h" ]; then echo "skip: no GL context"; exit 77; fi
for size in 1x1 "${max_w}x8" "8x${max_h}"; do
  png="$out/hard_size_$size.png"
  rm -f "$png"
  start=$(date +%s.%N)
  "$bin" --headless --size "$size" --frames 1 --gl-debug --scene "$scene" --screenshot "$png" \
    2>"$out/hard_size.err"
  rc=$?
  end=$(date +%s.%N)
  if [ $rc -eq 77 ]; then echo "skip: no GL context"; exit 77; fi
  if [ $rc -ne 0 ]; then echo "FAIL $size: exit $rc: $(head -2 "$out/hard_size.err")"; fail=1; continue; fi
  # imgdiff against itself checks the PNG loads; bytes 16..23 of the header are its width and height.
  read -r w h < <(od -An -tu1 -j16 -N8 "$png" |
    awk '{print $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}')
  if [ "${w}x${h}" != "$size" ] || ! "$imgdiff" --quiet "$png" "$png"; then
    echo "FAIL $size: wrote ${w}x${h}"; fail=1; continue
  fi
  printf 'ok   %s: %.2f s\n' "$size" "$(echo "$end - $start" | bc -l)"
done
exit $fail
