#!/usr/bin/env bash
# Flags override a mission file's fields: glider_plan --mission m.yaml --FLAG ... plans exactly the mission edited
# to what the flags say (bit-identical travel time, CFC, CMC, path), so comparing planners or speeds needs no copies
# of the mission. The forecast and its reading options stay the mission's (--currents and its flags are refused).
# Usage: check_mission_overrides.sh GLIDER_PLAN
set -euo pipefail
exe="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT

same() {  # same SUMMARY_A SUMMARY_B: every figure of the plan, and the path
  python3 - "$1" "$2" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
for key in ["solved", "status", "travel_time", "travel_time_raw", "path_length", "cost_function_calls",
            "current_model_calls", "waypoints", "speed", "planner", "departure", "start", "goal"]:
    assert key in a, key
    assert a[key] == b[key], f"{key}: {a[key]!r} != {b[key]!r}"
assert a["solved"] is True
PY
  cmp "$(dirname "$1")/path.csv" "$(dirname "$2")/path.csv"
}
mission() {  # mission SPEED PLANNER_LINE START GOAL DEPARTURE
  cat <<YAML
name: jet
current: {type: meandering_jet}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: $3, y: $4}
goal: {x: 8, y: 3}
departure: {time: $5}
vehicle: {speed: $1}
planner: $2
outputs: {directory: $dir/unused, files: [summary, path]}
YAML
}

# 1. --speed: the travel time of the mission edited to that speed.
mission 0.5 "{name: ZA*TVE, horizon: 60}" 1 -3 0 > "$dir/m.yaml"
mission 0.6 "{name: ZA*TVE, horizon: 60}" 1 -3 0 > "$dir/m_speed.yaml"
"$exe" --mission "$dir/m.yaml" --speed 0.6 --out "$dir/flag_speed" > /dev/null 2>&1
"$exe" --mission "$dir/m_speed.yaml" --out "$dir/file_speed" > /dev/null 2>&1
same "$dir/flag_speed/summary.json" "$dir/file_speed/summary.json"
python3 - "$dir/flag_speed/summary.json" "$dir/file_speed/summary.json" <<'PY'
import json, sys
a = json.load(open(sys.argv[1]))
assert a["speed"] == 0.6, a["speed"]
PY
# ... and not the file's own speed (the flag was applied)
"$exe" --mission "$dir/m.yaml" --out "$dir/file_plain" > /dev/null 2>&1
python3 -c "import json,sys; a,b=(json.load(open(p)) for p in sys.argv[1:]); assert a['travel_time'] != b['travel_time']" \
  "$dir/flag_speed/summary.json" "$dir/file_plain/summary.json"

# 2. The planner, its lattice, smoothing, refinement, start and departure at once.
mission 0.5 "{name: A*TVE, horizon: 60, grid_size: 0.5, sectors: 2, refinement: false}" 2 -2 3 > "$dir/m_many.yaml"
"$exe" --mission "$dir/m.yaml" --planner 'A*TVE' --grid-size 0.5 --sectors 2 --no-refine --start 2,-2 \
  --departure 3 --out "$dir/flag_many" > /dev/null 2>&1
"$exe" --mission "$dir/m_many.yaml" --out "$dir/file_many" > /dev/null 2>&1
same "$dir/flag_many/summary.json" "$dir/file_many/summary.json"

# 3. --planner naming another planner drops the file's planner parameters (they are the other planner's):
# ZA*TVE's certify_tolerance would be an unknown parameter of Wavefront.
mission 0.5 "{name: ZA*TVE, horizon: 60, parameters: {certify_tolerance: 0}}" 1 -3 0 > "$dir/m_params.yaml"
mission 0.5 "{name: Wavefront, horizon: 60}" 1 -3 0 > "$dir/m_wavefront.yaml"
"$exe" --mission "$dir/m_params.yaml" --planner Wavefront --out "$dir/flag_wavefront" > /dev/null 2>&1
"$exe" --mission "$dir/m_wavefront.yaml" --out "$dir/file_wavefront" > /dev/null 2>&1
same "$dir/flag_wavefront/summary.json" "$dir/file_wavefront/summary.json"

# 4. The forecast is the mission's: --currents and its reading flags are refused (exit 2, naming the flag).
for flags in "--currents x.nc" "--u-var u" "--depth 10"; do
  set +e
  # shellcheck disable=SC2086
  "$exe" --mission "$dir/m.yaml" $flags --out "$dir/refused" > /dev/null 2> "$dir/err.txt"
  rc=$?
  set -e
  [ "$rc" -eq 2 ] || { echo "expected exit 2 for --mission with $flags, got $rc"; exit 1; }
  grep -q -- "${flags%% *} cannot be combined with --mission" "$dir/err.txt" || { cat "$dir/err.txt"; exit 1; }
  [ ! -e "$dir/refused" ] || { echo "files written despite the error"; exit 1; }
done
echo "flags override the mission file: ok"
