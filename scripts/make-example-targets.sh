#!/usr/bin/env bash
# Makes the example targets of `curvefold fit` in examples/targets/ (issue 27): a design folded
# with the command line, written as a plain mesh (the OBJ's development, vt, dropped: a target is
# any mesh), and shapes given by formulas (gridded surfaces written by awk, not folded by
# curvefold). Usage: scripts/make-example-targets.sh [CURVEFOLD]   (default build/app/curvefold)
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

# A gridded surface (u, v in [0, 1], NU x NV cells, two triangles each) as an OBJ; SHAPE names its
# formula below. Usage: grid SHAPE NU NV COMMENT
grid() {
  awk -v shape="$1" -v nu="$2" -v nv="$3" -v comment="$4" '
    BEGIN {
      pi = 3.141592653589793
      print "# a target for curvefold fit: " comment " (scripts/make-example-targets.sh)"
      for (j = 0; j <= nv; j++) for (i = 0; i <= nu; i++) {
        u = i / nu; v = j / nv
        if (shape == "saddle") {
          # z = (x^2 - y^2) / 0.3 over the default 20 cm square.
          x = -0.1 + 0.2 * u; y = -0.1 + 0.2 * v; z = (x * x - y * y) / 0.3
        } else if (shape == "lampshade") {
          # A cone 12 cm tall narrowing from a radius of 8 cm to 3 cm (cone --top_radius 0.03),
          # its brim below 2 cm under the middle turned up: a surface of revolution whose
          # profile turns back at y = -0.02.
          a = 2 * pi * u; along = -0.06 + 0.12 * v
          y = along < -0.02 ? -0.04 - along : along
          r = 0.08 - (along + 0.06) / 0.12 * 0.05
          x = r * sin(a); z = -r * cos(a)
        }
        if (shape == "vase") {
          # A vase about the y axis, 20 cm tall: a belly of 5.2 cm radius low down, a neck of
          # 3 cm and a lip flaring to 4 cm.
          a = 2 * pi * u; y = -0.1 + 0.2 * v
          r = 0.04 + 0.012 * sin(1.6 * pi * v) - 0.01 * v + 0.01 * v ^ 6
          x = r * sin(a); z = -r * cos(a)
        } else if (shape == "bowl") {
          # A round bowl opening up: a paraboloid z = r^2 / 0.16 out to a rim of 8 cm radius,
          # 4 cm deep (a small hole at its bottom, where the grid meets itself).
          a = 2 * pi * u; rr = 0.004 + 0.076 * v
          x = rr * cos(a); y = rr * sin(a); z = rr * rr / 0.16 - 0.02
        }
        printf "v %.9g %.9g %.9g\n", x, y, z
      }
      for (j = 0; j < nv; j++) for (i = 0; i < nu; i++) {
        k = j * (nu + 1) + i + 1
        printf "f %d %d %d\nf %d %d %d\n", k, k + 1, k + nu + 2, k, k + nu + 2, k + nu + 1
      }
    }' >"$scratch/$1.obj"
  mv "$scratch/$1.obj" "$out/$1.obj"
  echo "wrote $out/$1.obj"
}
grid lampshade 96 60 "a lampshade with its brim turned up, from cone --top_radius 0.03"
grid saddle 40 40 "a saddle z = (x^2 - y^2) / 0.3, from the default square"
grid vase 64 40 "a vase about the y axis with a belly, a neck and a lip"
grid bowl 64 24 "a round bowl, a paraboloid 4 cm deep and 16 cm across"
