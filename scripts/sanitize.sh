#!/usr/bin/env bash
# The test suite under AddressSanitizer and UndefinedBehaviorSanitizer
# (issue 17): clang 14 (docs/fuzzing.md's compiler; GCC works too with
# CXX=g++), every target built with -fsanitize=address,undefined and
# -fno-sanitize-recover=undefined (UMBRA_SANITIZE=ON), then ctest.
#   scripts/sanitize.sh [--edge] [-j N] [CTEST_ARGS...]   # e.g. -R GltfPathRule
# --edge: only the programs and tests labelled `edge` (the fuzz replays of
# every corpus and regression input, the generator's seeded smoke run, the
# CLI's refusals of hostile input); what CI runs (scripts/test.sh), about
# 9 minutes on 2 cores against 25 for every test but `slow`.
# Build tree: build-asan/ (kept, so a second run only rebuilds what changed).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=2
edge=0
while [ $# -gt 0 ]; do
  case "$1" in
    --edge) edge=1; shift ;;
    -j) jobs=$2; shift 2 ;;
    *) break ;;
  esac
done
: "${CXX:=clang++-14}"
export CXX
# -O1 with line tables: what the sanitizers' authors recommend (readable
# stacks, tests at a usable speed), and twice as quick to build as -O2 -g.
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DUMBRA_SANITIZE=ON \
  -DUMBRA_BUILD_BENCH=OFF "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG"
# halt_on_error: the first report fails its test. Leaks are reported too
# (none, Debian's libraries included, at the time of writing).
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
if [ "$edge" = 1 ]; then
  cmake --build build-asan -j "$jobs" --target umbra_edge_programs
  ctest --test-dir build-asan -j "$jobs" --output-on-failure --timeout 1800 -L edge "$@"
else
  cmake --build build-asan -j "$jobs"
  ctest --test-dir build-asan -j "$jobs" --output-on-failure --timeout 1800 "$@"
fi
