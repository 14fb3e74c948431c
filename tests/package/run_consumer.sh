#!/usr/bin/env bash
# Installs a build of the project into a scratch prefix, checks that the exported targets name no path of the
# build machine's source or build tree, then configures, builds and runs the consumer against it.
# Usage: run_consumer.sh BUILD_DIR CONSUMER_SRC WORK_DIR [PROJECT_SRC]
#   With PROJECT_SRC, BUILD_DIR is first configured and built from it as a STATIC library with the NetCDF and map
#   components switched off (the other ways a library user builds it).
set -euo pipefail
build_dir=$1; src_dir=$2; work=$3; project_src=${4:-}
rm -rf "$work"; mkdir -p "$work"
if [ -n "$project_src" ]; then
  cmake -S "$project_src" -B "$build_dir" -DCMAKE_BUILD_TYPE=None -DBUILD_SHARED_LIBS=OFF \
    -DOMPL_GLIDER_WITH_NETCDF=OFF -DOMPL_GLIDER_WITH_MAP=OFF -DOMPL_GLIDER_BUILD_TESTS=OFF \
    -DOMPL_GLIDER_BUILD_BENCHMARKS=OFF -DOMPL_GLIDER_BUILD_APPS=OFF >/dev/null
  cmake --build "$build_dir" -j"$(nproc)" >/dev/null
fi
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
targets=$(find "$work/prefix" -name 'ompl_gliderTargets*.cmake')
root=$(cd "$(dirname "$0")/../.." && pwd)
if grep -l -e "$root" -e "$build_dir" $targets; then
  echo "the exported targets name paths of this machine's source or build tree"; exit 1
fi
# Only the public API is installed: no header of src/, and the internals only under detail/ folders.
for internal in $(cd "$root/src" && find . -name '*.h' | sed 's|^\./||'); do
  if [ -e "$work/prefix/include/ompl_glider/$internal" ]; then
    echo "internal header src/$internal was installed"; exit 1
  fi
done
# Headers per component: a build without NetCDF and maps installs none of their headers (their functions are not in
# the library); the full build installs them.
for h in current/GriddedCurrents.h io/GriddedBathymetry.h io/DepthGrid.h io/GliderObservations.h mission/ForecastMission.h \
         output/MapRenderer.h output/MissionMap.h output/MapHtml.h; do
  if [ -n "$project_src" ] && [ -e "$work/prefix/include/ompl_glider/$h" ]; then
    echo "the build without NetCDF and maps installed $h"; exit 1
  elif [ -z "$project_src" ] && [ ! -e "$work/prefix/include/ompl_glider/$h" ]; then
    echo "the full build did not install $h"; exit 1
  fi
done
# The installed glider_plan runs from its prefix, and from the prefix moved elsewhere, with no library path set:
# its RPATH ($ORIGIN/../lib) finds libompl_glider.
if [ -x "$work/prefix/bin/glider_plan" ]; then
  mv "$work/prefix" "$work/moved_prefix"
  out=$(env -u LD_LIBRARY_PATH "$work/moved_prefix/bin/glider_plan" --speed 0.5 --planner ZAStarTVE \
        --out "$work/route" 2>&1) || { echo "installed glider_plan failed: $out"; exit 1; }
  grep -q "Travel time" <<<"$out" || { echo "installed glider_plan printed no travel time: $out"; exit 1; }
  [ -s "$work/route/summary.json" ] || { echo "installed glider_plan wrote no summary.json"; exit 1; }
  # a polygon's check loads the library's GDAL module (src/io/GdalModule.h), found beside the moved library
  printf '%s\n' 'name: island' 'current: {type: uniform, parameters: {u: 0.1, v: 0.0}}' \
    'region: {x_min: 0, x_max: 10, y_min: -5, y_max: 5}' 'start: {x: 1, y: 0}' 'goal: {x: 9, y: 0}' \
    'vehicle: {speed: 1.0}' 'forbidden:' '  obstacles:' '    - {name: Rock, points: [[4, -1], [6, -1], [6, 1], [4, 1]]}' \
    > "$work/island.yaml"
  out=$(env -u LD_LIBRARY_PATH "$work/moved_prefix/bin/glider_plan" --mission "$work/island.yaml" \
        --out "$work/island" 2>&1) || { echo "installed glider_plan failed on a polygon: $out"; exit 1; }
  grep -q "Travel time" <<<"$out" || { echo "installed glider_plan printed no travel time: $out"; exit 1; }
  echo "installed glider_plan ran from $work/moved_prefix (a polygon checked through the GDAL module)"
  mv "$work/moved_prefix" "$work/prefix"
fi
cmake -S "$src_dir" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release
cmake --build "$work/build" >/dev/null
env -u LD_LIBRARY_PATH "$work/build/consumer"
