#!/usr/bin/env bash
# Proof that a change leaves every float image unchanged, bit for bit: builds
# the pre-change commit (default: this branch's base, `git merge-base HEAD
# main`) and the current working tree in separate build directories, renders
# every case of Utilities/hov_identical_images.py (every bundled dataset, every
# render mode, both opacity semantics, with and without the features) with
# both, and compares the float32 images (and the RAY_CAST error images and the
# per-case counts) byte for byte.
#
#   Utilities/check_identical_images.sh [<commit>] [--only REGEX]
#
# HOV_IDENTICAL_DIR (default <repo>/build-identical) holds base-src/,
# base-build/, head-build/ and images/{base,head}/. HOV_BASE_BUILD /
# HOV_HEAD_BUILD name existing build directories to use instead (nothing is
# built then). Rendering runs under xvfb-run when it is available (else with
# the current DISPLAY or, without one, Mesa EGL).
# Exit code 0: every image identical (the one documented exception, RAY_CAST's
# default TerminationTransmittance, is reported but allowed); 1 otherwise.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
base=""
only=""
while [ $# -gt 0 ]; do
  case "$1" in
    --only) only="$2"; shift 2 ;;
    *) base="$1"; shift ;;
  esac
done
cd "$root"
base="${base:-$(git merge-base HEAD main)}"
work="${HOV_IDENTICAL_DIR:-$root/build-identical}"
mkdir -p "$work"
flags=(-DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 -DBUILD_TESTING=OFF
  -DHOV_PARAVIEW_PLUGIN=OFF -DHOV_BUILD_BENCHMARKS=OFF)

build() { # <source> <build dir>
  nice -n 5 cmake -S "$1" -B "$2" "${flags[@]}" > "$2.log" 2>&1
  nice -n 5 cmake --build "$2" -j"$(nproc)" >> "$2.log" 2>&1 || {
    echo "build of $1 failed: see $2.log" >&2; exit 1; }
}

base_build="${HOV_BASE_BUILD:-}"
if [ -z "$base_build" ]; then
  echo "== building $base (base) in $work/base-build"
  rm -rf "$work/base-src"
  mkdir -p "$work/base-src"
  git archive "$base" | tar -x -C "$work/base-src"
  base_build="$work/base-build"
  build "$work/base-src" "$base_build"
fi
head_build="${HOV_HEAD_BUILD:-}"
if [ -z "$head_build" ]; then
  echo "== building the working tree in $work/head-build"
  head_build="$work/head-build"
  build "$root" "$head_build"
fi

run=()
if command -v xvfb-run > /dev/null; then
  run=(xvfb-run -a -s "-screen 0 1280x1024x24 -noreset")
fi
for side in base head; do
  dir="$work/images/$side"
  rm -rf "$dir"
  mkdir -p "$dir"
  bdir="$base_build"
  [ "$side" = head ] && bdir="$head_build"
  echo "== rendering with the $side build ($bdir)"
  PYTHONPATH="$bdir/lib/python3/dist-packages" "${run[@]}" /usr/bin/python3 \
    "$root/Utilities/hov_identical_images.py" --out "$dir" --only "$only" 2> "$dir.log" ||
    { echo "rendering failed: see $dir.log" >&2; exit 1; }
done
echo "== comparing $(ls "$work/images/base" | wc -l) files (base $base vs the working tree)"
/usr/bin/python3 "$root/Utilities/hov_identical_images.py" --compare \
  "$work/images/base" "$work/images/head"
