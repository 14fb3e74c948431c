#!/usr/bin/env bash
# Prints a ctest regular expression matching exactly the test names listed in tests/ci_only.txt (the slow cases that
# CI alone runs; comments and blank lines skipped). Used by run_tests.sh and run_sanitizers.sh with ctest -E.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
grep -v '^\s*#' "$root/tests/ci_only.txt" | sed '/^\s*$/d' | sed 's/[].[^$*+?(){}|\\]/\\&/g' |
  paste -sd'|' | sed 's/^/^(/; s/$/)$/'
