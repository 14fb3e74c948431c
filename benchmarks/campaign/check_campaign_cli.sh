#!/usr/bin/env bash
# glider_campaign from the command line: a small campaign writes an OMPL benchmark log that OMPL's own statistics
# script turns into a database with one row per run; a misspelt problem and an output directory that cannot be made
# are refused with exit 2 and a message, before any run.
# Usage: check_campaign_cli.sh GLIDER_CAMPAIGN [OMPL_BENCHMARK_STATISTICS]
set -euo pipefail
campaign=$1; stats=${2:-}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
args=(--no-reference --problems open_water --planners "ZA*TVE,A*TVE" --runs 2 --time 20 --control none)

# a fresh output directory (two levels) is made, and the log holds both planners' runs
"$campaign" "${args[@]}" "$work/out/new" > "$work/run.txt" 2>&1 || { cat "$work/run.txt"; fail "the campaign failed"; }
[ -s "$work/out/new/open_water.log" ] || fail "no open_water.log"
grep -q '^2 planners' "$work/out/new/open_water.log" || fail "the log does not list 2 planners"
if [ -n "$stats" ] && [ -x "$stats" ]; then
  (cd "$work" && "$stats" "$work/out/new/open_water.log" -d "$work/c.db" > "$work/stats.txt" 2>&1) ||
    { cat "$work/stats.txt"; fail "ompl_benchmark_statistics cannot read the log"; }
  runs=$(python3 -c "import sqlite3,sys; print(sqlite3.connect(sys.argv[1]).execute('select count(*) from runs').fetchone()[0])" "$work/c.db")
  [ "$runs" = 4 ] || fail "the database holds $runs runs, not 2 runs x 2 planners"
fi

# refusals: exit 2, the reason named, nothing written
set +e
"$campaign" "${args[@]}" --problems open_watr "$work/bad1" > "$work/bad1.txt" 2>&1; rc=$?
set -e
[ "$rc" = 2 ] || fail "a misspelt problem gave exit $rc"
grep -q "unknown problem 'open_watr'" "$work/bad1.txt" || { cat "$work/bad1.txt"; fail "no message naming the problem"; }
[ ! -e "$work/bad1" ] || fail "a refused campaign made its output directory"
touch "$work/file"
set +e
"$campaign" "${args[@]}" "$work/file/out" > "$work/bad2.txt" 2>&1; rc=$?
set -e
[ "$rc" = 2 ] || fail "an output directory under a file gave exit $rc"
grep -q "cannot make the output directory '$work/file/out'" "$work/bad2.txt" || { cat "$work/bad2.txt"; fail "no message naming the directory"; }
echo "campaign cli: ok"
