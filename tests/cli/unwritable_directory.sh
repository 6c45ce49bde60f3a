#!/bin/sh
# An output in a directory umbra may not write to is refused before any
# work, with one line (issue 24): `umbra ARGS...` where the word @DIR@ in
# ARGS is replaced by such a directory. Not writable: a fresh directory of
# mode 555; for root, whom modes do not stop, /proc/sys (procfs creates no
# files there); when neither is refused by access(2), the test is skipped
# (exit 77, CTest's SKIP_RETURN_CODE).
#   unwritable_directory.sh UMBRA WORK_DIR ARGS...
set -u
umbra=$1 work=$2
shift 2
rm -rf "$work" && mkdir -p "$work/ro" && chmod 555 "$work/ro" || exit 1
dir=$work/ro
if [ -w "$dir" ]; then
  dir=/proc/sys
  [ -w "$dir" ] && { echo "no unwritable directory here; skipped"; exit 77; }
fi
args=""
for a in "$@"; do
  a=$(printf '%s' "$a" | sed "s|@DIR@|$dir|g")
  args="$args '$a'"
done
err=$(cd "$work" && eval exec "\"$umbra\"" "$args" 2>&1 >/dev/null)
code=$?
fail=0
[ "$code" -eq 2 ] || { echo "exit code $code, expected 2"; fail=1; }
case $err in
  "umbra: $dir/"*": directory '$dir' is not writable: "*) ;;
  *) echo "stderr: '$err'"; fail=1 ;;
esac
[ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] || { echo "more than one line on stderr"; fail=1; }
chmod 755 "$work/ro"
[ -z "$(ls -A "$work/ro")" ] || { echo "left behind in $work/ro"; fail=1; }
exit $fail
