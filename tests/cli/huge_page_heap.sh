#!/bin/sh
# cli/heap.cpp: the program turns on mimalloc's large OS pages before the
# allocator starts, unless the user set MIMALLOC_LARGE_OS_PAGES (which then
# wins either way). mimalloc's own verbose start-up report says which
# value it took.
#   huge_page_heap.sh UMBRA
set -u
umbra=$1
fail=0
option() {
  # Prints the value mimalloc reports for large_os_pages, with $@ as the
  # environment.
  env "$@" MIMALLOC_VERBOSE=1 "$umbra" --version 2>&1 >/dev/null |
    sed -n "s/^mimalloc: option 'large_os_pages': \([0-9]*\)$/\1/p"
}
got=$(option -u MIMALLOC_LARGE_OS_PAGES)
[ "$got" = 1 ] || { echo "unset: large_os_pages '$got', expected 1"; fail=1; }
got=$(option MIMALLOC_LARGE_OS_PAGES=0)
[ "$got" = 0 ] || { echo "MIMALLOC_LARGE_OS_PAGES=0: large_os_pages '$got', expected 0"; fail=1; }
got=$(option MIMALLOC_LARGE_OS_PAGES=1)
[ "$got" = 1 ] || { echo "MIMALLOC_LARGE_OS_PAGES=1: large_os_pages '$got', expected 1"; fail=1; }
exit $fail
