#!/usr/bin/env bash
# The test suites where the sanitizers pay, again, built with AddressSanitizer
# + UndefinedBehaviorSanitizer (CMake option BISO_SANITIZE) in build-sanitize/:
# the readers and parsers of untrusted files and the core algorithms
# (BISO_SANITIZED_TESTS in test/Boolean_isosurfacing_3/CMakeLists.txt).  Not
# the tools, the benchmarks, the examples, the Python module nor the MPI
# drivers (OpenMPI's own allocations are not ours to check); the readers the
# tools use are also fuzzed (scripts/fuzz.sh).  It skips the tests that only
# re-check the build (headers, install) and the slow reference tests whose
# code paths the quick tests already cover.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="$(nproc)"
# -O1: the sanitizers need no more, and it compiles the CGAL-heavy
# translation units faster than -O3.
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DBISO_SANITIZE=ON -DBISO_BUILD_TESTS=ON \
      -DBISO_BUILD_EXAMPLES=OFF -DBISO_BUILD_TOOLS=OFF -DBISO_BUILD_BENCHMARKS=OFF -DBISO_BUILD_PYTHON=OFF -DBISO_WITH_MPI=OFF \
      -DBISO_BUILD_DOC=OFF
cmake --build build-sanitize -j "$jobs"
cd build-sanitize
# detect_leaks: CGAL and TBB keep a few process-lifetime singletons; leaks are
# still reported for everything else (suppressions in scripts/lsan.supp).
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$(pwd)/../scripts/lsan.supp"
# Skipped: the build checks, and the reference tests on real data whose code
# paths quicker tests already run (under ASan the contouring references take
# 3 to 8 minutes each).
skip='^(headers_compile_alone|headers_compile_together|install_package|downstream_find_package'
skip+='|Reconstruct\..*|Topology\..*|TbisoTool\.BunnyOnAGridHasOneCutLoop'
# The sharp-feature cases against an exact corefinement (1-5 min each under
# ASan; BoxMinusMovedBox and the table tests keep the feature code covered).
skip+='|CsgFeatures\.(CylinderUnitedWithABox|BoxIntersectedWithARotatedBox|IsotropicRemeshingKeepsTheCreases)'
skip+='|Meshes/SharedMesh\.AgreesWithExactVolumeAndPmpVolume/meshes_(armadillo|bunny_hoppe)_.*)$'
ctest -j "$jobs" --output-on-failure --timeout 1500 -E "$skip"
