#!/usr/bin/env bash
# Configure and build the module, its Python package and its tests in
# <repo>/build (override with HOV_BUILD_DIR). Used by demo.sh and test.sh;
# arguments, if any, are the targets to build.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HOV_BUILD_DIR:-$root/build}"
"$root/Utilities/setup-debian.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DPython3_EXECUTABLE=/usr/bin/python3 -DBUILD_TESTING=ON
# Optional arguments: targets to build (default: everything).
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$build" -j"$(nproc)" "${targets[@]}"
