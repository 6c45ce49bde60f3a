#!/usr/bin/env bash
# Submits one of umbra's big jobs to Slurm as an array and its merge job,
# which starts when the array is done (docs/scale.md):
#
#   scripts/slurm/submit.sh [--wait] frame SCENE OUTDIR N [render options...]
#       N tiles (tiled-frame.sbatch), merged into OUTDIR/frame.exr
#   scripts/slurm/submit.sh [--wait] truth MODELS.txt OUTDIR N [fuzz real options...]
#       the real-model sweep in N shards (truth-suite.sbatch), merged into
#       OUTDIR/summary.json and OUTDIR/junit.xml
#   scripts/slurm/submit.sh [--wait] fuzz OUTDIR N SEED COUNT [SECONDS [HARNESSES]]
#       a fuzz campaign of N tasks (fuzz-campaign.sbatch, fuzz-campaign-merge.sbatch)
#   scripts/slurm/submit.sh [--wait] batch MANIFEST.jsonl OUTDIR N
#       an umbra batch manifest in N slices (batch.sbatch), the jobs' result
#       lines joined into OUTDIR/results.jsonl
#
# Prints the array's and the merge's job ids. --wait returns when the merge
# job ends: 0 when it completed, 1 when it failed or was cancelled (a failing
# shard or tile fails the call).
# Slurm's logs go to OUTDIR/logs/. SBATCH_* variables (partition, account,
# time limit) pass through to sbatch; UMBRA names the executable the jobs run
# (an absolute path: the jobs run on other nodes), FUZZ_BUILD the libFuzzer
# build for `fuzz`.
#
# The frame's merge waits for every tile to succeed (afterok: a frame with a
# missing tile cannot be merged, and the merge is cancelled rather than left
# pending). The other merges run after any ending (afterany): a shard that
# found a failing scene exits 1, and that is exactly when its summary must be
# merged; a shard that wrote nothing makes the merge refuse, naming it.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
wait=()
if [ "${1:-}" = --wait ]; then wait=(--wait); shift; fi
[ $# -ge 1 ] || { sed -n 2,28p "$0" >&2; exit 2; }
kind=$1
shift
umbra=${UMBRA:-umbra}
q() { printf '%q ' "$@"; }
# PREFIX0SUFFIX … PREFIX(N-1)SUFFIX, quoted for the merge job's shell.
parts() { local k; for ((k = 0; k < n; k++)); do q "$1$k$2"; done; }

case "$kind" in
  frame)
    [ $# -ge 3 ] || { echo "submit: usage: frame SCENE OUTDIR N [render options...]" >&2; exit 2; }
    out=$2 n=$3 script=tiled-frame.sbatch dependency=afterok ;;
  truth)
    [ $# -ge 3 ] || { echo "submit: usage: truth MODELS.txt OUTDIR N [fuzz real options...]" >&2; exit 2; }
    out=$2 n=$3 script=truth-suite.sbatch dependency=afterany ;;
  batch)
    [ $# -eq 3 ] || { echo "submit: usage: batch MANIFEST.jsonl OUTDIR N" >&2; exit 2; }
    out=$2 n=$3 script=batch.sbatch dependency=afterany ;;
  fuzz)
    [ $# -ge 4 ] || { echo "submit: usage: fuzz OUTDIR N SEED COUNT [SECONDS [HARNESSES]]" >&2; exit 2; }
    out=$1 n=$2 script=fuzz-campaign.sbatch dependency=afterany ;;
  *) echo "submit: unknown job '$kind' (frame, truth, fuzz or batch)" >&2; exit 2 ;;
esac
case "$n" in
  '' | *[!0-9]* | 0*) echo "submit: N must be a positive whole number, not '$n'" >&2; exit 2 ;;
esac
case "$kind" in
  frame) merge="$(q "$umbra" merge) $(parts "$out/tile-" .exr) -o $(q "$out/frame.exr")" ;;
  truth) merge="$(q "$umbra" fuzz merge) $(parts "$out/part-" .json) -o $(q "$out/summary.json")"
         merge+=" --junit $(q "$out/junit.xml")" ;;
  fuzz) merge="$(q "$here/fuzz-campaign-merge.sbatch" "$out")" ;;
  # The result lines in task order; the step fails when a job did.
  batch) merge="cat $(parts "$out/results-" .jsonl) > $(q "$out/results.jsonl") && "
         merge+="! grep -q '\"exit\":[1-9]' $(q "$out/results.jsonl")" ;;
esac

mkdir -p "$out/logs"
array=$(sbatch --parsable --array="0-$((n - 1))" --output="$out/logs/%x-%A_%a.out" \
  "$here/$script" "$@")
array=${array%%;*}
echo "submit: $kind array job $array ($n tasks)"
merge_job=$(sbatch --parsable --dependency="$dependency:$array" --kill-on-invalid-dep=yes \
  --job-name="umbra-$kind-merge" --output="$out/logs/%x-%j.out" --export=ALL --wrap="$merge")
merge_job=${merge_job%%;*}
echo "submit: $kind merge job $merge_job"
[ ${#wait[@]} -gt 0 ] || exit 0

# Waiting asks the controller every 2 s; not sbatch --wait, which answers
# 0 for a job cancelled before it ran (a tile failed and the merge's
# dependency can never be met) and whose polling backs off: it returned
# 30 s after an array of 9 s had been merged.
state() {
  scontrol show job -o "$1" 2> /dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2 | sort |
    uniq -c | awk '{ printf " %s %s", $1, $2 }'
}
unknown=0
while :; do
  now=$(state "$merge_job")
  case "$now" in
    *PENDING* | *RUNNING* | *CONFIGURING* | *COMPLETING* | *SUSPENDED* | *REQUEUE*) ;;
    '') unknown=$((unknown + 1))
        [ "$unknown" -lt 5 ] || { echo "submit: the controller no longer knows job $merge_job" >&2; exit 1; } ;;
    *) break ;;
  esac
  sleep 2
done
echo "submit: array $array:$(state "$array"); merge:$now"
if [ "$now" != ' 1 COMPLETED' ]; then
  echo "submit: the merge job did not complete; see $out/logs/" >&2
  exit 1
fi
