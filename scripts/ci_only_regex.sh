#!/usr/bin/env bash
# Prints a ctest regular expression matching exactly the test names listed in tests/ci_only.txt (the slow cases that
# CI alone runs; comments and blank lines skipped). Used by run_tests.sh and run_sanitizers.sh with ctest -E.
# Usage: ci_only_regex.sh [KEEP]: names matching the extended regular expression KEEP are left out of it (run_sanitizers.sh
# runs the OPeNDAP case, which mostly waits on its servers, beside the others).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
keep=${1:-'^$'}
grep -v '^\s*#' "$root/tests/ci_only.txt" | sed '/^\s*$/d' | { grep -Ev "$keep" || true; } |
  sed 's/[].[^$*+?(){}|\\]/\\&/g' | paste -sd'|' | sed 's/^/^(/; s/$/)$/'
