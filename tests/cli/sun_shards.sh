#!/bin/sh
# A sun series in three shards (`umbra footprint --sun-times --shard I/3`)
# joined by `umbra merge`: the schedule and the per-step table are the
# bytes of the series run whole; parts out of order are refused.
# Usage: sun_shards.sh UMBRA SCENE WORK_DIR
set -eu
umbra=$1 scene=$2 work=$3
series=2026-03-21T00:00+01:00/2026-03-22T00:00+01:00/PT30M
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$umbra" footprint "$scene" --sun-times "$series" --schedule whole.schedule.csv --csv whole.csv -q
for i in 0 1 2; do
  "$umbra" footprint "$scene" --sun-times "$series" --shard $i/3 \
    --schedule part$i.schedule.csv --csv part$i.csv -q
done
"$umbra" merge part0.schedule.csv part1.schedule.csv part2.schedule.csv -o merged.schedule.csv -q
"$umbra" merge part0.csv part1.csv part2.csv -o merged.csv -q
cmp merged.schedule.csv whole.schedule.csv
cmp merged.csv whole.csv
test "$(wc -l < part1.schedule.csv)" -eq 17  # the header and 16 of the 48 rows
if "$umbra" merge part1.csv part0.csv part2.csv -o bad.csv 2> err.txt; then exit 1; fi
grep -q "^umbra: part0.csv: time .* is not after .*: give the parts in shard order" err.txt
test ! -e bad.csv
echo "shards: 3 parts merge into the whole series' bytes"
