#!/usr/bin/env bash
# Screenshot of `segslam view` on a run of tum_fr1_xyz_300, for the notes: runs the sequence once
# (reused when the run folder exists), serves it and captures the page in headless chromium.
#
#   bench/viewer_screenshot.sh [--build DIR] [--run DIR] [--out FILE] [--size WxH]
#
# Writes bench/results/viewer_tum_fr1_xyz_300.png by default. Needs ../shared (or
# SEGSLAM_SHARED_DIR), chromium and the web build (scripts/build_web.sh).
set -euo pipefail

source "$(dirname "$0")/common.sh"
run="$root/out/fr1_view"
out="$root/bench/results/viewer_tum_fr1_xyz_300.png"
size="1200x760"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --run) run="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --size) size="$2"; shift 2 ;;
    *) bench_unknown_option "$1" ;;
  esac
done
bench_require_segslam
dataset="$shared/data/tum_fr1_xyz_300"
bench_require_dir "$dataset"

if [[ ! -f "$run/CameraTrajectory.txt" ]]; then
  "$segslam" run --dataset "$dataset" --out "$run" --deterministic >/dev/null
fi
mkdir -p "$(dirname "$out")"
node "$root/web/test/viewer_browser_test.mjs" --cli "$segslam" --run "$run" --screenshot "$out" --size "$size"
