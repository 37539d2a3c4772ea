#!/usr/bin/env bash
# Installs, from Debian 12's archive only, everything the build, the demo and
# the tests need. Idempotent: does nothing when every package is present.
# Never installs python3-paraview (it removes python3-vtk9 and libvtk9-dev).
set -euo pipefail

packages=(
  build-essential cmake git pkg-config
  libvtk9-dev python3-vtk9 python3-numpy python3-matplotlib
  libegl-dev libx11-dev
  libcerf-dev libboost-dev libglm-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup-debian: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup-debian: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}"
