#!/bin/sh
# Issue 17, row 6: std::bad_alloc is a resource error, never "internal
# error". `umbra ARGS...` runs under an address-space limit of 3 GB
# (ulimit -v, in KiB) in an empty WORK_DIR; the scene's frame alone needs
# more, and --memory-limit is raised past the estimate so that the
# allocation itself fails. Expect exit 2, one line, nothing written.
# Before: "umbra: internal error: std::bad_alloc", exit 3.
#   out_of_memory.sh UMBRA WORK_DIR ARGS...
set -u
umbra=$1 work=$2
shift 2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
err=$( (ulimit -v 3000000; exec "$umbra" "$@") 2>&1 >/dev/null)
code=$?
fail=0
[ "$code" -eq 2 ] || { echo "exit code $code, expected 2"; fail=1; }
case $err in
  "umbra: out of memory: "*) ;;
  *) echo "stderr: '$err'"; fail=1 ;;
esac
[ -z "$(ls -A)" ] || { echo "left behind: $(ls -A)"; fail=1; }
exit $fail
