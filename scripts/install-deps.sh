#!/usr/bin/env bash
# Installs every build and test dependency of umbra from Debian's packages.
# Idempotent: apt-get skips what is already installed. Needs root (or sudo).
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libopenmesh-dev libglm-dev libopenimageio-dev openimageio-tools libopenexr-dev libpng-dev
  nlohmann-json3-dev libsimdjson-dev libcli11-dev libtinygltf-dev libfmt-dev libtbb-dev libmimalloc-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  assimp-testmodels libassimp-dev libcgal-demo
  clang-14 libclang-rt-14-dev clang-format-14
  libembree-dev python3-matplotlib
  libproj-dev python3-gdal python3-jsonschema
  python3-meshio assimp-utils
  slurmctld slurmd slurm-client munge iproute2 python3-distributed help2man
  python3-dev python3-numpy pybind11-dev python3-pytest
)
# node and npm run the Khronos glTF validator (tests/cli/gltf_validate.sh);
# Debian's packages unless some node with npm is installed already.
command -v npm > /dev/null 2>&1 || packages+=(nodejs npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
else
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO=sudo
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# The validator itself, the exact version package-lock.json pins, from the
# npm registry into tools/gltf-validator/node_modules (never at build time);
# skipped when that version is there already.
cd "$(dirname "$0")/../tools/gltf-validator"
pinned=$(node -p "require('./package.json').dependencies['gltf-validator']")
present=$(node -p "require('./node_modules/gltf-validator/package.json').version" 2>/dev/null || true)
if [ "$present" = "$pinned" ]; then
  echo "install-deps: glTF validator $pinned present"
else
  npm ci --no-audit --no-fund --loglevel=error
fi
