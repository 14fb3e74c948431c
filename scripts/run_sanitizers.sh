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
# The package tests build and install a second copy of the library with the system compiler flags: they run in the
# ordinary build (scripts/run_tests.sh), not here.
# StrongCurrentsFine: the slow references (a level set at a fine resolution, 5 min sanitized) that the ordinary run
# already covers; the same code runs sanitized in the faster StrongCurrents cases
# mission.bundled_files_land, current.glider_plan_pop_land: glider_plan on real model files, minutes each sanitized;
# the same reading and planning code runs sanitized in the NetCDF and forecast suites (the ordinary run has them)
# TrustProperty: more than a hundred random plans against the extremal sweep (the ordinary run has it; TrustFast,
# the same code on a dozen pairs, runs here)
# demo.benchmark_ice: OMPL's Benchmark gives every planner a fixed time, which ZA*TVE does not meet sanitized; the
# other demos run here, the benchmark in the ordinary run
# badinput.resource_limits: ulimit -v and -t on glider_plan; AddressSanitizer reserves terabytes of address space for
# its shadow memory and runs several times slower, so the limits mean something else here (the ordinary run has it)
ctest --output-on-failure -j"$(nproc)" -E '^(package|StrongCurrentsFine|TrustProperty)\.|^demo\.benchmark_ice$|^badinput\.resource_limits$|^mission\.bundled_files_land$|^current\.glider_plan_pop_land$' "$@"
