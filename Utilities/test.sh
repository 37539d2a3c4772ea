#!/usr/bin/env bash
# README command 2 (and CI): set up, build, run the whole test suite under Xvfb.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HOV_BUILD_DIR:-$root/build}"
"$root/Utilities/build.sh"
cd "$build"
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --output-on-failure -j2 "$@"
