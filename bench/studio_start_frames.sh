#!/bin/sh
# The designer window's frames while it opens on a target alone (issue 38, 4: `curvefold design
# --target T.obj`): the window shows the rule's sheet at once and takes the start `fit` chooses
# when the thread revising it has it (StudioTarget::reviseStart). Runs the window on a private
# Xvfb (lavapipe), moves the pointer over it every 0.1 s for SECONDS (so that frames are drawn, as
# a designer looking on would), quits with Ctrl+Q and prints, from the window's --frame-times:
# the frames drawn, the longest frame (wall and the frame thread's CPU, ms) after the first second
# (the window's start: pipelines, the font atlas), the longest before it, the frame the start was
# swapped in ("start" note) and the seconds it came at.
#
#   bench/studio_start_frames.sh TARGET.obj [SECONDS] [CURVEFOLD]
#   (default 30 s, build/app/curvefold; needs Xvfb and xdotool)
set -eu
target=$1
seconds=${2:-30}
binary=${3:-build/app/curvefold}
dir=$(mktemp -d /tmp/curvefold-start-frames.XXXXXX)
Xvfb -displayfd 3 -screen 0 1600x900x24 -nolisten tcp 3>"$dir/display" >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
i=0
while [ ! -s "$dir/display" ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
export DISPLAY=":$(cat "$dir/display")"
"$binary" design --target "$target" --size 1280x720 --autosave "$dir/auto.curvefold.json" \
  --frame-times "$dir/frames.txt" >"$dir/designer.log" 2>&1 &
designer=$!
window=$(timeout 60 xdotool search --sync --name '^curvefold$' | head -1)
end=$(($(date +%s) + seconds))
x=700
while [ "$(date +%s)" -lt $end ]; do
  x=$((x == 700 ? 720 : 700))
  xdotool mousemove --window "$window" $x 400 2>/dev/null || true
  sleep 0.1
done
xdotool key --window "$window" ctrl+q || true
wait $designer || { echo "the window failed:"; cat "$dir/designer.log"; exit 1; }
# Each line: wall ms, frame-thread CPU ms, phases=..., waited=..., [note]; the window's time is the
# sum of the walls and the waits before them.
awk -v walls="$dir/walls" '{
  waited = $4; sub("waited=", "", waited); t += waited / 1000.0;
  n++;
  if (t >= 1.0) {
    print $1 > walls;
    if ($1 > longest) { longest = $1; cpu = $2; at = t }
    if ($2 > mostCpu) { mostCpu = $2; mostCpuAt = t }
  } else if ($1 > first) first = $1;
  if ($5 == "start") { start = $1; startCpu = $2; startAt = t }
  t += $1 / 1000.0;
} END {
  close(walls);
  while (("sort -n " walls) | getline w) wall[++m] = w;
  printf "frames %d; after the first second: median %.1f ms, 99th percentile %.1f ms, longest %.1f ms (frame thread %.1f ms CPU) at %.1f s; most frame-thread CPU %.1f ms at %.1f s; longest in the first second %.1f ms\n", n, wall[int((m + 1) / 2)], wall[int(0.99 * m)], longest, cpu, at, mostCpu, mostCpuAt, first;
  if (startAt > 0) printf "start swapped in at %.1f s, in a frame of %.1f ms (frame thread %.1f ms CPU)\n", startAt, start, startCpu;
  else print "no start swapped in";
}' "$dir/frames.txt"
grep "^start" "$dir/designer.log" || true
rm -rf "$dir"
