#!/usr/bin/env bash
# run-all.sh - install what is missing, build, render every chapter's screenshot into out/,
# and write the forward-vs-deferred timing and error table (out/bench.md, out/bench.csv).
# Headless unless a display is available; pass --quick for the short benchmark.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
"$root/scripts/build.sh" "$root/build"
mkdir -p out

mode=(--headless)
if [ -n "${DISPLAY:-}" ]; then mode=(--frames 3 --paused); fi

echo "== screenshots (800x600, default scene) into out/"
for bin in build/bin/[0-9][0-9]_*; do
  name=$(basename "$bin")
  "$bin" "${mode[@]}" --size 800x600 --screenshot "out/$name.png"
done

echo "== forward vs deferred"
if [ -x build/bin/bench ]; then
  build/bin/bench --out out "$@"
  cat out/bench.md
else
  for bin in build/bin/[0-9][0-9]_*; do
    for r in deferred forward; do
      "$bin" --headless --size 800x800 --bench --renderer "$r" 2>/dev/null || true
    done
  done | tee out/bench.txt
fi
