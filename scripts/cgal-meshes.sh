#!/usr/bin/env bash
# Extracts meshes from CGAL's data tarball (Debian's libcgal-demo, installed
# here if missing) into build/cgal-data/data/meshes and prints that folder.
# Usage: scripts/cgal-meshes.sh MESH.off...   (names inside data/meshes/)
#        scripts/cgal-meshes.sh --all        (every mesh: what `umbra fuzz real` walks)
set -euo pipefail
cd "$(dirname "$0")/.."
tarball=/usr/share/doc/libcgal-dev/data.tar.gz
if [ ! -f "$tarball" ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO=sudo
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends libcgal-demo >&2
fi
data=build/cgal-data
mkdir -p "$data"
wanted=()
if [ "${1:-}" = "--all" ]; then
  # Once: a marker says the whole folder is there (single meshes may be already).
  [ -f "$data/.all-meshes" ] || { tar -xzf "$tarball" -C "$data" data/meshes && touch "$data/.all-meshes"; }
else
  for mesh in "$@"; do
    [ -f "$data/data/meshes/$mesh" ] || wanted+=("data/meshes/$mesh")
  done
fi
[ ${#wanted[@]} -eq 0 ] || tar -xzf "$tarball" -C "$data" "${wanted[@]}"
echo "$data/data/meshes"
