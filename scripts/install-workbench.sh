#!/usr/bin/env bash
# Installs the FreeCAD workbench Hex-Layer: Mod/HexLayer, the hexlayer executable it runs as a child process
# (into Mod/HexLayer/bin) and, for macros in a matching Python, the module pyhexlayer (built for /usr/bin/python3,
# FreeCAD 0.20's interpreter; the workbench itself does not import it), copied into FreeCAD's user Mod folder.
# Usage: scripts/install-workbench.sh            installs the Debian packages (FreeCAD too), builds, installs
#        scripts/install-workbench.sh BUILD_DIR  installs from a build folder that already holds the module
# The Mod folder is $FREECAD_MOD_DIR, else the one FreeCAD itself names (FreeCAD.getUserAppDataDir() + "Mod":
# ~/.local/share/FreeCAD/Mod for 0.20 on Debian, a versioned folder such as .../FreeCAD/v1-1/Mod for 1.1), else
# ${XDG_DATA_HOME:-~/.local/share}/FreeCAD/Mod if no freecadcmd is found.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-}
if [ -z "$build" ]; then
  build=build
  scripts/install-deps.sh
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j"$(nproc)" --target hexlayer pyhexlayer
fi
if [ ! -x "$build/hexlayer" ]; then
  echo "install-workbench: no hexlayer executable in $build (build first)" >&2
  exit 1
fi
modules=("$build"/python/pyhexlayer*.so)
if [ ! -f "${modules[0]}" ]; then
  echo "install-workbench: no pyhexlayer module in $build/python (is pybind11-dev installed? build first)" >&2
  exit 1
fi
mod_dir() {
  if [ -n "${FREECAD_MOD_DIR:-}" ]; then echo "$FREECAD_MOD_DIR"; return; fi
  local asked=""
  if command -v freecadcmd >/dev/null 2>&1; then
    asked=$(freecadcmd -c "import FreeCAD, os; print('MODDIR=' + os.path.join(FreeCAD.getUserAppDataDir(), 'Mod'))" 2>/dev/null \
              | sed -n 's/^MODDIR=//p' | tail -1)
  fi
  echo "${asked:-${XDG_DATA_HOME:-$HOME/.local/share}/FreeCAD/Mod}"
}
target="$(mod_dir)/HexLayer"
rm -rf "$target"
mkdir -p "$target"
cp -r Mod/HexLayer/. "$target/"
find "$target" -name __pycache__ -prune -exec rm -rf {} +
cp "${modules[0]}" "$target/"
mkdir -p "$target/bin"
cp "$build/hexlayer" "$target/bin/hexlayer"
echo "Hex-Layer workbench installed in $target: (re)start FreeCAD and choose the Hex-Layer workbench."
