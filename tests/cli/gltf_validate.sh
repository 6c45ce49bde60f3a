#!/bin/sh
# The Khronos glTF validator (npm package gltf-validator, pinned in
# tools/gltf-validator/package-lock.json, installed by scripts/install-deps.sh
# with `npm ci`) on umbra's glTF exports: volumes and footprints, .gltf and
# .glb, an opaque and a tinted scene and a glTF scene. Zero errors required;
# warnings and infos are printed. Exit 77 (CTest: skipped), with one line,
# where node or the validator is missing.
# Usage: gltf_validate.sh UMBRA SOURCE_DIR WORK_DIR
set -eu
umbra=$1 source=$2 work=$3
tool=$source/tools/gltf-validator
if ! command -v node > /dev/null 2>&1; then
  echo "SKIP: node is missing (Debian's nodejs and npm; scripts/install-deps.sh)"
  exit 77
fi
if [ ! -f "$tool/node_modules/gltf-validator/package.json" ]; then
  echo "SKIP: the glTF validator is not installed: run 'npm ci' in $tool (scripts/install-deps.sh does)"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work" && cd "$work"
scenes=$source/data/scenes
for ext in gltf glb; do
  "$umbra" volume "$scenes/two_lights.json" -q -o "two_lights.volume.$ext"
  "$umbra" volume "$scenes/gltf/two_lights.glb" -q -o "gltf_two_lights.volume.$ext"
  "$umbra" volume "$scenes/tinted/coloured.json" -q -o "coloured.volume.$ext"
  "$umbra" footprint "$scenes/two_lights.json" -q --ignore-light-end -o "two_lights.footprint.$ext"
  "$umbra" footprint "$scenes/tinted/coloured.json" -q -o "coloured.footprint.$ext"
done
node "$tool/validate.js" ./*.gltf ./*.glb
