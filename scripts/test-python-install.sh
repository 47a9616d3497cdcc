#!/usr/bin/env bash
# The README's Python install, as written, into a scratch virtual environment, and the module's
# tests against the installed package (not the build tree). Run by CI after scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
venv="$(mktemp -d)/.venv"
trap 'rm -rf "$(dirname "$venv")"' EXIT
/usr/bin/python3 -m venv --system-site-packages "$venv"
"$venv/bin/pip" install --quiet --no-build-isolation .
cd "$(dirname "$venv")"  # away from python/, so the installed package is the one imported
CURVEFOLD_BINARY="$OLDPWD/build/app/curvefold" CURVEFOLD_SOURCE_DIR="$OLDPWD" \
  "$venv/bin/python" -m pytest -q -p no:cacheprovider "$OLDPWD/python/tests"
