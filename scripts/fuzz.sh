#!/bin/sh
# Fuzzes the reader and the pipeline with libFuzzer (tests/fuzz/fuzz_reader.cpp): builds the target with
# clang, AddressSanitizer and UndefinedBehaviorSanitizer in build-fuzz/ (-DHEXLAYER_FUZZ=ON), then mutates
# the seeds of tests/fuzz/corpus (a STEP and a BREP plate, a truncated STEP) for SECONDS (default 300).
# The growing corpus stays in build-fuzz/corpus; a crash leaves its input as build-fuzz/crash-*.
# Each input is cut off after 120 s (-timeout), so a hang is reported like a crash.
# The reader runs in a child process, and libFuzzer's handler writes a crash-* file there too when
# OpenCASCADE's reader crashes: afterwards every crash-* input is run through the CLI (built here with
# the same sanitizers); those the CLI ends with exit 3 ("the ... reader crashed") are moved to
# build-fuzz/contained/, the others stay and fail the script.
#   scripts/fuzz.sh [SECONDS]
set -eu
cd "$(dirname "$0")/.."
seconds=${1:-300}
build=build-fuzz
CXX=clang++ CC=clang cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHEXLAYER_FUZZ=ON -DBUILD_TESTING=OFF >/dev/null
cmake --build "$build" -j2 --target hexlayer_fuzz hexlayer
mkdir -p "$build/corpus"
cp -n tests/fuzz/corpus/* "$build/corpus/"
# alloc_dealloc_mismatch=0: OpenCASCADE 7.6's own new[]/delete mismatch (see scripts/sanitize.sh).
export ASAN_OPTIONS=detect_leaks=0:alloc_dealloc_mismatch=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd "$build"
./hexlayer_fuzz -max_total_time="$seconds" -timeout=120 -rss_limit_mb=4096 -max_len=32768 -print_final_stats=1 corpus

mkdir -p contained
left=0
for crash in crash-*; do
  [ -e "$crash" ] || continue
  ext=step
  [ $(($(head -c1 "$crash" | od -An -tu1) % 2)) = 1 ] && ext=brep
  tail -c +2 "$crash" >"input.$ext"
  set +e
  ./hexlayer mesh "input.$ext" -o triage.inp --quiet --force 2>triage.err
  code=$?
  set -e
  if [ $code = 3 ] && grep -q "reader crashed" triage.err; then mv "$crash" contained/; else left=$((left + 1)); echo "fuzz: $crash: exit $code"; cat triage.err; fi
done
echo "fuzz: $(find contained -type f | wc -l) reader crashes contained by the child process (exit 3), $left other crash(es)"
[ $left = 0 ]
