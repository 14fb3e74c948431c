#!/usr/bin/env bash
# Every test named in tests/ci_only.txt exists in this build's ctest list; the regex built from the file matches
# exactly those names. Usage (in the build directory): check_ci_only_list.sh CTEST SOURCE_DIR
set -uo pipefail
CTEST=$1 SRC=$2
all=$("$CTEST" -N | sed -n 's/^ *Test *#[0-9]*: //p')
listed=$(grep -v '^\s*#' "$SRC/tests/ci_only.txt" | sed '/^\s*$/d')
# a name of a component this build leaves out (the Python module, MPI, the benchmarks: no python., mpi. or campaign.
# test at all, as in the sanitizer build) is no error
missing=$(comm -23 <(sort -u <<<"$listed") <(sort -u <<<"$all") | while read -r name; do
  case "$name" in
    python.* | mpi.* | campaign.*) grep -q "^${name%%.*}\." <<<"$all" && echo "$name" ;;
    *) echo "$name" ;;
  esac
done)
if [ -n "$missing" ]; then
  echo "FAIL: tests/ci_only.txt names tests this build does not have:"; echo "$missing"; exit 1
fi
matched=$("$CTEST" -N -FA ".*" -R "$(bash "$SRC/scripts/ci_only_regex.sh")" | sed -n 's/^ *Test *#[0-9]*: //p' | sort -u)
[ "$matched" = "$(comm -12 <(sort -u <<<"$listed") <(sort -u <<<"$all"))" ] ||
  { echo "FAIL: the regex matches other tests than the list"; exit 1; }
echo "ok: $(wc -l <<<"$listed") slow cases listed, each a test of this build"
