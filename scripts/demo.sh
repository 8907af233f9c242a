#!/usr/bin/env bash
# The main job on built-in inputs: installs what is missing, builds the
# command-line tool, and runs it on meshes the project makes itself, writing
# them to demo_output/ and printing their volumes next to the exact ones.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build --target volume -j "$(nproc)" >> build.log 2>&1 || { cat build.log; exit 1; }
./build/examples/Boolean_isosurfacing_3/volume --demo demo_output
