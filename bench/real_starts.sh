#!/usr/bin/env bash
# Starts among people: the real Bonn crowd sequence (../shared/data/rgbd_bonn_crowd_300) from its
# first frame and from frames where people walk in (200-280), the same frames played backwards from
# where two people cover much of the view (bench/reversed_sequence.py), and composites whose people
# stand near the camera in the first frames (../shared/tools); each run as users run it (`segslam
# run`: 30 Hz, default masks) N times, and once --deterministic. Per case: ATE, frames tracked,
# the largest step between consecutive tracked frames against the true one.
# Writes bench/results/real_starts.md and real_starts.json.
#
#   bench/real_starts.sh [--build DIR] [--out DIR] [--runs N] [--only NAME[,NAME...]]
set -euo pipefail

source "$(dirname "$0")/common.sh"
out="$root/out/bench_real_starts"
runs=3
bench_parse_runs_only "$@"
bench_require_segslam
out=$(realpath -m "$out")
bonn="$shared/data/rgbd_bonn_crowd_300"
bench_require_dir "$bonn"
bench_require_dir "$shared/tools"
/usr/bin/python3 -c "import cv2, numpy" 2>/dev/null ||
  bench_fail "/usr/bin/python3 lacks OpenCV or numpy, which ../shared/tools needs (scripts/install_deps.sh)"
sequences="$root/out/real_starts_sequences"
mkdir -p "$sequences" "$out" "$root/bench/results"

# The Bonn frames backwards from a frame with people in view; the folder keeps a Bonn name, so
# that its marker ground truth is converted as the source's is, and gets the source's camera with
# the rolling shutter's rows read the other way (`segslam check` writes the camera it resolves).
make_reversed() {  # first frame
  local dir="$sequences/rgbd_bonn_crowd_rev$1"
  [[ -f "$dir/camera.yaml" ]] && return
  "$segslam" --log-level warn check --dataset "$bonn" --max-frames 1 --out "$sequences/bonn_check" \
    > /dev/null 2>&1 || bench_fail "segslam check failed for $bonn"
  /usr/bin/python3 "$root/bench/reversed_sequence.py" "$bonn" "$dir" --from "$1" \
    --camera "$sequences/bonn_check/camera.yaml" > /dev/null
}

make_composite() {  # name options
  local dir="$sequences/$1"
  [[ -f "$dir/mask.txt" ]] && return
  echo "real_starts.sh: making $1"
  # shellcheck disable=SC2086
  /usr/bin/python3 "$shared/tools/composite.py" --out "$dir" --jpeg 95 $2 > "$dir.log" 2>&1 ||
    bench_fail "composite.py failed for $1 (see $dir.log)"
}

make_reversed 299
make_reversed 270
make_composite fr1_near_p1_s41 "--people 1 --seed 41 --distance-fraction 0.3 --pause 1.5"
make_composite fr1_near_p2_s42 "--people 2 --seed 42 --distance-fraction 0.3,0.5 --pause 1.0"
make_composite fr1_near_p2_s43 "--people 2 --seed 43 --distance-fraction 0.35,0.45 --speed 0.6:1.0"

# name | dataset | start frame (where people cover 20-45 % of the first view, or none yet)
cases=(
  "bonn_from0|$bonn|0"
  "bonn_from200|$bonn|200"
  "bonn_from240|$bonn|240"
  "bonn_from280|$bonn|280"
  "bonn_rev299|$sequences/rgbd_bonn_crowd_rev299|0"
  "bonn_rev270|$sequences/rgbd_bonn_crowd_rev270|0"
  "fr1_near_p1_s41_from115|$sequences/fr1_near_p1_s41|115"
  "fr1_near_p2_s42_from0|$sequences/fr1_near_p2_s42|0"
  "fr1_near_p2_s43_from25|$sequences/fr1_near_p2_s43|25"
)

runs_file="$out/real_starts.jsonl"
: > "$runs_file"
run_one() {  # name dataset start mode index options...
  local name=$1 dataset=$2 start=$3 mode=$4 index=$5
  shift 5
  local run_dir="$out/$name/${mode}_$index"
  rm -rf "$run_dir"
  mkdir -p "$(dirname "$run_dir")"
  "$segslam" --log-level warn run --dataset "$dataset" --start-frame "$start" --out "$run_dir" \
    --seed "$index" --no-map "$@" > "$run_dir.log" 2>&1 ||
    bench_fail "segslam run failed: see $run_dir.log"
  PYTHONPATH="$build/python" /usr/bin/python3 "$root/bench/real_starts_steps.py" "$run_dir" \
    "$dataset" --name "$name" --mode "$mode" --index "$index" 2> /dev/null >> "$runs_file"
  echo "real_starts.sh: $name $mode $index: $(tail -1 "$runs_file" | /usr/bin/python3 -c \
    'import json,sys; r=json.load(sys.stdin); print("ATE %.4f m, %d lost, largest step error %.3f m" % (r["ate_m"], r["lost_frames"], r["max_step_error_m"]))')"
}

for entry in "${cases[@]}"; do
  IFS='|' read -r name dataset start <<< "$entry"
  if [[ -n "$only" && ",$only," != *",$name,"* ]]; then continue; fi
  for index in $(seq 1 "$runs"); do run_one "$name" "$dataset" "$start" camera_rate "$index"; done
  run_one "$name" "$dataset" "$start" deterministic 1 --deterministic
done

commit=$(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet || echo "+changes")
/usr/bin/python3 "$root/bench/real_starts_report.py" "$runs_file" --commit "$commit" \
  --markdown "$root/bench/results/real_starts.md" --json "$root/bench/results/real_starts.json"
echo "real_starts.sh: wrote bench/results/real_starts.md"
