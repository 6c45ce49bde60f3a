#!/usr/bin/env bash
# The renderer benchmark on CGAL's data meshes (issue 4): frame time with and
# without shadows at 1280x720 with 1, 4 and 16 lights, and on a 60 x 60 floor
# with a low directional light ("<mesh>-floor60"), as a table; beside it
# Embree's shadow and primary rays and a float z-buffer (issue 20), and the
# scene parser's MB/s on the same scenes as inline JSON; and the night city
# under 1, 64 and 1,024 street lamps (lights that cost what they reach).
# UMBRA_BENCH_THREADS=N renders every pass on N threads (default: all).
# Usage: scripts/bench.sh [extra Google Benchmark flags]
# Needs Debian's libcgal-demo for the meshes (installed here if missing);
# writes out/bench.json and prints the table of scripts/bench_table.py, after
# a table of every benchmark scene validated on 50,000 seeded pixels.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --target umbra_render_bench umbra_parse_bench
m=$(./scripts/cgal-meshes.sh bunny00.off elephant.off refined_elephant.off)
mkdir -p out
UMBRA_BENCH_CITY=1 UMBRA_BENCH_DUMP=out/bench-scenes UMBRA_BENCH_VALIDATE=1 UMBRA_BENCH_MESHES="$m/elephant.off:$m/bunny00.off:$m/refined_elephant.off" \
  ./build/bench/umbra_render_bench --benchmark_filter=Render \
  --benchmark_out=out/bench.json --benchmark_out_format=json "$@"
python3 scripts/bench_table.py out/bench.json
echo
./build/bench/umbra_parse_bench out/bench-scenes/*-lights-16.json
