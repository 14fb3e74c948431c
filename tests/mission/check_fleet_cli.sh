#!/usr/bin/env bash
# glider_plan --mission with a fleet: the example (exit 0, a folder per glider, fleet.csv, the table), a glider
# without a route (exit 1 naming it, every folder written, an empty travel time in fleet.csv), a NetCDF-4 forecast
# read on the fleet's threads without HDF5 diagnostics, a bad entry (exit 2 with file:line, nothing written),
# and --start refused with a fleet.
#   check_fleet_cli.sh GLIDER_PLAN SOURCE_DIR
set -uo pipefail
PLAN=$1 SRC=$2
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*"; cat "$WORK/stderr" 2>/dev/null; exit 1; }

"$PLAN" --mission "$SRC/tests/mpi/fleet.yaml" --out "$WORK/ok" >"$WORK/stdout" 2>"$WORK/stderr" || fail "exit $?"
for g in alpha bravo charlie delta echo; do
  [ -f "$WORK/ok/$g/summary.json" ] && [ -f "$WORK/ok/$g/waypoints.csv" ] || fail "no folder for $g"
done
[ "$(wc -l <"$WORK/ok/fleet.csv")" = 6 ] || fail "fleet.csv rows"
grep -q "^charlie  *route" "$WORK/stdout" || fail "no table line for charlie"
python3 - "$WORK/ok/summary.json" <<'PY' || fail "summary.json"
import json, sys
s = json.load(open(sys.argv[1]))
assert [g["name"] for g in s["fleet"]] == ["alpha", "bravo", "charlie", "delta", "echo"], s["fleet"]
assert all(g["solved"] and g["travel_time"] > 0 for g in s["fleet"])
assert "alpha/waypoints.csv" in s["files"] and "fleet.csv" in s["files"]
PY

# a forecast fleet: the problems read the NetCDF file one at a time (the library is not thread-safe), then plan in
# threads; each glider's route equals its own mission's
cat >"$WORK/forecast.yaml" <<Y
name: labrador_fleet
current:
  type: netcdf
  file: $SRC/examples/labrador_forecast.nc
  variables: {u: u, v: v, lon: lon, lat: lat, depth: depth, time: time}
region: {lon_min: -52.9, lon_max: -51.1, lat_min: 47.7, lat_max: 48.7}
departure: {time: "2026-03-15T06:00:00Z"}
vehicle: {speed: 0.3}
fleet:
  - {name: east, start: {lon: -52.7, lat: 47.9}, goal: {lon: -51.5, lat: 48.45}}
  - {name: west, start: {lon: -52.6, lat: 48.1}, goal: {lon: -51.7, lat: 48.3}}
outputs: {directory: fc, files: [csv, summary]}
Y
"$PLAN" --mission "$WORK/forecast.yaml" >"$WORK/stdout" 2>"$WORK/stderr" || fail "forecast fleet: exit $?"
sed -e '/^fleet:/,/^outputs/{/^outputs/!d}' -e 's/^outputs: {directory: fc/start: {lon: -52.6, lat: 48.1}\ngoal: {lon: -51.7, lat: 48.3}\noutputs: {directory: alone/' \
  "$WORK/forecast.yaml" >"$WORK/west.yaml"
"$PLAN" --mission "$WORK/west.yaml" >/dev/null 2>"$WORK/stderr" || fail "west alone: exit $?"
cmp "$WORK/fc/west/waypoints.csv" "$WORK/alone/waypoints.csv" || fail "the fleet's west differs from its own mission"
# the same forecast as NetCDF-4 (HDF5 underneath), read on the fleet's threads: no HDF5 diagnostics on the console
nccopy -k nc4 "$SRC/examples/labrador_forecast.nc" "$WORK/labrador4.nc" || fail "nccopy"
sed -e "s|file: .*labrador_forecast.nc|file: $WORK/labrador4.nc|" -e 's/directory: fc/directory: fc4/' \
  "$WORK/forecast.yaml" >"$WORK/forecast4.yaml"
"$PLAN" --mission "$WORK/forecast4.yaml" >"$WORK/stdout" 2>"$WORK/stderr" || fail "NetCDF-4 fleet: exit $?"
grep -q "HDF5" "$WORK/stdout" "$WORK/stderr" && fail "HDF5 diagnostics printed: $(grep -c HDF5 "$WORK/stderr") lines"
cmp "$WORK/fc/west/waypoints.csv" "$WORK/fc4/west/waypoints.csv" || fail "the NetCDF-4 fleet's west differs"

# a glider that cannot make headway against the current: exit 1, named; the others' routes are written
cat >"$WORK/nopath.yaml" <<'Y'
name: nopath
current: {type: uniform, parameters: {u: 0.3, v: 0.0}}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
planner: {name: zastartve, grid_size: 0.5}
fleet:
  - {name: with, start: {x: 1, y: 0}, goal: {x: 9, y: 0}}
  - {name: against, start: {x: 9, y: 1}, goal: {x: 1, y: 1}, speed: 0.1}
outputs: {directory: out, files: [csv, summary]}
Y
"$PLAN" --mission "$WORK/nopath.yaml" >"$WORK/stdout" 2>"$WORK/stderr"
[ $? = 1 ] || fail "no path: exit 1 expected"
grep -q "glider 'against' has no route" "$WORK/stderr" || fail "the glider without a route is not named"
[ -f "$WORK/out/with/waypoints.csv" ] && [ -f "$WORK/out/against/summary.json" ] || fail "folders not written"
[ -e "$WORK/out/against/waypoints.csv" ] && fail "a route file for the glider without a route"
# fleet.csv: no travel time for it (an empty cell, as summary.json's null), never "inf"
python3 - "$WORK/out/fleet.csv" <<'PY' || fail "fleet.csv of the glider without a route"
import csv, sys
rows = {r["name"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert rows["against"]["travel_time"] == "" and rows["against"]["arrival_time"] == "", rows["against"]
assert float(rows["with"]["travel_time"]) > 0, rows["with"]
assert "inf" not in open(sys.argv[1]).read().lower()
PY

# a bad entry: exit 2 with file:line, nothing written
sed 's/- {name: against, start: {x: 9, y: 1}, /- {name: against, /' "$WORK/nopath.yaml" >"$WORK/bad.yaml"
"$PLAN" --mission "$WORK/bad.yaml" --out "$WORK/bad" >"$WORK/stdout" 2>"$WORK/stderr"
[ $? = 2 ] || fail "bad entry: exit 2 expected"
grep -q "bad.yaml:7: field 'fleet\[1\].start': missing" "$WORK/stderr" || fail "bad entry not placed"
[ -e "$WORK/bad" ] && fail "output written for bad input"

"$PLAN" --mission "$WORK/nopath.yaml" --start 1,1 --out "$WORK/flag" >"$WORK/stdout" 2>"$WORK/stderr"
[ $? = 2 ] || fail "--start with a fleet: exit 2 expected"
grep -q "cannot be combined with a mission file's fleet" "$WORK/stderr" || fail "--start with a fleet not refused"
echo "ok: fleet from the command line"
