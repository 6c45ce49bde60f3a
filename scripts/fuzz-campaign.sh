#!/usr/bin/env bash
# A fuzzing campaign with a time budget: every libFuzzer harness gets an equal
# share of the time, and so do the degenerate-scene generator (umbra fuzz
# check with fresh seeds) and the real-model sweep (umbra fuzz real over every
# shipped mesh, fresh seeds). Prints executions, crashes and mismatches per
# harness, scenes and failures per generator. docs/fuzzing.md.
#
#   scripts/fuzz-campaign.sh --minutes 30 [--build build-fuzz] [--only h1,h2] [--seed S]
#
# Builds build-fuzz with clang (UMBRA_FUZZ=ON) if it is missing. Findings go
# to BUILD/campaign/artifacts/<harness>/ (crash-*, timeout-*, oom-*); grown
# corpora to BUILD/campaign/corpus/<harness>/; failing generated scenes to
# BUILD/campaign/generator-failures.txt, failing real-model scenes to
# BUILD/campaign/real-failures.txt with their files under
# BUILD/campaign/real-failures/<scene>/ (scene.json, mesh, recipe.txt). Turn a
# finding into a regression: see docs/fuzzing.md.
set -euo pipefail
cd "$(dirname "$0")/.."

minutes=10
build=build-fuzz
only=""
seed=$(date +%s)
while [ $# -gt 0 ]; do
  case "$1" in
    --minutes) minutes="$2"; shift 2 ;;
    --build) build="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    --seed) seed="$2"; shift 2 ;;
    -h|--help) sed -n 2,16p "$0"; exit 0 ;;
    *) echo "fuzz-campaign: unknown argument '$1'" >&2; exit 2 ;;
  esac
done

harnesses=(scene_json mesh_off mesh_obj mesh_ply mesh_stl volume twist render gltf glb image footprint)
if [ -n "$only" ]; then IFS=, read -r -a harnesses <<< "$only"; fi

if [ ! -x "$build/fuzz/fuzz_${harnesses[0]}" ]; then
  CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DUMBRA_FUZZ=ON -DUMBRA_BUILD_TESTS=OFF
  cmake --build "$build" -j2 --target $(printf 'fuzz_%s ' "${harnesses[@]}")
fi

