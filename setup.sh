#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a finished run: installs dependencies, builds
# build/ (Release with debug info, the configuration test.sh builds too, so that it compiles nothing
# again) and runs the main job on the embedded default, a synthetic dynamic sequence that segslam
# generates itself (no downloads, no external data).
set -euo pipefail
cd "$(dirname "$0")"
scripts/install_deps.sh
scripts/build_web.sh
scripts/build.sh build
./build/segslam synth --out out/demo_sequence --seed 1
# Geometric masks need no model, so the run is the same with or without ../shared beside it.
./build/segslam run --dataset out/demo_sequence --out out/demo_run --seg geometric
