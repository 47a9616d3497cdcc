#!/bin/bash
# Reachable fit targets made by issue 38's "Measured" recipe read literally, with bash and awk
# driving the `curvefold` command line alone (no Python, no project code but the binary):
#   every catalogue surface at its default parameters; each fold grabs a vertex in the outer
#   third of the sheet, measured from its bounding box's centre (distance >= 2/3 of the farthest
#   vertex's), and drops it 10-35% of the bounding-box diagonal away in a uniform direction on the
#   sphere; a fold is kept when `check` passes whole (else another vertex and drop are drawn, at
#   most 30 times per fold); the design is exported with `export --obj` and its `vt` lines are
#   removed (and the faces' `/vt` indices with them, so that an older `fit` reads the target; the
#   OBJ reader now also takes the faces' dangling `a/b` indices of a file without `vt` lines).
#
#   bench/make_outer_third_targets.sh OUT [--seed S] [--per K] [--buckets 1-2,3-4,5-8]
#       [--surfaces a,b] [--curvefold build/app/curvefold]
#   /usr/bin/python3 bench/reach_targets.py fit OUT --folds 8 --time 60
#
# Unlike make_rim_targets.py (Python, rim vertices, short drags or tucks) and reach_targets.py
# (the Python module), the random numbers come from bash's $RANDOM seeded once (RANDOM=S), each
# draw handed to awk's srand. Writes OUT/NAME.obj (the target), OUT/NAME.curvefold.json (its
# design) and OUT/manifest.jsonl as `reach_targets.py make` does (recipe "outer-third-sh").
set -u
out=""
seed=9
per=3
buckets="1-2,3-4,5-8"
surfaces="square,rectangle,disk,star,cylinder,half_cylinder,cone,swept_curve,helix_tangent"
cf=build/app/curvefold
while [ $# -gt 0 ]; do
  case "$1" in
    --seed) seed=$2; shift 2 ;;
    --per) per=$2; shift 2 ;;
    --buckets) buckets=$2; shift 2 ;;
    --surfaces) surfaces=$2; shift 2 ;;
    --curvefold) cf=$2; shift 2 ;;
    -*) echo "unknown option $1" >&2; exit 2 ;;
    *) out=$1; shift ;;
  esac
done
[ -n "$out" ] || { echo "usage: $0 OUT [--seed S] [--per K] [--buckets ...] [--surfaces ...]" >&2; exit 2; }
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
RANDOM=$seed
: > "$out/manifest.jsonl"

draw() { echo $(( RANDOM * 32768 + RANDOM )); }

# Prints "X,Y,Z TX,TY,TZ": a vertex of OBJ $1 in the outer third from the bounding box's centre and
# the point 10-35% of the diagonal away from it in a uniform direction; awk seeded with $2.
grab() {
  awk -v s="$2" '
    $1 == "v" { n++; x[n] = $2; y[n] = $3; z[n] = $4
      if (n == 1) { lx = hx = $2; ly = hy = $3; lz = hz = $4 }
      if ($2 < lx) lx = $2; if ($2 > hx) hx = $2
      if ($3 < ly) ly = $3; if ($3 > hy) hy = $3
      if ($4 < lz) lz = $4; if ($4 > hz) hz = $4 }
    END {
      srand(s)
      cx = (lx + hx) / 2; cy = (ly + hy) / 2; cz = (lz + hz) / 2
      diag = sqrt((hx - lx) ^ 2 + (hy - ly) ^ 2 + (hz - lz) ^ 2)
      far = 0
      for (i = 1; i <= n; i++) { d[i] = sqrt((x[i] - cx) ^ 2 + (y[i] - cy) ^ 2 + (z[i] - cz) ^ 2); if (d[i] > far) far = d[i] }
      m = 0
      for (i = 1; i <= n; i++) if (d[i] >= far * 2 / 3) pick[++m] = i
      v = pick[1 + int(rand() * m)]
      do { # uniform direction: a normal sample, normalised (Box-Muller)
        for (k = 0; k < 3; k++) g[k] = sqrt(-2 * log(1 - rand())) * cos(6.283185307179586 * rand())
        len = sqrt(g[0] ^ 2 + g[1] ^ 2 + g[2] ^ 2)
      } while (len < 1e-9)
      r = diag * (0.10 + 0.25 * rand())
      printf "%.9g,%.9g,%.9g %.9g,%.9g,%.9g\n", x[v], y[v], z[v], \
        x[v] + r * g[0] / len, y[v] + r * g[1] / len, z[v] + r * g[2] / len
    }' "$1"
}

IFS=, read -r -a bucketList <<< "$buckets"
IFS=, read -r -a surfaceList <<< "$surfaces"
for bucket in "${bucketList[@]}"; do
  lo=${bucket%-*}; hi=${bucket#*-}
  for surface in "${surfaceList[@]}"; do
    for ((k = 0; k < per; k++)); do
      folds=$(( lo + RANDOM % (hi - lo + 1) ))
      name=$(printf "outer-third-sh-%s-%02d-%s" "$bucket" "$k" "$surface")
      design="$work/$name.curvefold.json"
      "$cf" new "$surface" -o "$design" > /dev/null || exit 1
      made=0
      for ((f = 0; f < folds; f++)); do
        for ((try = 0; try < 30; try++)); do
          "$cf" export "$design" --obj "$work/now.obj" > /dev/null || exit 1
          read -r from to <<< "$(grab "$work/now.obj" "$(draw)")"
          if "$cf" fold "$design" --vertex-near "$from" --to "$to" -o "$work/next.curvefold.json" > /dev/null 2>&1 &&
             "$cf" check "$work/next.curvefold.json" > /dev/null 2>&1; then
            mv "$work/next.curvefold.json" "$design"
            made=$((made + 1))
            break
          fi
        done
      done
      [ "$made" -eq "$folds" ] || { echo "$name: $made of $folds folds kept, dropped" >&2; continue; }
      "$cf" export "$design" --obj "$work/full.obj" > /dev/null || exit 1
      grep -v '^vt ' "$work/full.obj" | sed '/^f /s#/[0-9]*##g' > "$out/$name.obj"
      cp "$design" "$out/$name.curvefold.json"
      printf '{"name": "%s", "recipe": "outer-third-sh", "bucket": "%s", "surface": "%s", "parameters": {}, "symmetry": null, "folds": %d}\n' \
        "$name" "$bucket" "$surface" "$folds" >> "$out/manifest.jsonl"
      echo "$name: $folds folds"
    done
  done
done
