#!/usr/bin/env bash
# Installs segslam's build and test dependencies from Debian 12's apt, idempotently:
# `apt-get update` runs once, and only when something is missing; present packages are skipped.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libopencv-dev libeigen3-dev libceres-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev libspdlog-dev libfmt-dev nlohmann-json3-dev libyaml-cpp-dev libtbb-dev
  libopen3d-dev
  # Occupancy maps: OctoMap's library, and its tools (octovis, bt2vrml) to look at the .bt files.
  liboctomap-dev octomap-tools
  clang libclang-rt-14-dev clang-format
  libcpp-httplib-dev chromium
  # The benches: ../shared/tools makes dynamic sequences with Debian's Python OpenCV, and
  # stress-ng keeps a core busy to measure a shared CPU.
  python3-opencv stress-ng
  # The Python module (python/, docs/python.md): Debian's pybind11 and numpy, its tests' pytest
  # and the map example's Open3D.
  pybind11-dev python3-numpy python3-pytest python3-open3d
)
# The viewer's front end is built with node and npm (scripts/build_web.sh). Debian's packages are
# used only when no node is installed: a NodeSource nodejs already provides npm and conflicts
# with Debian's.
if ! command -v npm >/dev/null 2>&1; then packages+=(nodejs npm); fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "[deps] all ${#packages[@]} packages already installed"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
echo "[deps] installing: ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
