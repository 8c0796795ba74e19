#!/bin/sh
# Builds HexLayer with AddressSanitizer + UndefinedBehaviorSanitizer (-DHEXLAYER_SANITIZE=ON) in
# build-sanitize/, then runs the C++ unit tests and a few CLI runs (good parts, bad and hard inputs)
# under them. Fails on any sanitizer report or an unexpected exit code. Not part of scripts/test.sh
# (it takes several times as long); run it by hand after changing the core.
#   scripts/sanitize.sh [BUILD_DIR]
set -eu
cd "$(dirname "$0")/.."
build=${1:-build-sanitize}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHEXLAYER_SANITIZE=ON >/dev/null
cmake --build "$build" -j2 --target hexlayer hexlayer_tests
# Leaks are not checked: OpenCASCADE and Gmsh keep singletons to the end of the process.
# alloc_dealloc_mismatch=0: OpenCASCADE 7.6's IntCurvesFace_ShapeIntersector allocates with new[] in
# PerformNearest and frees with delete in Destroy (its own bug, inside libTKTopAlgo).
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:alloc_dealloc_mismatch=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
"$build/tests/hexlayer_tests" --gtest_brief=1

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
failed=0
# expect CODE INPUT [OPTIONS...]: the CLI ends with CODE and no sanitizer report.
expect() {
  code=$1 input=$2
  shift 2
  set +e
  "$build/hexlayer" mesh "$input" -o "$out/m.inp" --quiet "$@" 2>"$out/stderr"
  got=$?
  set -e
  if [ "$got" != "$code" ] || grep -q -e "Sanitizer" -e "runtime error:" "$out/stderr"; then
    echo "sanitize: FAILED $input $*: exit $got (expected $code)"; cat "$out/stderr"; failed=1
  else
    echo "sanitize: ok $input $* (exit $got)"
  fi
}
data=tests/data/robustness
expect 0 Resources/samples/plate_holes.step
expect 0 Resources/samples/lbracket.step --order 2 --sizing adaptive
expect 0 $data/two_plates.step
expect 0 $data/small_fillets.step
expect 4 Resources/samples/thick_block.step
expect 4 $data/t_junction.step
expect 3 $data/truncated.brep
expect 3 $data/truncated.step
expect 3 $data/garbage.step
expect 3 $data/open_shell.brep
expect 2 $data/plate.brep --size 1e-4
exit $failed
