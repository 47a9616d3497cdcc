#!/usr/bin/env bash
# Writes the design fixtures of one curvefold build, as a user makes them: `new`, then `fold`, then
# the OBJ that build exports of each. Usage: make_fixtures.sh CURVEFOLD SUFFIX SET [OUT_DIR], SET
# "every" (every kind of surface) or "symmetric" (flat sheets with a symmetry: builds from
# 2026-12-04 on). README.md here says which commits made which files.
set -euo pipefail
cf=$1
suffix=$2
set=$3
out=${4:-.}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_CACHE_HOME="$work/cache"  # no sheet cache shared with other builds

# make NAME SURFACE "NEW OPTIONS" "NEAR TO" ...: a design of small resolution and its folds.
make() {
  local name=$1 surface=$2 options=$3
  shift 3
  local design="$out/${name}_$suffix.curvefold.json"
  # shellcheck disable=SC2086
  "$cf" new "$surface" $options -o "$design" >/dev/null
  for fold in "$@"; do
    read -r near to <<<"$fold"
    "$cf" fold "$design" --vertex-near "$near" --to "$to" -o "$design"
  done
  "$cf" export "$design" --obj "$out/${name}_$suffix.obj" >/dev/null
}

if [ "$set" = symmetric ]; then
  make square_mirror square "--resolution 6 --symmetry mirror:x" "0.09,0.05,0 0.03,0.06,0.06"
  make disk_rotational disk "--resolution 8 --symmetry rotational:6" "0.098,0.003,0 0.092,0.003,0.006"
  make star_rotational star "--resolution 8 --symmetry rotational:5" "0,0.1,0 0,0.03,0.06"
  exit 0
fi

make square square "--resolution 6" "0.09,0.05,0 0.03,0.06,0.06" "-0.09,-0.08,0 -0.04,-0.02,0.05"
make rectangle rectangle "--resolution 6 --hole_radius 0.03" "0.14,0,0 0.08,0.02,0.07"
# The first fold grabs the old disk's polygon at a corner (26 sides at resolution 8), outside the
# newer 48-sided one.
make disk disk "--resolution 8" "0.1122,0.0995,0 0.03,0.04,0.06" "-0.05,-0.06,0 -0.01,-0.02,0.05"
make star star "--resolution 8" "0,0.1,0 0,0.03,0.06"
make cylinder cylinder "--resolution 8" "0,0.09,0.05 0,0.05,0.09"
make half_cylinder half_cylinder "--resolution 8" "0,0.09,0.06 0,0.05,0.1"
make cone cone "--resolution 8 --top_radius 0.02" "0,-0.05,0.06 0,-0.02,0.09"
make swept_curve swept_curve "--resolution 12" "0.09,0.09,0 0.05,0.05,0.05"
make helix_tangent helix_tangent "--resolution 16" "0.05,0,0.05 0.03,0.02,0.08"
# An embedded mesh: an OBJ (a half cylinder) imported.
"$cf" new half_cylinder --resolution 4 -o "$work/half.curvefold.json" >/dev/null
"$cf" export "$work/half.curvefold.json" --obj "$work/half.obj" >/dev/null
make mesh "$work/half.obj" "" "0,0.09,0.06 0,0.05,0.1"
