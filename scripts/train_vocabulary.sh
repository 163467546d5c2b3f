#!/usr/bin/env bash
# Rebuilds the shipped bag-of-words vocabulary, config/vocabulary/orb_synth_k10_d4.bin, from the
# synthetic sequences of scripts/render_vocabulary_sequences.sh (see docs/vocabulary.md).
#
#   scripts/train_vocabulary.sh [BUILD_DIR=build] [WORK_DIR=out/vocabulary_training]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
work="${2:-$root/out/vocabulary_training}"
"$root/scripts/render_vocabulary_sequences.sh" "$build/segslam" "$work"
datasets=()
for sequence in "$work"/*/; do datasets+=(--dataset "$sequence"); done
mkdir -p "$root/config/vocabulary"
"$build/segslam" vocab train "${datasets[@]}" --k 10 --depth 4 --every 5 --features 1000 --seed 1 \
  --out "$root/config/vocabulary/orb_synth_k10_d4.bin"
"$build/segslam" vocab info "$root/config/vocabulary/orb_synth_k10_d4.bin"
