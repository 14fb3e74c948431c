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
  cmake -S "$project_src" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=OFF \
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
cmake -S "$src_dir" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release
cmake --build "$work/build" >/dev/null
LD_LIBRARY_PATH="$work/prefix/lib:$work/prefix/lib/x86_64-linux-gnu:${LD_LIBRARY_PATH:-}" "$work/build/consumer"
