#!/usr/bin/env bash
# Regenerates the example recordings from their gesture scripts:
#   scripts/make-examples.sh [CURVEFOLD]   (default build/app/curvefold)
# A test checks that the recordings in examples/recordings match their scripts.
set -euo pipefail
cd "$(dirname "$0")/.."
curvefold="${1:-build/app/curvefold}"
for script in examples/scripts/*.gesture.json; do
  name="$(basename "$script" .gesture.json)"
  "$curvefold" record-script "$script" -o "examples/recordings/$name.jsonl"
done
