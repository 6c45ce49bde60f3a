#!/usr/bin/env bash
# Issue 25's measurement: the truth suite over every shipped mesh (the
# real-model sweep, umbra fuzz real) run four ways on this machine, with
# wall and CPU seconds each, and the merged summaries checked equal:
#   1. one process over every mesh;
#   2. one process per mesh file (what an array of one task per model pays:
#      each process's start-up);
#   3. a Slurm array of N shards on the local one-node cluster
#      (scripts/slurm/local-cluster.sh), merged by umbra fuzz merge;
#   4. the same with one array task per mesh file;
# and a suite of scene files (render + validate of SCENES generated scenes,
# umbra fuzz export) as a process per job, as one umbra batch, and as a
# Slurm array of umbra batch slices: the start-up share before and after
# batch mode. Markdown on stdout; work files under build/truth-suite-bench/.
#   scripts/slurm/truth-suite-bench.sh [--per-mesh 2] [--seed 1] [--shards 8] [--scenes 50]
set -euo pipefail
cd "$(dirname "$0")/../.."
per_mesh=2 seed=1 shards=8 count=50
while [ $# -gt 0 ]; do
  case "$1" in
    --per-mesh) per_mesh=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --shards) shards=$2; shift 2 ;;
    --scenes) count=$2; shift 2 ;;
    -h|--help) sed -n 2,17p "$0"; exit 0 ;;
    *) echo "truth-suite-bench: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
./scripts/install-deps.sh >&2
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
cmake --build build --target umbra umbra_fuzz_cli >&2
umbra=$PWD/build/cli/umbra
work=$PWD/build/truth-suite-bench
rm -rf "$work" && mkdir -p "$work"

# Every shipped mesh: Debian's assimp test models and CGAL's data meshes.
{
  for sub in OBJ PLY OFF STL; do echo "/usr/share/assimp/models/$sub"; done
  [ ! -f /usr/share/doc/libcgal-dev/data.tar.gz ] || ./scripts/cgal-meshes.sh --all
} > "$work/models.txt"
mapfile -t roots < "$work/models.txt"
meshes=()
for root in "${roots[@]}"; do meshes+=(--meshes "$root"); done
# The files the sweep walks, in its order (sorted by path).
find "${roots[@]}" -type f \( -iname '*.off' -o -iname '*.obj' -o -iname '*.ply' -o -iname '*.stl' \) |
  LC_ALL=C sort > "$work/files.txt"
files=$(wc -l < "$work/files.txt")
sweep=(--per-mesh "$per_mesh" --seed "$seed" --threads 1 -q)

# CPU seconds of the commands run since the last call, from bash's `times`
# (children's user and system time), into the variable named $1; not in a
# command substitution, whose subshell has no children of its own.
cpu_mark=0
cpu_since() {
  local now
  times > "$work/times"
  now=$(tail -n 1 "$work/times" | awk '{ gsub(/[ms]/, " "); print $1 * 60 + $2 + $3 * 60 + $4 }')
  printf -v "$1" '%.1f' "$(awk -v a="$now" -v b="$cpu_mark" 'BEGIN { print a - b }')"
  cpu_mark=$now
}
clock() { date +%s.%N; }
span() { awk -v a="$1" -v b="$(clock)" 'BEGIN { printf "%.1f", b - a }'; }

cpu_since ignored
start=$(clock)
"$umbra" fuzz real "${meshes[@]}" "${sweep[@]}" --summary "$work/one.json" > /dev/null || true
one_wall=$(span "$start")
cpu_since one_cpu

start=$(clock)
k=0
while IFS= read -r file; do
  "$umbra" fuzz real --meshes "$file" "${sweep[@]}" --summary "$work/file-$k.json" \
    > /dev/null 2>&1 || true
  k=$((k + 1))
done < "$work/files.txt"
each_wall=$(span "$start")
cpu_since each_cpu

array() {  # N OUTDIR: the suite as an N-task array and its merge, waited for
  UMBRA=$umbra ./scripts/slurm/local-cluster.sh sh -c \
    "start=\$(date +%s.%N); ./scripts/slurm/submit.sh --wait truth '$work/models.txt' '$2' $1 \
       --per-mesh $per_mesh --seed $seed --threads 1 > /dev/null || true
     awk -v a=\"\$start\" -v b=\"\$(date +%s.%N)\" 'BEGIN { printf \"%.1f\", b - a }' > '$2.wall'"
}
array "$shards" "$work/array"
cpu_since array_cpu
array "$files" "$work/array-each"
cpu_since array_each_cpu

