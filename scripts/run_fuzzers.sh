#!/usr/bin/env bash
# Runs the libFuzzer targets of fuzz/ (fuzz_mission, fuzz_netcdf, fuzz_cli) on the clang-14 sanitizer build
# (build-fuzz, scripts/build_sanitized.sh), all at once, each for SECONDS from a fresh copy of its seed
# corpus (build-fuzz/corpus/<target>; fuzz/corpus/<target>, plus the NetCDF seeds made from fuzz/corpus/netcdf/*.cdl
# and examples/labrador_forecast.nc). A crash, a sanitizer report, a leak, an input slower than 10 s or one using
# more than 2 GB is a finding: its reproducer goes to build-fuzz/findings/<target>/ and the script exits with
# status 1 after running every target. Logs: build-fuzz/findings/<target>.log.
# Reproduce a finding: build-fuzz/fuzz/<target> build-fuzz/findings/<target>/crash-...
# Usage: scripts/run_fuzzers.sh SECONDS [TARGET...]   (TARGET: mission, netcdf, cli or fuzz_<name>; default all)
# FUZZ_UNIT_TIMEOUT (seconds, default 10) sets how slow an input may be: raise it when the machine is shared, so
# that a starved process is not reported as a hang.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ $# -lt 1 ] || ! [[ "$1" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: scripts/run_fuzzers.sh SECONDS [TARGET...]   (TARGET: mission, netcdf, cli)" >&2
  exit 2
fi
seconds="$1"
unit_timeout="${FUZZ_UNIT_TIMEOUT:-10}"
[[ "$unit_timeout" =~ ^[1-9][0-9]*$ ]] || { echo "run_fuzzers: FUZZ_UNIT_TIMEOUT must be a whole number of seconds" >&2; exit 2; }
shift
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(mission netcdf cli)
for i in "${!targets[@]}"; do
  targets[$i]="${targets[$i]#fuzz_}"
  case "${targets[$i]}" in
    mission | netcdf | cli) ;;
    *) echo "run_fuzzers: unknown target '${targets[$i]}' (mission, netcdf, cli)" >&2; exit 2 ;;
  esac
done
mapfile -t targets < <(printf '%s\n' "${targets[@]}" | awk '!seen[$0]++')  # each target once

bash "$root/scripts/build_sanitized.sh"
build="$root/build-fuzz"
# Leaks are findings too; libFuzzer stops at the first report and writes the input. A single malloc() of 2 GB or more
# fails (returns null) as it would under a memory limit, and the code must cope: NetCDF-C asks for what a corrupt
# header announces (6.4 GB for a 640-byte classic file) without touching it. A C++ new that large is still a finding,
# as is any input whose resident memory passes 2 GB.
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:allocator_may_return_null=1:max_allocation_size_mb=2047"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0"

status=0
summary=()
# the targets run at once (each is one process on one core): SECONDS of wall time each, the machine's cores shared
declare -A pid
for t in "${targets[@]}"; do
  corpus="$build/corpus/$t"
  findings="$build/findings/$t"
  log="$build/findings/$t.log"
  rm -rf "$corpus"
  mkdir -p "$corpus" "$findings"
  cp "$root/fuzz/corpus/$t/"* "$corpus/" 2>/dev/null || true
  rm -f "$corpus"/*.cdl "$corpus"/README*
  if [ "$t" = netcdf ]; then
    cp "$build/fuzz/corpus/netcdf/"*.nc "$corpus/"
  fi
  dict=()
  [ -f "$root/fuzz/$t.dict" ] && dict=(-dict="$root/fuzz/$t.dict")
  echo "run_fuzzers: fuzz_$t for ${seconds}s ($(ls "$corpus" | wc -l) seeds)"
  "$build/fuzz/fuzz_$t" "$corpus" -max_total_time="$seconds" -timeout="$unit_timeout" -rss_limit_mb=2048 -malloc_limit_mb=2048 \
    "${dict[@]}" -artifact_prefix="$findings/" -print_final_stats=1 > "$log" 2>&1 &
  pid[$t]=$!
done
for t in "${targets[@]}"; do
  corpus="$build/corpus/$t"
  findings="$build/findings/$t"
  log="$build/findings/$t.log"
  set +e
  wait "${pid[$t]}"
  rc=$?
  set -e
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  cov=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -n 1)
  line=$(printf 'fuzz_%-8s %10s executions  %-22s corpus %s' "$t" "${execs:-?}" "${cov:-cov: ?}" \
    "$(ls "$corpus" | wc -l)")
  if [ "$rc" -ne 0 ]; then
    status=1
    line="$line  FINDING (exit $rc): $(grep -m1 -E 'ERROR: |runtime error|==ERROR|Test unit written' "$log" || true)"
    echo "run_fuzzers: fuzz_$t found something; log $log, reproducer in $findings/:" >&2
    grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error|artifact_prefix|Test unit written)' "$log" | head -n 8 >&2 || true
  fi
  summary+=("$line")
done
echo "run_fuzzers: ${seconds}s per target, the targets at once"
printf '%s\n' "${summary[@]}"
exit "$status"
