#!/usr/bin/env bash
# Builds the libFuzzer harnesses of test/fuzz with clang (ASan + UBSan) in
# build-fuzz/ and runs each for SECONDS seconds (default 30), as many at a
# time as there are cores (BISO_FUZZ_JOBS).  Fails if any
# harness finds a crash, a sanitizer report, an input slower than 25 s, an
# allocation over 64 MB (a size taken from a header count), or more than
# 2 GB of memory.  Findings are kept in build-fuzz/artifacts/.
#
#   scripts/fuzz.sh [SECONDS]
#   BISO_FUZZ_TARGETS="fuzz_pts fuzz_tris" scripts/fuzz.sh 60   # a subset
#
# The corpora grow in build-fuzz/corpus/<target>/ across runs; the seeds
# are regenerated each time by test/fuzz/make_seed_corpus.py.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
cxx="${BISO_FUZZ_CXX:-clang++-14}"
build=build-fuzz
all_targets="fuzz_pts fuzz_tris fuzz_medit fuzz_tetgen fuzz_scalar_fields_text fuzz_scalar_fields_raw
             fuzz_ply_with_fields fuzz_expression_letters fuzz_expression_f fuzz_closed_triangle_mesh"
targets="${BISO_FUZZ_TARGETS:-$all_targets}"

# Debug: CGAL's assertions on; the harnesses add -O1 themselves.
mkdir -p "$build"
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Debug -DBISO_BUILD_FUZZERS=ON \
      -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE \
      -DBISO_BUILD_TESTS=OFF -DBISO_BUILD_EXAMPLES=OFF -DBISO_BUILD_TOOLS=OFF -DBISO_BUILD_BENCHMARKS=OFF > "$build/configure.log" 2>&1 \
  || { cat "$build/configure.log"; exit 1; }
# shellcheck disable=SC2086
cmake --build "$build" --target $targets -j "$(nproc)"

rm -rf "$build/seeds"
/usr/bin/env python3 test/fuzz/make_seed_corpus.py "$build/seeds"
mkdir -p "$build/artifacts"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# The harnesses run $jobs at a time (one core each): libFuzzer is single-threaded.
jobs="${BISO_FUZZ_JOBS:-$(nproc)}"
run_one() {
  local target="$1" log="$build/artifacts/$1.log"
  mkdir -p "$build/corpus/$target"
  if "$build/test/fuzz/$target" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=64 -timeout=25 \
       -print_final_stats=1 -artifact_prefix="$build/artifacts/$target-" \
       "$build/corpus/$target" "$build/seeds/$target" > "$log" 2>&1; then
    echo "== $target, ${seconds} s: $(grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "$log" | tr '\n' ' ')"
  else
    echo "== $target: FINDING (log: $log):"
    grep -E "ERROR|SUMMARY|==[0-9]+==|Test unit written|check failed|timeout|out-of-memory|malloc" "$log" | head -20
    touch "$build/artifacts/$target.failed"
  fi
}
rm -f "$build"/artifacts/*.failed
start=$(date +%s)
running=0
for target in $targets; do
  run_one "$target" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then
    wait -n || true
    running=$((running - 1))
  fi
done
wait
failed=""
for target in $targets; do
  if [ -e "$build/artifacts/$target.failed" ]; then failed="$failed $target"; fi
done
echo "fuzzing took $(( $(date +%s) - start )) s"
if [ -n "$failed" ]; then
  echo "fuzz.sh: findings in:$failed" >&2
  exit 1
fi
echo "fuzz.sh: no finding"