# The scene-file suite: a render and a validate a scene, as separate
# processes, as one batch, and as a Slurm array of batch slices.
"$umbra" fuzz export "$work/scenes" --count "$count" --seed "$seed" -q > /dev/null
jobs() {  # OUTDIR: the manifest's lines
  local scene name
  for scene in "$work"/scenes/*/scene.json; do
    name=$(basename "$(dirname "$scene")")
    printf '{"verb": "render", "scene": "%s", "output": "%s/%s.exr", "options": {"threads": 1}}\n' \
      "$scene" "$1" "$name"
    printf '{"verb": "validate", "scene": "%s", "output": "%s/%s.json", "options": {"image": "%s/%s.exr", "threads": 1}}\n' \
      "$scene" "$1" "$name" "$1" "$name"
  done
}
mkdir -p "$work/apart" "$work/batch" "$work/array-batch/out"
cpu_since ignored
start=$(clock)
for scene in "$work"/scenes/*/scene.json; do
  name=$(basename "$(dirname "$scene")")
  "$umbra" render "$scene" --threads 1 -q -o "$work/apart/$name.exr"
  "$umbra" validate "$scene" --image "$work/apart/$name.exr" --threads 1 -q \
    --stats-json "$work/apart/$name.json" || true
done
apart_wall=$(span "$start")
cpu_since apart_cpu
jobs "$work/batch" > "$work/batch.jsonl"
start=$(clock)
"$umbra" batch "$work/batch.jsonl" > "$work/batch-results.jsonl" || true
batch_wall=$(span "$start")
cpu_since batch_cpu
jobs "$work/array-batch/out" > "$work/array-batch.jsonl"
UMBRA=$umbra ./scripts/slurm/local-cluster.sh sh -c \
  "start=\$(date +%s.%N); ./scripts/slurm/submit.sh --wait batch '$work/array-batch.jsonl' \
     '$work/array-batch' $shards > /dev/null || true
   awk -v a=\"\$start\" -v b=\"\$(date +%s.%N)\" 'BEGIN { printf \"%.1f\", b - a }' > '$work/array-batch.wall'"
cpu_since array_batch_cpu
images_same() {  # the renders of the batch runs are the separate processes' bytes
  local f
  for f in "$work"/apart/*.exr; do
    cmp -s "$f" "$work/$1/$(basename "$f")" || { echo NO; return; }
  done
  echo yes
}

same() {
  python3 -c "
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:])
for d in (a, b):
    d.pop('seconds'), d.pop('seconds_load')
print('yes' if a == b else 'NO')" "$1" "$2"
}
scenes=$(python3 -c "import json; print(json.load(open('$work/one.json'))['scenes'])")
cat << EOF
Truth suite: umbra fuzz real over $files mesh files ($scenes scenes: --per-mesh $per_mesh
--seed $seed, 48x36, one thread a process), $(nproc) CPUs, $(date -u +%Y-%m-%d).

| run | processes | wall s | CPU s | summary = one process |
| --- | ---: | ---: | ---: | --- |
| one process | 1 | $one_wall | $one_cpu | — |
| a process per mesh file | $files | $each_wall | $each_cpu | — |
| Slurm array, local cluster | $shards + merge | $(cat "$work/array.wall") | $array_cpu | $(same "$work/one.json" "$work/array/summary.json") |
| Slurm array, a task per file | $files + merge | $(cat "$work/array-each.wall") | $array_each_cpu | $(same "$work/one.json" "$work/array-each/summary.json") |


Render + validate of $count generated scenes (umbra fuzz export --seed $seed), one thread:

| run | processes | wall s | CPU s | renders = separate processes' |
| --- | ---: | ---: | ---: | --- |
| a process per job | $((2 * count)) | $apart_wall | $apart_cpu | — |
| umbra batch | 1 | $batch_wall | $batch_cpu | $(images_same batch) |
| Slurm array of umbra batch slices | $shards + join | $(cat "$work/array-batch.wall") | $array_batch_cpu | $(images_same array-batch/out) |

CPU s: user + system of every process this script waited for (for the
arrays: the cluster's daemons, every job step and the merge); an array's
wall time includes starting and stopping the cluster (~1 s).
EOF
