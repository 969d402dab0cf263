#!/usr/bin/env bash
# run_assets.sh GEN_SCENES SCENE_CHECK SOURCE_DIR WORK_DIR: the committed scenes and the teapot
# are exactly what tools/gen_scenes writes (the refined bunny and the PBR images too), and every committed
# scene parses.
set -u
gen=$1 check=$2 src=$3 work=$4
rm -rf "$work" && mkdir -p "$work/scenes" "$work/models" "$work/textures"
cp "$src/assets/models/bunny.ply" "$work/models/"   # converted once from the npm package `bunny`
"$gen" --out "$work/scenes" --models "$work/models" >/dev/null || { echo "FAIL: gen_scenes exited $?"; exit 1; }
pass=0 fail=0
for f in scenes/city.scene scenes/bunnies.scene scenes/sphere.scene scenes/teapots.scene models/teapot.obj \
         models/bunny_loop2.ply scenes/pbr_teapots.scene textures/tiles_base.png textures/tiles_mr.png \
         textures/tiles_normal.png textures/tiles_ao.png textures/panel_base.png textures/panel_mr.png \
         textures/panel_normal.png textures/panel_ao.png textures/teapot_base.png textures/teapot_mr.png \
         textures/teapot_normal.png textures/teapot_ao.png; do
  if cmp -s "$work/$f" "$src/assets/$f"; then pass=$((pass + 1)); echo "ok   $f is reproducible"
  else fail=$((fail + 1)); echo "FAIL $f differs from what gen_scenes writes"; fi
done
for s in "$src"/assets/scenes/*.scene; do
  # gltf_engine.scene imports a sample of Debian's assimp-testmodels (scripts/install-deps.sh installs it)
  model=$(sed -n 's/^model \(\/[^ ]*\).*/\1/p' "$s" | head -n 1)
  if [ -n "$model" ] && [ ! -f "$model" ]; then echo "skip $(basename "$s"): $model is not installed"; continue; fi
  if "$check" "$s" >/dev/null; then pass=$((pass + 1)); echo "ok   $(basename "$s") parses"
  else fail=$((fail + 1)); echo "FAIL $(basename "$s") does not parse"; fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
