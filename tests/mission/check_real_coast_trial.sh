#!/usr/bin/env bash
# A real-data coastal trial: glider_plan on 6 coastal and island routes with GSHHG intermediate coastlines
# (scripts/make_coastline.sh, GMT), a 2 km keep-off and a 50 m depth limit from ETOPO5 (Debian's ferret-datasets),
# each route checked independently of the program by real_coast_trial.py (distance to every coastline edge, ETOPO5
# depth, map.png, summary.json), plus a channel closed by a 16 km keep-off that must be refused naming it.
# Usage: check_real_coast_trial.sh GLIDER_PLAN REPO_DIR   (exit 77, ctest's skip, when the data packages are absent)
set -euo pipefail
glider_plan=$1 repo=$2
missing=()
command -v gmt >/dev/null || missing+=("gmt")
[ -e /usr/share/gmt-gshhg/binned_GSHHS_i.nc ] || missing+=("gmt-gshhg-low")
[ -e /usr/share/ferret-vis/data/etopo5.cdf ] || missing+=("ferret-datasets")
command -v ncgen >/dev/null || missing+=("netcdf-bin")
py=""
for p in python3 /usr/bin/python3; do
  if command -v "$p" >/dev/null && "$p" -c "import numpy" 2>/dev/null; then py=$p; break; fi
done
[ -n "$py" ] || missing+=("python3-numpy")
if [ ${#missing[@]} -gt 0 ]; then
  echo "SKIP: the real-data trial needs ${missing[*]} (scripts/setup.sh installs them)"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$py" "$(dirname "$0")/real_coast_trial.py" "$glider_plan" "$repo" "$work"
