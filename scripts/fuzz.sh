#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang++-14 (-fsanitize=fuzzer,address,undefined)
# in build-fuzz/ and runs each for SECONDS (default 10) on its seed corpus fuzz/corpus/NAME/ and
# the crashers of earlier runs, fuzz/regressions/NAME/.
# New inputs go to build-fuzz/corpus/NAME/ (the committed seeds stay small); a crash, hang,
# sanitizer report or leak stops the run with the reproducer in build-fuzz/crashes/NAME/ and a
# non-zero exit status.
#   scripts/fuzz.sh [SECONDS-PER-TARGET] [TARGET...]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

seconds="${1:-10}"
shift || true
build=build-fuzz
# Line tables only: a report names file and line, without the full debug info's compile time.
flags="-fsanitize=fuzzer-no-link,address,undefined,float-cast-overflow -fno-sanitize-recover=all -fno-omit-frame-pointer -gline-tables-only"

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DSCANTRACE_BUILD_FUZZ=ON -DSCANTRACE_BUILD_TESTS=OFF -DSCANTRACE_BUILD_BENCH=OFF \
  -DSCANTRACE_BUILD_PYTHON=OFF >/dev/null
cmake --build "$build" --target scantrace_fuzz -j"$(nproc)"

targets=("$@")
if [ "${#targets[@]}" -eq 0 ]; then
  targets=($(sed -n 's/^scantrace_fuzz_target(\([a-z_0-9]*\).*/\1/p' fuzz/CMakeLists.txt))
fi
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
for t in "${targets[@]}"; do
  mkdir -p "$build/corpus/$t" "$build/crashes/$t"
  # Seeds, then every crasher found so far (fuzz/regressions/NAME/, also Catch2 tests): libFuzzer
  # runs all inputs of the directories before mutating, and writes new ones to the first only.
  seeds=""
  for d in "fuzz/corpus/$t" "fuzz/regressions/$t"; do [ -d "$d" ] && seeds="$seeds $d"; done
  dict=""
  [ -f "fuzz/$t.dict" ] && dict="-dict=fuzz/$t.dict"
  # Inputs up to fuzz/NAME.max_len bytes (default 64 KiB): the JSON readers get megabytes, since
  # what broke them (nesting a few hundred thousand levels deep) is far beyond the default.
  max_len=65536
  [ -f "fuzz/$t.max_len" ] && max_len="$(cat "fuzz/$t.max_len")"
  echo "== fuzz_$t: ${seconds} s"
  # -timeout: an input taking longer than 10 s is reported as a hang; -rss_limit_mb: one that
  # needs more than 2 GB as an out-of-memory failure. The last lines are the run's summary.
  "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len="$max_len" -print_final_stats=1 $dict -artifact_prefix="$build/crashes/$t/" \
    "$build/corpus/$t" $seeds 2>"$build/fuzz_$t.log" || {
    tail -n 60 "$build/fuzz_$t.log"
    echo "fuzz_$t FAILED: reproducer in $build/crashes/$t/" >&2
    exit 1
  }
  grep -E '^#[0-9]+ +DONE|^stat::number_of_executed_units|^stat::peak_rss_mb' "$build/fuzz_$t.log" || true
done
