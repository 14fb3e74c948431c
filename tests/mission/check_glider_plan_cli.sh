#!/usr/bin/env bash
# glider_plan's mission and forecast modes (issues 5 and 6): --mission writes the mission's files (summary JSON
# with the issue-3 keys, waypoints CSV, goto list, GeoJSON, map PNG); --currents plans on the example NetCDF
# forecast in lon/lat (path.csv t,x,y,lon,lat inside the file's bounds, from start to goal); --speeds prints one
# table line per speed; bad input exits with status 2, a one-line message naming the fault, and writes nothing.
# Usage: check_glider_plan_cli.sh GLIDER_PLAN SOURCE_DIR
set -euo pipefail
exe="$1"
src="$2"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
nc="$src/examples/labrador_forecast.nc"

# 1. --mission with --out
"$exe" --mission "$src/examples/gulf_stream_window.yaml" --out "$dir/mission" > "$dir/mission.txt" 2> "$dir/mission.err"
python3 - "$dir/mission" <<'PY'
import json, os, sys
d = sys.argv[1]
s = json.load(open(os.path.join(d, "gulf_stream_window_summary.json"))) if os.path.exists(os.path.join(d, "gulf_stream_window_summary.json")) else json.load(open(os.path.join(d, "mission_summary.json")))
for k in ["travel_time", "path_length", "waypoints_raw", "waypoints_smoothed", "cost_function_calls",
          "current_model_calls", "planning_time_s", "feasible"]:
    assert k in s, "mission summary lacks key " + k
assert s["feasible"] is True and s["travel_time"] > 0
assert s["cost_function_calls"] == s["cfc"] and s["current_model_calls"] == s["cmc"]
names = os.listdir(d)
csv = [n for n in names if n.endswith("_waypoints.csv")]
assert csv, names
head = open(os.path.join(d, csv[0])).readline().strip()
assert head.startswith("index,x,y,lon,lat,time"), head
assert "goto_l11.ma" in names, names
gj = [n for n in names if n.endswith(".geojson")]
assert gj and json.load(open(os.path.join(d, gj[0])))["type"] == "FeatureCollection"
png = [n for n in names if n.endswith("_map.png")]
assert png and open(os.path.join(d, png[0]), "rb").read()[:8] == b"\x89PNG\r\n\x1a\n"
print("--mission OK")
PY
# the mission's own speeds (0.4, 0.5, 0.6) appear as table lines
for v in 0.4 0.5 0.6; do grep -Eq "^ +$v +[0-9.]+ " "$dir/mission.txt" || { echo "no sweep line for $v"; cat "$dir/mission.txt"; exit 1; }; done

# 2. --currents with geographic start/goal
"$exe" --currents "$nc" --start=-52.7,47.9 --goal=-51.5,48.45 --speed 0.3 --xy-interp bicubic --time-interp akima \
    --departure 2026-03-15T06:00:00Z --out "$dir/nc" > "$dir/nc.txt" 2> "$dir/nc.err" || {
    echo "--currents failed"; cat "$dir/nc.txt" "$dir/nc.err"; exit 1; }
python3 - "$dir/nc" <<'PY'
import json, os, sys
d = sys.argv[1]
s = json.load(open(os.path.join(d, "summary.json")))
for k in ["travel_time", "path_length", "waypoints_raw", "waypoints_smoothed", "cost_function_calls",
          "current_model_calls", "planning_time_s", "feasible"]:
    assert k in s, "summary.json lacks key " + k
assert s["feasible"] is True
assert s["departure"] == 21600, s["departure"]              # 6 h after the first forecast time
assert s["departure_iso"] == "2026-03-15T06:00:00Z", s["departure_iso"]
assert s["speed"] == 0.3
lines = open(os.path.join(d, "path.csv")).read().strip().splitlines()
assert lines[0] == "t,x,y,lon,lat", lines[0]
rows = [list(map(float, l.split(","))) for l in lines[1:]]
assert len(rows) >= 2
for t, x, y, lon, lat in rows:
    assert -53 <= lon <= -51 and 47.6 <= lat <= 48.8, (lon, lat)
assert abs(rows[0][3] + 52.7) < 1e-6 and abs(rows[0][4] - 47.9) < 1e-6, rows[0]
assert abs(rows[-1][3] + 51.5) < 1e-6 and abs(rows[-1][4] - 48.45) < 1e-6, rows[-1]
assert rows[0][0] == 21600
assert abs(rows[-1][0] - rows[0][0] - s["travel_time"]) < 1e-3 * s["travel_time"]
assert all(b[0] > a[0] for a, b in zip(rows, rows[1:]))
# at least the straight distance / (V + max current 0.6 m/s), at most 5 days
dist = ((rows[-1][1] - rows[0][1]) ** 2 + (rows[-1][2] - rows[0][2]) ** 2) ** 0.5
assert dist / (0.3 + 0.6) < s["travel_time"] < 5 * 86400
for f in ["map.png", "map.svg", "waypoints.csv", "path.geojson", "goto_l10.ma"]:
    assert os.path.exists(os.path.join(d, f)), f
assert open(os.path.join(d, "map.png"), "rb").read()[:8] == b"\x89PNG\r\n\x1a\n"
print("--currents OK")
PY

