#!/usr/bin/env bash
# The Debian package: cpack -G DEB in the build directory makes ompl-glider_<version>_<arch>.deb holding the library,
# the headers, the CMake package files, glider_plan and (when built) the Python module, with its Depends.
# apt resolves it (apt-get install --simulate). Only as root in a throwaway environment (CI=true) it is installed
# with apt, glider_plan and `python3 -c "import ompl_glider"` run from the system, and it is removed again.
# Usage: check_deb.sh BUILD_DIR [PYTHON]   (PYTHON: the interpreter the module was built for, default /usr/bin/python3)
set -euo pipefail
build="$1"
py="${2:-/usr/bin/python3}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
(cd "$build" && cpack -G DEB -B "$out" > "$out/cpack.log" 2>&1) || { cat "$out/cpack.log"; exit 1; }
deb=$(ls "$out"/ompl-glider_*.deb)
echo "built $(basename "$deb")"
dpkg-deb -c "$deb" > "$out/contents.txt"
for f in ./usr/bin/glider_plan 'libompl_glider.so.0' 'libompl_glider_gdal.so' ./usr/include/ompl_glider/mission/Planning.h \
         ompl_gliderConfig.cmake; do
  grep -q -- "$f" "$out/contents.txt" || { echo "the package lacks $f"; exit 1; }
done
python=$(grep -c 'dist-packages/ompl_glider/_core' "$out/contents.txt" || true)
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
case "$depends" in *libompl*) ;; *) echo "Depends lacks OMPL's library"; exit 1 ;; esac
if [ "$python" -gt 0 ]; then
  grep -q 'dist-packages/ompl_glider/__init__.py' "$out/contents.txt" || { echo "the package lacks __init__.py"; exit 1; }
  case "$depends" in *python3-numpy*) ;; *) echo "Depends lacks python3-numpy"; exit 1 ;; esac
fi
# the files run from the unpacked package (the library found through glider_plan's relative RPATH)
dpkg-deb -x "$deb" "$out/root"
"$out/root/usr/bin/glider_plan" > "$out/plan.txt"
grep -q '^Travel time: *11\.39' "$out/plan.txt" || { cat "$out/plan.txt"; exit 1; }
if [ "$python" -gt 0 ]; then
  PYTHONPATH=$(dirname "$(find "$out/root" -path '*dist-packages/ompl_glider' -type d)") \
    "$py" -c "import ompl_glider; r = ompl_glider.plan(); assert abs(r.travel_time - 11.3988) < 1e-3, r.travel_time"
fi
if command -v apt-get > /dev/null; then
  apt-get install --simulate -q "$deb" > "$out/apt.txt" 2>&1 || { cat "$out/apt.txt"; exit 1; }
fi
if [ "$(id -u)" = 0 ] && [ "${CI:-}" = true ]; then
  apt-get install -y -q "$deb"
  (cd / && glider_plan > "$out/installed.txt")
  grep -q '^Travel time: *11\.39' "$out/installed.txt" || { cat "$out/installed.txt"; exit 1; }
  if [ "$python" -gt 0 ]; then
    (cd / && env -u PYTHONPATH /usr/bin/python3 -c "import ompl_glider; print(ompl_glider.__file__, ompl_glider.plan().travel_time)")
  fi
  apt-get remove -y -q ompl-glider
  echo "installed with apt, ran glider_plan and import ompl_glider, removed"
else
  echo "not installed (only as root with CI=true)"
fi
echo "package.deb: ok"
