#!/usr/bin/env bash
# glider_plan on forecast files as pilots have them, written with ncgen as models write them:
#  1. a steady file (u/v without time dimension, in cm/s) plans from --currents and from a mission file with exit 0,
#     without --beyond hold, with the travel time of the uniform current's closed form; a date as --departure
#     (or a mission's epoch) dates the undated steady field;
#  2. a file whose time axis is in "month" (no date) is refused with a message naming --time-units and
#     --steady-record, then plans with --time-units "days since 2026-01-15" and with --steady-record 0 (and in a
#     mission file with current.time_units / current.steady_record);
#  3. --velocity-units replaces the file's units (a file that says degC for velocities in knots).
# Usage: check_glider_plan_forecast_files.sh GLIDER_PLAN
set -euo pipefail
exe="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"  # absolute: the script works in a scratch directory
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
cd "$dir"

values() {  # values N V: N copies of V, comma-separated
  python3 -c "import sys; print(', '.join([sys.argv[2]] * int(sys.argv[1])))" "$1" "$2"
}
LAT="47.0, 47.2, 47.4, 47.6, 47.8, 48.0"
LON="-53.0, -52.8, -52.6, -52.4, -52.2, -52.0"

# u = 20 cm/s eastward, v = 0, no time dimension
cat > steady.cdl <<CDL
netcdf steady {
dimensions: lat = 6 ; lon = 6 ;
variables:
  double lat(lat) ; lat:units = "degrees_north" ;
  double lon(lon) ; lon:units = "degrees_east" ;
  float UVEL(lat, lon) ; UVEL:units = "centimeter/s" ;
  float VVEL(lat, lon) ; VVEL:units = "centimeter/s" ;
data:
  lat = $LAT ; lon = $LON ;
  UVEL = $(values 36 20) ; VVEL = $(values 36 0) ;
}
CDL
ncgen -o steady.nc steady.cdl

# a climatology-like file: time in "month" (0, 1, 2), u = 0.2 m/s eastward
cat > months.cdl <<CDL
netcdf months {
dimensions: time = 3 ; lat = 6 ; lon = 6 ;
variables:
  double time(time) ; time:units = "month" ;
  double lat(lat) ; lat:units = "degrees_north" ;
  double lon(lon) ; lon:units = "degrees_east" ;
  float uo(time, lat, lon) ; uo:units = "m s-1" ;
  float vo(time, lat, lon) ; vo:units = "m s-1" ;
data:
  time = 0, 1, 2 ; lat = $LAT ; lon = $LON ;
  uo = $(values 108 0.2) ; vo = $(values 108 0) ;
}
CDL
ncgen -o months.nc months.cdl

# velocities in knots labelled degC: 0.2 m/s = 0.388769 kn
cat > mislabelled.cdl <<CDL
netcdf mislabelled {
dimensions: lat = 6 ; lon = 6 ;
variables:
  double lat(lat) ; lat:units = "degrees_north" ;
  double lon(lon) ; lon:units = "degrees_east" ;
  float u(lat, lon) ; u:units = "degC" ;
  float v(lat, lon) ; v:units = "degC" ;
data:
  lat = $LAT ; lon = $LON ;
  u = $(values 36 0.3887689) ; v = $(values 36 0) ;
}
CDL
ncgen -o mislabelled.nc mislabelled.cdl

START=--start=-52.9,47.1
GOAL=--goal=-52.1,47.9

# check SUMMARY SPEED [ISO]: solved, and the travel time is the closed form of a uniform eastward current of
# 0.2 m/s along the straight line (the optimum in a uniform current) within 0.5 %; the departure's ISO date if given
check() {
  python3 - "$@" <<'PY'
import json, math, sys
s = json.load(open(sys.argv[1]))
V = float(sys.argv[2])
assert s["solved"] is True, s["reason"]
dx, dy = s["goal"]["x"] - s["start"]["x"], s["goal"]["y"] - s["start"]["y"]
d = math.hypot(dx, dy)
pc = 0.2 * dx / d
T = d / (pc + math.sqrt(pc * pc + V * V - 0.2 * 0.2))
assert abs(s["travel_time"] - T) <= 5e-3 * T, (s["travel_time"], T)
# without the current (or with u read in the wrong units) the time would differ by far more than 0.5 %
assert abs(d / V - T) > 0.1 * T
if len(sys.argv) > 3:
    assert s["departure"]["iso"] == sys.argv[3], s["departure"]
PY
}

