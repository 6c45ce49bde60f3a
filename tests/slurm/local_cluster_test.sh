#!/bin/sh
# Slurm for real (issue 25): a one-node cluster in private namespaces
# (scripts/slurm/local-cluster.sh) runs a 4-task truth-suite array and a
# 2-tile frame, each with its merge job, as scripts/slurm/submit.sh submits
# them; the merged outputs must be the single-process runs' bytes (the
# summary's but its CPU seconds). A frame of a broken scene must leave its tiles
# FAILED, its merge cancelled and submit.sh failing. Exit 77 (CTest: skipped)
# when Slurm or private namespaces are missing here.
# Usage: local_cluster_test.sh UMBRA SOURCE_DIR WORK_DIR
set -eu
umbra=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
work=$(cd "$work" && pwd)
cd "$work"

# Small meshes of three formats; 4 shards over 5 files (one shard gets two).
cat > models.txt << MODELS
# the truth suite's models
$source/data/meshes/cube.off
$source/data/meshes/torus.off
$source/data/meshes/open_box.off
/usr/share/assimp/models/PLY/cube.ply
/usr/share/assimp/models/OBJ/box.obj
MODELS
sweep="--per-mesh 2 --seed 11 --width 40 --height 30"
meshes=$(grep -v '^#' models.txt | sed 's/^/--meshes /' | tr '\n' ' ')
# shellcheck disable=SC2086  # word splitting of the option lists is meant
"$umbra" fuzz real $meshes $sweep -q --summary whole.json --junit whole.xml > /dev/null
scene=$source/data/scenes/two_lights.json
"$umbra" render "$scene" --method volume -q -o whole.exr
printf '{\n' > broken.json

status=0
UMBRA=$umbra "$source/scripts/slurm/local-cluster.sh" sh -c "
  set -e
  submit=$source/scripts/slurm/submit.sh
  \$submit --wait truth models.txt truth 4 $sweep
  \$submit --wait frame $scene frame 2 --method volume
  if \$submit --wait frame broken.json broken 2 > broken.out 2>&1; then
    echo 'a frame of a broken scene was merged' >&2; exit 1
  fi
  scontrol show job -o > jobs.txt
" || status=$?
[ "$status" -ne 77 ] || exit 77
[ "$status" -eq 0 ] || { echo "local cluster run failed ($status)" >&2; exit 1; }

cmp frame/frame.exr whole.exr
# The summaries agree but for the wall-clock seconds each process measured.
python3 - << 'PY'
import json
whole, merged = (json.load(open(f)) for f in ("whole.json", "truth/summary.json"))
for d in (whole, merged):
    d.pop("seconds"), d.pop("seconds_load")
assert merged == whole, (merged, whole)
assert whole["scenes"] == 10, whole["scenes"]
import xml.etree.ElementTree as ET
cases = [c.get("name") for c in ET.parse("truth/junit.xml").getroot().iter("testcase")]
whole_cases = [c.get("name") for c in ET.parse("whole.xml").getroot().iter("testcase")]
assert cases == whole_cases and len(cases) == 10, (cases, whole_cases)
PY
for i in 0 1 2 3; do test -s "truth/part-$i.json"; done
grep -q 'JobName=umbra-tile .*JobState=FAILED' jobs.txt
grep -q 'JobName=umbra-frame-merge .*JobState=CANCELLED' jobs.txt
grep -q 'the merge job did not complete' broken.out
test ! -e broken/frame.exr
echo "slurm: 4 truth-suite shards and 2 tiles merged into the single runs' results"
