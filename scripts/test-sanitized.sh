#!/usr/bin/env bash
# Builds with AddressSanitizer + UndefinedBehaviorSanitizer (the "asan" CMake preset, into
# build-asan/) and runs the whole test suite under them; then ThreadSanitizer (the "tsan" preset,
# into build-tsan/) over what several threads share: only its test and the libraries it needs
# (about 130 s of CPU: a minute on 2 idle cores).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
werror=()
[ "${CI:-}" = "true" ] && werror=(-DCURVEFOLD_WERROR=ON)  # as scripts/build.sh
cmake --preset asan "${werror[@]}" >/dev/null
cmake --build --preset asan -j"${CURVEFOLD_JOBS:-2}"
scripts/seed-test-costs.sh build-asan tests/costs/asan.txt
# The fit-search tests labelled heavy_fit (tests/heavy_fit.cmake) run in the plain suite only.
ctest --preset asan -j"${CURVEFOLD_JOBS:-2}" -LE heavy_fit
cmake --preset tsan "${werror[@]}" >/dev/null
cmake --build --preset tsan -j"${CURVEFOLD_JOBS:-2}"
ctest --preset tsan -j"${CURVEFOLD_JOBS:-2}"
