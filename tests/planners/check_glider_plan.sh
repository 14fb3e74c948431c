#!/usr/bin/env bash
# Runs glider_plan (the main job) with --out into a temporary directory and checks what it writes:
# summary.json with the required keys and a feasible, finite result; path.csv with header t,x,y from start to goal;
# map.svg with an <svg> root; map.png with the PNG signature. Also: a bad flag exits with status 2.
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
for k in ["travel_time", "path_length", "waypoints_raw", "waypoints_smoothed", "cost_function_calls",
          "current_model_calls", "planning_time_s", "feasible"]:
    assert k in s, "summary.json lacks key " + k
assert s["feasible"] is True
assert math.isfinite(s["travel_time"]) and s["travel_time"] > 0
assert s["travel_time"] <= s["travel_time_raw"] + 1e-12, "post-processing made the arrival later"
assert s["waypoints_smoothed"] <= s["waypoints_raw"]
assert s["cost_function_calls"] > 0 and s["current_model_calls"] > 0
assert s["path_checked"] is True
lines = open(os.path.join(d, "path.csv")).read().strip().splitlines()
assert lines[0] == "t,x,y", lines[0]
rows = [list(map(float, l.split(","))) for l in lines[1:]]
assert len(rows) >= 2
assert rows[0] == [0.0, 1.0, -3.0], rows[0]
assert abs(rows[-1][1] - 8) < 1e-9 and abs(rows[-1][2] - 3) < 1e-9
assert abs(rows[-1][0] - s["travel_time"]) < 1e-6
assert all(b[0] > a[0] for a, b in zip(rows, rows[1:])), "times must increase"
svg = open(os.path.join(d, "map.svg"), encoding="utf-8").read()
assert "<svg" in svg and "</svg>" in svg and len(svg) > 1000
png = open(os.path.join(d, "map.png"), "rb").read()
assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 1000
print("glider_plan outputs OK")
PY

set +e
"$exe" --no-such-flag > /dev/null 2>&1
rc=$?
set -e
if [ "$rc" -ne 2 ]; then echo "bad flag: expected exit status 2, got $rc"; exit 1; fi
"$exe" --start 1 > /dev/null 2>&1 && { echo "bad --start accepted"; exit 1; } || true
echo "OK"
