#!/usr/bin/env bash
# glider_plan --currents on real-sized global forecasts (0.5 degrees, float32, Copernicus-Marine layout, written by
# make_global_forecast with NetCDF-C) in both longitude conventions (geography):
#   files     write the forecasts once (the ctest fixture of the other scenarios)
#   dateline  175E -> 175W on a -180..180 file, round a land block on the antimeridian; the goal as -175 and as 185
#             give the same route; outputs in -180..180, the GeoJSON path split at the antimeridian, the goto list
#             within +-18000 with 175W as -17500.0000
#   greenwich 5W -> 5E on a 0..360 file, start as -5 and as 355: the same route
#   seam      a regional 0..360 extract written across Greenwich (359.75, 0): 5W -> 5E round an island on the
#             seam, in either convention; --region across Greenwich as a bbox in 0..360
#   duplicate a global file with both seam columns (-180 and 180): across the antimeridian
#   wide      70 degrees of longitude at 40S on a global file without land
#   polar     80N with a margin that reaches the pole (the pole rows are left out); a start at 89.95N is refused
#   region    --region across the antimeridian as a bbox and unwrapped: the same route; bad --region values exit 2
#             naming the flag and write nothing
# Usage: check_geography.sh SCENARIO GLIDER_PLAN MAKE_GLOBAL_FORECAST DATA_DIR
set -euo pipefail
scenario="$1"
exe="$2"
make="$3"
data="$4"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT

if [ "$scenario" = files ]; then
  mkdir -p "$data"
  # -180..179.5 with the pole rows, land on the antimeridian at 28.5..32N
  "$make" "$data/g180.nc" -180 0.5 720 -90 0.5 361 land=178.5,-178.5,28.5,32
  # 0..359.5 with the pole rows, no land
  "$make" "$data/g360.nc" 0 0.5 720 -90 0.5 361
  # a 0.25-degree extract 340E..20E written in 0..360 (359.75 then 0), an island across the seam
  "$make" "$data/extract.nc" 340 0.25 161 30 0.25 81 wrap land=359,1,36.5,38.5
  # -180..180: both seam columns
  "$make" "$data/dup.nc" -180 0.5 721 -89.5 0.5 359
  ls -l "$data"
  exit 0
fi

plan() {  # plan NAME FILE ARGS...: exit 0 expected, outputs in $dir/NAME
  local name="$1" file="$2"
  shift 2
  if ! "$exe" --currents "$data/$file" "$@" --out "$dir/$name" > "$dir/$name.txt" 2>&1; then
    echo "glider_plan --currents $file $* failed:"
    cat "$dir/$name.txt"
    exit 1
  fi
}

refused() {  # refused PHRASE ARGS...: exit 2, the phrase in the message, nothing written
  local phrase="$1"
  shift
  set +e
  "$exe" "$@" --out "$dir/refused" > "$dir/refused.txt" 2>&1
  local status=$?
  set -e
  if [ $status -ne 2 ] || ! grep -qi -- "$phrase" "$dir/refused.txt" || [ -e "$dir/refused" ]; then
    echo "expected exit 2 with '$phrase' and nothing written for: $*  (exit $status)"
    cat "$dir/refused.txt"
    exit 1
  fi
}

