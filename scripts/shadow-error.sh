#!/usr/bin/env bash
# shadow-error.sh BUILD_DIR - chapter 14's shadows against exact shadow rays, and the shadow pass's
# work, for docs/data/shadows.md (scripts/update-docs.sh writes it; docs/14_shadows.md embeds it):
#   reference  the tables hard.shadow_reference_* print (tests/shadows/shadows.cmake names each
#              test's configurations: the defaults first, then the sweep), one per small scene
#   teapots    the same test on the teapots' 80 lights (8 of them, each alone)
#   culling    the teapots' first frame, every tile drawn, with and without the caster culling: its
#              'shadows:' lines
# The tables come from running the tests themselves, so the page shows what they check; a failing
# test fails this script. Prints markdown sections on stdout.
set -euo pipefail
build=$1
root=$(cd "$(dirname "$0")/.." && pwd)
[ -x "$build/tests/test_shadow_reference" ] || { echo "shadow-error.sh: no $build/tests/test_shadow_reference (build first)" >&2; exit 2; }

# The tests matching PATTERN, run by ctest: each one's scene (relative to the tree), then its table.
tables() {
  ctest --test-dir "$build" -R "$1" -V 2>/dev/null | awk -v root="$root/" '
    / Test command: / {
      for (i = 1; i <= NF; i++)
        if ($i ~ /\.scene"?$/) { s = $i; gsub(/"/, "", s); sub(root, "", s); printf "%s%s\n", (n++ ? "\n" : ""), s }
    }
    /^[0-9]+: atlas / || /^[0-9]+: [0-9]+ +[0-9]+ +[0-9.]+ +[0-9.]+ +[0-9]+ / { sub(/^[0-9]+: /, ""); print }'
}

echo "## reference"
echo ""
echo "320x240, time 0; each scene's one light (a point light, or one spot)."
echo ""
echo '```'
tables 'hard\.shadow_reference_(one_light|spot|contact|grazing|inside)$'
echo '```'
echo ""
echo "## teapots"
echo ""
echo "320x240, time 0; 8 of the 80 lights (every 10th), each alone (\`--view-light K\`), their lit pixels pooled;"
echo "the defaults, then the defaults before 2026-12-02 (PCF 3, 1.5 texels of normal offset)."
echo ""
echo '```'
tables 'hard\.shadow_reference_teapots$'
echo '```'
echo ""
echo "## culling"
echo ""
echo '```'
for cull in on off; do
  "$build/bin/14_shadows" --headless --size 320x240 --frames 1 --warmup 0 --bench --shadow-cull "$cull" \
    --scene "$root/assets/scenes/teapots.scene" 2>/dev/null | grep '^shadows:'
done
echo '```'
