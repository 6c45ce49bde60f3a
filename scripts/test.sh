#!/usr/bin/env bash
# Fresh machine to passing tests (what .ci/run calls): install dependencies,
# check formatting and the include rules, build warning-free (-Werror) and run
# every test; then build with AddressSanitizer + UBSan and run the `edge`
# slice (hostile input: fuzz replays, the seeded generator run, the CLI's
# refusals). Two builds on two cores are most of CI's time; the sanitized
# unit tests and renders (another ~16 minutes) are scripts/sanitize.sh's.
#   UMBRA_TEST_SANITIZE=0 scripts/test.sh     # skip the sanitizer half
#   UMBRA_TEST_SANITIZE=all scripts/test.sh   # every test but `slow` sanitized
set -euo pipefail
cd "$(dirname "$0")/.."
sanitize=${UMBRA_TEST_SANITIZE:-edge}
case "$sanitize" in
  0 | edge | all) ;;
  *) echo "test.sh: UMBRA_TEST_SANITIZE is 0, edge or all, not '$sanitize'" >&2; exit 2 ;;
esac
start=$(date +%s)
./scripts/install-deps.sh
./scripts/check-format.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DUMBRA_WERROR=ON
cmake --build build
ctest --test-dir build --output-on-failure -j"$(nproc)"
echo "test.sh: release build and tests done in $(( $(date +%s) - start )) s"
case "$sanitize" in
  0) exit 0 ;;
  all) ./scripts/sanitize.sh -j "$(nproc)" -LE slow ;;
  edge) ./scripts/sanitize.sh --edge -j "$(nproc)" ;;
esac
echo "test.sh: sanitizer build and tests done in $(( $(date +%s) - start )) s"
