#!/usr/bin/env bash
# Installs everything, builds HexLayer and runs every test (C++ unit tests and end-to-end tests). Fails if no
# test ran or if any part of the suite has fewer tests registered than it has (a missing FreeCAD, Xvfb, pybind11
# or OpenMP fails the configure step: HEXLAYER_FULL_SUITE), whatever build/ held before (scripts/demo.sh
# configures it without tests).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON -DHEXLAYER_FULL_SUITE=ON >/dev/null
cmake --build build -j"$(nproc)"
# The suite, part by part: every GoogleTest TEST in tests/cpp (a TEST_P registers one test per parameter), every
# test_*.py script of each folder, the workbench install and the GUI run. A part with fewer tests registered than
# it has (a tool missing that HEXLAYER_FULL_SUITE did not catch, a glob gone wrong) fails the run before ctest
# reports 100 % of a smaller suite.
tests=$(cd build && ctest -N | sed -n 's/^ *Test *#[0-9]*: //p')
short=0
require() {  # name of the part, how many of its tests are registered, how many it has
  if [ "$2" -lt "$3" ]; then
    echo "scripts/test.sh: $1: $2 test(s) registered, the suite has $3" >&2
    short=1
  fi
}
named() { grep -cE "$1" <<<"$tests" || true; }  # registered tests whose names match
scripts() { find "tests/$1" -maxdepth 1 -name 'test_*.py' | wc -l; }  # test scripts in tests/$1
require "C++ unit tests" "$(grep -cvE '^$|^(integration|python|freecad)\.' <<<"$tests" || true)" \
  "$(cat tests/cpp/test_*.cpp | grep -cE '^TEST(_F|_P)?\(')"
require "integration" "$(named '^integration\.')" "$(scripts integration)"
require "Python binding" "$(named '^python\.')" "$(scripts python)"
require "FreeCAD headless" "$(named '^freecad\.test_')" "$(scripts freecad)"
require "FreeCAD workbench install" "$(named '^freecad\.install$')" 1
require "FreeCAD GUI" "$(named '^freecad\.gui_hexlayer$')" 1
[ "$short" -eq 0 ] || exit 1
cd build && ctest --output-on-failure --no-tests=error -j"$(nproc)"
