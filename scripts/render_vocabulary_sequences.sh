#!/usr/bin/env bash
# Renders the synthetic sequences the shipped bag-of-words vocabulary
# (config/vocabulary/orb_synth_k10_d4.bin) is trained on; see docs/vocabulary.md. Deterministic:
# the same segslam build renders the same images.
#
#   scripts/render_vocabulary_sequences.sh SEGSLAM_BINARY OUT_DIR
set -euo pipefail
segslam="$1"
out="$2"
mkdir -p "$out"

# name | synth options: different seeds (room textures and layout), both camera paths, people
# (their pixels are masked out of training by mask.txt)
sequences=(
  "xyz_s101|--path xyz --people 2 --seed 101"
  "loop_s102|--path loop --people 1 --seed 102"
  "xyz_s103|--path xyz --people 0 --seed 103"
  "loop_s104|--path loop --people 2 --seed 104"
)
for sequence in "${sequences[@]}"; do
  IFS='|' read -r name options <<< "$sequence"
  [[ -f "$out/$name/groundtruth.txt" ]] && continue
  # shellcheck disable=SC2086
  "$segslam" --log-level warn synth --out "$out/$name" --frames 300 $options
done
