#!/usr/bin/env bash
# The coloured-shadow picture in docs/transmittance.md and docs/methods.md
# (issue 22): data/scenes/tinted/coloured.json at 480x360 with the volume
# method (exact τ) and the map method (Ikedo's transparency buffer: one
# tinted layer per texel), side by side, and under each its light-0 τ
# errors painted red where some channel is off by more than 1e-6 (the
# validator's rule; τ read back with oiiotool). About 10 s.
# Usage: scripts/transmittance-pictures.sh [OUT.png]   (default docs/images/transmittance.png)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/images/transmittance.png}
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target umbra >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 -c "import json,sys; s=json.load(open(\"data/scenes/tinted/coloured.json\")); s[\"camera\"][\"width\"],s[\"camera\"][\"height\"]=480,360; json.dump(s,open(sys.argv[1],\"w\"))" "$work/scene.json"
# Mesh paths relative to the copied scene: point them at data/meshes.
sed -i "s#\"[^\"]*meshes/#\"$PWD/data/meshes/#g" "$work/scene.json"
for m in volume map; do
  ./build/cli/umbra render "$work/scene.json" --method "$m" -q -o "$work/$m.exr"
  ./build/cli/umbra render "$work/scene.json" --method "$m" -q -o "$work/$m.png"
done
# Red where the map's τ differs from the volume's (the exact τ) by more
# than 1e-6 in some channel: the summed differences times 1e6, clamped.
oiiotool "$work/map.exr" --ch transmittance.0.R,transmittance.0.G,transmittance.0.B \
  "$work/volume.exr" --ch transmittance.0.R,transmittance.0.G,transmittance.0.B \
  --absdiff --chsum --mulc 1000000 --clamp:min=0:max=1 -o "$work/wrong.exr"
oiiotool "$work/map.png" --ch R,G,B "$work/wrong.exr" --chnames R --ch "R,G=0.0,B=0.0" --add \
  --clamp:min=0:max=1 -d uint8 -o "$work/map-wrong.png"
mkdir -p "$(dirname "$out")"
oiiotool "$work/volume.png" "$work/map-wrong.png" --mosaic 2x1 -d uint8 -o "$out"
echo "wrote $out"
