#!/usr/bin/env bash
# The sanitizer run (issue 21): build the module, its Python package and every
# test with AddressSanitizer + UndefinedBehaviorSanitizer (float-cast-overflow
# included, -fno-sanitize-recover: the first report aborts the test; CMake
# option HOV_SANITIZE) in <repo>/build-asan (override with
# HOV_SANITIZE_BUILD_DIR), then run ctest under Xvfb. The C++ and kernel test
# executables carry the sanitizer runtime; the Python tests run Debian's
# python3 with it preloaded (Testing/Python/CMakeLists.txt).
#
#   ./Utilities/sanitize.sh                   # the whole suite (but the remote-module build)
#   ./Utilities/sanitize.sh -L 'kernels|cxx'  # a subset (arguments go to ctest)
#
# Leaks are checked in the C++ executables (Utilities/sanitizer/lsan.supp
# lists the third-party allocations kept until exit) and not in python3.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HOV_SANITIZE_BUILD_DIR:-$root/build-asan}"
"$root/Utilities/setup-debian.sh"
# Not built here: the benchmarks, and the ParaView plugin (built against
# ParaView's own VTK; its tests run pvbatch, nothing of this build).
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHOV_SANITIZE=ON \
  -DPython3_EXECUTABLE=/usr/bin/python3 -DBUILD_TESTING=ON -DHOV_BUILD_BENCHMARKS=OFF \
  -DHOV_PARAVIEW_PLUGIN=OFF
cmake --build "$build" -j"$(nproc)"

supp="$root/Utilities/sanitizer"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:check_initialization_order=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$supp/lsan.supp:print_suppressions=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
cd "$build"
"$root/Utilities/check-registered.sh" kernels cxx
start=$(date +%s)
status=0
# The remote-module test builds a second, unsanitized copy of the module: left out.
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  ctest --output-on-failure --no-tests=error -j2 -LE remote "$@" || status=$?
echo "sanitize.sh: ctest finished in $(( $(date +%s) - start )) s (status $status)"
exit $status
