#!/usr/bin/env bash
# Installs, from Debian's packages, whatever the build needs and is missing.
set -euo pipefail
packages=(cmake make g++ libcgal-dev libeigen3-dev libboost-dev libgmp-dev libmpfr-dev
          libgtest-dev libbenchmark-dev libtbb-dev libfast-float-dev libcli11-dev
          pybind11-dev python3-dev python3-numpy python3-pytest python3-setuptools python3-venv  # Python module
          clang libclang-rt-14-dev   # libFuzzer harnesses (scripts/fuzz.sh)
          libopenmpi-dev openmpi-bin # distributed drivers (mpirun)
          doxygen                    # the manual (CTest doc_builds_without_warnings)
          libopenvdb-dev libboost-iostreams-dev)  # OpenVDB: only a rival measured in a benchmark
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "dependencies: all installed"
  exit 0
fi
echo "dependencies: installing ${missing[*]}"
as_root=()
[ "$(id -u)" -eq 0 ] || as_root=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