slots=$(( ${#harnesses[@]} + 2 ))
share=$(( minutes * 60 / slots ))
[ "$share" -ge 5 ] || share=5
work="$build/campaign"
mkdir -p "$work"
report="$work/report.txt"
: > "$report"
printf '%-12s %12s %8s %8s %10s %8s\n' harness executions exec/s crashes mismatches seconds | tee -a "$report"

for h in "${harnesses[@]}"; do
  corpus="$work/corpus/$h"
  artifacts="$work/artifacts/$h"
  mkdir -p "$corpus" "$artifacts"
  execs=0 crashes=0 mismatches=0
  start=$(date +%s)
  # libFuzzer stops at the first finding; start again until the share is used.
  while :; do
    left=$(( share - ($(date +%s) - start) ))
    [ "$left" -ge 3 ] || break
    log="$work/$h.log"
    before=$(ls "$artifacts" | wc -l)
    "$build/fuzz/fuzz_$h" -max_total_time="$left" -timeout=20 -rss_limit_mb=2048 -max_len=4096 \
      -print_final_stats=1 -artifact_prefix="$artifacts/" "$corpus" "fuzz/corpus/$h" \
      > "$log" 2>&1 || true
    n=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | awk '{s+=$2} END {print s+0}')
    execs=$(( execs + n ))
    after=$(ls "$artifacts" | wc -l)
    if [ "$after" -gt "$before" ]; then
      if grep -q "^umbra fuzz $h: " "$log"; then mismatches=$((mismatches + 1)); else crashes=$((crashes + 1)); fi
      cp "$log" "$artifacts/finding-$(date +%s).log"
    fi
  done
  secs=$(( $(date +%s) - start ))
  printf '%-12s %12d %8d %8d %10d %8d\n' "$h" "$execs" $(( execs / (secs > 0 ? secs : 1) )) \
    "$crashes" "$mismatches" "$secs" | tee -a "$report"
done

# The generator: batches of 200 scenes with fresh seeds until its share is used.
# The generator needs no libFuzzer: any build's umbra will do.
umbra="$build/cli/umbra"
[ -x "$umbra" ] || umbra=build/cli/umbra
[ -x "$umbra" ] || cmake --build "$build" -j2 --target umbra
[ -x "$umbra" ] || umbra="$build/cli/umbra"
scenes=0 failed=0 refused=0 start=$(date +%s) s=$seed
: > "$work/generator-failures.txt"
while [ $(( $(date +%s) - start )) -lt "$share" ]; do
  out=$("$umbra" fuzz check --count 200 --seed "$s" -q 2>&1) || true
  line=$(grep '^fuzz check:' <<< "$out" || true)
  scenes=$(( scenes + 200 ))
  f=$(sed -n 's/.* \([0-9]*\) failed;.*/\1/p' <<< "$line")
  r=$(sed -n 's/.* \([0-9]*\) refused;.*/\1/p' <<< "$line")
  failed=$(( failed + ${f:-200} ))
  refused=$(( refused + ${r:-0} ))
  grep '^FAIL' <<< "$out" >> "$work/generator-failures.txt" || true
  s=$(( s + 1 ))
done
secs=$(( $(date +%s) - start ))
printf '%-12s %12d %8d %8d %10d %8d   (scenes, %d refused; seeds %d..%d)\n' generator "$scenes" \
  $(( scenes / (secs > 0 ? secs : 1) )) 0 "$failed" "$secs" "$refused" "$seed" $(( s - 1 )) | tee -a "$report"

# The real-model sweep: every shipped mesh once per seed, fresh seeds until
# its share is used; failing scenes exported (at most 50 a seed).
meshes=()
if [ -f /usr/share/doc/libcgal-dev/data.tar.gz ]; then
  meshes+=(--meshes "$(./scripts/cgal-meshes.sh --all)")
fi
for sub in OBJ PLY OFF STL; do
  [ -d "/usr/share/assimp/models/$sub" ] && meshes+=(--meshes "/usr/share/assimp/models/$sub")
done
scenes=0 failed=0 refused=0 start=$(date +%s) s=$seed
: > "$work/real-failures.txt"
while [ ${#meshes[@]} -gt 0 ] && [ $(( $(date +%s) - start )) -lt "$share" ]; do
  out=$("$umbra" fuzz real "${meshes[@]}" --per-mesh 1 --seed "$s" -q \
        --export "$work/real-failures" 2>&1) || true
  line=$(grep '^fuzz real:' <<< "$out" || true)
  n=$(sed -n 's/^fuzz real: \([0-9]*\) scenes.*/\1/p' <<< "$line")
  f=$(sed -n 's/.* \([0-9]*\) failed;.*/\1/p' <<< "$line")
  r=$(sed -n 's/.* \([0-9]*\) refused;.*/\1/p' <<< "$line")
  scenes=$(( scenes + ${n:-0} ))
  failed=$(( failed + ${f:-1} ))
  refused=$(( refused + ${r:-0} ))
  grep '^FAIL' <<< "$out" | sort -u >> "$work/real-failures.txt" || true
  s=$(( s + 1 ))
done
secs=$(( $(date +%s) - start ))
printf '%-12s %12d %8d %8d %10d %8d   (scenes, %d refused; seeds %d..%d)\n' real "$scenes" \
  $(( scenes / (secs > 0 ? secs : 1) )) 0 "$failed" "$secs" "$refused" "$seed" $(( s - 1 )) | tee -a "$report"
echo "report: $report; findings under $work/artifacts/, $work/generator-failures.txt, $work/real-failures.txt"
