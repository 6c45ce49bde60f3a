#!/usr/bin/env bash
# The footprint benchmark of issue 19: exact footprints against pixel
# counting on CGAL's bunny00 and refined_elephant (the floor under a sun and
# under a point light; every bunny triangle as a receiver) and the night
# city under a low sun, as a Markdown table on stdout.
# Usage: scripts/footprint-bench.sh [extra umbra_footprint_bench flags]
# Needs Debian's libcgal-demo for the meshes (installed here if missing).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh >&2
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
cmake --build build --target umbra_footprint_bench >&2
m=$(./scripts/cgal-meshes.sh bunny00.off refined_elephant.off)
./build/bench/umbra_footprint_bench --meshes "$m/bunny00.off" --meshes "$m/refined_elephant.off" "$@"
