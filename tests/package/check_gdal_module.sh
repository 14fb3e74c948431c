#!/usr/bin/env bash
# The library's GDAL part is a module loaded when first needed (src/io/GdalModule.h): glider_plan on an analytic
# problem does not load GDAL; a mission with a polygon (GEOS's check through GDAL) loads the module and GDAL and
# plans; and a library whose module is missing says which file it looked for, with exit status 2, instead of
# planning without the check. Usage: check_gdal_module.sh GLIDER_PLAN LIBRARY_DIR
set -euo pipefail
plan=$1; libdir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/island.yaml" <<'YAML'
name: island
current: {type: uniform, parameters: {u: 0.1, v: 0.0}}
region: {x_min: 0, x_max: 10, y_min: -5, y_max: 5}
start: {x: 1, y: 0}
goal: {x: 9, y: 0}
vehicle: {speed: 1.0}
forbidden:
  obstacles:
    - name: Rock
      kind: island
      points: [[4, -1], [6, -1], [6, 1], [4, 1]]
YAML
loaded() { grep -c 'file=libgdal\.so' "$1" || true; }

LD_DEBUG=files "$plan" --speed 0.5 --planner ZAStarTVE --out "$work/analytic" > "$work/analytic.txt" 2> "$work/analytic.ld"
grep -q '^Travel time: *11\.39' "$work/analytic.txt" || { cat "$work/analytic.txt"; exit 1; }
[ "$(loaded "$work/analytic.ld")" = 0 ] || { echo "an analytic plan loaded GDAL"; exit 1; }
grep -q 'libompl_glider_gdal' "$work/analytic.ld" && { echo "an analytic plan loaded the GDAL module"; exit 1; }

LD_DEBUG=files "$plan" --mission "$work/island.yaml" --out "$work/island" > "$work/island.txt" 2> "$work/island.ld"
[ "$(loaded "$work/island.ld")" -gt 0 ] || { echo "the polygon's check did not load GDAL"; exit 1; }
# the straight line crosses the rock: the route goes round it, longer than 8 / 1.1
python3 - "$work/island.txt" <<'PY'
import re, sys
t = float(re.search(r"^Travel time: *([0-9.]+)", open(sys.argv[1]).read(), re.M).group(1))
assert t > 8 / 1.1 + 0.05, t
print("round the rock in", t)
PY

# the library copied alone (LD_LIBRARY_PATH before the build's RUNPATH): the module it looks for is missing
mkdir "$work/lib"
cp -a "$libdir"/libompl_glider.so* "$work/lib/"
set +e
LD_LIBRARY_PATH="$work/lib" "$plan" --mission "$work/island.yaml" --out "$work/missing" > "$work/missing.txt" 2>&1
rc=$?
set -e
[ "$rc" = 2 ] || { echo "without the module: exit $rc"; cat "$work/missing.txt"; exit 1; }
grep -q "$work/lib/libompl_glider_gdal.so' (Zarr stores, GRIB2 files, coastline files, polygon checks, ERDDAP) cannot be loaded" \
  "$work/missing.txt" || { cat "$work/missing.txt"; exit 1; }
[ ! -e "$work/missing" ] || { echo "a failed run left its output folder"; exit 1; }
echo "package.gdal_module_on_demand: ok"
