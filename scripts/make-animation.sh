#!/usr/bin/env bash
# An animated GIF of a session replayed: every 6th frame rendered headlessly (Vulkan, with the
# crease pattern growing at the right), encoded by Debian's ImageMagick 6. Written whole or not
# at all (encoded beside the target, then renamed).
#   scripts/make-animation.sh RECORDING OUT.gif [CURVEFOLD]   (default build/app/curvefold)
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: make-animation.sh RECORDING OUT.gif [CURVEFOLD]" >&2; exit 2; }
recording="$(realpath "$1")"
gif="$(realpath -m "$2")"
curvefold="$(realpath "${3:-$(dirname "$0")/../build/app/curvefold}")"
work="$(mktemp -d)"
part="$(mktemp "$gif.XXXXXX")"  # beside the target, so that the rename is atomic
trap 'rm -rf "$work" "$part"' EXIT
"$curvefold" replay "$recording" --out "$work/design" --frames "$work/frames" --every 6 \
  --size 560x315 --crease-pattern-panel >/dev/null
# Debian's by its package's name first: a `convert` earlier in PATH may be something else.
encoder=""
for candidate in convert-im6.q16 magick convert; do
  if command -v "$candidate" >/dev/null; then encoder="$candidate"; break; fi
done
[ -n "$encoder" ] || { echo "make-animation: ImageMagick is not installed (scripts/setup.sh installs it)" >&2; exit 1; }
"$encoder" -delay 10 -loop 0 "$work"/frames/frame_*.png -layers Optimize "GIF:$part"
chmod a+r "$part"  # mktemp made it private
mv "$part" "$gif"