check() {  # check NAME [LAND lon0,lon1,lat0,lat1] [SPLIT yes|no]: the outputs a pilot loads
  python3 - "$dir/$1" "${2:-}" "${3:-}" <<'PY'
import csv, json, math, os, re, sys
d, land, split = sys.argv[1], sys.argv[2], sys.argv[3]
s = json.load(open(os.path.join(d, "summary.json")))
assert s["solved"] is True, s["reason"]
lons = [s["start"]["lon"], s["goal"]["lon"]]
rows = list(csv.DictReader(open(os.path.join(d, "waypoints.csv"))))
path = list(csv.DictReader(open(os.path.join(d, "path.csv"))))
assert len(rows) == len(path) == s["waypoints"]["final"] >= 2
lons += [float(r["lon"]) for r in rows] + [float(r["lon"]) for r in path]
g = json.load(open(os.path.join(d, "path.geojson")))
geometry = g["features"][0]["geometry"]
lines = [geometry["coordinates"]] if geometry["type"] == "LineString" else geometry["coordinates"]
for line in lines:
    assert len(line) >= 2, line
    for (a, _), (b, _) in zip(line, line[1:]):
        assert abs(b - a) <= 180, (a, b)  # no segment the long way round the globe
    lons += [p[0] for p in line]
lons += [f["geometry"]["coordinates"][0] for f in g["features"][1:]]
bad = [x for x in lons if not -180 <= x <= 180]
assert not bad, "longitudes outside -180..180: %s" % bad[:5]
if split:
    assert (geometry["type"] == "MultiLineString") == (split == "yes"), geometry["type"]
if geometry["type"] == "MultiLineString":
    for a, b in zip(lines, lines[1:]):  # pieces meet on the antimeridian
        assert abs(a[-1][0]) == 180 and a[-1][0] == -b[0][0] and abs(a[-1][1] - b[0][1]) < 1e-9, (a[-1], b[0])
# the goto list: [-]DDDMM.MMMM within +-18000 (lon) and +-9000 (lat), the last entry the goal
goto = open(os.path.join(d, "goto_l10.ma")).read()
wp = goto.split("<start:waypoints>")[1].split("<end:waypoints>")[0].split()
assert 2 <= len(wp) <= 2 * (len(rows) - 1), (len(wp), len(rows))  # the turns of the route, the goal last
def degmin(v):
    m = re.fullmatch(r"(-?)(\d+)(\d\d\.\d{4})", v)
    assert m, v
    x = int(m.group(2)) + float(m.group(3)) / 60
    return -x if m.group(1) else x
for lon, lat in zip(wp[0::2], wp[1::2]):
    assert abs(float(lon)) <= 18000 and abs(float(lat)) <= 9000, (lon, lat)
    assert int(abs(float(lon))) % 100 < 60 and int(abs(float(lat))) % 100 < 60, (lon, lat)
for lon, lat in zip(wp[0::2], wp[1::2]):  # each listed waypoint is one of the route's
    assert any(abs(degmin(lon) - float(r["lon"])) * 60 <= 0.5e-4 + 1e-9 and
               abs(degmin(lat) - float(r["lat"])) * 60 <= 0.5e-4 + 1e-9 for r in rows), (lon, lat)
# route.kml: every coordinate in -180..180
kml = open(os.path.join(d, "route.kml")).read()
for block in re.findall(r"<coordinates>([^<]*)</coordinates>", kml):
    for p in block.split():
        assert -180 <= float(p.split(",")[0]) <= 180, p
goal = (float(rows[-1]["lon"]), float(rows[-1]["lat"]))
for got, want in zip((degmin(wp[-2]), degmin(wp[-1])), goal):
    assert abs(got - want) * 60 <= 0.5e-4 + 1e-9, (wp[-2:], goal)  # rounded to 1e-4 minutes
if land:  # no waypoint on the land block, and the path goes round it
    l0, l1, b0, b1 = map(float, land.split(","))
    east = lambda a, b: (b - a) % 360
    on = lambda lon, lat: b0 <= lat <= b1 and east(l0, lon) <= east(l0, l1)
    pts = [(float(r["lon"]), float(r["lat"])) for r in rows]
    assert not any(on(*p) for p in pts), pts
    assert max(p[1] for p in pts) > b1 or min(p[1] for p in pts) < b0, pts
print("%s: %d waypoints, travel time %.0f s, path %.1f km, geometry %s" % (
    os.path.basename(d), len(rows), s["travel_time"], s["path_length"] / 1e3, geometry["type"]))
PY
}

same() {  # same NAME_A NAME_B: the same route, to the digits written
  if ! cmp "$dir/$1/path.csv" "$dir/$2/path.csv"; then
    echo "$1 and $2 differ"
    diff "$dir/$1/path.csv" "$dir/$2/path.csv" | head
    exit 1
  fi
  cmp "$dir/$1/goto_l10.ma" "$dir/$2/goto_l10.ma"
}

