#!/usr/bin/env bash
# README command 2 (and CI): set up, build, run the whole test suite.
#
# Under xvfb-run: every test, the rendering tests twice (as registered, on the
# Xvfb display, and their headless twins, label "headless", with DISPLAY unset:
# Mesa EGL), plus the VTK remote-module build (label "remote").
# HOV_NO_X=1: no X server at all (no xvfb-run, DISPLAY unset): the headless
# pass and every test that needs no display.
# Arguments go to ctest (e.g. -L headless, -R Regression, -LE remote).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HOV_BUILD_DIR:-$root/build}"
"$root/Utilities/build.sh"
cd "$build"
"$root/Utilities/check-registered.sh" kernels cxx regression robustness python headless layout
if [ "${HOV_NO_X:-0}" = 1 ]; then
  # The X pass of the rendering tests (label x11) needs a display: skip it.
  exec env -u DISPLAY ctest --output-on-failure --no-tests=error -j2 -LE x11 "$@"
fi
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --output-on-failure --no-tests=error -j2 \
  "$@"
