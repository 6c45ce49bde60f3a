#!/bin/sh
# `umbra batch` against the same jobs run as separate commands (docs/cli.md
# "umbra batch"): every output byte-identical (JSON reports compared with
# their "seconds" left out); a re-run with --skip-existing skips every job;
# a manifest with one bad line runs nothing and names the line.
# Usage: batch_same_bytes.sh UMBRA DATA_DIR WORK_DIR
set -eu
umbra=$1 data=$2 work=$3
rm -rf "$work" && mkdir -p "$work/batch" "$work/alone"
cat > "$work/jobs.jsonl" <<JOBS
{"verb": "render", "scene": "$data/scenes/open.json", "output": "open.exr", "options": {"threads": 1}}
{"verb": "render", "scene": "$data/scenes/tinted/coloured.json", "output": "map.exr", "options": {"method": "map", "map-resolution": 256}}

{"verb": "validate", "scene": "$data/scenes/open.json", "output": "validate.json", "options": {"image": "open.exr", "no-mask": true}}
{"verb": "footprint", "scene": "$data/scenes/sun/golden.json", "output": "golden.ply", "options": {"csv": "golden.csv", "lights": [0, 1]}}
{"verb": "volume", "scene": "$data/scenes/open.json", "output": "open.volume.ply"}
{"verb": "sunlight", "scene": "$data/scenes/city/block.json", "output": "sun.json", "options": {"area": "ground", "date": "2026-03-21", "step": "PT30M"}}
JOBS
(cd "$work/batch" && "$umbra" batch ../jobs.jsonl > report.jsonl)
(cd "$work/alone" &&
  "$umbra" render "$data/scenes/open.json" -o open.exr --threads=1 -q &&
  "$umbra" render "$data/scenes/tinted/coloured.json" -o map.exr --method=map --map-resolution=256 -q &&
  "$umbra" validate "$data/scenes/open.json" --stats-json validate.json --image=open.exr --no-mask -q &&
  "$umbra" footprint "$data/scenes/sun/golden.json" -o golden.ply --csv=golden.csv --lights=0,1 -q &&
  "$umbra" volume "$data/scenes/open.json" -o open.volume.ply -q &&
  "$umbra" sunlight "$data/scenes/city/block.json" --json sun.json --area=ground --date=2026-03-21 --step=PT30M -q)
python3 - "$work" <<'PY'
import json, os, sys
work = sys.argv[1]
def strip(x):
    if isinstance(x, dict):
        return {k: strip(v) for k, v in x.items() if k != "seconds"}
    return [strip(v) for v in x] if isinstance(x, list) else x
lines = [json.loads(l) for l in open(os.path.join(work, "batch", "report.jsonl"))]
assert [l["line"] for l in lines] == [1, 2, 4, 5, 6, 7], lines
assert all(l["exit"] == 0 and not l["skipped"] for l in lines), lines
names = sorted(os.listdir(os.path.join(work, "alone")))
assert sorted(set(os.listdir(os.path.join(work, "batch"))) - {"report.jsonl"}) == names, names
for name in names:
    a, b = (open(os.path.join(work, d, name), "rb").read() for d in ("batch", "alone"))
    if name.endswith(".json"):
        a, b = strip(json.loads(a)), strip(json.loads(b))
    assert a == b, "%s differs between the batch and the separate command" % name
print("batch: %d jobs, %d files the same as separate commands" % (len(lines), len(names)))
PY
# Re-submitted: every job with an output that exists is skipped.
(cd "$work/batch" && "$umbra" batch ../jobs.jsonl --skip-existing > again.jsonl)
test "$(grep -c '"skipped":true' "$work/batch/again.jsonl")" -eq 6
# One bad line: refused whole, before any job (nothing written), line named.
mkdir -p "$work/bad"
printf '%s\n%s\n' \
  "{\"verb\": \"volume\", \"scene\": \"$data/scenes/open.json\", \"output\": \"v.ply\"}" \
  '{"verb": "batch", "scene": "x.json"}' > "$work/bad/jobs.jsonl"
if (cd "$work/bad" && "$umbra" batch jobs.jsonl 2> err.txt); then exit 1; fi
grep -q "^umbra: jobs.jsonl:2: verb 'batch' cannot be batched" "$work/bad/err.txt"
test ! -e "$work/bad/v.ply"
refused() {  # a one-line manifest and the message it must get
  printf '%s\n' "$1" > "$work/bad/one.jsonl"
  if (cd "$work/bad" && "$umbra" batch one.jsonl 2> err.txt); then exit 1; fi
  grep -q "$2" "$work/bad/err.txt" || { cat "$work/bad/err.txt"; exit 1; }
}
refused 'not json' "one.jsonl:1: not JSON"
refused '{"verb": "volume", "scene": "s.json", "options": {"a": [[[1]]]}}' "nested deeper than a job"
refused '{"verb": "volume", "scene": "s.json", "options": {"stats-json": "-"}}' "other than '-'"
refused '{"verb": "volume", "scene": "s.json", "options": {"quiet": true}}' "jobs run quietly"
refused '{"verb": "volume", "scene": "s.json", "extra": 1}' "unknown field 'extra'"
refused '{"verb": "volume"}' '"scene" is required'
echo "batch: --skip-existing and a bad line behave"