goal_line() {  # goal_line NAME "LON LAT": the goto list's last waypoint, as written
  local last
  last="$(grep -B1 '^<end:waypoints>' "$dir/$1/goto_l10.ma" | head -1)"
  [ "$last" = "$2" ] || { echo "goto list of $1 ends with '$last', expected '$2'"; cat "$dir/$1/goto_l10.ma"; exit 1; }
}

case "$scenario" in
dateline)
  plan west g180.nc --start 175,30 --goal=-175,30.5
  plan east g180.nc --start 175,30 --goal 185,30.5
  check west 178.5,-178.5,28.5,32 yes
  same west east
  goal_line west "-17500.0000 3030.0000"  # 175W 30.5N
  ;;
greenwich)
  plan west g360.nc --start=-5,50 --goal 5,50.5
  plan east g360.nc --start 355,50 --goal 5,50.5
  check west "" no
  same west east
  goal_line west "500.0000 5030.0000"  # 5E 50.5N
  ;;
seam)
  plan east extract.nc --start 355,36 --goal 5,39
  plan west extract.nc --start=-5,36 --goal 5,39
  check east 359,1,36.5,38.5 no
  same east west
  plan region extract.nc --start 355,36 --goal 5,39 --region 350,33,10,42
  check region 359,1,36.5,38.5 no
  refused "outside --region" --currents "$data/extract.nc" --start 355,36 --goal 5,39 --region 356,33,10,42
  ;;
duplicate)
  plan dup dup.nc --start 175,30 --goal=-175,30.5
  check dup "" yes
  ;;
wide)
  plan wide g360.nc --start 325,-40 --goal 35,-40
  check wide "" no
  python3 - "$dir/wide/summary.json" <<'PY'
import json, math, sys
s = json.load(open(sys.argv[1]))
# the great circle from 35W to 35E at 40S is 5796.5 km (sphere); the planar path is no shorter than 99 % of it
# and, in a current of at most 0.16 m/s against 0.3 m/s, no longer than 110 %
a, b = math.radians(40), math.radians(70)
gc = 6371.0088 * math.acos(math.sin(a) ** 2 + math.cos(a) ** 2 * math.cos(b))
assert 0.99 * gc <= s["path_length"] / 1e3 <= 1.10 * gc, (s["path_length"], gc)
print("wide: path %.1f km against a great circle of %.1f km" % (s["path_length"] / 1e3, gc))
PY
  ;;
polar)
  plan polar g360.nc --start=-35,80 --goal 35,80
  check polar "" no
  refused "pole" --currents "$data/g360.nc" --start 0,89.95 --goal 10,85
  ;;
region)
  plan bbox g180.nc --start 175,33 --goal=-175,33.5 --region 170,25,-170,40
  plan unwrapped g180.nc --start 175,33 --goal=-175,33.5 --region=170,25,190,40
  check bbox "" yes
  same bbox unwrapped
  g="$data/g180.nc"
  refused "--region" --currents "$g" --start 175,33 --goal=-175,33.5 --region 170,25,-170,95
  refused "lat_max" --currents "$g" --start 175,33 --goal=-175,33.5 --region 170,40,-170,25
  refused "less than 360" --currents "$g" --start 175,33 --goal=-175,33.5 --region=-180,25,180,40
  refused "no width" --currents "$g" --start 175,33 --goal=-175,33.5 --region 170,25,170,40
  refused "-180..180 or 0..360" --currents "$g" --start 175,33 --goal=-175,33.5 --region 170,25,400,40
  refused "four numbers" --currents "$g" --start 175,33 --goal=-175,33.5 --region 170,25,-170
  refused "finite number" --currents "$g" --start 175,33 --goal=-175,33.5 --region 170,25,-170,north
  refused "outside --region" --currents "$g" --start 175,33 --goal=-175,33.5 --region=-60,30,-40,45
  ;;
*)
  echo "unknown scenario $scenario"
  exit 2
  ;;
esac
echo "geography $scenario OK"
