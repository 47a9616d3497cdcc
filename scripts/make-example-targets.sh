#!/usr/bin/env bash
# Makes the example targets of `curvefold fit` in examples/targets/ (issue 27): designs folded
# with the command line, written as plain meshes (the OBJ's development, vt, dropped: a target is
# any mesh). Usage: scripts/make-example-targets.sh [CURVEFOLD]   (default build/app/curvefold)
set -euo pipefail
cd "$(dirname "$0")/.."
curvefold="$(realpath "${1:-build/app/curvefold}")"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
out=examples/targets
mkdir -p "$out"

# A tube with its top front tucked in and its bottom side folded in: two folds of the default
# cylinder.
"$curvefold" new cylinder -o "$scratch/tube.curvefold.json" >/dev/null
"$curvefold" fold "$scratch/tube.curvefold.json" --vertex-near 0,0.105,0.045 \
  --to 0,0.085,0.02 -o "$scratch/tube.curvefold.json" >/dev/null
"$curvefold" fold "$scratch/tube.curvefold.json" --vertex-near 0.045,-0.105,0 \
  --to 0.02,-0.08,0 -o "$scratch/tube.curvefold.json" >/dev/null
"$curvefold" check "$scratch/tube.curvefold.json" >/dev/null
"$curvefold" export "$scratch/tube.curvefold.json" --obj "$scratch/tube.obj" >/dev/null
{
  echo "# a target for curvefold fit: the default cylinder, two folds (scripts/make-example-targets.sh)"
  grep -v -e '^vt ' -e '^#' "$scratch/tube.obj" | sed -E 's#/[0-9]+##g'
} >"$scratch/tube_tucked.obj"
mv "$scratch/tube_tucked.obj" "$out/tube_tucked.obj"
echo "wrote $out/tube_tucked.obj"
