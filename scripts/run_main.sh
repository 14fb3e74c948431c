#!/usr/bin/env bash
# Installs what is missing, builds (Release) and runs the main job: the built-in Gulf Stream mission.
# Extra arguments are passed to glider_plan.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build" -j"$(nproc)" --target glider_plan
"$root/build/apps/glider_plan" "$@"
