#!/usr/bin/env bash
# Regenerates the README's gallery: each example recording replayed and rendered (iso view with
# the crease-pattern panel) into docs/gallery/<name>.png, the showcase's among them, and the
# README's animated picture, docs/gallery/wave_chevrons.gif, and the fitted designs of
# examples/targets/fitted.txt, each beside its target, as docs/gallery/fitted_<name>.png.
#   scripts/make-gallery-images.sh [CURVEFOLD]   (default build/app/curvefold)
set -euo pipefail
cd "$(dirname "$0")/.."
curvefold="${1:-build/app/curvefold}"
mkdir -p docs/gallery
for recording in examples/recordings/*.jsonl examples/showcase/recordings/*.jsonl; do
  name="$(basename "$recording" .jsonl)"
  "$curvefold" render "$recording" --png "docs/gallery/$name.png" --size 800x450 --view iso \
    --crease-pattern-panel
done
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
grep -v '^#' examples/targets/fitted.txt | while read -r name target view arguments; do
  # shellcheck disable=SC2086 # the fit's arguments are words
  "$curvefold" fit "$target" $arguments --time 120 -o "$scratch/$name.curvefold.json" >/dev/null
  "$curvefold" render "$scratch/$name.curvefold.json" --target "$target" --view "$view" \
    --png "docs/gallery/fitted_$name.png" --size 800x400 >/dev/null
done
scripts/make-animation.sh examples/showcase/recordings/wave_chevrons.jsonl \
  docs/gallery/wave_chevrons.gif "$curvefold"
