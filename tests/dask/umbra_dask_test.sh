#!/bin/sh
# Dask instead of Slurm (scripts/dask/umbra_dask.py): a 2-tile frame and a
# 3-shard truth suite run as Dask tasks on a local cluster, merged; the
# frame must be the single render's bytes and the summary the one-process
# run's but its CPU seconds. Exit 77 (CTest: skipped) without Dask.
# Usage: umbra_dask_test.sh UMBRA SOURCE_DIR WORK_DIR
set -eu
umbra=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
run() { UMBRA=$umbra /usr/bin/python3 "$source/scripts/dask/umbra_dask.py" "$@"; }

scene=$source/data/scenes/two_lights.json
status=0
run frame "$scene" frame 2 --workers 2 -- --method volume || status=$?
[ "$status" -ne 77 ] || exit 77
[ "$status" -eq 0 ] || { echo "umbra_dask.py frame exited $status" >&2; exit 1; }
"$umbra" render "$scene" --method volume -q -o whole.exr
cmp frame/frame.exr whole.exr

set -- "$source/data/meshes/cube.off" "$source/data/meshes/torus.off" \
  /usr/share/assimp/models/PLY/cube.ply
run truth truth 3 --workers 2 --meshes "$@" -- --per-mesh 2 --seed 5 > truth.out
"$umbra" fuzz real --meshes "$1" --meshes "$2" --meshes "$3" --per-mesh 2 --seed 5 -q \
  --summary whole.json > /dev/null
/usr/bin/python3 - << 'PY'
import json
whole, merged = (json.load(open(f)) for f in ("whole.json", "truth/summary.json"))
for d in (whole, merged):
    d.pop("seconds"), d.pop("seconds_load")
assert merged == whole, (merged, whole)
assert whole["scenes"] == 6, whole["scenes"]
PY
# Tiles that cannot run (a broken scene): nothing is merged, exit 1.
printf '{\n' > broken.json
if run frame broken.json broken 2 --workers 2 2> broken.err; then exit 1; fi
grep -q 'umbra_dask: tiles \[0, 1\] failed; nothing merged' broken.err
test ! -e broken/frame.exr
echo "dask: 2 tiles and 3 truth shards merged into the single runs' results"
