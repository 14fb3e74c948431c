#!/usr/bin/env bash
# glider_plan's mission and forecast modes: --mission writes the mission's files with fixed names
# (summary.json in the one schema of docs/SUMMARY_JSON.md, waypoints.csv, path.geojson, the goto list, map.svg and
# map.png) into --out or the mission's outputs.directory, plus <prefix>_<name> copies when outputs.prefix is set;
# --currents plans on the example NetCDF forecast in lon/lat (path.csv t,x,y,lon,lat inside the file's bounds,
# from start to goal); --speeds prints one table line per speed; a trip the forecast cannot carry exits with
# status 1; bad input exits with status 2, a one-line message naming the fault, and writes nothing.
# Usage: check_glider_plan_cli.sh GLIDER_PLAN SOURCE_DIR
set -euo pipefail
exe="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"  # absolute: 1b runs it from another directory
src="$2"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
nc="$src/examples/labrador_forecast.nc"

# 1. --mission with --out: a departure window, a speed sweep, geographic outputs
"$exe" --mission "$src/examples/gulf_stream_window.yaml" --out "$dir/mission" > "$dir/mission.txt" 2> "$dir/mission.err"
python3 - "$dir/mission" <<'PY'
import json, os, sys
d = sys.argv[1]
s = json.load(open(os.path.join(d, "summary.json")))
for k in ["schema", "mission", "source", "solved", "status", "planner", "travel_time", "path_length", "waypoints",
          "cost_function_calls", "current_model_calls", "wall_time_s", "departure", "arrival", "departure_search",
          "speed_sweep", "files"]:
    assert k in s, "mission summary lacks key " + k
assert s["schema"] == "ompl_glider-summary/1", s["schema"]
assert s["mission"] == "gulf_stream_window" and s["source"].endswith("gulf_stream_window.yaml"), (s["mission"], s["source"])
assert s["solved"] is True and s["status"] == "Exact solution" and s["travel_time"] > 0
assert s["planner"]["name"] == "ZA*TVE", s["planner"]   # "zastartve" in the file: stored by its canonical name
assert s["planner"]["refinement"] is True, s["planner"]  # on by default in mission files
c = s["cost_function_calls"]
assert c["search"] > 0 and c["total"] == c["search"] + c["postprocess"], c
assert s["current_model_calls"] > 0 and s["wall_time_s"]["planning"] >= 0
assert s["waypoints"]["smoothed"] <= s["waypoints"]["raw"], s["waypoints"]
assert s["travel_time"] <= s["travel_time_smoothed"] <= s["travel_time_raw"] * (1 + 1e-12)
# the departure window [day 5, day 21] was searched; the plan departs at the best departure found
ds = s["departure_search"]
assert ds["found"] is True and 5 <= ds["departure"] <= 21, ds
assert ds["window"] == [5, 21], ds["window"]
assert s["departure"]["time"] == ds["departure"], (s["departure"], ds["departure"])
assert s["departure"]["iso"].startswith("2026-06-"), s["departure"]
assert s["start"]["lon"] is not None and s["goal"]["lat"] is not None
# the mission's speeds: one row each; the mission's own speed gives the plan's travel time
rows = {r["speed"]: r for r in s["speed_sweep"]}
assert sorted(rows) == [0.4, 0.5, 0.6], rows
assert all(r["solved"] for r in rows.values())
assert rows[0.4]["travel_time"] > rows[0.5]["travel_time"] > rows[0.6]["travel_time"], rows
assert abs(rows[0.5]["travel_time"] - s["travel_time"]) <= 1e-9 * s["travel_time"], (rows[0.5], s["travel_time"])
# fixed file names, all listed in the summary
names = sorted(os.listdir(d))
assert names == sorted(["summary.json", "waypoints.csv", "path.geojson", "route.kml", "goto_l11.ma", "targets",
                        "map.svg", "map.png", "map.html"]), names
