#!/usr/bin/env bash
# One problem, every way in: the built-in mission and the same problem as a mission file; a NetCDF forecast with
# --currents and the same forecast as a mission file. Each pair must report bit-identical travel time, CFC, CMC,
# status and path. Then the output directory: a run without a path removes the earlier route files, and a run
# that fails with exit 2 leaves the directory exactly as it was.
# Usage: check_three_modes.sh GLIDER_PLAN SOURCE_DIR
set -euo pipefail
exe="$1"
src="$2"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT

same() {  # same SUMMARY_A SUMMARY_B: the figures that must not depend on the way in
  python3 - "$1" "$2" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
for key in ["solved", "status", "travel_time", "travel_time_raw", "path_length", "cost_function_calls",
            "current_model_calls", "expanded_vertices", "waypoints", "straight_line", "speed", "planner"]:
    assert a[key] == b[key], f"{key}: {a[key]!r} != {b[key]!r}"
assert a["solved"] is True
PY
  cmp "$(dirname "$1")/path.csv" "$(dirname "$2")/path.csv"
}

# 1. The built-in Gulf Stream mission and the same problem written as a mission file.
cat > "$dir/gulf.yaml" <<'YAML'
name: gulf_stream
current: {type: meandering_jet}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: -3}
goal: {x: 8, y: 3}
vehicle: {speed: 0.5}
planner: {name: ZA*TVE, horizon: 60, goal_tolerance: 0.001}
outputs: {files: [summary, path]}
YAML
"$exe" --out "$dir/builtin" > /dev/null
"$exe" --mission "$dir/gulf.yaml" --out "$dir/gulf" > /dev/null 2>&1
same "$dir/builtin/summary.json" "$dir/gulf/summary.json"

# 2. A NetCDF forecast from the command line and the same forecast as a mission file.
nc="$src/examples/labrador_forecast.nc"
"$exe" --currents "$nc" --start=-52.7,47.9 --goal=-51.5,48.45 --speed 0.3 --out "$dir/currents" > /dev/null 2>&1
cat > "$dir/forecast.yaml" <<YAML
name: labrador_forecast
current: {type: netcdf, file: "$nc"}
start: {lon: -52.7, lat: 47.9}
goal: {lon: -51.5, lat: 48.45}
vehicle: {speed: 0.3}
outputs: {files: [summary, path, csv, geojson, goto, map]}
YAML
"$exe" --mission "$dir/forecast.yaml" --out "$dir/forecast" > /dev/null 2>&1
same "$dir/currents/summary.json" "$dir/forecast/summary.json"
cmp "$dir/currents/goto_l10.ma" "$dir/forecast/goto_l10.ma"

# 3. No path (the horizon is far too short): exit 1, the earlier route files are gone, summary.json says why.
sed 's/horizon: 60/horizon: 2/' "$dir/gulf.yaml" > "$dir/short.yaml"
set +e
"$exe" --mission "$dir/short.yaml" --out "$dir/gulf" > /dev/null 2>&1
rc=$?
set -e
[ "$rc" -eq 1 ] || { echo "no path: expected exit 1, got $rc"; exit 1; }
[ ! -e "$dir/gulf/path.csv" ] || { echo "stale path.csv left after a run without a path"; exit 1; }
python3 -c "
import json, sys
s = json.load(open('$dir/gulf/summary.json'))
assert s['solved'] is False and 'no path exists: the reachable front never reaches the goal' in s['reason'], s['reason']
assert s['files'] == ['summary.json'], s['files']"

# 4. Exit 2 (a bad planner parameter, found before planning) changes nothing in the directory.
before="$(cd "$dir/currents" && sha256sum * | sort)"
sed 's/vehicle: {speed: 0.3}/vehicle: {speed: 0.3}\nplanner: {parameters: {no_such_parameter: 1}}/' \
  "$dir/forecast.yaml" > "$dir/bad.yaml"
set +e
"$exe" --mission "$dir/bad.yaml" --out "$dir/currents" > /dev/null 2> "$dir/err.txt"
rc=$?
set -e
[ "$rc" -eq 2 ] || { echo "bad parameter: expected exit 2, got $rc"; exit 1; }
grep -q "bad.yaml:6: field 'planner.parameters.no_such_parameter'" "$dir/err.txt" || { cat "$dir/err.txt"; exit 1; }
after="$(cd "$dir/currents" && sha256sum * | sort)"
[ "$before" = "$after" ] || { echo "exit 2 changed the output directory"; exit 1; }
[ -z "$(ls -A "$dir" | grep '\.tmp-')" ] || { echo "temporary directory left behind"; exit 1; }
echo "OK: every way in gives the same answer; outputs change all or nothing"
