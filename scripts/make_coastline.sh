#!/usr/bin/env bash
# Writes the land polygons of a region as GeoJSON from GSHHG (the Global Self-consistent, Hierarchical,
# High-resolution Geography database, LGPL) through GMT's `coast`, both from Debian (gmt, gmt-gshhg-low or
# gmt-gshhg-full). Use the result with `glider_plan --coastline FILE` or `forbidden.coastline` in a mission.
#
# Usage: scripts/make_coastline.sh LON_MIN/LON_MAX/LAT_MIN/LAT_MAX OUT.geojson [RESOLUTION]
#   RESOLUTION: c (crude), l (low, default), i, h, f (intermediate, high, full: need gmt-gshhg-full)
#
# GMT dumps shorelines as lines; this keeps those that close on themselves (islands, and coasts wholly inside the
# region), which become polygons. A shoreline cut by the region's edge is left out and named on stderr: widen the
# region until none is, or take land polygons from another source (Natural Earth's land shapefile, a chart's land
# area), which --coastline reads as well (GeoJSON, Shapefile, KML, GeoPackage through GDAL/OGR).
# examples/jamaica_coast.geojson was made with: scripts/make_coastline.sh -79/-75.5/17/19 examples/jamaica_coast.geojson
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: scripts/make_coastline.sh LON_MIN/LON_MAX/LAT_MIN/LAT_MAX OUT.geojson [c|l|i|h|f]" >&2
  exit 2
fi
region=$1 out=$2 res=${3:-l}
command -v gmt >/dev/null || { echo "make_coastline: needs gmt and gmt-gshhg-low (apt-get install gmt gmt-gshhg-low)" >&2; exit 2; }
# (GMT writes gmt.history into the working directory: run it in a temporary one)
(cd "$(mktemp -d)" && gmt coast -R"$region" -D"$res" -M -W -A0/1/1) | python3 -c '
import json, sys
segments, cur = [], None
for line in sys.stdin:
    line = line.strip()
    if line.startswith(">"):
        cur = []
        segments.append(cur)
    elif line and cur is not None:
        x, y = map(float, line.split()[:2])
        cur.append([round(x, 6), round(y, 6)])
features, open_ = [], 0
for s in segments:
    if len(s) >= 4 and s[0] == s[-1]:
        features.append({"type": "Feature", "properties": {"kind": "land", "source": "GSHHG via GMT coast"},
                         "geometry": {"type": "Polygon", "coordinates": [s]}})
    elif len(s) >= 2:
        open_ += 1
        print("make_coastline: a shoreline from %s to %s is cut by the region: left out" % (s[0], s[-1]),
              file=sys.stderr)
json.dump({"type": "FeatureCollection", "features": features}, sys.stdout)
sys.stdout.write("\n")
print("make_coastline: %d polygons, %d cut shorelines left out" % (len(features), open_), file=sys.stderr)
' > "$out"
