#!/usr/bin/env bash
# Runs glider_plan (the main job) with --out into a temporary directory and checks what it writes:
# summary.json (docs/SUMMARY_JSON.md) with the required keys and a solved, finite result; path.csv with header
# t,x,y,lon,lat from start to goal (lon/lat empty: the built-in mission has no projection); map.svg with an <svg>
# root; map.png with the PNG signature. Also: a bad flag or a bad --start exits with status 2 and writes nothing.
set -euo pipefail
exe="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT

"$exe" --start 1,-3 --goal 8,3 --departure 0 --planner 'ZA*TVE' --grid-size 0.4 --sectors 3 --out "$dir/out" > "$dir/stdout.txt"
grep -q "Travel time" "$dir/stdout.txt"
grep -q "CFC" "$dir/stdout.txt"

python3 - "$dir/out" <<'PY'
import json, math, sys, os
d = sys.argv[1]
s = json.load(open(os.path.join(d, "summary.json")))
for k in ["schema", "solved", "status", "travel_time", "travel_time_raw", "travel_time_smoothed", "path_length",
          "waypoints", "cost_function_calls", "current_model_calls", "wall_time_s", "path_checked", "files"]:
    assert k in s, "summary.json lacks key " + k
for k in ["raw", "smoothed", "final"]:
    assert k in s["waypoints"], "summary.json lacks waypoints." + k
for k in ["search", "postprocess", "total"]:
    assert k in s["cost_function_calls"], "summary.json lacks cost_function_calls." + k
assert "planning" in s["wall_time_s"], "summary.json lacks wall_time_s.planning"
assert s["solved"] is True and s["status"] == "Exact solution", (s["solved"], s["status"])
assert s["reason"] is None, s["reason"]
assert s["planner"]["name"] == "ZA*TVE" and s["planner"]["grid_size"] == 0.4 and s["planner"]["sectors"] == 3, s["planner"]
assert math.isfinite(s["travel_time"]) and s["travel_time"] > 0
assert s["travel_time"] <= s["travel_time_smoothed"] <= s["travel_time_raw"] * (1 + 1e-12), \
    "post-processing made the arrival later"
assert s["waypoints"]["smoothed"] <= s["waypoints"]["raw"]
c = s["cost_function_calls"]
assert c["search"] > 0 and c["postprocess"] > 0 and c["total"] == c["search"] + c["postprocess"], c
assert s["current_model_calls"] > 0
assert s["wall_time_s"]["planning"] >= 0
assert s["path_checked"] is True
assert s["start"] == {"x": 1.0, "y": -3.0, "lon": None, "lat": None}, s["start"]
assert s["goal"]["x"] == 8.0 and s["goal"]["y"] == 3.0, s["goal"]
assert s["departure"]["time"] == 0 and s["departure"]["iso"] is None, s["departure"]
# the straight line from (1, -3) to (8, 3) crosses the jet against the current
assert s["straight_line"]["passable"] is False and s["straight_line"]["travel_time"] is None, s["straight_line"]
lines = open(os.path.join(d, "path.csv")).read().strip().splitlines()
assert lines[0] == "t,x,y,lon,lat", lines[0]
cells = [l.split(",") for l in lines[1:]]
assert all(len(c) == 5 and c[3] == "" and c[4] == "" for c in cells), "lon/lat must be empty: " + lines[1]
rows = [list(map(float, c[:3])) for c in cells]
assert len(rows) == s["waypoints"]["final"], (len(rows), s["waypoints"])
assert rows[0] == [0.0, 1.0, -3.0], rows[0]
assert abs(rows[-1][1] - 8) < 1e-9 and abs(rows[-1][2] - 3) < 1e-9
assert abs(rows[-1][0] - s["travel_time"]) < 1e-6
assert abs(s["arrival"]["time"] - rows[-1][0]) < 1e-6, s["arrival"]
assert all(b[0] > a[0] for a, b in zip(rows, rows[1:])), "times must increase"
svg = open(os.path.join(d, "map.svg"), encoding="utf-8").read()
assert "<svg" in svg and "</svg>" in svg and len(svg) > 1000
png = open(os.path.join(d, "map.png"), "rb").read()
assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 1000
for f in ["summary.json", "path.csv", "map.svg", "map.png"]:
    assert f in s["files"], (f, s["files"])
assert sorted(s["files"]) == sorted(os.listdir(d)), (s["files"], os.listdir(d))
print("glider_plan outputs OK")
PY

expect_status_2() {  # args...: exit status 2 and nothing written
    local out="$dir/bad"
    rm -rf "$out"
    set +e
    "$exe" "$@" --out "$out" > /dev/null 2>&1
    local rc=$?
    set -e
    if [ "$rc" -ne 2 ]; then echo "$*: expected exit status 2, got $rc"; exit 1; fi
    if [ -e "$out" ]; then echo "$*: files written despite the error"; exit 1; fi
}
expect_status_2 --no-such-flag
expect_status_2 --start 1
echo "OK"