assert sorted(s["files"]) == names and s["files"][0] == "summary.json", s["files"]
head = open(os.path.join(d, "waypoints.csv")).readline().strip()
assert head.startswith("index,x,y,lon,lat,time"), head
assert json.load(open(os.path.join(d, "path.geojson")))["type"] == "FeatureCollection"
assert open(os.path.join(d, "map.png"), "rb").read()[:8] == b"\x89PNG\r\n\x1a\n"
goto = open(os.path.join(d, "goto_l11.ma")).read()
n = int(goto.split("num_waypoints(nodim) ")[1].split()[0])
assert "behavior_name=goto_list" in goto and 1 <= n <= s["waypoints"]["final"] - 1, goto  # thinned to the turns
assert "list_when_wpt_dist(m) 100" in goto, goto
print("--mission OK")
PY
# the mission's own speeds (0.4, 0.5, 0.6) appear as table lines
for v in 0.4 0.5 0.6; do grep -Eq "^ +$v +[0-9.]+ " "$dir/mission.txt" || { echo "no sweep line for $v"; cat "$dir/mission.txt"; exit 1; }; done
grep -q "wrote $dir/mission/summary.json" "$dir/mission.txt" || { echo "no 'wrote' line"; cat "$dir/mission.txt"; exit 1; }

# 1b. --mission without --out: the files land in the mission's outputs.directory (relative to the mission file,
# not to the working directory), with <prefix>_ copies; planner parameters by their OMPL names.
mkdir -p "$dir/m" "$dir/cwd"
cat > "$dir/m/trip.yaml" <<'YAML'
name: trip
current: {type: uniform, parameters: {u: 0.1, v: 0.0}}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: 0}
goal: {x: 9, y: 0}
vehicle: {speed: 0.5}
planner: {name: ztve, grid_size: 0.5, parameters: {delta_phi_max: 20, zermelo_steps: 4}}
outputs: {directory: results, files: [summary, csv, path, geojson], prefix: trip}
YAML
(cd "$dir/cwd" && "$exe" --mission ../m/trip.yaml > out.txt 2>&1) || { echo "--mission without --out failed"; cat "$dir/cwd/out.txt"; exit 1; }
[ -z "$(ls -A "$dir/cwd" | grep -v '^out.txt$')" ] || { echo "files written into the working directory"; ls "$dir/cwd"; exit 1; }
python3 - "$dir/m/results" <<'PY'
import json, os, sys
d = sys.argv[1]
base = ["summary.json", "waypoints.csv", "path.csv", "path.geojson"]
names = sorted(os.listdir(d))
assert names == sorted(base + ["trip_" + n for n in base]), names
s = json.load(open(os.path.join(d, "summary.json")))
assert s["files"] == base + ["trip_" + n for n in base], s["files"]
assert s["solved"] is True and abs(s["travel_time"] - 8 / 0.6) < 1e-9, s["travel_time"]
assert s["planner"]["name"] == "ZTVE", s["planner"]
assert s["planner"]["parameters"] == {"delta_phi_max": "20", "zermelo_steps": "4"}, s["planner"]["parameters"]
for n in base:
    assert open(os.path.join(d, n), "rb").read() == open(os.path.join(d, "trip_" + n), "rb").read(), n
lines = open(os.path.join(d, "path.csv")).read().strip().splitlines()
assert lines[0] == "t,x,y,lon,lat" and lines[1] == "0,1,0,,", lines[:2]
print("--mission outputs.directory and prefix OK")
PY

# 2. --currents with geographic start/goal
"$exe" --currents "$nc" --start=-52.7,47.9 --goal=-51.5,48.45 --speed 0.3 --xy-interp bicubic --time-interp akima \
    --departure 2026-03-15T06:00:00Z --out "$dir/nc" > "$dir/nc.txt" 2> "$dir/nc.err" || {
    echo "--currents failed"; cat "$dir/nc.txt" "$dir/nc.err"; exit 1; }
python3 - "$dir/nc" <<'PY'
import json, os, sys
d = sys.argv[1]
s = json.load(open(os.path.join(d, "summary.json")))
for k in ["travel_time", "path_length", "waypoints", "cost_function_calls", "current_model_calls", "wall_time_s",
          "solved", "departure", "speed", "current"]:
    assert k in s, "summary.json lacks key " + k
