#!/usr/bin/env bash
# Installs every Debian 12 package HexLayer needs to build, test and run.
# Usage: sudo scripts/install-deps.sh   (idempotent; does nothing slow when all is present)
set -euo pipefail
packages=(
  build-essential cmake pkg-config ninja-build
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev
  libgmsh-dev libtet1.5-dev
  libeigen3-dev libcli11-dev nlohmann-json3-dev libfmt-dev libtbb-dev
  libgtest-dev googletest clang-format
  calculix-ccx
  python3-meshio python3-numpy python3-gmsh python3-matplotlib python3-jsonschema
  pybind11-dev python3-dev
  freecad xvfb xauth
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
