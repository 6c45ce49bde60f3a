#!/usr/bin/env bash
# Issue 23's benchmark: a year at 1 h of the CityJSON block's sunlit
# fractions (every receiver polygon, as `umbra footprint --sun-times
# --schedule` computes them), exact, and pixel counting beside it at 512²
# and 2048² with its error against the exact fractions. Markdown on stdout.
# Usage: scripts/sun-year-bench.sh [extra umbra_sun_year_bench flags]
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh >&2
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
cmake --build build --target umbra_sun_year_bench umbra >&2
./build/bench/umbra_sun_year_bench "$@"
