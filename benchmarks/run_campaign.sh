#!/usr/bin/env bash
# The OMPL Benchmark campaign in one command.
#
#   benchmarks/run_campaign.sh [--quick] OUTDIR
#
# Builds glider_campaign and glider_campaign_paths if needed (build dir: $GLIDER_BUILD_DIR, default
# <repo>/build-campaign, Release), runs the four meandering-jet problems with TVE, A*TVE, ZTVE, ZA*TVE, Wavefront, RRT*, PRM,
# PRM*, RRTConnect, RRT#, LBTRRT and SST on the identical SpaceInformation (--quick: 5 runs per planner, 2 s budget,
# about 7 minutes on 2 cores; default: 20 runs, 10 s), converts the logs with OMPL's ompl_benchmark_statistics
# into OUTDIR/campaign.db (load it in Planner Arena), and writes the plots OUTDIR/travel_time.png,
# solve_time.png, success_rate.png, maps.png and the Markdown table OUTDIR/table.md (also printed).
# Extra arguments after OUTDIR are passed to glider_campaign (e.g. --runs 3 --time 1 --problems islands).
# The strong-current set (the jet at V = 0.2 and 0.15, a double gyre six times V; ZA*TVE, LevelSet,
# Isochrone and OMPL's control planners oc::SST, oc::RRT, oc::KPIECE1), alone and quickly:
#   benchmarks/run_campaign.sh --quick OUTDIR --runs 3 --time 5 --problems strong
# (the maps of maps.png stay those of the four classic problems).
# GLIDER_MPIRUN="mpirun -np N" runs glider_campaign as an MPI job (a build with OMPL_GLIDER_WITH_MPI; docs/MPI.md).
set -euo pipefail

QUICK=0
OUT=""
EXTRA=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) QUICK=1 ;;
    -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
    *) if [ -z "$OUT" ]; then OUT="$1"; else EXTRA+=("$1"); fi ;;
  esac
  shift
done
[ -n "$OUT" ] || { echo "usage: $0 [--quick] OUTDIR [glider_campaign options]" >&2; exit 2; }

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${GLIDER_BUILD_DIR:-$ROOT/build-campaign}"
PY="${PYTHON:-/usr/bin/python3}"
STATS="${OMPL_BENCHMARK_STATISTICS:-$(command -v ompl_benchmark_statistics || echo /usr/bin/ompl_benchmark_statistics)}"
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"

if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DOMPL_GLIDER_BUILD_TESTS=OFF >/dev/null
fi
cmake --build "$BUILD" -j2 --target glider_campaign glider_campaign_paths >/dev/null

if [ "$QUICK" = 1 ]; then
  ARGS=(--quick --runs 5 --time 2)
  BUDGET=2
else
  ARGS=(--runs 20 --time 10)
  BUDGET=10
fi

start=$(date +%s)
rm -f "$OUT"/*.log "$OUT/campaign.db"
# GLIDER_MPIRUN="mpirun -np 8" (or "srun"): the runs spread over the ranks of an MPI job (docs/MPI.md)
${GLIDER_MPIRUN:-} "$BUILD/benchmarks/glider_campaign" "${ARGS[@]}" ${EXTRA[@]+"${EXTRA[@]}"} "$OUT"
"$BUILD/benchmarks/glider_campaign_paths" --time "$BUDGET" "$OUT" > "$OUT/paths.txt"
"$PY" "$STATS" "$OUT"/*.log -d "$OUT/campaign.db" >/dev/null
"$PY" "$ROOT/benchmarks/campaign/report.py" "$OUT/campaign.db" "$OUT" "$OUT/reference.csv"
"$PY" "$ROOT/benchmarks/campaign/plot_maps.py" "$OUT"
cat "$OUT/paths.txt"
echo "campaign finished in $(( $(date +%s) - start )) s"
echo "database (Planner Arena): $OUT/campaign.db"
echo "plots: $OUT/travel_time.png $OUT/solve_time.png $OUT/success_rate.png $OUT/maps.png; table: $OUT/table.md"