# 2b. a Cartesian forecast (x/y in metres, undated): uniform current 0.2 m/s east, speed 0.3 m/s, 20 km east:
# the travel time is 20000 / 0.5 = 40000 s exactly (the integrator's tolerance is 1 s).
cart="$dir/cart.nc"
python3 - "$dir/cart.cdl" <<'PY'
import sys
vals = lambda c: ", ".join([c] * (3 * 5 * 6))
open(sys.argv[1], "w").write(f"""netcdf cart {{ dimensions: time = 3 ; y = 5 ; x = 6 ;
variables: double time(time) ; time:units = "seconds" ; double y(y) ; y:units = "m" ; double x(x) ; x:units = "m" ;
 float u(time, y, x) ; u:units = "m/s" ; float v(time, y, x) ; v:units = "m/s" ;
data: time = 0, 50000, 100000 ; y = 0, 5000, 10000, 15000, 20000 ; x = 0, 5000, 10000, 15000, 20000, 25000 ;
 u = {vals("0.2")} ; v = {vals("0")} ; }}
""")
PY
ncgen -o "$cart" "$dir/cart.cdl"
"$exe" --currents "$cart" --start 2000,10000 --goal 22000,10000 --departure 1000 --out "$dir/cart" > /dev/null 2>&1
python3 - "$dir/cart" <<'PY'
import json, os, sys
d = sys.argv[1]
s = json.load(open(os.path.join(d, "summary.json")))
assert abs(s["travel_time"] - 40000) < 5, s["travel_time"]
lines = open(os.path.join(d, "path.csv")).read().strip().splitlines()
assert lines[0] == "t,x,y,lon,lat" and lines[1] == "1000,2000,10000,,", lines[:2]
print("Cartesian --currents OK")
PY
# past the last forecast time (100000 s): refused -> no path (status 1); held -> the same 40000 s
set +e
"$exe" --currents "$cart" --start 2000,10000 --goal 22000,10000 --departure 90000 > /dev/null 2>&1
rc=$?
set -e
[ "$rc" -eq 1 ] || { echo "--beyond refuse: expected status 1, got $rc"; exit 1; }
"$exe" --currents "$cart" --start 2000,10000 --goal 22000,10000 --departure 90000 --beyond hold 2>/dev/null \
    | grep -q "^travel time 399" || { echo "--beyond hold: expected travel time 40000"; exit 1; }

# 3. --speeds on the built-in mission: one line per speed, travel time falling with speed
"$exe" --speeds 0.4,0.5,0.6 --grid-size 0.5 --no-refine > "$dir/sweep.txt"
python3 - "$dir/sweep.txt" <<'PY'
import sys
rows = {}
for l in open(sys.argv[1]):
    p = l.split()
    if len(p) >= 3 and p[0] in ("0.4", "0.5", "0.6"):
        rows[float(p[0])] = (float(p[1]), float(p[2]))
assert sorted(rows) == [0.4, 0.5, 0.6], rows
assert rows[0.4][0] > rows[0.5][0] > rows[0.6][0], rows
print("--speeds OK")
PY

# 4. bad input: exit status 2, a message naming the fault, nothing written
expect_error() {  # pattern, args...
    local pattern="$1"; shift
    local out="$dir/bad"
    rm -rf "$out"
    set +e
    "$exe" "$@" --out "$out" > "$dir/bad.txt" 2> "$dir/bad.err"
    local rc=$?
    set -e
    if [ "$rc" -ne 2 ]; then echo "expected status 2, got $rc: $*"; cat "$dir/bad.err"; exit 1; fi
    grep -qi -- "$pattern" "$dir/bad.err" || { echo "message lacks '$pattern': $*"; cat "$dir/bad.err"; exit 1; }
    if [ -e "$out" ]; then echo "files written despite the error: $*"; exit 1; fi
}
expect_error "no-such-flag" --no-such-flag
expect_error "cannot be combined" --mission "$src/examples/gulf_stream_window.yaml" --start 1,2
expect_error "missing.nc" --currents "$dir/missing.nc" --start=-52.7,47.9 --goal=-51.5,48.45
# a NetCDF file without u/v (the bathymetry-like file made here)
ncgen -o "$dir/nouv.nc" - <<'CDL'
netcdf nouv { dimensions: lat = 2 ; lon = 2 ;
variables: double lat(lat) ; lat:units = "degrees_north" ; double lon(lon) ; lon:units = "degrees_east" ;
  float depth(lat, lon) ;
data: lat = 47, 48 ; lon = -53, -52 ; depth = 1, 2, 3, 4 ; }
CDL
expect_error "nouv.nc" --currents "$dir/nouv.nc" --start=-52.7,47.9 --goal=-52.5,47.95
expect_error "on land" --currents "$nc" --start=-51.9,48.7 --goal=-52.7,47.9
expect_error "departure" --currents "$nc" --start=-52.7,47.9 --goal=-51.5,48.45 --departure 2026-04-01T00:00:00Z
expect_error "outside the grid" --currents "$nc" --start=-60,47.9 --goal=-51.5,48.45
expect_error "deepest layer" --currents "$nc" --start=-52.7,47.9 --goal=-51.5,48.45 --depth 500
expect_error "not on the grid" --currents "$nc" --start=-70,40 --goal=-69,41
expect_error "xy-interp" --currents "$nc" --start=-52.7,47.9 --goal=-51.5,48.45 --xy-interp spline
expect_error "needs --currents" --u-var u
echo "OK"
