#!/usr/bin/env bash
# Loop detection with and without the union mask: runs `segslam eval loops` (every CNN layer, the
# method's flattened descriptor and our masked pooling; oracle masks and our semantic masks) on a
# synthetic closed lap with two walking people, tum_fr1_xyz_300 and tum_fr1_xyz_300_walker, and
# writes bench/results/loops.md (the AUC tables), loops.json and the PR plots
# (loops_<sequence>.svg, and .png where rsvg-convert exists). With --every other than 5 the files
# are named loops_every<N>* instead, so that a denser run (more loop pairs, less noisy AUC) sits
# beside the default one.
#
#   bench/loop_detection.sh [--build DIR] [--out DIR] [--every N (default 5)]
#
# Needs ../shared beside the project (or SEGSLAM_SHARED_DIR) for the real sequences and models.
set -euo pipefail

source "$(dirname "$0")/common.sh"
out="$root/out/bench_loops"
every=5
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --every) every="$2"; shift 2 ;;
    *) bench_unknown_option "$1" ;;
  esac
done
bench_require_segslam
bench_require_dir "$shared/data"
results="$root/bench/results"
mkdir -p "$out" "$results"
base=loops
[[ "$every" == 5 ]] || base="loops_every$every"

[[ -f "$out/synth_loop/groundtruth.txt" ]] ||
  "$segslam" synth --path loop --people 2 --frames 300 --seed 1 --out "$out/synth_loop" >/dev/null

# name | dataset
sequences=(
  "synth_loop|$out/synth_loop"
  "tum_fr1_xyz_300|$shared/data/tum_fr1_xyz_300"
  "tum_fr1_xyz_300_walker|$shared/data/tum_fr1_xyz_300_walker"
)

{
  echo "# Loop detection: AUC with and without the union mask"
  echo
  echo "\`bench/loop_detection.sh --every $every\`: \`segslam eval loops\` with the default thresholds"
  echo "(0.3 m, 20 deg, pairs at least 5 s apart). Machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores."
  echo
} > "$results/$base.md"
echo "[" > "$results/$base.json"
separator=""
for sequence in "${sequences[@]}"; do
  IFS='|' read -r name dataset <<< "$sequence"
  masks=(semantic)
  [[ -f "$dataset/mask.txt" ]] && masks=(oracle semantic)
  echo "== $name (masks: ${masks[*]})"
  "$segslam" --log-level warn eval loops --dataset "$dataset" --every "$every" \
    --masks "${masks[@]}" --out "$out/$name" >/dev/null
  cat "$out/$name/loops.md" >> "$results/$base.md"
  echo >> "$results/$base.md"
  { printf '%s' "$separator"; cat "$out/$name/loops.json"; } >> "$results/$base.json"
  separator=","
  cp "$out/$name/pr_curves.svg" "$results/${base}_$name.svg"
  if command -v rsvg-convert >/dev/null; then
    rsvg-convert "$results/${base}_$name.svg" -o "$results/${base}_$name.png"
  fi
done
echo "]" >> "$results/$base.json"
cat "$results/$base.md"
