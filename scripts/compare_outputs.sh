#!/usr/bin/env bash
# Compares what two builds of glider_plan write, to the bit: the built-in Gulf Stream mission and every example
# mission (examples/*.yaml), each output file and the printed summary. For a change that must not change any answer
# (a refactoring, a formatting pass, a faster build): build before and after, then
#   scripts/compare_outputs.sh BEFORE/apps/glider_plan AFTER/apps/glider_plan
# What differs between two runs of one binary (the wall time of a plan in summary.json and the report) is found by
# running BEFORE a second time where a file differs: in such a file only the lines both runs of BEFORE agree on are
# compared (a binary file that differs between them is reported and skipped). Exit 0 when every file is the same, 1
# otherwise. Every example takes about 15 minutes on 2 cores (jet_execution_ensemble alone several); name missions to
# compare fewer.
# Usage: scripts/compare_outputs.sh GLIDER_PLAN_BEFORE GLIDER_PLAN_AFTER [MISSION.yaml ...]
set -uo pipefail
if [ $# -lt 2 ]; then
  echo "usage: scripts/compare_outputs.sh GLIDER_PLAN_BEFORE GLIDER_PLAN_AFTER [MISSION.yaml ...]" >&2
  exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
before=$(realpath "$1"); after=$(realpath "$2"); shift 2
for exe in "$before" "$after"; do
  [ -x "$exe" ] || { echo "compare_outputs: '$exe' is not an executable" >&2; exit 2; }
done
missions=()
for m in "$@"; do
  if [ "$m" = builtin ]; then missions+=(builtin); else missions+=("$(realpath "$m")"); fi
done
[ ${#missions[@]} -gt 0 ] || missions=(builtin "$root"/examples/*.yaml)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# run EXE MISSION DIR: glider_plan in DIR (outputs in DIR/out, its printed lines in DIR/out/stdout.txt)
run() {
  local exe=$1 mission=$2 dir=$3
  mkdir -p "$dir"
  if [ "$mission" = builtin ]; then
    (cd "$dir" && "$exe" --out out > stdout.txt 2>&1; echo "exit $?" >> stdout.txt)
  else
    (cd "$dir" && "$exe" --mission "$mission" --out out > stdout.txt 2>&1; echo "exit $?" >> stdout.txt)
  fi
  mkdir -p "$dir/out"
  # the printed wall times (to 2 or 3 decimals: two runs may agree by chance) and OMPL's source lines of a message
  sed -E -e 's/^(Planning time:).*/\1 (wall time)/' -e 's/^(Global check:.*) \([0-9.]+ s\)$/\1 (wall time)/' \
    -e 's/at line [0-9]+ in .*/at line (n) in (source file)/' "$dir/stdout.txt" > "$dir/out/stdout.txt"
  rm "$dir/stdout.txt"
}

status=0
files=0
for mission in "${missions[@]}"; do
  name=$(basename "$mission" .yaml)
  case_dir="$work/$name"
  # the same path on each side, so that paths written into the outputs are the same text; BEFORE a second time only
  # when some file differs (to tell a change from what varies between runs)
  for side in a1 b a2; do
    exe=$before
    [ $side = b ] && exe=$after
    if [ $side = a2 ] && diff -rq "$case_dir.a1" "$case_dir.b" > /dev/null; then
      cp -a "$case_dir.a1" "$case_dir.a2"
      continue
    fi
    run "$exe" "$mission" "$work/run"
    mv "$work/run" "$case_dir.$side"
  done
  differ=0
  while IFS= read -r rel; do
    files=$((files + 1))
    a1="$case_dir.a1/$rel"; a2="$case_dir.a2/$rel"; b="$case_dir.b/$rel"
    if [ ! -e "$b" ]; then
      echo "$name: $rel: written before, not after"; differ=1; continue
    fi
    cmp -s "$a1" "$b" && continue
    if cmp -s "$a1" "$a2"; then
      echo "$name: $rel differs (and two runs before agree)"; cmp "$a1" "$b" | head -1; differ=1; continue
    fi
    if ! grep -qI . "$a1"; then
      echo "$name: $rel: binary, differs between two runs before: not compared"; continue
    fi
    # the lines two runs before agree on must be the same after
    if ! python3 - "$a1" "$a2" "$b" <<'PY'
import sys
a1, a2, b = (open(p, encoding="utf-8", errors="replace").read().splitlines() for p in sys.argv[1:])
if not (len(a1) == len(a2) == len(b)):
    print(f"  {len(a1)} / {len(a2)} lines in two runs before, {len(b)} after")
    sys.exit(1)
bad = [i for i, (x, y, z) in enumerate(zip(a1, a2, b)) if x == y and x != z]
for i in bad[:3]:
    print(f"  line {i + 1}: {a1[i][:150]!r} -> {b[i][:150]!r}")
sys.exit(1 if bad else 0)
PY
    then
      echo "$name: $rel differs on lines two runs before agree on"; differ=1
    fi
  done < <(cd "$case_dir.a1" && find . -type f | sed 's|^\./||' | sort)
  extra=$(comm -13 <(cd "$case_dir.a1" && find . -type f | sort) <(cd "$case_dir.b" && find . -type f | sort))
  [ -z "$extra" ] || { echo "$name: written after, not before: $extra"; differ=1; }
  if [ $differ = 0 ]; then
    echo "same   $name ($(cd "$case_dir.b" && find . -type f | wc -l) files, $(grep -m1 -E '^(Travel time|exit)' "$case_dir.b/out/stdout.txt"))"
  else
    status=1
  fi
done
echo "compare_outputs: ${#missions[@]} missions, $files files: $([ $status = 0 ] && echo "all the same" || echo "DIFFERENCES")"
exit $status
