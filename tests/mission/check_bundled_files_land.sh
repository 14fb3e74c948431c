#!/usr/bin/env bash
# glider_plan on every real forecast file the project bundles (examples/*.nc) or installs (NCL's POP sample,
# /usr/share/ncarg/data/cdf/pop.nc, Debian's libncarg-data), two or three coastal trips each, every route sample
# checked against the file's own land read independently with ncdump (check_bundled_files_land.py). A missing file,
# ncdump or numpy is a failure, not a skip.
# Usage: check_bundled_files_land.sh GLIDER_PLAN REPO_DIR
set -euo pipefail
glider_plan=$1 repo=$2
if ! command -v ncdump >/dev/null; then
  echo "FAIL: ncdump is missing (Debian package netcdf-bin; scripts/setup.sh installs it)" >&2
  exit 1
fi
py=""
for p in python3 /usr/bin/python3; do
  if command -v "$p" >/dev/null && "$p" -c "import numpy" 2>/dev/null; then py=$p; break; fi
done
if [ -z "$py" ]; then
  echo "FAIL: no python3 with numpy (Debian package python3-numpy; scripts/setup.sh installs it)" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$py" "$(dirname "$0")/check_bundled_files_land.py" "$glider_plan" "$repo" "$work"
