#!/usr/bin/env bash
# Issue 21's speed table for area lights: bunny00 and refined_elephant on a
# floor (the render benchmark's scenes), 1280x720, under one square area
# light of side a tenth of the model's size, horizontal, centred where the
# benchmark's single point light is. Times the volume method (the
# certified visible fraction), the hard frame of a point light at the
# light's centre, Embree with N = 16, 64, 256, 1024 light samples, the
# map method's PCSS and Ikedo's penumbra with each of his coefficient sets;
# scores each against the exact V on 20,000 seeded samples.
#
#   scripts/area-light-bench.sh [OUT_DIR] [THREADS]
#
# Builds umbra and the render benchmark (which dumps the scenes) in build/;
# the meshes come from CGAL's data (scripts/cgal-meshes.sh). Prints one line
# per measurement; the table in docs/bench/2026-12-06-area-lights.md came
# from it.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-build/area-light-bench}
threads=${2:-2}
umbra=$PWD/build/cli/umbra
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target umbra umbra_render_bench >/dev/null
m=$(./scripts/cgal-meshes.sh bunny00.off refined_elephant.off)
mkdir -p "$out/dump"
UMBRA_BENCH_DUMP="$out/dump" UMBRA_BENCH_MESHES="$m/bunny00.off:$m/refined_elephant.off" \
  build/bench/umbra_render_bench --benchmark_filter=none >/dev/null 2>&1
for model in bunny00 refined_elephant; do
  python3 - "$out/dump/$model-lights-1.json" "$out/$model" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
model = [m for m in scene["models"] if m["name"] != "floor"][0]
vs = model["polygons"]["vertices"]
size = max(max(v[i] for v in vs) - min(v[i] for v in vs) for i in range(3))
p = scene["lights"][0]["position"]
h = size / 20  # half the side: the side is a tenth of the model
area = {"type": "area", "intensity": [1, 1, 1],
        "vertices": [[p[0] - h, p[1], p[2] - h], [p[0] + h, p[1], p[2] - h],
                     [p[0] + h, p[1], p[2] + h], [p[0] - h, p[1], p[2] + h]]}
json.dump(dict(scene, lights=[area]), open(sys.argv[2] + "-area.json", "w"))
json.dump(dict(scene, lights=[{"type": "point", "position": p}]),
          open(sys.argv[2] + "-centre.json", "w"))
PY
  run() { /usr/bin/time -f "$model $1 %e s" "${@:2}"; }
  run "hard frame (point light at the centre), volume" \
    "$umbra" render "$out/$model-centre.json" --threads "$threads" -q -o "$out/$model-centre.exr"
  run "area light, volume (certified V)" \
    "$umbra" render "$out/$model-area.json" --threads "$threads" -q -o "$out/$model-volume.exr"
  for n in 16 64 256 1024; do
    run "area light, ray N=$n" "$umbra" render "$out/$model-area.json" --threads "$threads" -q \
      --method ray --area-samples "$n" -o "$out/$model-ray$n.exr"
  done
  run "area light, map (PCSS)" "$umbra" render "$out/$model-area.json" --threads "$threads" -q \
    --method map -o "$out/$model-pcss.exr"
  for set in a b c d; do
    run "area light, map (Ikedo's penumbra, set $set)" "$umbra" render "$out/$model-area.json" \
      --threads "$threads" -q --method map --map-variant ikedo --ikedo-coeffs "$set" \
      -o "$out/$model-ikedo$set.exr"
  done
  for image in volume ray16 ray64 ray256 ray1024 pcss ikedoa ikedob ikedoc ikedod; do
    # Exit 1 is expected for the sampled methods: their penumbra errs.
    run "validate $image on 20000 samples (the exact V)" "$umbra" validate \
      "$out/$model-area.json" --image "$out/$model-$image.exr" --samples 20000 \
      --threads "$threads" --no-mask --json >"$out/$model-$image.validate.json" || true
    python3 - "$out/$model-$image.validate.json" "$model $image" <<'PY'
import json, sys
light = json.load(open(sys.argv[1]))["lights"][0]
scored = light["compared"] - light["boundary"]
print(f"{sys.argv[2]}: {scored} scored, {light['mismatches']} over 1e-6, "
      f"largest {light['max_error']:.3g}, sum {light['mean_error'] * scored:.4g}")
PY
  done
done
