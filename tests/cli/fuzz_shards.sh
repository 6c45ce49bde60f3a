#!/bin/sh
# `umbra fuzz check` and `umbra fuzz real` run whole and in shards
# (--shard I/N --summary), joined by `umbra fuzz merge`: the merged summary
# is the whole run's but for "seconds" and "seconds_load", the merged text
# is the whole run's -q output but for the time, the exit codes agree, and
# every JUnit report reads back with python3's xml.etree. Failures and
# refusals added to the parts (fuzz_inject_failures.py) merge in the
# one-process order. Parts that are not the shards of one run are refused
# with one line, exit 2 and no output file.
# Usage: fuzz_shards.sh UMBRA SCRIPTS_DIR WORK_DIR MESH...
set -eu
umbra=$1 scripts=$2 work=$3
shift 3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
# Runs a command that may exit 0 or 1 (scenes failed); its code in $rc.
run() { rc=0; "$@" || rc=$?; test $rc -le 1; }
timeless() { grep -v '"seconds' "$1"; }
untimed() { sed -E 's/; [0-9]+\.[0-9] s( \([0-9]+\.[0-9] s loading\))?$//' "$1"; }
same() { cmp "$1" "$2" || { diff "$1" "$2" | head -20; exit 1; }; }
junit() { python3 "$scripts/fuzz_junit_check.py" "$1" "$2"; }

# fuzz check: 12 scenes in one process, and in 3 shards merged in any order.
check="fuzz check --count 12 --seed 5 --width 16 --height 12 --threads 1 -q"
run "$umbra" $check --summary whole.json --junit whole.xml > whole.txt
whole_rc=$rc
for i in 0 1 2; do
  run "$umbra" $check --shard $i/3 --summary c$i.json --junit c$i.xml > c$i.txt
  junit c$i.json c$i.xml
done
grep -q "^fuzz check: 4 scenes (seed 5, shard 1/3)" c1.txt
run "$umbra" fuzz merge c2.json c0.json c1.json -o merged.json --junit merged.xml > merged.txt
test $rc -eq $whole_rc
timeless whole.json > a && timeless merged.json > b && same a b
untimed whole.txt > a && untimed merged.txt > b && same a b
junit whole.json whole.xml && junit merged.json merged.xml

# Failures and refusals in the parts merge into the whole run's order.
cp whole.json fail-whole.json
for f in fail-whole c0 c1 c2; do
  test $f = fail-whole || cp $f.json fail-$f.json
  python3 "$scripts/fuzz_inject_failures.py" fail-${f#fail-}.json 10:mismatch 3:refused 4:mismatch
done
run "$umbra" fuzz merge fail-c1.json fail-c2.json fail-c0.json -o fail-merged.json \
  --junit fail-merged.xml > fail-merged.txt
test $rc -eq 1
python3 -c 'import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:])
for d in (a, b): d["seconds"] = 0
assert json.dumps(a) == json.dumps(b), "merged failures differ from the whole run with them"
assert [f["index"] for f in b["failures"]] == [3, 4, 10]' fail-whole.json fail-merged.json
grep -q "^FAIL s5-3 .*refused: shadow volume count -1 for light 0" fail-merged.txt
test "$(grep -c '^FAIL' fail-merged.txt)" -eq 3
test "$(grep '^FAIL' fail-merged.txt | cut -d' ' -f2 | tr '\n' ' ')" = "s5-3 s5-4 s5-10 "
junit fail-merged.json fail-merged.xml
grep -q '<testsuites tests="12" failures="2" errors="1"' fail-merged.xml

# fuzz real: two shards of the mesh files.
real="fuzz real --per-mesh 2 --seed 3 --width 24 --height 18 --threads 1 -q"
for m in "$@"; do real="$real --meshes $m"; done
run "$umbra" $real --summary real.json --junit real.xml > real.txt
real_rc=$rc
run "$umbra" $real --shard 0/2 --summary r0.json > r0.txt
run "$umbra" $real --shard 1/2 --summary r1.json > r1.txt
run "$umbra" fuzz merge r1.json r0.json -o real-merged.json --junit real-merged.xml > real-merged.txt
test $rc -eq $real_rc
timeless real.json > a && timeless real-merged.json > b && same a b
grep -v '^FAIL' real.txt | untimed /dev/stdin > a
untimed real-merged.txt | grep -v '^FAIL' > b && same a b
junit real.json real.xml && junit real-merged.json real-merged.xml

# Refused: one line on stderr, exit 2, no output file.
refused() {
  expect=$1
  shift
  rc=0
  "$umbra" fuzz merge "$@" -o out.json --junit out.xml > /dev/null 2> err.txt || rc=$?
  test $rc -eq 2 || { echo "exit $rc for merge $*"; exit 1; }
  test "$(wc -l < err.txt)" -eq 1 && grep -q "^umbra: $expect" err.txt ||
    { echo "merge $*:"; cat err.txt; exit 1; }
  test ! -e out.json && test ! -e out.xml
}
refused "shard 2/3: missing: no part holds it" c0.json c1.json
refused "\\./c0.json: shard 0/3 again: c0.json is that shard too" c0.json c1.json c2.json ./c0.json
"$umbra" fuzz check --count 12 --seed 6 --width 16 --height 12 --shard 2/3 -q --summary s6.json \
  > /dev/null || true
refused 's6.json: "seed" is 6, 5 in c0.json: not a part of the same run' c0.json c1.json s6.json
refused 'r0.json: "verb" is "real", "check" in c0.json' c0.json r0.json
printf '{"verb": "check", "seed": 5,' > bad.json
refused "bad.json: not JSON: " c0.json bad.json
printf '{"verb": "check", "seed": 18446744073709551616}' > huge.json
refused 'huge.json: "seed" is not what a fuzz summary holds' huge.json
echo "fuzz shards: check in 3 shards and real in 2 merge into the whole runs' summaries"
