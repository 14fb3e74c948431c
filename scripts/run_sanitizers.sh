#!/usr/bin/env bash
# Runs the test suite on the clang-14 AddressSanitizer + UndefinedBehaviorSanitizer build (build-fuzz, made by
# scripts/build_sanitized.sh and shared with the fuzzers); every report is an error. The only suppression is
# fontconfig's font cache, which cairo's text drawing keeps for the life of the process (tests/sanitizers/lsan.supp).
# Part of CI (.ci/run). Usage: scripts/run_sanitizers.sh [ctest arguments]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/build_sanitized.sh"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0"
cd "$root/build-fuzz"
mkdir -p Testing/Temporary  # the longest cases first (as scripts/run_tests.sh)
[ -s Testing/Temporary/CTestCostData.txt ] || cp "$root/tests/ctest_costs.txt" Testing/Temporary/CTestCostData.txt
# Left out here, run in CI's ordinary build (.ci/run: run_tests.sh --all):
# - the package tests (a second copy of the library built and installed with the system's flags) and the cases
#   labelled ci, StrongCurrentsFine and TrustProperty (minutes of planning each);
# - the slow cases listed in tests/ci_only.txt (2 s or more in the ordinary build, or 15 s or more here: planning
#   runs 10 to 60 times slower under ASan+UBSan at -O1); the same code runs here in the faster cases;
# - demo.benchmark_ice: OMPL's Benchmark gives every planner a fixed time, which ZA*TVE does not meet sanitized;
# - badinput.resource_limits: ulimit -v and -t on glider_plan; AddressSanitizer reserves terabytes of address space
#   for its shadow memory and runs several times slower, so the limits mean something else here;
# - mission.bundled_files_land, current.glider_plan_pop_land: glider_plan on real model files, minutes each.
sanitized_out='^package\.|^(demo\.benchmark_ice|badinput\.resource_limits|mission\.bundled_files_land|current\.glider_plan_pop_land)$'
# The OPeNDAP reader (time limits, retries, the cache) runs only against the tests' DAP2 server, a case of
# tests/ci_only.txt: it runs here too, so that the remote reader is checked under ASan+UBSan, beside the other cases
# (about 65 s sanitized alone, its plans without the global check: the reader is what it checks).
ctest --output-on-failure -j"$(nproc)" -LE ci -E "$(bash "$root/scripts/ci_only_regex.sh" '^opendap\.')|$sanitized_out" \
  "$@"
