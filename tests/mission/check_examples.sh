#!/usr/bin/env bash
# Every example mission (examples/*.yaml) planned by glider_plan as a user runs it: each must exit 0 with a solved
# plan and its outputs written; a failure names the example, its exit status and the end of what it printed. The
# executions' batches of random pairs are left out (--execution-pairs 0: the mission's own plan is still flown by
# every strategy listed); docs/EXECUTION.md's tables give the batches' figures with their commands.
# Usage: check_examples.sh GLIDER_PLAN SOURCE_DIR
set -u
G=$(readlink -f "$1")
root=$(readlink -f "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
count=0
# the forecast runs of examples/jet_runs_execution.yaml are generated, not kept in git (scripts/make_forecast_runs.py)
[ -d "$root/examples/jet_runs" ] || python3 "$root/scripts/make_forecast_runs.py" --out "$root/examples/jet_runs" >/dev/null
for f in "$root"/examples/*.yaml; do
  name=$(basename "$f" .yaml)
  extra=()
  grep -q '^execution:' "$f" && extra=(--execution-pairs 0)
  start=$(date +%s.%N)
  (cd "$work" && timeout 900 "$G" --mission "$f" --out "$work/$name" "${extra[@]}" >"$work/$name.log" 2>&1)
  rc=$?
  seconds=$(echo "$(date +%s.%N) - $start" | bc)
  count=$((count + 1))
  if [ $rc -ne 0 ]; then
    echo "FAIL $name: exit $rc after ${seconds} s"
    tail -15 "$work/$name.log"
    fail=1
  elif ! python3 -c '
import json, sys
s = json.load(open(sys.argv[1]))
# a plan: its own "solved"; a fleet: every glider solved
sys.exit(0 if s.get("solved") is True or (s.get("gliders") and s.get("gliders_with_route") == s.get("gliders")) else 1)
' "$work/$name/summary.json" 2>/dev/null; then
    echo "FAIL $name: exit 0 but summary.json does not say solved (for every glider of a fleet)"
    fail=1
  else
    printf 'ok   %-28s %6.1f s  %s\n' "$name" "$seconds" "$(grep -m1 '^Status:' "$work/$name.log" | sed 's/  */ /g')"
  fi
done
[ $count -gt 0 ] || { echo "FAIL no example mission found under $root/examples"; exit 1; }
exit $fail
