#!/usr/bin/env bash
# CNN backbone cost per image (segslam_bench_cnn_extraction) with the shipped Tiny-Darknet config
# (320 x 240) and with a copy at 640 x 480 (the former default): all layers, and each layer alone
# (the network stops there, as in the cnn loop detector). Writes bench/results/cnn_extraction.md.
#
#   bench/cnn_extraction.sh [--build DIR] [--frames N (default 20)]
#
# Needs ../shared beside the project (or SEGSLAM_SHARED_DIR): tum_fr1_xyz_300 and the model.
set -euo pipefail

source "$(dirname "$0")/common.sh"
frames=20
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    *) bench_unknown_option "$1" ;;
  esac
done
bench="$build/bench/segslam_bench_cnn_extraction"
[[ -x "$bench" ]] || bench_fail "$bench not built (cmake --build build --target segslam_bench_cnn_extraction)"
bench_require_dir "$shared/data/tum_fr1_xyz_300"
config="$root/config/models/tiny_darknet_imagenet.yaml"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
sed -e "s#^  model: .*#  model: $shared/models/tiny_darknet_imagenet.onnx#" \
    -e "s/input_width: .*/input_width: 640/" -e "s/input_height: .*/input_height: 480/" \
    -e "s/stored_grid: .*/stored_grid: [40, 30]/" "$config" > "$work/tiny_darknet_640.yaml"

{
  echo "# CNN extraction per image"
  echo
  echo "\`bench/cnn_extraction.sh --frames $frames\` on tum_fr1_xyz_300: median per image of the"
  echo "backbone's forward pass (OpenCV dnn, CPU). Process CPU counts OpenCV's worker threads too."
  echo "Machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores;"
  echo "load before: \`$(uptime)\`."
  echo
  echo "## Shipped config"
  echo
  "$bench" "$config" "$shared/data/tum_fr1_xyz_300" "$frames"
  echo
  echo "## 640 x 480 (the former default)"
  echo
  "$bench" "$work/tiny_darknet_640.yaml" "$shared/data/tum_fr1_xyz_300" "$frames"
  echo
  echo "Load after: \`$(uptime)\`."
} > "$root/bench/results/cnn_extraction.md"
cat "$root/bench/results/cnn_extraction.md"
