#!/bin/sh
# Issue 17, row 4, through the executable: `umbra ARGS...` under a file size
# limit of BLOCKS 512-byte blocks (ulimit -f), run in an empty WORK_DIR.
# The write must fail with exit 2 and one line naming the file, and leave no
# file behind: before, the PNG writer's failed fwrite went unnoticed, umbra
# printed "wrote ..." with exit 0 and left a truncated PNG.
#   file_size_limit.sh UMBRA WORK_DIR BLOCKS ARGS...
set -u
umbra=$1 work=$2 blocks=$3
shift 3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
err=$( (ulimit -f "$blocks"; exec "$umbra" "$@") 2>&1 >/dev/null)
code=$?
fail=0
[ "$code" -eq 2 ] || { echo "exit code $code, expected 2"; fail=1; }
case $err in
  "umbra: "*": cannot write file: File too large") ;;
  *) echo "stderr: '$err'"; fail=1 ;;
esac
left=$(ls -A)
[ -z "$left" ] || { echo "left behind: $left"; fail=1; }
exit $fail
