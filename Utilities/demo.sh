#!/usr/bin/env bash
# README command 1: set up, build, then render the bundled datasets (the bracket,
# the quadratic-tet T-junction and the mixed-cell zoo) with
# vtkHighOrderVolumeMapper and VTK's unstructured mappers side by side.
# Output: <build>/demo/ (PNGs, montage, float image, table.md).
# Renders under xvfb-run; HOV_NO_X=1: without any X server (DISPLAY unset, Mesa EGL).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HOV_BUILD_DIR:-$root/build}"
# The demo needs the module and its Python package only.
"$root/Utilities/build.sh" vtkRenderingHighOrderVolumePython
export PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
if [ "${HOV_NO_X:-0}" = 1 ]; then
  exec env -u DISPLAY /usr/bin/python3 "$root/Utilities/hov_demo.py" --out "$build/demo" "$@"
fi
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  /usr/bin/python3 "$root/Utilities/hov_demo.py" --out "$build/demo" "$@"
