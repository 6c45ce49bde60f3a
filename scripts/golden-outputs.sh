#!/usr/bin/env bash
# Writes every output a refactor must keep byte for byte, then compares two
# such folders: for "behaviour does not change" steps (CONTRIBUTING.md).
#
#   scripts/golden-outputs.sh write UMBRA OUT_DIR [BENCH_SCENES_DIR]
#   scripts/golden-outputs.sh compare DIR_A DIR_B
#
# `write` renders every scene of data/scenes (JSON, Bergeron's figures, glTF)
# with the volume, map and ray methods (and the exact oracle where the frame
# is small), at 1 and 2 threads, and exports every scene's volumes in every
# format; BENCH_SCENES_DIR adds the benchmark's dumped scenes (volume method,
# UMBRA_BENCH_DUMP=DIR umbra_render_bench --benchmark_filter=none).
# `compare` lists files that differ or exist on one side only; exit 1 if any.
set -euo pipefail
cd "$(dirname "$0")/.."

write() {
  local umbra=$1 out=$2 bench=${3:-}
  mkdir -p "$out"
  local scenes=(data/scenes/*.json data/scenes/bergeron/*.json data/scenes/gltf/*.gltf data/scenes/gltf/*.glb)
  for scene in "${scenes[@]}"; do
    local stem
    stem=$(echo "${scene#data/scenes/}" | tr '/.' '__')
    for threads in 1 2; do
      "$umbra" render "$scene" -q --threads "$threads" -o "$out/$stem.volume.t$threads.exr"
    done
    "$umbra" render "$scene" -q --method map -o "$out/$stem.map.exr"
    "$umbra" render "$scene" -q --method ray -o "$out/$stem.ray.exr"
    "$umbra" render "$scene" -q --spp 9 -o "$out/$stem.spp9.png"
    case "$scene" in
      *night_city*) ;;  # the oracle at every pixel of the city takes minutes
      *) "$umbra" render "$scene" -q --method exact -o "$out/$stem.exact.exr" ;;
    esac
    for ext in ply obj off gltf glb; do
      "$umbra" volume "$scene" -q -o "$out/$stem.volume.$ext"
    done
  done
  if [ -n "$bench" ]; then
    for scene in "$bench"/*.json; do
      local stem
      stem=bench_$(basename "$scene" .json)
      "$umbra" render "$scene" -q -o "$out/$stem.volume.exr"
      "$umbra" volume "$scene" -q -o "$out/$stem.volume.ply"
    done
  fi
  echo "golden-outputs: $(find "$out" -type f | wc -l) files in $out"
}

compare() {
  local a=$1 b=$2 bad=0
  while IFS= read -r name; do
    if [ ! -f "$a/$name" ] || [ ! -f "$b/$name" ]; then
      echo "only on one side: $name"; bad=1
    elif ! cmp -s "$a/$name" "$b/$name"; then
      echo "differs: $name"; bad=1
    fi
  done < <( (cd "$a" && find . -type f; cd "$b" && find . -type f) | sort -u)
  local n
  n=$(find "$a" -type f | wc -l)
  if [ "$bad" -eq 0 ]; then echo "golden-outputs: $n files byte-identical"; fi
  return "$bad"
}

case "${1:-}" in
  write) shift; write "$@" ;;
  compare) shift; compare "$@" ;;
  *) echo "usage: $0 write UMBRA OUT_DIR [BENCH_SCENES_DIR] | compare DIR_A DIR_B" >&2; exit 2 ;;
esac
