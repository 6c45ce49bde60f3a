#!/usr/bin/env bash
# The pictures of docs/methods.md, "how each method fails": each method's
# render with every pixel scored against the oracle and its mistakes painted
# (umbra_chart --images, every pixel), composed into panels.
# Usage: scripts/failure-pictures.sh [OUTDIR]   (default docs/images/methods)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/images/methods}
./scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --target umbra_chart
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
chart=./build/bench/umbra_chart
$chart --samples 0 --runs 1 --no-sweeps --only default --images "$work" -o "$work/a.csv"
$chart --samples 0 --runs 1 --no-sweeps --only fig08 --methods volume,ray --images "$work" \
  -o "$work/b.csv"
$chart --samples 0 --runs 1 --no-scenes --only grazing --images "$work" -o "$work/c.csv"
$chart --samples 0 --runs 1 --no-scenes --only far_from --images "$work" -o "$work/d.csv"
mkdir -p "$out"
f=scripts/failure_figure.py
/usr/bin/python3 $f "$out/map.png" 3 \
  "$work/default-map-1024-nearest-b0-s0-pcf1.png|map 1024, no bias: acne" \
  "$work/default-map-256-nearest-b4-s1.5-pcf1.png|map 256, default bias: edges (crop x4)|130,190,290,290" \
  "$work/grazing-0.5-map-512-nearest-b4-s1.5-pcf1.png|map 512, light 0.5° above the floor" \
  "$work/default-map-2048-nearest-b4-s1.5-pcf1.png|map 2048 (defaults): edges (crop x4)|130,190,290,290" \
  "$work/default-map-256-bilinear-b4-s1.5-pcf1.png|map 256, bilinear (crop x4)|130,190,290,290" \
  "$work/grazing-0.5-map-2048-nearest-b4-s1.5-pcf1.png|map 2048, light 0.5° above the floor"
/usr/bin/python3 $f "$out/ray.png" 3 \
  "$work/default-ray-eps0.png|ray, epsilon 0: acne" \
  "$work/far_from_origin-1e+06-ray-eps1e-05.png|ray (default), scene 1e6 from the origin" \
  "$work/far_from_origin-1e+06-ray-eps1e-05.png|the same (crop x3)|85,140,215,215" \
  "$work/fig08_twisted_quad-ray-eps1e-05.png|ray (default), Bergeron's twisted quad" \
  "$work/default-ray-eps1e-05.png|ray (default epsilon): no mistake here" \
  "$work/grazing-0.5-ray-eps1e-05.png|ray (default), light 0.5° above the floor: none"
/usr/bin/python3 $f "$out/volume.png" 3 \
  "$work/default-volume.png|volume" \
  "$work/fig08_twisted_quad-volume.png|volume, Bergeron's twisted quad" \
  "$work/far_from_origin-1e+06-volume.png|volume, scene 1e6 from the origin"
echo "wrote $out/map.png $out/ray.png $out/volume.png"
