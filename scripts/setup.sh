#!/usr/bin/env bash
# Install (idempotently, non-interactively) the Debian 12 packages ompl_glider needs.
# Usage: scripts/setup.sh   (as root, or with sudo available)
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config
  libompl-dev ompl-demos
  libeigen3-dev
  libboost-dev libboost-serialization-dev libboost-filesystem-dev libboost-system-dev
  libboost-program-options-dev
  libnetcdf-dev netcdf-bin libudunits2-dev libhdf5-dev liblz4-dev
  libgtest-dev libgmock-dev
  libbenchmark-dev
  libyaml-cpp-dev
  libproj-dev
  libnlopt-cxx-dev
  libcairo2-dev
  libcli11-dev nlohmann-json3-dev
  libgdal-dev
  libopenmpi-dev openmpi-bin
  python3 python3-matplotlib
  gmt gmt-gshhg-low ferret-datasets
  libncarg-data
  pybind11-dev python3-dev python3-numpy python3-pytest
  clang-14 libfuzzer-14-dev clang-format-14
  libjs-leaflet chromium python3-websocket python3-netcdf4
  python3-zarr python3-numcodecs python3-xarray python3-gdal gdal-bin
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
