#!/usr/bin/env bash
# Regenerates every picture the README and docs/ show, from the commands they name, into docs/ and docs/images/.
# Usage: docs/make_figures.sh [BUILD_DIR]   (default: build; build it first with scripts/run_tests.sh or
#        scripts/run_main.sh). The campaign's plots (benchmarks/campaign/results/quick/) are made by
#        benchmarks/run_campaign.sh --quick OUTDIR, which takes minutes; pass --campaign to run it too.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build"
campaign=0
for a in "$@"; do
  case "$a" in
    --campaign) campaign=1 ;;
    *) build=$(cd "$a" && pwd) ;;
  esac
done
plan="$build/apps/glider_plan"
[ -x "$plan" ] || { echo "make_figures: $plan not built (run scripts/run_tests.sh first)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
images="$root/docs/images"
cd "$root"

# the built-in mission (README, docs/CLI.md)
"$plan" --out "$work/main" > /dev/null
cp "$work/main/map.png" docs/main_job_map.png

# around Jamaica with a GSHHG coastline (docs/NETCDF_GEOGRAPHY.md)
"$plan" --currents examples/caribbean_forecast.nc --start=-78.8,18.2 --goal=-75.8,18.1 --speed 0.4 \
  --coastline examples/jamaica_coast.geojson --out "$work/jamaica" > /dev/null
cp "$work/jamaica/map.png" "$images/jamaica_coastline_map.png"

# the interactive map (map.html) of the same trip with a keep-off band and isochrones, as headless Chromium shows it
# offline (README, docs/MAP_HTML.md)
"$plan" --currents examples/caribbean_forecast.nc --start=-78.8,18.2 --goal=-75.8,18.1 --speed 0.4 \
  --coastline examples/jamaica_coast.geojson --keep-off 5km --isochrones --out "$work/jamaica_html" > /dev/null
python3 tests/maphtml/check_map_html.py "$work/jamaica_html/map.html" --screenshot "$images/jamaica_map_html.png" \
  > /dev/null

# the level-set optimum and isochrones around islands (docs/REACHABILITY.md)
"$plan" --mission examples/campaign_islands.yaml --out "$work/islands" > /dev/null
cp "$work/islands/map.png" "$images/campaign_islands_isochrones.png"
cp "$work/islands/isochrones.geojson" docs/data/campaign_islands_isochrones.geojson

# plans flown in a perturbed jet: box plot and tracks (docs/EXECUTION.md)
"$plan" --mission examples/jet_execution.yaml --out "$work/jet" > /dev/null
cp "$work/jet/execution.png" "$images/execution_jet_boxplot.png"
cp "$work/jet/map.png" "$images/execution_jet_map.png"

# forecast against nowcast (docs/EXECUTION.md)
"$plan" --mission examples/labrador_execution.yaml --out "$work/labrador" > /dev/null
cp "$work/labrador/model_difference.png" "$images/labrador_model_difference.png"

# the four stint planners (docs/STINTS.md)
"$build/benchmarks/bench_stints" --map "$images/stints_methods.png" --pair 0 > /dev/null

if [ "$campaign" = 1 ]; then
  bash benchmarks/run_campaign.sh --quick "$work/campaign"
  cp "$work/campaign"/{maps,travel_time,success_rate,solve_time}.png benchmarks/campaign/results/quick/
fi
echo "make_figures: docs/main_job_map.png and docs/images/ rewritten"
