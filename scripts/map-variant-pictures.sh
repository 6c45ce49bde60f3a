#!/usr/bin/env bash
# The pictures of the source papers' shadow-map variants in docs/methods.md
# (issue 22): renders of small scenes in tests/data/scenes/map_variants/ with
# `umbra render --method map --map-variant ...`, scored pixel by pixel
# against `--method exact` (shadow.0 exported with oiiotool), composed by
# scripts/map_variant_figure.py. About 10 s.
# Usage: scripts/map-variant-pictures.sh [OUT.png]   (default docs/images/methods/map-variants.png)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/images/methods/map-variants.png}
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target umbra >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
umbra=./build/cli/umbra
scenes=tests/data/scenes/map_variants
# render NAME SCENE [umbra render options]: NAME.png (beauty) and NAME.s.png (shadow.0).
render() {
  local name=$1 scene=$2
  shift 2
  "$umbra" render "$scene" -q -o "$work/$name.exr" "$@"
  "$umbra" render "$scene" -q -o "$work/$name.png" "$@"
  oiiotool "$work/$name.exr" --ch shadow.0 -d uint8 -o "$work/$name.s.png"
}
for s in l_self_shadow grazing highlight_in_shadow; do
  render "$s-exact" "$scenes/$s.json" --method exact
done
render l-depth "$scenes/l_self_shadow.json" --method map
render l-id "$scenes/l_self_shadow.json" --method map --map-variant id
render l-idp "$scenes/l_self_shadow.json" --method map --map-variant id-polygon
render g-nobias "$scenes/grazing.json" --method map --map-bias 0 --map-slope-bias 0
render g-id "$scenes/grazing.json" --method map --map-variant id
render g-idp "$scenes/grazing.json" --method map --map-variant id-polygon
render h-depth "$scenes/highlight_in_shadow.json" --method map
render h-post "$scenes/highlight_in_shadow.json" --method map --map-variant post
render d-depth data/scenes/default.json --method map --map-bias 0
render d-post data/scenes/default.json --method map --map-bias 0 --map-variant post
render d-exact data/scenes/default.json --method exact
mkdir -p "$(dirname "$out")"
w=$work
/usr/bin/python3 scripts/map_variant_figure.py "$out" 3 \
  "beauty|depth map (defaults): the L's self-shadow|$w/l-depth.png|$w/l-depth.s.png|$w/l_self_shadow-exact.s.png" \
  "beauty|ID per object (Ikedo): self-shadow lost|$w/l-id.png|$w/l-id.s.png|$w/l_self_shadow-exact.s.png" \
  "beauty|ID per polygon: kept|$w/l-idp.png|$w/l-idp.s.png|$w/l_self_shadow-exact.s.png" \
  "beauty|depth map, no bias, grazing light: acne|$w/g-nobias.png|$w/g-nobias.s.png|$w/grazing-exact.s.png" \
  "beauty|ID per object, no bias: no acne|$w/g-id.png|$w/g-id.s.png|$w/grazing-exact.s.png" \
  "beauty|ID per polygon, no bias: no acne|$w/g-idp.png|$w/g-idp.s.png|$w/grazing-exact.s.png" \
  "beauty|depth map: no highlight in the shadow|$w/h-depth.png" \
  "beauty|post-process (Williams): highlight darkened, kept|$w/h-post.png" \
  "diff|post-process minus depth map (x4)|$w/h-post.png|$w/h-depth.png|4" \
  "beauty|depth map, --map-bias 0 (slope bias only)|$w/d-depth.png|$w/d-depth.s.png|$w/d-exact.s.png" \
  "beauty|post-process, --map-bias 0: the depth buffer's rounding|$w/d-post.png|$w/d-post.s.png|$w/d-exact.s.png"
echo "wrote $out"