assert s["solved"] is True and s["current"] == "gridded"
assert s["departure"]["time"] == 21600, s["departure"]              # 6 h after the first forecast time
assert s["departure"]["iso"] == "2026-03-15T06:00:00Z", s["departure"]
assert s["speed"] == 0.3
assert abs(s["start"]["lon"] + 52.7) < 1e-9 and abs(s["start"]["lat"] - 47.9) < 1e-9, s["start"]
lines = open(os.path.join(d, "path.csv")).read().strip().splitlines()
assert lines[0] == "t,x,y,lon,lat", lines[0]
rows = [list(map(float, l.split(","))) for l in lines[1:]]
assert len(rows) == s["waypoints"]["final"] >= 2
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
names = sorted(os.listdir(d))
assert names == sorted(["summary.json", "path.csv", "map.png", "map.svg", "map.html", "waypoints.csv",
                        "path.geojson", "route.kml", "goto_l10.ma", "targets"]), names
assert sorted(s["files"]) == names, s["files"]
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
assert s["start"]["lon"] is None and s["departure"]["iso"] is None, (s["start"], s["departure"])
lines = open(os.path.join(d, "path.csv")).read().strip().splitlines()
assert lines[0] == "t,x,y,lon,lat" and lines[1] == "1000,2000,10000,,", lines[:2]
# no lon/lat: no goto list
assert "goto_l10.ma" not in os.listdir(d), os.listdir(d)
print("Cartesian --currents OK")
PY
# past the last forecast time (100000 s): refused -> no path (status 1, the reason printed, summary.json says
# why); held -> the same 40000 s
set +e
"$exe" --currents "$cart" --start 2000,10000 --goal 22000,10000 --departure 90000 --out "$dir/refuse" > "$dir/refuse.txt" 2>&1
rc=$?
set -e
[ "$rc" -eq 1 ] || { echo "--beyond refuse: expected status 1, got $rc"; cat "$dir/refuse.txt"; exit 1; }
grep -q "no path" "$dir/refuse.txt" || { echo "--beyond refuse: no reason printed"; cat "$dir/refuse.txt"; exit 1; }
grep -q "the forecast ends .* after the departure.*--beyond hold" "$dir/refuse.txt" || { echo "--beyond refuse: the reason does not name the forecast end"; cat "$dir/refuse.txt"; exit 1; }
python3 - "$dir/refuse" <<'PY'
import json, os, sys
s = json.load(open(os.path.join(sys.argv[1], "summary.json")))
assert s["solved"] is False and s["reason"] and s["travel_time"] is None, s
names = sorted(os.listdir(sys.argv[1]))
assert sorted(s["files"]) == names and s["files"][0] == "summary.json", (s["files"], names)
# no route without a path (the map of the field is still drawn)
assert not set(names) & {"path.csv", "waypoints.csv", "path.geojson"}, names
PY
"$exe" --currents "$cart" --start 2000,10000 --goal 22000,10000 --departure 90000 --beyond hold 2>/dev/null \
    > "$dir/hold.txt" || { echo "--beyond hold: expected a path"; cat "$dir/hold.txt"; exit 1; }
