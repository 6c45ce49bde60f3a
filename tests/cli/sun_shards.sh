#!/bin/sh
# A sun series in three shards (`umbra footprint --sun-times --shard I/3`)
# joined by `umbra merge`: the schedule, the per-step table and the GeoJSON
# are the bytes of the series run whole; parts out of order are refused.
# Usage: sun_shards.sh UMBRA SCENE WORK_DIR
set -eu
umbra=$1 scene=$2 work=$3
series=2026-03-21T00:00+01:00/2026-03-22T00:00+01:00/PT30M
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$umbra" footprint "$scene" --sun-times "$series" --schedule whole.schedule.csv --csv whole.csv \
  -o whole.geojson -q
for i in 0 1 2; do
  "$umbra" footprint "$scene" --sun-times "$series" --shard $i/3 \
    --schedule part$i.schedule.csv --csv part$i.csv -o part$i.geojson -q
done
"$umbra" merge part0.schedule.csv part1.schedule.csv part2.schedule.csv -o merged.schedule.csv -q
"$umbra" merge part0.csv part1.csv part2.csv -o merged.csv -q
"$umbra" merge part0.geojson part1.geojson part2.geojson -o merged.geojson -q
cmp merged.schedule.csv whole.schedule.csv
cmp merged.csv whole.csv
cmp merged.geojson whole.geojson
# The parts really split the features, and the walls they skip repeat from
# part to part: the merge counts the distinct ones, not the sum.
python3 - << 'PY'
import json
whole = json.load(open("whole.geojson"))["umbra"]
parts = [json.load(open(f"part{i}.geojson"))["umbra"] for i in range(3)]
assert all(0 < p["features"] < whole["features"] for p in parts), parts
assert sum(p["features"] for p in parts) == whole["features"]
assert sum(p["receivers_skipped"] for p in parts) > whole["receivers_skipped"] > 0
PY
if "$umbra" merge part0.geojson part2.geojson part1.geojson -o bad.geojson 2> err.txt; then exit 1; fi
grep -q "^umbra: part1.geojson: time .* is not after .*: give the parts in shard order" err.txt
test ! -e bad.geojson
head -c 200 part1.geojson > cut.geojson
if "$umbra" merge part0.geojson cut.geojson -o bad.geojson 2> err.txt; then exit 1; fi
grep -q "^umbra: cut.geojson: is not a part of .*: not valid JSON" err.txt
test ! -e bad.geojson
python3 -c "print('[' * 100000)" > deep.geojson
if "$umbra" merge deep.geojson -o bad.geojson 2> err.txt; then exit 1; fi
test "$(wc -l < err.txt)" -eq 1
grep -q "^umbra: deep.geojson: is not a part of .*: nested deeper than 8" err.txt
test ! -e bad.geojson
test "$(wc -l < part1.schedule.csv)" -eq 17  # the header and 16 of the 48 rows
if "$umbra" merge part1.csv part0.csv part2.csv -o bad.csv 2> err.txt; then exit 1; fi
grep -q "^umbra: part0.csv: time .* is not after .*: give the parts in shard order" err.txt
test ! -e bad.csv
echo "shards: 3 parts merge into the whole series' bytes (schedule, table, GeoJSON)"
