#!/bin/bash
# Fit every target of bench/make_judge_shapes.py as issue 38's judge would, one at a time:
#   bench/run_judge_shapes.sh CURVEFOLD TARGETS_DIR OUT_DIR [TIME] [FOLDS]
# For each target: `fit --from KIND --folds FOLDS --time TIME` (wall, user and system seconds by
# /usr/bin/time), `check` of the design, `export --obj` and `distance` (40,000 samples), and
# bench/judge_distance.py's own measure; one row per target in OUT_DIR/table.tsv.
set -u
cf=$1 dir=$2 out=$3 time=${4:-60} folds=${5:-16}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
while IFS=$'\t' read -r name kind _; do
  [ -n "${ONLY:-}" ] && [[ ! " $ONLY " == *" $name "* ]] && continue
  o=$out/$name
  /usr/bin/time -f "%e %U %S" -o "$o.time" timeout 600 nice "$cf" fit "$dir/$name.obj" --from "$kind" \
    --folds "$folds" --time "$time" --seed 1 --log "$o.folds.jsonl" -o "$o.curvefold.json" >"$o.fit.txt" 2>&1
  rc=$?
  start=$(grep -m1 '^start:' "$o.fit.txt" | sed 's/.*Chamfer [^(]*(\([0-9.e+-]*\)%).*/\1/')
  chk=none dist=none mine=none
  if [ -f "$o.curvefold.json" ]; then
    "$cf" check "$o.curvefold.json" >"$o.check.txt" 2>&1 && chk=pass || chk=FAIL
    "$cf" export "$o.curvefold.json" --obj "$o.obj" >/dev/null 2>&1
    dist=$(timeout 300 nice "$cf" distance "$o.curvefold.json" "$dir/$name.obj" --samples 40000 2>&1 | tr '\n' ' ')
    mine=$(timeout 600 nice /usr/bin/python3 "$here/judge_distance.py" "$o.obj" "$dir/$name.obj")
  fi
  printf '%s\t%s\trc=%s\tstart=%s\tcheck=%s\ttime=%s\tmine=%s\tdistance=%s\n' "$name" "$kind" "$rc" "$start" \
    "$chk" "$(cat "$o.time" | tail -1)" "$mine" "$dist" | tee -a "$out/table.tsv"
done <"$dir/targets.tsv"