python3 - "$dir/hold.txt" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
# days/hours with the seconds beside them: "11.1 h (40000.0 s)"
m = re.search(r"^Travel time: +[0-9.]+ h \(([0-9.]+) s\)", text, re.M)
assert m and abs(float(m.group(1)) - 40000) < 5, "--beyond hold: expected travel time 40000"
# planning on the frozen last field is said
assert "on its last field, held frozen (current.horizon: hold_last, --beyond hold)" in text, text
PY

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
expect_error "cannot be combined" --mission "$src/examples/gulf_stream_window.yaml" --u-var u
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
expect_error "lies outside the grid of" --currents "$nc" --start=-70,40 --goal=-69,41
expect_error "xy-interp" --currents "$nc" --start=-52.7,47.9 --goal=-51.5,48.45 --xy-interp spline
expect_error "needs --currents" --u-var u
expect_error "unknown planner 'Dijkstra'" --planner Dijkstra
# the speed list: every item a positive number
expect_error "got 'fast'" --speeds 0.25,fast
expect_error "got -1" --speeds 0.25,-1
expect_error "got ''" --speeds 0.4,,0.5
# bad mission files: the message names the file, the line and the field
expect_error "cannot read mission file" --mission "$dir/no-such-mission.yaml"
printf 'current: {type: uniform}\nregion: {x_min: 0, x_max: 1, y_min: 0, y_max: 1}\nstart: {x: 0, y: 0}\n'\
'goal: {x: 1, y: 1}\nplanner: {gird_size: 0.1}\n' > "$dir/bad1.yaml"
expect_error "bad1.yaml:5: unknown field 'planner.gird_size'" --mission "$dir/bad1.yaml"
sed 's/planner: .*/planner: {name: dijkstra}/' "$dir/m/trip.yaml" > "$dir/bad2.yaml"
expect_error "bad2.yaml:7: field 'planner.name': unknown planner 'dijkstra'" --mission "$dir/bad2.yaml"
# the old parameter name (delta_phi_max_deg) is gone: parameters go by their OMPL names
sed 's/delta_phi_max: 20/delta_phi_max_deg: 20/' "$dir/m/trip.yaml" > "$dir/bad3.yaml"
expect_error "bad3.yaml:7: field 'planner.parameters.delta_phi_max_deg': planner ZTVE has no parameter" \
    --mission "$dir/bad3.yaml"
# an ensemble drawn from one flow's parameters: a spread outside [0, 1) and members without the spread
printf 'current: {type: meandering_jet, parameters: {B0: 1.2}, members: 24,\n  spread: {B0: 1.5}}\n'\
'region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\nstart: {x: 1, y: -3}\ngoal: {x: 8, y: 3}\n' > "$dir/bad4.yaml"
expect_error "bad4.yaml:2: field 'current.spread.B0': expected a relative spread in \[0, 1)" --mission "$dir/bad4.yaml"
sed 's/members: 24,/members: 1001,/' "$dir/bad4.yaml" > "$dir/bad5.yaml"
expect_error "bad5.yaml:1: field 'current.members': expected an integer in 2..1000" --mission "$dir/bad5.yaml"
# the plan flown in another ocean from the command line: the built-in jet with another amplitude as the
# truth, two strategies, a small batch; the second run of the same directory without --truth removes the files
"$exe" --truth B0=1.38,c=0.138 --surfacing-interval 0.25 --strategies current_sensitive,greedy --radius 0.1 \
    --execution-pairs 3 --out "$dir/exec" > "$dir/exec.txt" 2> "$dir/exec.err"
python3 - "$dir/exec" <<'PY'
import csv, json, os, sys
d = sys.argv[1]
s = json.load(open(os.path.join(d, "summary.json")))
e = s["execution"]
assert e["truth"] == "meandering jet" and e["surfacing_interval"] == 0.25 and e["radius"] == 0.1, e
assert e["runs"] == 4 and e["model_difference"]["rms"] > 0, e
assert sorted(k for k in e if isinstance(e[k], dict) and "batch" in e[k]) == ["current_sensitive", "greedy"], e.keys()
for k in ["current_sensitive", "greedy"]:
    o = e[k]
    assert isinstance(o["reached"], bool) and isinstance(o["grounded"], bool), o
    assert o["final_distance"] >= 0 and o["batch"]["runs"] == e["runs_planned"], o
    assert o["arrival_time"] is None or o["arrival_time"] > s["departure"]["time"], o
rows = list(csv.DictReader(open(os.path.join(d, "execution.csv"))))
assert len(rows) == 2 * e["runs_planned"] + (e["runs"] - e["runs_planned"]), len(rows)
for name in ["execution_tracks.csv", "execution.png", "execution.svg", "model_difference.png", "map.png"]:
    assert name in s["files"] and os.path.exists(os.path.join(d, name)), name
print("execution OK")
PY
"$exe" --out "$dir/exec" > /dev/null 2>&1
test ! -e "$dir/exec/execution.csv" && test ! -e "$dir/exec/model_difference.png"
# an empty speed list is bad input too (was parseSpeedList("") -> error)
expect_error "speeds" --speeds ""
echo "OK"
