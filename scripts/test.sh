#!/usr/bin/env bash
# The test command (what CI runs through .ci/run).  Installs what is missing,
# then:
#  1. builds the library's tests, examples, tools, benchmarks, Python module
#     and MPI drivers (Release) and runs the whole suite with CTest;
#  2. scripts/sanitize.sh: the suite again under AddressSanitizer +
#     UndefinedBehaviorSanitizer (build-sanitize/);
#  3. scripts/fuzz.sh: every libFuzzer harness of test/fuzz for
#     BISO_FUZZ_SECONDS seconds (default 20), one per core at a time (build-fuzz/).
# Set BISO_QUICK=1 to run step 1 only.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
jobs="$(nproc)"
start=$(date +%s)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBISO_BUILD_TESTS=ON -DBISO_BUILD_EXAMPLES=ON \
      -DBISO_BUILD_BENCHMARKS=ON -DBISO_BUILD_PYTHON=ON
cmake --build build -j "$jobs"
(cd build && ctest -j "$jobs" --output-on-failure --timeout 1500)
echo "test.sh: Release build and suite took $(( $(date +%s) - start )) s"
if [ "${BISO_QUICK:-0}" = 1 ]; then
  exit 0
fi
start=$(date +%s)
bash scripts/sanitize.sh
echo "test.sh: sanitized build and suite took $(( $(date +%s) - start )) s"
start=$(date +%s)
bash scripts/fuzz.sh "${BISO_FUZZ_SECONDS:-20}"
echo "test.sh: fuzzing took $(( $(date +%s) - start )) s"
