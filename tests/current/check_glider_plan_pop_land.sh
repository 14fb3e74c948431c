#!/usr/bin/env bash
# glider_plan on a real model file: NCL's POP sample (Debian's libncarg-data, /usr/share/ncarg/data/cdf/pop.nc; B grid,
# urot/vrot in centimeter/s on the u-grid lat2d/lon2d, potential temperature t at 500 m masked on land; the velocities
# are fill values inside land and exact zeros at the coast). Coastal trips in several basins: every route sample
# (every 2 km or less along each leg of path.csv) must lie in a tracer cell the model's own mask calls water, read
# independently of ompl_glider (pop_route_check.py: ncdump, the tracer cells as quadrilaterals of the velocity
# points). The Gulf of Mexico to the Atlantic must go round Florida; the Pacific and the Caribbean are not joined at
# 500 m in the model (Central America is closed), so that trip has no path.
# Usage: check_glider_plan_pop_land.sh GLIDER_PLAN
set -euo pipefail
exe="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
here="$(cd "$(dirname "$0")" && pwd)"
pop=/usr/share/ncarg/data/cdf/pop.nc
if [ ! -f "$pop" ]; then
  echo "FAIL: $pop is missing: scripts/setup.sh installs it (Debian package libncarg-data)" >&2
  exit 1
fi
py=python3
if /usr/bin/python3 -c "import numpy" 2>/dev/null; then py=/usr/bin/python3; fi
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
cd "$dir"

plan() {  # plan NAME START GOAL: glider_plan's exit status, its output in NAME.log, files in NAME/
  set +e
  "$exe" --currents "$pop" --u-var urot --v-var vrot --start="$2" --goal="$3" --speed 0.5 --out "$1" > "$1.log" 2>&1
  local rc=$?
  set -e
  return $rc
}

route() {  # route NAME START GOAL [--south-of LAT]: a path, every sample in the model's water
  local name=$1 start=$2 goal=$3
  shift 3
  if ! plan "$name" "$start" "$goal"; then
    echo "FAIL: $name ($start -> $goal): expected a route" >&2
    cat "$name.log" >&2
    exit 1
  fi
  grep -E "^(Travel time|Closest to land):" "$name.log"
  "$py" "$here/pop_route_check.py" "$pop" "$dir/pop_cache.npz" "$name" "$@"
}

# Gulf of Mexico to the Atlantic: round the model's Florida (its tip at 26.3 N), through the Florida Straits
route gulf_atlantic -84,27 -78.5,27.5 --south-of 25.3
# past Jamaica, an island whose velocity points are all zeros (none of them a fill value)
route jamaica -79.5,18.6 -74.5,17.6
# Mozambique Channel to the east of Madagascar (Indian Ocean)
route madagascar 38,-22 52,-20
# Pacific to Caribbean across Costa Rica and Panama: no path (exit 1), the start's water does not reach the goal's
rc=0
plan panama -85,8 -81,12 || rc=$?
if [ "$rc" -ne 1 ] || [ -e panama/path.csv ]; then
  echo "FAIL: panama: expected no path (exit 1) across Central America, which the model closes at 500 m; exit $rc" >&2
  cat panama.log >&2
  exit 1
fi
"$py" - panama/summary.json <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
assert s["solved"] is False, s["solved"]
print("panama: no path:", s["reason"])
PY
echo "PASS"
