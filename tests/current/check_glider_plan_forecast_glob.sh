#!/usr/bin/env bash
# glider_plan --currents with several files: one forecast written as one file and as three daily files (each with
# its own "since" date and unit, the second overlapping the third by a record with other values), given as a glob
# pattern and as a comma-separated list in the wrong order. The travel time must equal the combined file's (within
# 1e-9 relative), and summary.json must list the files read, in time order. A pattern that matches nothing is
# exit 2 naming the pattern.
# Usage: check_glider_plan_forecast_glob.sh GLIDER_PLAN
set -euo pipefail
exe="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"  # absolute: the script works in a scratch directory
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
cd "$dir"

# files: combined.nc (hours since 2026-03-01, 3-hourly, 0..69 h) and fc_a.nc / fc_b.nc / fc_c.nc (one day each)
python3 - <<'PY'
import math, subprocess
LAT = [47.0 + 0.2 * j for j in range(6)]
LON = [-53.0 + 0.2 * i for i in range(6)]
def u(lon, lat, h): return 0.25 * math.sin(2 * math.pi * h / 26 + 3 * lon) + 0.05 * (lat - 47.5)
def v(lon, lat, h): return 0.15 * math.cos(4 * lat + h / 9) - 0.03 * (lon + 52.5)
def write(name, units, raw, hours, bias):
    uu, vv = [], []
    for h, b in zip(hours, bias):
        for la in LAT:
            for lo in LON:
                uu.append("%.7g" % (u(lo, la, h) + b))
                vv.append("%.7g" % v(lo, la, h))
    cdl = f"""netcdf {name} {{
dimensions: time = UNLIMITED ; lat = 6 ; lon = 6 ;
variables:
  double time(time) ; time:units = "{units}" ; time:standard_name = "time" ;
  double lat(lat) ; lat:units = "degrees_north" ;
  double lon(lon) ; lon:units = "degrees_east" ;
  float u(time, lat, lon) ; u:units = "m s-1" ; u:standard_name = "eastward_sea_water_velocity" ;
  float v(time, lat, lon) ; v:units = "m s-1" ; v:standard_name = "northward_sea_water_velocity" ;
data:
  time = {", ".join(repr(r) for r in raw)} ;
  lat = {", ".join(map(repr, LAT))} ;
  lon = {", ".join(map(repr, LON))} ;
  u = {", ".join(uu)} ;
  v = {", ".join(vv)} ;
}}
"""
    subprocess.run(["ncgen", "-o", name + ".nc", "-"], input=cdl.encode(), check=True)
hours = [3.0 * k for k in range(24)]
write("combined", "hours since 2026-03-01 00:00:00", hours, hours, [0] * 24)
# day 1 in hours, day 2 in days since its own date (plus 2026-03-03T00:00, biased: day 3's file replaces it),
# day 3 in minutes since the day before
h1 = hours[0:8]; h2 = hours[8:16] + [48.0]; h3 = hours[16:24]
write("fc_a", "hours since 2026-03-01", h1, h1, [0] * 8)
write("fc_b", "days since 2026-03-02", [(h - 24) / 24 for h in h2], h2, [0] * 8 + [0.5])
write("fc_c", "minutes since 2026-03-02", [(h - 24) * 60 for h in h3], h3, [0] * 8)
PY

trip=(--start=-52.8,47.2 --goal=-52.2,47.8 --speed 0.5 --departure 2026-03-01T18:00:00Z)
"$exe" --currents combined.nc "${trip[@]}" --out one > one.txt
"$exe" --currents 'fc_*.nc' "${trip[@]}" --out glob > glob.txt
"$exe" --currents 'fc_c.nc, fc_a.nc,fc_b.nc' "${trip[@]}" --out list > list.txt
python3 - <<'PY'
import json, os
one = json.load(open("one/summary.json"))
for run in ("glob", "list"):
    s = json.load(open(run + "/summary.json"))
    assert s["solved"] and one["solved"], run
    a, b = one["travel_time"], s["travel_time"]
    assert abs(a - b) <= 1e-9 * a, (run, a, b)
    files = [os.path.basename(f) for f in s["forecast_files"]]
    assert files[0] == "fc_a.nc" and files == sorted(files), (run, files)
    assert s["departure"]["iso"] == one["departure"]["iso"], run
assert [os.path.basename(f) for f in one["forecast_files"]] == ["combined.nc"], one["forecast_files"]
print("travel time", one["travel_time"], "s on the combined file and on the daily files")
PY

# a pattern that matches nothing: exit 2, the pattern named, nothing written
set +e
"$exe" --currents 'fc_a.nc,hycom_*.nc' "${trip[@]}" --out none > none.txt 2>&1
status=$?
set -e
[ "$status" -eq 2 ] || { echo "expected exit 2, got $status"; cat none.txt; exit 1; }
grep -q "no file matches the pattern 'hycom_\*.nc'" none.txt || { cat none.txt; exit 1; }
[ ! -e none ] || { echo "wrote outputs"; exit 1; }
echo "ok"
