#!/usr/bin/env bash
# The tree's C++ (.h and .cpp of src/, include/, apps/, python/src/, tests/, benchmarks/, demos/, fuzz/) formatted as
# the project's .clang-format says, by clang-format-14 (scripts/setup.sh installs it). Exit 0 when every file is,
# 1 with each file that is not (and the first of its changes), 2 when clang-format-14 is missing.
#   scripts/check_format.sh          check
#   scripts/check_format.sh --fix    format every file in place (then review and commit the change alone)
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
fix=0
[ "${1:-}" = --fix ] && fix=1
formatter=$(command -v clang-format-14 || true)
if [ -z "$formatter" ]; then
  echo "check_format: clang-format-14 is not installed (scripts/setup.sh installs it)" >&2
  exit 2
fi
cd "$root" || exit 2
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  mapfile -t files < <(git ls-files -- '*.h' '*.cpp' | grep -E '^(src|include|apps|python/src|tests|benchmarks|demos|fuzz)/')
else
  mapfile -t files < <(find src include apps python/src tests benchmarks demos fuzz -name '*.h' -o -name '*.cpp' | sort)
fi
if [ $fix = 1 ]; then
  printf '%s\0' "${files[@]}" | xargs -0 "$formatter" --style=file -i
  exit $?
fi
# one run of the formatter per batch of files; a file not formatted is named in its first complaint
bad=$(printf '%s\0' "${files[@]}" | xargs -0 -n 64 "$formatter" --style=file --dry-run --Werror 2>&1 |
  grep -E '^[^ :]+:[0-9]+:[0-9]+: error: code should be clang-formatted' | cut -d: -f1 | sort -u)
count=0
[ -n "$bad" ] && count=$(echo "$bad" | wc -l)
[ -n "$bad" ] && echo "$bad" | sed 's/$/: not formatted as .clang-format says (scripts\/check_format.sh --fix formats it)/'
echo "check_format: ${#files[@]} files, $count not formatted"
[ "$count" = 0 ]
