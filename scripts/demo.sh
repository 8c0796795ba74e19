#!/usr/bin/env bash
# Installs everything (also the FreeCAD workbench, into FreeCAD's user Mod folder), builds HexLayer and
# meshes a bundled sample part (mesh written, quality printed).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -DHEXLAYER_FULL_SUITE=OFF >/dev/null
cmake --build build -j"$(nproc)" --target hexlayer pyhexlayer
scripts/install-workbench.sh build
mkdir -p out
build/hexlayer mesh Resources/samples/plate_holes.step -o out/plate_holes.inp --layers 2 --report out/plate_holes.json
