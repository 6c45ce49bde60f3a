#!/usr/bin/env bash
# Fresh machine to a picture: install dependencies, build, render the default scene.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --target umbra
mkdir -p out
./build/cli/umbra render data/scenes/default.json -o out/default.png
echo "wrote out/default.png"
