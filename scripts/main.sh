#!/usr/bin/env bash
# The main job: installs what is needed, builds, and makes the gallery of the paper's Figure 5
# initial surfaces, each folded several times with the command line, checked, and exported.
# Usage: scripts/main.sh [OUT]   (default out/gallery)
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-out/gallery}"
scripts/setup.sh
scripts/build.sh
exec scripts/gallery.sh build/app/curvefold "$out"
