#!/usr/bin/env bash
# The ParaView plugin benchmark (not a ctest case): a >= 2M-tetrahedron mesh at 1024^2 in
# pvbatch, Accurate Volume beside ParaView's Volume, 1 rank x 2 threads, 1 x 1 and 2 ranks x
# 1 thread; and the native zoo through the plugin vs the standalone module. Builds first
# (Utilities/build.sh); arguments go to ParaView/Benchmarks/run_benchmarks.py
# (e.g. --size 512 --frames 3 --parts A). Writes <build>/paraview-benchmark.md.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HOV_BUILD_DIR:-$root/build}"
python_root="${HOV_PARAVIEW_PYTHON_ROOT:-/opt/highordervolume/python3-paraview}"
"$root/Utilities/build.sh"
mkdir -p "$build/Testing/Temporary/paraview-benchmark"
PYTHONPATH="$build/lib/python3/dist-packages" xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  /usr/bin/python3 "$root/ParaView/Benchmarks/run_benchmarks.py" \
    --plugin "$build/paraview/lib/paraview-5.11/plugins/HighOrderVolume/HighOrderVolume.so" \
    --pvpython "$python_root/usr/lib/python3/dist-packages" \
    --data "$root/Testing/Data" \
    --temp "$build/Testing/Temporary/paraview-benchmark" \
    --markdown "$build/paraview-benchmark.md" "$@"
