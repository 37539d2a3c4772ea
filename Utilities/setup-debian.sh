#!/usr/bin/env bash
# Installs, from Debian 12's archive only, everything the build, the demo and
# the tests need. Idempotent: does nothing when every package is present.
#
# ParaView (the plugin in ParaView/): paraview and paraview-dev are installed
# with --no-install-recommends, because their recommendation python3-paraview
# Conflicts with python3-vtk9 and would remove python3-vtk9 and libvtk9-dev.
# python3-paraview is never installed: its files (ParaView's Python package,
# which pvbatch needs, and what ParaView's CMake package checks for) are
# extracted into $HOV_PARAVIEW_PYTHON_ROOT (default
# /opt/highordervolume/python3-paraview) with dpkg-deb -x. The script fails
# loudly if python3-vtk9 or libvtk9-dev is missing afterwards.
set -euo pipefail

packages=(
  build-essential cmake git pkg-config
  libvtk9-dev python3-vtk9 python3-numpy python3-matplotlib
  libegl-dev libx11-dev
  libcerf-dev libboost-dev libglm-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth
)
# Installed without recommends (see above); openmpi-bin for mpirun.
paraview_packages=(paraview paraview-dev openmpi-bin)
python_root="${HOV_PARAVIEW_PYTHON_ROOT:-/opt/highordervolume/python3-paraview}"

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive

installed() {
  dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"
}

missing_of() {
  local p
  for p in "$@"; do
    installed "$p" || echo "$p"
  done
}

mapfile -t missing < <(missing_of "${packages[@]}")
mapfile -t missing_pv < <(missing_of "${paraview_packages[@]}")

updated=0
if [ ${#missing[@]} -gt 0 ] || [ ${#missing_pv[@]} -gt 0 ]; then
  "${sudo_cmd[@]}" apt-get update -qq
  updated=1
fi
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup-debian: installing ${missing[*]}"
  "${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}"
fi
if [ ${#missing_pv[@]} -gt 0 ]; then
  echo "setup-debian: installing ${missing_pv[*]} (--no-install-recommends)"
  # Refuse anything that would remove a package (python3-paraview would
  # remove python3-vtk9 and libvtk9-dev).
  removals="$(apt-get -s install --no-install-recommends "${missing_pv[@]}" | grep '^Remv' || true)"
  if [ -n "$removals" ]; then
    echo "setup-debian: ERROR: installing ${missing_pv[*]} would remove packages:" >&2
    echo "$removals" >&2
    exit 1
  fi
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing_pv[@]}"
fi

# python3-paraview, extracted (never installed), matching paraview's version.
pv_version="$(dpkg-query -W -f='${Version}' paraview)"
stamp="$python_root/.hov-python3-paraview-version"
if [ ! -f "$stamp" ] || [ "$(cat "$stamp")" != "$pv_version" ]; then
  echo "setup-debian: extracting python3-paraview $pv_version into $python_root"
  [ "$updated" -eq 1 ] || "${sudo_cmd[@]}" apt-get update -qq
  download="$(mktemp -d)"
  chmod 755 "$download" # apt's sandbox user writes here
  (cd "$download" && apt-get download -qq "python3-paraview=$pv_version" 2>/dev/null \
    || apt-get download "python3-paraview=$pv_version")
  "${sudo_cmd[@]}" rm -rf "$python_root"
  "${sudo_cmd[@]}" mkdir -p "$python_root"
  "${sudo_cmd[@]}" dpkg-deb -x "$download"/python3-paraview_*.deb "$python_root"
  echo "$pv_version" | "${sudo_cmd[@]}" tee "$stamp" > /dev/null
  rm -rf "$download"
fi

# The VTK 9.1 build needs these; nothing above may have removed them.
for p in python3-vtk9 libvtk9-dev; do
  if ! installed "$p"; then
    echo "setup-debian: ERROR: $p is not installed (was python3-paraview installed? it" \
      "removes python3-vtk9 and libvtk9-dev). Remove python3-paraview and re-run." >&2
    exit 1
  fi
done
if installed python3-paraview; then
  echo "setup-debian: ERROR: python3-paraview is installed; it conflicts with python3-vtk9." >&2
  exit 1
fi
echo "setup-debian: all $(( ${#packages[@]} + ${#paraview_packages[@]} )) packages present," \
  "python3-paraview $pv_version extracted in $python_root"
