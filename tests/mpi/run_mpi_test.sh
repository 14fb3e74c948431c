#!/usr/bin/env bash
# One MPI test of ctest (tests/mpi/tests.cmake): the same work in one process and under mpirun -np NP, compared
# (compare_runs.py), or a job whose task fails or overruns, which must exit non-zero naming the rank and the task
# and leave nothing written.
#   run_mpi_test.sh MODE NP MPIEXEC GLIDER_PLAN GLIDER_CAMPAIGN
# MODE: campaign | ensemble | execution | fleet | sweep_departure | fail_plan | fail_fleet | fail_outside |
#       fail_campaign | time_limit
set -uo pipefail
MODE=$1 NP=$2 MPIEXEC=$3 PLAN=$4 CAMPAIGN=$5
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
# OpenMPI refuses root without these (CI runs as root); several ranks on few cores need --oversubscribe
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
MPIRUN=("$MPIEXEC" --oversubscribe -np "$NP")
CAMPAIGN_ARGS=(--no-reference --problems open_water --planners "ZA*TVE,A*TVE" --runs 2 --time 20)  # ample: a run cut by its limit on a loaded machine does less work
fail() { echo "FAIL: $*"; exit 1; }

# a failing job: non-zero exit, the rank and the task in the message, no output left
expect_failure() {  # expect_failure PATTERN OUTDIR command...
  local pattern=$1 out=$2
  shift 2
  "$@" >"$WORK/stdout" 2>"$WORK/stderr" && fail "the job exited 0"
  grep -q "$pattern" "$WORK/stderr" || { cat "$WORK/stderr"; fail "no '$pattern' in the message"; }
  if [ -e "$out" ] && [ -n "$(ls -A "$out")" ]; then ls -la "$out"; fail "output left in $out"; fi
  ls "$(dirname "$out")" | grep -q "staging\|\.part" && fail "temporary files left beside $out"
  echo "ok: $(grep -m1 "$pattern" "$WORK/stderr")"
}

