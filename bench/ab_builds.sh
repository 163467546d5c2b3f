#!/usr/bin/env bash
# A change against its base, as every "tried, not kept" figure is judged: two builds of segslam run
# the real crowd, the walker and dev-suite composites at 30 Hz (`segslam run --no-map --seed N`),
# base and change alternating seed by seed, so that both see the machine in the same state.
# Writes a table per sequence and build (bench/ab_builds_report.py): ATE median and worst, runs
# that lost frames (lost frames come in rare long streaks: one run's 40 outweigh twenty runs'
# none, so the count of runs says more than the sum), tracking median, keyframes, network runs.
#
#   bench/ab_builds.sh --base DIR --change DIR [--seeds "1 2 3"] [--only NAME,NAME] [--out DIR]
#                      [--report FILE]
#
# DIR: a build folder holding `segslam` (e.g. a `git worktree` of the base, built with
# scripts/build.sh). Composites are made once into out/dev_suite/ and reused.
set -euo pipefail

source "$(dirname "$0")/common.sh"
base=""
change=""
seeds="1 2 3 4 5 6"
only=""
out="$root/out/bench_ab_builds"
report=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --base) base="$2"; shift 2 ;;
    --change) change="$2"; shift 2 ;;
    --seeds) seeds="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --report) report="$2"; shift 2 ;;
    *) bench_unknown_option "$1" ;;
  esac
done
[[ -n "$base" && -n "$change" ]] || bench_fail "--base DIR and --change DIR are both needed"
for dir in "$base" "$change"; do
  [[ -x "$dir/segslam" ]] || bench_fail "$dir/segslam not built (scripts/build.sh $dir)"
done
bench_require_dir "$shared/data/rgbd_bonn_crowd_300"
bench_require_dir "$shared/tools"
/usr/bin/python3 -c "import cv2" 2>/dev/null ||
  bench_fail "/usr/bin/python3 lacks OpenCV, which ../shared/tools needs (scripts/install_deps.sh)"
suite="$root/out/dev_suite"
mkdir -p "$suite" "$out"
out=$(realpath "$out")

# name | dataset folder | camera preset | composite.py options (composites only)
sequences=(
  "bonn_crowd|$shared/data/rgbd_bonn_crowd_300||"
  "walker|$shared/data/tum_fr1_xyz_300_walker|freiburg1|"
  "fr1_p2_s12_fast|$suite/fr1_p2_s12_fast|freiburg1|--people 2 --seed 12 --distance-fraction 0.6,0.8 --speed 0.8:1.2"
  "fr1_p2_s93_near_fast|$suite/fr1_p2_s93_near_fast|freiburg1|--people 2 --seed 93 --distance-fraction 0.35,0.6 --speed 1.2:1.8"
  "fr1_p1_s11_near|$suite/fr1_p1_s11_near|freiburg1|--people 1 --seed 11 --distance-fraction 0.55"
)

for entry in "${sequences[@]}"; do
  IFS='|' read -r name dataset preset options <<< "$entry"
  if [[ -n "$only" && ",$only," != *",$name,"* ]]; then continue; fi
  if [[ -n "$options" && ! -f "$dataset/mask.txt" ]]; then
    echo "ab_builds.sh: making $name"
    # shellcheck disable=SC2086
    /usr/bin/python3 "$shared/tools/composite.py" --out "$dataset" --jpeg 95 $options \
      > "$suite/$name.log" 2>&1 || bench_fail "composite.py failed for $name (see $suite/$name.log)"
  fi
  preset_option=()
  [[ -n "$preset" ]] && preset_option=(--camera-preset "$preset")
  for seed in $seeds; do
    for build_entry in "base|$base" "change|$change"; do
      IFS='|' read -r label dir <<< "$build_entry"
      run_dir="$out/${name}_${label}_$seed"
      rm -rf "$run_dir"
      "$dir/segslam" --log-level warn run --dataset "$dataset" "${preset_option[@]}" --no-map \
        --seed "$seed" --out "$run_dir" > "$run_dir.log" 2>&1 ||
        bench_fail "segslam run failed: see $run_dir.log"
      echo "ab_builds.sh: $name $label seed $seed: $(python3 -c 'import json, sys
s = json.load(open(sys.argv[1])); print("ATE %.4f m, %d lost" % (s["ate_rmse_m"], s["lost_frames"]))' \
        "$run_dir/summary.json")"
    done
  done
done

report_option=()
[[ -n "$report" ]] && report_option=(--markdown "$report")
python3 "$root/bench/ab_builds_report.py" "$out" "${report_option[@]}"
