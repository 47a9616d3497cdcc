#!/usr/bin/env bash
# Builds the Figure 5 gallery with a built curvefold: scripts/gallery.sh CURVEFOLD OUT
# Each design is made by `new`, a few `fold`s (grab the surface point nearest A, drag it to B;
# metres), then `check` and `export`.
set -euo pipefail
curvefold="$1"
out="$2"
mkdir -p "$out"

# design NAME "SURFACE [--param value ...]" "A>B" "A>B" ...
design() {
  local name="$1" surface="$2"
  shift 2
  local dir="$out/$name" file="$out/$name/$name.curvefold.json"
  mkdir -p "$dir"
  # shellcheck disable=SC2086
  "$curvefold" new $surface -o "$file" >/dev/null
  for drag in "$@"; do
    "$curvefold" fold "$file" --vertex-near "${drag%%>*}" --to "${drag##*>}" -o "$file" >/dev/null
  done
  # These folds predate the self-intersection check and pass the paper through itself, as the
  # recorded Figure 5 sessions do: check.txt lists the pairs; every other invariant must hold.
  "$curvefold" check "$file" --allow-self-intersection >"$dir/check.txt" ||
    { cat "$dir/check.txt" >&2; exit 1; }
  "$curvefold" export "$file" --fold "$dir/$name.fold" --svg "$dir/$name.svg" \
    --obj "$dir/$name.obj" --gltf "$dir/$name.glb" >/dev/null
  echo "$name: $# folds, $(head -1 "$dir/check.txt" | sed 's/.*folds, //'); $(grep -o 'creases: [^;]*' "$dir/check.txt")"
}

# (a, b) a sine curve swept along a line: two corners and an edge folded over.
design swept_curve "swept_curve" \
  "0.1,0.1,0>0.04,0.05,0.06" \
  "-0.1,-0.1,0>-0.05,-0.04,0.06" \
  "0,0.1,0>0,0.045,-0.05" \
  "0.1,-0.1,0>0.06,-0.05,-0.05"

# (c) the tangent developable of a helix: the outer rim folded in at three places.
design helix_tangent "helix_tangent" \
  "0.097,0.0,0.0>0.06,0.02,0.0" \
  "0.0,0.04,0.097>0.0,0.05,0.055" \
  "-0.097,0.07,0.0>-0.055,0.06,0.0"

# (d) half a cylinder: both ends folded back diagonally, and a dent in the middle.
design half_cylinder "half_cylinder" \
  "0.06,0.105,0>0.01,0.06,0.05" \
  "-0.06,-0.105,0>-0.01,-0.06,0.05" \
  "0,0,0.06>0,0.005,0.03"

# (e) a flat star: all five points folded up into a cup.
design star "star --resolution 64" \
  "0,0.1,0>0,0.055,0.045" \
  "-0.0951,0.0309,0>-0.0523,0.0170,0.045" \
  "-0.0588,-0.0809,0>-0.0323,-0.0445,0.045" \
  "0.0588,-0.0809,0>0.0323,-0.0445,0.045" \
  "0.0951,0.0309,0>0.0523,0.0170,0.045"

# (f) a cone with a slit: the base rim pushed in and up at three places.
design cone "cone" \
  "0.08,-0.06,0>0.045,-0.03,0" \
  "-0.04,-0.06,0.0693>-0.022,-0.03,0.04" \
  "-0.04,-0.06,-0.0693>-0.022,-0.03,-0.04"

echo "gallery written to $out"
