#!/usr/bin/env bash
# Configures and builds curvefold (Release) into build/. Usage: scripts/build.sh [extra cmake args]
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="${CURVEFOLD_JOBS:-2}"
# CI keeps the build free of warnings: there they are errors.
werror=()
[ "${CI:-}" = "true" ] && werror=(-DCURVEFOLD_WERROR=ON)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "${werror[@]}" "$@" >/dev/null
cmake --build build -j"$jobs"
