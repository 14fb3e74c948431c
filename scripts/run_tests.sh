#!/usr/bin/env bash
# Installs what is missing, builds (Release, with tests) and runs the test suite with ctest.
# Usage: scripts/run_tests.sh [--all] [CTEST_ARGS...]
#   Without --all the cases labelled "ci" (minutes each: a second, static build of the library) and the slow cases
#   listed in tests/ci_only.txt are left out; --all, or CI=true in the environment (.ci/run), runs every case.
#   Other arguments go to ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
select=(-LE ci -E "$(bash "$root/scripts/ci_only_regex.sh")")
if [ "${1:-}" = "--all" ]; then
  select=(); shift
elif [ "${CI:-}" = "true" ]; then
  select=()
fi
bash "$root/scripts/setup.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DOMPL_GLIDER_BUILD_TESTS=ON >/dev/null
cmake --build "$root/build" -j"$(nproc)"
cd "$root/build"
# a fresh build has no test times: seed ctest's cost data with the measured ones (tests/ctest_costs.txt: name, runs,
# seconds), so that -j starts the longest cases first instead of leaving one of them to run alone at the end
mkdir -p Testing/Temporary
[ -s Testing/Temporary/CTestCostData.txt ] || cp "$root/tests/ctest_costs.txt" Testing/Temporary/CTestCostData.txt
ctest --output-on-failure -j"$(nproc)" ${select[@]+"${select[@]}"} "$@"
