#!/usr/bin/env bash
# Fresh machine to passing tests (what .ci/run calls): install dependencies,
# check formatting and the include rules, build warning-free (-Werror) and run
# every test; then build with AddressSanitizer + UBSan and run the suite
# again but for the `slow` label (the sweeps; scripts/sanitize.sh runs all).
#   UMBRA_TEST_SANITIZE=0 scripts/test.sh   # skip the sanitizer half
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
./scripts/install-deps.sh
./scripts/check-format.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DUMBRA_WERROR=ON
cmake --build build
ctest --test-dir build --output-on-failure -j"$(nproc)"
echo "test.sh: release build and tests done in $(( $(date +%s) - start )) s"
if [ "${UMBRA_TEST_SANITIZE:-1}" != "0" ]; then
  ./scripts/sanitize.sh -j "$(nproc)" -LE slow
  echo "test.sh: sanitizer build and tests done in $(( $(date +%s) - start )) s"
fi
