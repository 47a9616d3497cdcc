#!/usr/bin/env bash
# Installs what is needed, builds, and runs the whole test suite. The README's test command.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
scripts/seed-test-costs.sh build tests/costs/release.txt
ctest --test-dir build --output-on-failure -j"${CURVEFOLD_JOBS:-2}"
