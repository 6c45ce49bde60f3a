#!/usr/bin/env bash
# The speed/accuracy chart of issue 5, from one command: every shadow method
# and parameter setting on the chart scenes (paper cases from data/, CGAL's
# elephant and bunny00, the night city) and the stability sweeps, timed and
# scored against the exact oracle; then the CSV drawn with matplotlib.
# Usage: scripts/chart.sh [--quick] [--out DIR] [more umbra_chart flags]
#   default: writes DIR=docs/chart (results.csv, machine.txt, chart-*.png,
#   sweep-*.png, summary.md); --quick: a CI smoke into out/chart-quick.
set -euo pipefail
cd "$(dirname "$0")/.."
quick=0
out=docs/chart
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1; out=out/chart-quick; shift ;;
    --out) out="$2"; shift 2 ;;
    *) extra+=("$1"); shift ;;
  esac
done
./scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --target umbra_chart
mkdir -p "$out"
if [ $quick -eq 1 ]; then
  ./build/bench/umbra_chart --quick -o "$out/results.csv" "${extra[@]}"
else
  m=$(./scripts/cgal-meshes.sh elephant.off bunny00.off)
  ./build/bench/umbra_chart --meshes "$m/elephant.off:$m/bunny00.off" -o "$out/results.csv" \
    "${extra[@]}"
fi
{
  echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')," \
    "$(free -g | awk '/Mem:/ {print $2}') GiB"
  echo "command: scripts/chart.sh $([ $quick -eq 1 ] && echo --quick) ${extra[*]}"
} > "$out/machine.txt"
# Debian's interpreter: its python3-matplotlib is the plotting library.
/usr/bin/python3 scripts/chart.py "$out/results.csv" "$out"
