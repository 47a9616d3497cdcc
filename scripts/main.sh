#!/usr/bin/env bash
# The main job: installs what is needed, builds, and replays the bundled example recordings
# (two-handed sessions on the paper's Figure 5 surfaces, a desktop one, and two symmetric designs:
# a 6-fold crown vessel and mirrored wave pleats) and the showcase's nine rich designs headlessly
# into a gallery: per example the design, FOLD, SVG crease pattern, the PDF to print, OBJ, the
# per-fold log, the checked invariants and a rendered picture (Vulkan, headless: lavapipe without
# a GPU), three designs fitted to target shapes (each pictured beside its target), and an
# animated GIF of one showcase session. Then one example
# again through the OpenXR path (the Khronos loader and the simulated runtime), keeping both eyes'
# last images, and the headset studio session (xr_studio) with its panel's exports, with
# controllers and with bare hands.
# Usage: scripts/main.sh [OUT]   (default out/gallery)
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-out/gallery}"
scripts/setup.sh
scripts/build.sh
mkdir -p "$out"
# examples/showcase/: nine rich designs (8 folds or more each, every initial surface kind with
# the symmetric examples).
for recording in examples/recordings/*.jsonl examples/showcase/recordings/*.jsonl; do
  name="$(basename "$recording" .jsonl)"
  build/app/curvefold replay "$recording" --out "$out/$name"
  # Every example passes the whole check, self-intersections included.
  build/app/curvefold check "$out/$name/$name.curvefold.json" \
    >"$out/$name/check.txt" ||
    { cat "$out/$name/check.txt" >&2; exit 1; }
  build/app/curvefold export "$out/$name/$name.curvefold.json" --pdf "$out/$name/$name.pdf" \
    >/dev/null
  build/app/curvefold render "$out/$name/$name.curvefold.json" --png "$out/$name/$name.png" \
    --size 1280x720 --view iso --crease-pattern-panel
done
# Designs fitted to target shapes (issue 27, listed in examples/targets/fitted.txt): each fit's
# progress, the design, its check, its distance to the target, and a picture of the target (grey,
# left) beside the result.
grep -v '^#' examples/targets/fitted.txt | while read -r name target view arguments; do
  dir="$out/fitted-$name"
  mkdir -p "$dir"
  # shellcheck disable=SC2086 # the fit's arguments are words
  build/app/curvefold fit "$target" $arguments --time 120 -o "$dir/$name.curvefold.json" \
    >"$dir/fit.txt"
  build/app/curvefold check "$dir/$name.curvefold.json" >"$dir/check.txt" ||
    { cat "$dir/check.txt" >&2; exit 1; }
  build/app/curvefold distance "$dir/$name.curvefold.json" "$target" >"$dir/distance.txt"
  build/app/curvefold render "$dir/$name.curvefold.json" --target "$target" --view "$view" \
    --png "$dir/$name.png" --size 1280x640 >/dev/null
done
# One showcase session as an animated picture: folding happens before a line is read.
scripts/make-animation.sh examples/showcase/recordings/wave_chevrons.jsonl \
  "$out/wave_chevrons/wave_chevrons.gif"
xr="$out/star-xr"
mkdir -p "$xr"
rm -f "$xr/star-xr.jsonl"  # a recording is never overwritten
XR_RUNTIME_JSON=build/sim_input/xr_runtime/curvefold_sim_openxr.json \
  CURVEFOLD_SIM_INPUT=examples/recordings/star.jsonl CURVEFOLD_SIM_SAVE_VIEWS="$xr" \
  build/app/curvefold xr examples/recordings/star.jsonl --record "$xr/star-xr.jsonl" \
  --autosave "$xr/star-xr.curvefold.json" >"$xr/xr.txt"
# A whole design made in the headset through its panel (a new cone, folds, a two-handed scale,
# FOLD, SVG and PNG exported from the panel), played through the simulated runtime.
studio="$out/xr_studio-xr"
rm -rf "$studio"  # its autosaves are numbered, not overwritten: start clean
mkdir -p "$studio"
XR_RUNTIME_JSON=build/sim_input/xr_runtime/curvefold_sim_openxr.json \
  CURVEFOLD_SIM_INPUT=examples/recordings/xr_studio.jsonl CURVEFOLD_SIM_SAVE_VIEWS="$studio/views" \
  build/app/curvefold xr examples/recordings/xr_studio.jsonl --export-dir "$studio/exports" \
  --autosave "$studio/xr_studio.curvefold.json" >"$studio/xr.txt"
# The same session with bare hands and no controllers (XR_EXT_hand_tracking, 2 mm of jitter on
# every joint), recorded: the views show the hands drawn as joints and bones.
hands="$out/xr_studio-hands"
rm -rf "$hands"
mkdir -p "$hands"
XR_RUNTIME_JSON=build/sim_input/xr_runtime/curvefold_sim_openxr.json CURVEFOLD_SIM_HANDS=1 \
  CURVEFOLD_SIM_JITTER=2 CURVEFOLD_SIM_INPUT=examples/recordings/xr_studio.jsonl \
  CURVEFOLD_SIM_SAVE_VIEWS="$hands/views" \
  build/app/curvefold xr examples/recordings/xr_studio.jsonl --export-dir "$hands/exports" \
  --record "$hands/xr_studio-hands.jsonl" --autosave "$hands/xr_studio.curvefold.json" \
  >"$hands/xr.txt"
echo "gallery written to $out"
