#!/usr/bin/env bash
# Regenerates the example recordings (examples/recordings, and the showcase's in
# examples/showcase/recordings) from their gesture scripts:
#   scripts/make-examples.sh [CURVEFOLD]   (default build/app/curvefold)
# A test checks that the recordings match their scripts.
set -euo pipefail
cd "$(dirname "$0")/.."
curvefold="${1:-build/app/curvefold}"
for dir in examples examples/showcase; do
  for script in "$dir"/scripts/*.gesture.json; do
    name="$(basename "$script" .gesture.json)"
    "$curvefold" record-script "$script" -o "$dir/recordings/$name.jsonl"
  done
done
