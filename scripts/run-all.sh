#!/usr/bin/env bash
# run-all.sh [--full | --quick] [bench options...] - install what is missing, build the chapters
# and the benchmark (not the tests), render every chapter's screenshot into out/, and write the
# forward-vs-deferred timing and error table (out/bench.md, out/bench.csv, two plots).
#
#   (default)  the course's sweep: the scenes and light counts where the renderers' order changes,
#              every renderer, the cut-off at three points; about 5 minutes in all on 2 cores
#   --full     the pages' sweep (what scripts/update-docs.sh measures): about 20 minutes in all (23 in the
#              dated run of 2026-12-02 18:29, as README says)
#   --quick    the test-sized sweep: under a minute
# Headless unless a display is available. Every option is passed to build/bin/bench (its --help).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
case " $* " in
  *" --full "*) sweep="the pages' full sweep: about 20 minutes" ;;
  *" --quick "*) sweep="the quick sweep: under a minute" ;;
  *) sweep="the course's sweep: 3 to 5 minutes" ;;
esac
chapters=$(ls chapters/[0-9][0-9]_*.c | wc -l)
echo "== run-all: build (under a minute), $chapters screenshots (seconds), then the benchmark ($sweep on 2 cores"
echo "   with llvmpipe; a GPU is faster). Results: $root/out/"
start=$SECONDS
"$root/scripts/build.sh" "$root/build" course
mkdir -p out

mode=(--headless)
if [ -n "${DISPLAY:-}" ]; then mode=(--frames 3 --paused); fi

echo "== screenshots (800x600, each chapter's default scene) into out/"
for bin in build/bin/[0-9][0-9]_*; do
  name=$(basename "$bin")
  "$bin" "${mode[@]}" --size 800x600 --screenshot "out/$name.png"
done

echo "== forward vs deferred"
build/bin/bench --out out "$@"
cat out/bench.md
echo
echo "== run-all: done in $((SECONDS - start)) s"
echo "   screenshots: $root/out/NN_chapter.png"
echo "   the table:   $root/out/bench.md (and bench.csv)"
if [ -f out/time_vs_lights.png ]; then
  echo "   the plots:   $root/out/time_vs_lights.png, $root/out/speed_vs_error.png"
fi