case "$MODE" in
  campaign)
    mkdir -p "$WORK/one" "$WORK/mpi"
    "$CAMPAIGN" "${CAMPAIGN_ARGS[@]}" "$WORK/one" >/dev/null || fail "one process"
    "${MPIRUN[@]}" "$CAMPAIGN" "${CAMPAIGN_ARGS[@]}" "$WORK/mpi" >/dev/null 2>"$WORK/stderr" || { cat "$WORK/stderr"; fail "mpirun"; }
    python3 "$HERE/compare_runs.py" campaign "$WORK/one" "$WORK/mpi" || fail "the logs differ"
    ;;
  ensemble|execution)
    "$PLAN" --mission "$HERE/$MODE.yaml" --out "$WORK/one" >/dev/null 2>&1 || fail "one process"
    "${MPIRUN[@]}" "$PLAN" --mission "$HERE/$MODE.yaml" --out "$WORK/mpi" >"$WORK/stdout" 2>"$WORK/stderr" ||
      { cat "$WORK/stderr"; fail "mpirun"; }
    [ "$(grep -c "^wrote" "$WORK/stdout")" = "$(ls "$WORK/one" | wc -l)" ] || fail "not one set of files written by rank 0"
    python3 "$HERE/compare_runs.py" plan "$WORK/one" "$WORK/mpi" || fail "the outputs differ"
    ;;
  fleet|sweep_departure)
    "$PLAN" --mission "$HERE/$MODE.yaml" --out "$WORK/one" >/dev/null 2>&1 || fail "one process"
    "${MPIRUN[@]}" "$PLAN" --mission "$HERE/$MODE.yaml" --out "$WORK/mpi" >"$WORK/stdout" 2>"$WORK/stderr" ||
      { cat "$WORK/stderr"; fail "mpirun"; }
    [ "$(grep -c "^wrote" "$WORK/stdout")" = 1 ] || [ "$MODE" != fleet ] || fail "not one write by rank 0"
    [ "$MODE" != fleet ] || [ "$(ls -d "$WORK"/mpi/*/ | wc -l)" = 5 ] || fail "not a folder per glider"
    python3 "$HERE/compare_runs.py" plan "$WORK/one" "$WORK/mpi" || fail "the outputs differ"
    ;;
  fail_fleet)
    OMPL_GLIDER_FAIL_TASK="fleet glider:3" expect_failure "rank [0-9]*, fleet glider 3: failure injected" \
      "$WORK/fl" "${MPIRUN[@]}" "$PLAN" --mission "$HERE/fleet.yaml" --out "$WORK/fl"
    expect_failure "glider 'c': .*fleet_bad_start.yaml:14: field 'start'" \
      "$WORK/bad" "${MPIRUN[@]}" "$PLAN" --mission "$HERE/fleet_bad_start.yaml" --out "$WORK/bad"
    grep -q "rank [0-9]*, fleet glider" "$WORK/stderr" && fail "a bad input every rank meets is not a rank's failure"
    ;;
  fail_outside)
    # one rank cannot read its mission (a file on one node only): the job ends, naming the rank, instead of hanging
    expect_failure "rank [1-9][0-9]* failed outside the tasks: cannot read mission file" "$WORK/fl" \
      timeout 60 "$MPIEXEC" --oversubscribe -np 1 "$PLAN" --mission "$HERE/fleet.yaml" --out "$WORK/fl" \
      : -np $((NP - 1)) "$PLAN" --mission "$WORK/missing.yaml" --out "$WORK/fl"
    expect_failure "rank 0 failed outside the tasks: cannot read mission file" "$WORK/fl" \
      timeout 60 "$MPIEXEC" --oversubscribe -np 1 "$PLAN" --mission "$WORK/missing.yaml" --out "$WORK/fl" \
      : -np $((NP - 1)) "$PLAN" --mission "$HERE/fleet.yaml" --out "$WORK/fl"
    # the other ranks read another version of the mission (a node-local copy): the job stops before any plan,
    # naming them, instead of mixing their gliders into rank 0's table
    mkdir -p "$WORK/node0" "$WORK/node1"
    cp "$HERE/fleet.yaml" "$WORK/node0/fleet.yaml"
    sed 's/speed: 0.5/speed: 0.45/' "$HERE/fleet.yaml" >"$WORK/node1/fleet.yaml"
    cmp -s "$WORK/node0/fleet.yaml" "$WORK/node1/fleet.yaml" && fail "the copies do not differ"
    expect_failure "the job's ranks read different inputs: the mission (its file and the files it reads) of ranks\? 1" \
      "$WORK/fl" timeout 60 "$MPIEXEC" --oversubscribe -np 1 "$PLAN" --mission "$WORK/node0/fleet.yaml" --out "$WORK/fl" \
      : -np $((NP - 1)) "$PLAN" --mission "$WORK/node1/fleet.yaml" --out "$WORK/fl"
    # the same contents at other paths are the same mission
    sed 's/speed: 0.45/speed: 0.5/' "$WORK/node1/fleet.yaml" >"$WORK/node1/same.yaml"
    timeout 60 "$MPIEXEC" --oversubscribe -np 1 "$PLAN" --mission "$WORK/node0/fleet.yaml" --out "$WORK/same" \
      : -np $((NP - 1)) "$PLAN" --mission "$WORK/node1/same.yaml" --out "$WORK/same" >/dev/null 2>"$WORK/stderr" ||
      { cat "$WORK/stderr"; fail "copies of the same mission at other paths were refused"; }
    ;;
  fail_plan)
    OMPL_GLIDER_FAIL_TASK="ensemble candidate:3" expect_failure "rank [0-9]*, ensemble candidate 3: failure injected" \
      "$WORK/ens" "${MPIRUN[@]}" "$PLAN" --mission "$HERE/ensemble.yaml" --out "$WORK/ens"
    OMPL_GLIDER_FAIL_TASK="execution run:5" expect_failure "rank [0-9]*, execution run 5: failure injected" \
      "$WORK/exe" "${MPIRUN[@]}" "$PLAN" --mission "$HERE/execution.yaml" --out "$WORK/exe"
    ;;
  fail_campaign)
    mkdir -p "$WORK/out"
    OMPL_GLIDER_FAIL_TASK="benchmark run:2" expect_failure "rank [0-9]*, benchmark run 2: failure injected" \
      "$WORK/out" "${MPIRUN[@]}" "$CAMPAIGN" "${CAMPAIGN_ARGS[@]}" "$WORK/out"
    ;;
  time_limit)
    OMPL_GLIDER_TASK_TIME_LIMIT=0.01 expect_failure "rank [0-9]*, execution run [0-9]*: still running after 0.01 s" \
      "$WORK/exe" "${MPIRUN[@]}" "$PLAN" --mission "$HERE/execution.yaml" --out "$WORK/exe"
    ;;
  *) fail "unknown mode $MODE" ;;
esac
echo "ok: $MODE with $NP processes"
