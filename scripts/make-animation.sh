#!/usr/bin/env bash
# An animated GIF of a session replayed: every 6th frame rendered headlessly (Vulkan, with the
# crease pattern growing at the right), encoded by Debian's ImageMagick 6. Written whole or not
# at all (encoded beside the target, then renamed; a killed run's leftovers are removed by the next).
#   scripts/make-animation.sh RECORDING OUT.gif [CURVEFOLD]   (default build/app/curvefold)
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: make-animation.sh RECORDING OUT.gif [CURVEFOLD]" >&2; exit 2; }
recording="$(realpath "$1")"
gif="$(realpath -m "$2")"
curvefold="$(realpath "${3:-$(dirname "$0")/../build/app/curvefold}")"
[ ! -d "$gif" ] || { echo "make-animation: $2 is a folder; name a .gif file" >&2; exit 1; }
# The frames and the GIF being encoded live beside the target as .NAME.work-PID and
# .NAME.part-PID (same file system, so the rename is atomic). A run killed outright leaves them;
# the next run for the same target removes those whose process is gone.
dir="$(dirname "$gif")"
name="$(basename "$gif")"
for left in "$dir/.$name".work-* "$dir/.$name".part-*; do
  [ -e "$left" ] || continue
  pid="${left##*-}"
  case "$pid" in '' | *[!0-9]*) continue ;; esac
  kill -0 "$pid" 2>/dev/null || rm -rf -- "$left"
done
work="$dir/.$name.work-$$"
part="$dir/.$name.part-$$"
trap 'rm -rf -- "$work" "$part"' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
mkdir -p -- "$work"
"$curvefold" replay "$recording" --out "$work/design" --frames "$work/frames" --every 6 \
  --size 560x315 --crease-pattern-panel >/dev/null
# Debian's by its package's name first: a `convert` earlier in PATH may be something else.
encoder=""
for candidate in convert-im6.q16 magick convert; do
  if command -v "$candidate" >/dev/null; then encoder="$candidate"; break; fi
done
[ -n "$encoder" ] || { echo "make-animation: ImageMagick is not installed (scripts/setup.sh installs it)" >&2; exit 1; }
"$encoder" -delay 10 -loop 0 "$work"/frames/frame_*.png -layers Optimize "GIF:$part"
chmod a+r "$part"
mv -T -- "$part" "$gif"  # -T: never into a folder of that name
