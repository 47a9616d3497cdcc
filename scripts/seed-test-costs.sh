#!/usr/bin/env bash
# Gives ctest the tests' costs on a build with no history (a clean clone, as CI's), so `ctest -j`
# starts the longest first instead of in the order they were declared, which left a minute-long
# test for last on one core (tests/costs/ has how). A build that has run its tests keeps its own.
# Usage: scripts/seed-test-costs.sh BUILD_DIR COSTS_FILE
set -euo pipefail
data="$1/Testing/Temporary/CTestCostData.txt"
[ -f "$data" ] && exit 0
mkdir -p "$(dirname "$data")"
# ctest's format: "name runs seconds" a line, then "---" and the tests that failed last.
{
  grep -v '^#' "$2" | awk 'NF == 2 { print $1, 1, $2 }'
  echo "---"
} >"$data"
