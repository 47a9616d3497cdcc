#!/usr/bin/env bash
# Installs every Debian 12 package curvefold needs to build, test and run. Idempotent and quiet
# when everything is already there; uses sudo when not run as root.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  # compiler cache: CI's fresh clones on one machine reuse each other's object files
  ccache
  libglm-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  nlohmann-json3-dev libcli11-dev libtinygltf-dev libstb-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  clang-format
  # folding toward a goal: both cores, the local search, nearest neighbours
  libtbb-dev libnlopt-cxx-dev libnanoflann-dev
  # SVG crease patterns from other tools (Origami Simulator's convention): an XML parser
  libxml2-dev
  # the folding simulation's static solver (sparse LDL^T)
  libeigen3-dev
  # the printable crease pattern (PDF)
  libcairo2-dev
  # the main job's animated picture of a replay (GIF)
  imagemagick
  # `simulate --gif`: giflib's colour quantizer and GIF encoder
  libgif-dev
  # sanitizer build and fuzzers: clang with its runtime libraries (libFuzzer, ASan, UBSan)
  clang libclang-rt-14-dev
  # renderer and desktop window: Vulkan with Mesa's lavapipe and the Khronos validation layer,
  # GLSL compiler, GLFW, Dear ImGui; Xvfb and xdotool for the window tests
  libvulkan-dev glslang-tools mesa-vulkan-drivers vulkan-validationlayers
  libglfw3-dev libimgui-dev xvfb xauth xdotool
  # the desktop portal's file chooser over D-Bus (GLib's GDBus); dbus-daemon for its tests
  libglib2.0-dev dbus-daemon
  # pgrep, for the crash-safety test
  procps
  # OpenXR: the Khronos loader and headers (the simulated runtime in sim_input/ serves tests)
  libopenxr-dev libopenxr-loader1
  # the Python module (python/): pybind11, numpy, pytest; a virtual environment and setuptools
  # for `pip install .`
  pybind11-dev python3-dev python3-numpy python3-pytest python3-venv python3-setuptools
  python3-pip
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "setup: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
