#!/usr/bin/env bash
# Writes the land polygons of a region as GeoJSON from GSHHG (the Global Self-consistent, Hierarchical,
# High-resolution Geography database, LGPL) through GMT's `coast`, both from Debian. Use the result with
# `glider_plan --coastline FILE` or `forbidden.coastline` in a mission.
#
# Usage: scripts/make_coastline.sh LON_MIN/LON_MAX/LAT_MIN/LAT_MAX OUT.geojson [RESOLUTION]
#   RESOLUTION: c (crude), l (low, default), i (intermediate): Debian's gmt-gshhg-low;
#               h (high): gmt-gshhg-high; f (full): gmt-gshhg-full  (files /usr/share/gmt-gshhg/binned_GSHHS_R.nc)
#
# GMT dumps the shorelines (level 1: land/ocean) as lines. scripts/close_shorelines.py keeps those that close on
# themselves (islands), clips the others to the region and closes them along its edges, so that a coast cut by the
# region (Florida and Cuba on a Florida Straits map) stays land. Which side is land is settled by asking GMT
# whether the region's south-west corner is on land (`gmt select -N`).
# GMT cuts shorelines at the edges of GSHHG's bins, runs some along the region's edge and writes lon -179 for 181:
# close_shorelines.py joins the pieces, cuts out those stretches and unwraps longitudes (boxes across 180 work).
# examples/jamaica_coast.geojson was made with: scripts/make_coastline.sh -79/-75.5/17/19 examples/jamaica_coast.geojson
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: scripts/make_coastline.sh LON_MIN/LON_MAX/LAT_MIN/LAT_MAX OUT.geojson [c|l|i|h|f]" >&2
  exit 2
fi
region=$1 out=$2 res=${3:-l}
case "$res" in
  c|l|i) package=gmt-gshhg-low ;;
  h) package=gmt-gshhg-high ;;
  f) package=gmt-gshhg-full ;;
  *) echo "make_coastline: resolution '$res': expected c, l, i, h or f" >&2; exit 2 ;;
esac
command -v gmt >/dev/null || { echo "make_coastline: needs gmt and $package (apt-get install gmt $package)" >&2; exit 2; }
installed=$(ls /usr/share/gmt-gshhg/binned_GSHHS_?.nc 2>/dev/null | sed 's/.*_\(.\)\.nc/\1/' | tr -d '\n')
if [ -d /usr/share/gmt-gshhg ] && [ ! -e "/usr/share/gmt-gshhg/binned_GSHHS_$res.nc" ]; then
  echo "make_coastline: resolution '$res' is not installed (installed: ${installed:-none}): apt-get install $package" >&2
  exit 2
fi
IFS=/ read -r lon0 lon1 lat0 lat1 <<< "$region"
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# (GMT writes gmt.history into the working directory: run it in the temporary one)
(cd "$tmp" && gmt coast -R"$region" -D"$res" -M -W -A0/1/1) > "$tmp/shore.txt"
# the south-west corner on land? (-N wet/dry: s skips water, k keeps land)
corner=$(cd "$tmp" && echo "$lon0 $lat0" | gmt select -R"$region" -D"$res" -A0/1/1 -Ns/k || true)
if [ -n "$corner" ]; then corner_land=yes; else corner_land=no; fi
python3 "$here/close_shorelines.py" --corner-land "$corner_land" -- "$lon0/$lon1/$lat0/$lat1" < "$tmp/shore.txt" > "$out"
