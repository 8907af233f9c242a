#!/usr/bin/env bash
# Installs what is missing, builds the library's tests, examples, tools,
# benchmarks and Python module, and runs the whole test suite with CTest.
# (scripts/sanitize.sh and scripts/fuzz.sh are the sanitized suite and the
# libFuzzer runs; they are not part of this command yet.)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
jobs="$(nproc)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBISO_BUILD_TESTS=ON -DBISO_BUILD_EXAMPLES=ON \
      -DBISO_BUILD_BENCHMARKS=ON -DBISO_BUILD_PYTHON=ON
cmake --build build -j "$jobs"
cd build
ctest -j "$jobs" --output-on-failure --timeout 1500