expect_fail() {  # expect_fail PHRASE... -- ARGS: exit 2 and every phrase in the message
  local phrases=()
  while [ "$1" != "--" ]; do phrases+=("$1"); shift; done
  shift
  set +e
  "$exe" "$@" > out.txt 2>&1
  local rc=$?
  set -e
  [ "$rc" -eq 2 ] || { echo "expected exit 2, got $rc: $*"; cat out.txt; exit 1; }
  for p in "${phrases[@]}"; do
    grep -qF -- "$p" out.txt || { echo "message lacks '$p': $*"; cat out.txt; exit 1; }
  done
}

# 1. the steady file from the command line, without --beyond hold
"$exe" --currents steady.nc "$START" "$GOAL" --speed 0.3 --out s1 > s1.txt 2>&1 || { cat s1.txt; exit 1; }
check s1/summary.json 0.3
# any departure: seconds, or a date that dates field time 0
"$exe" --currents steady.nc "$START" "$GOAL" --speed 0.3 --departure 2026-05-01T06:00:00Z --out s2 > s2.txt 2>&1 ||
  { cat s2.txt; exit 1; }
check s2/summary.json 0.3 2026-05-01T06:00:00Z
"$exe" --currents steady.nc "$START" "$GOAL" --speed 0.3 --departure 86400 --out s3 > s3.txt 2>&1 || { cat s3.txt; exit 1; }
check s3/summary.json 0.3
# the options for a time axis are refused for a file without one
expect_fail "--time-units" "no time dimension" -- --currents steady.nc "$START" "$GOAL" --time-units "days since 2026-01-01"
expect_fail "--steady-record" "no time dimension" -- --currents steady.nc "$START" "$GOAL" --steady-record 0
# ... and from a mission file, with an epoch for the ISO times
cat > steady.yaml <<'YAML'
current: {type: netcdf, file: steady.nc}
epoch: 2026-05-01T00:00:00Z
start: {lon: -52.9, lat: 47.1}
goal: {lon: -52.1, lat: 47.9}
vehicle: {speed: 0.3}
departure: {time: 2026-05-01T06:00:00Z}
outputs: {directory: m1, files: [summary]}
YAML
"$exe" --mission steady.yaml > m1.txt 2>&1 || { cat m1.txt; exit 1; }
check m1/summary.json 0.3 2026-05-01T06:00:00Z
echo "steady file OK"

# 2. a time axis in "month": refused naming both ways through, then each of them
expect_fail "time variable 'time': units 'month'" "--time-units" "--steady-record" -- \
  --currents months.nc "$START" "$GOAL" --speed 0.8
"$exe" --currents months.nc "$START" "$GOAL" --speed 0.8 --time-units "days since 2026-01-15" --out t1 > t1.txt 2>&1 ||
  { cat t1.txt; exit 1; }
check t1/summary.json 0.8 2026-01-15T00:00:00Z
"$exe" --currents months.nc "$START" "$GOAL" --speed 0.3 --steady-record 0 --out t2 > t2.txt 2>&1 || { cat t2.txt; exit 1; }
check t2/summary.json 0.3
expect_fail "--steady-record 3 is out of range" "3 records" -- --currents months.nc "$START" "$GOAL" --steady-record 3
for key in "time_units: days since 2026-01-15" "steady_record: 2"; do
  cat > months.yaml <<YAML
current:
  type: netcdf
  file: months.nc
  $key
start: {lon: -52.9, lat: 47.1}
goal: {lon: -52.1, lat: 47.9}
vehicle: {speed: 0.8}
outputs: {directory: m2, files: [summary]}
YAML
  "$exe" --mission months.yaml > m2.txt 2>&1 || { echo "$key"; cat m2.txt; exit 1; }
  check m2/summary.json 0.8
done
cat > months.yaml <<'YAML'
current: {type: netcdf, file: months.nc}
start: {lon: -52.9, lat: 47.1}
goal: {lon: -52.1, lat: 47.9}
YAML
expect_fail "months.yaml:1:" "current.time_units" "current.steady_record" -- --mission months.yaml
echo "undated time axis OK"

# 3. the units override: the file says degC (refused), the values are knots
expect_fail "variable 'u': units 'degC' are not a velocity" "--velocity-units" -- --currents mislabelled.nc "$START" "$GOAL"
"$exe" --currents mislabelled.nc "$START" "$GOAL" --speed 0.3 --velocity-units knots --out k1 > k1.txt 2>&1 ||
  { cat k1.txt; exit 1; }
check k1/summary.json 0.3
cat > knots.yaml <<'YAML'
current: {type: netcdf, file: mislabelled.nc, velocity_units: kt}
start: {lon: -52.9, lat: 47.1}
goal: {lon: -52.1, lat: 47.9}
vehicle: {speed: 0.3}
outputs: {directory: k2, files: [summary]}
YAML
"$exe" --mission knots.yaml > k2.txt 2>&1 || { cat k2.txt; exit 1; }
check k2/summary.json 0.3
echo "velocity units OK"
