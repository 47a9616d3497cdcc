#!/usr/bin/env bash
# The full soak: 1,000 random folds (with cancels, undos and redos) on every initial surface at
# 20k triangles, every invariant after every step. Usage: scripts/soak.sh [STEPS] [TRIANGLES] [SEED]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh >/dev/null
exec build/tests/curvefold_soak --steps "${1:-1000}" --triangles "${2:-20000}" --seed "${3:-1}"
