#!/usr/bin/env bash
# The main job on built-in inputs: installs what is missing, builds the
# command-line tools, and runs Marching Cubes CSG (union, intersection,
# difference) on a sphere and a torus the project makes itself, printing each
# result's volume next to the exact one and writing the meshes to
# demo_output/.  Then the volume tool's own demo (accuracy far from the origin),
# and TBISO's: four spheres on a 128^3 grid, 'at least two of four', with
# crease polylines and corners.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build --target csg volume tbiso -j "$(nproc)" >> build.log 2>&1 || { cat build.log; exit 1; }
./build/tools/Boolean_isosurfacing_3/csg --demo demo_output
echo
./build/tools/Boolean_isosurfacing_3/volume --demo demo_output/volume
echo
./build/tools/Boolean_isosurfacing_3/tbiso --demo demo_output/tbiso
