#!/usr/bin/env bash
# Fails when a tracked C++ source is not formatted as .clang-format says
# (clang-format 14, Debian's). The test command runs it before building;
# `scripts/check-format.sh --fix` rewrites the files instead.
set -euo pipefail
cd "$(dirname "$0")/.."
format=clang-format-14
command -v "$format" >/dev/null || { echo "check-format: $format not found (scripts/install-deps.sh)" >&2; exit 2; }
mapfile -t files < <(git ls-files '*.h' '*.cpp' ':!:tests/data/**' ':!:fuzz/corpus/**' ':!:fuzz/regressions/**')
if [ "${1:-}" = "--fix" ]; then
  "$format" -i "${files[@]}"
  exit 0
fi
bad=$("$format" --dry-run "${files[@]}" 2>&1 | grep -oE '^[^: ]+\.(h|cpp):[0-9]+:[0-9]+: warning' |
  cut -d: -f1 | sort -u || true)
if [ -n "$bad" ]; then
  echo "check-format: not formatted (run scripts/check-format.sh --fix):" >&2
  echo "$bad" | sed 's/^/  /' >&2
  exit 1
fi
echo "check-format: ${#files[@]} files formatted"
