#!/usr/bin/env bash
# The written camera trajectory smoothed (optim::smoothTrajectory) against the same run's poses as
# tracked (CameraTrajectoryTracked.txt): the smoothing changes no pose tracking uses, so both come
# from one run and differ by the smoothing alone. Cases: the real Bonn crowd from frames 0, 200
# and 240, the static tum_fr1_xyz_300, and composites with walkers (../shared/data's walker, the
# dev suite's, held-out ones); each run as users run it (`segslam run --no-map`, 30 Hz, default
# masks) with seeds 1..N, once --deterministic, and for the composites with exact masks
# (--seg oracle, seeds 1..N) as the reference of the camera-rate ratio.
# Writes bench/results/trajectory_smoothing.md and trajectory_smoothing.json.
#
#   bench/trajectory_smoothing.sh [--build DIR] [--out DIR] [--runs N] [--only NAME[,NAME...]]
set -euo pipefail

source "$(dirname "$0")/common.sh"
out="$root/out/bench_trajectory_smoothing"
runs=3
bench_parse_runs_only "$@"
bench_require_segslam
out=$(realpath -m "$out")
data="$shared/data"
bench_require_dir "$data/rgbd_bonn_crowd_300"
suite="$root/out/dev_suite"
mkdir -p "$suite" "$out" "$root/bench/results"
bench_make_composite "$suite" fr1_p2_s12_fast 300 \
  "--people 2 --seed 12 --distance-fraction 0.6,0.8 --speed 0.8:1.2"
bench_make_composite "$suite" fr1_p2_s93_near_fast 300 \
  "--people 2 --seed 93 --distance-fraction 0.35,0.6 --speed 1.2:1.8"
bench_make_composite "$suite" h91 300 "--people 1 --seed 91 --distance-fraction 0.4 --speed 1.0:1.5"
bench_make_composite "$suite" h92 300 \
  "--people 2 --seed 92 --distance-fraction 0.5,0.7 --speed 0.6:1.2 --pause 0.5"
bench_make_composite "$suite" h93 300 \
  "--people 2 --seed 93 --distance-fraction 0.35,0.6 --speed 1.2:1.8"
bench_make_composite "$suite" h94 300 \
  "--people 1 --seed 94 --distance-fraction 0.3 --pause 1.5 --speed 0.4:0.8"

# name | dataset | start frame | composite (has exact masks)
cases=(
  "bonn_from0|$data/rgbd_bonn_crowd_300|0|no"
  "bonn_from200|$data/rgbd_bonn_crowd_300|200|no"
  "bonn_from240|$data/rgbd_bonn_crowd_300|240|no"
  "tum_fr1_xyz_300|$data/tum_fr1_xyz_300|0|no"
  "walker|$data/tum_fr1_xyz_300_walker|0|yes"
  "s12|$suite/fr1_p2_s12_fast|0|yes"
  "s93|$suite/fr1_p2_s93_near_fast|0|yes"
  "h91|$suite/h91|0|yes"
  "h92|$suite/h92|0|yes"
  "h93|$suite/h93|0|yes"
  "h94|$suite/h94|0|yes"
)

runs_file="$out/trajectory_smoothing.jsonl"
: > "$runs_file"
run_one() {  # name dataset start mode index options...
  local name=$1 dataset=$2 start=$3 mode=$4 index=$5
  shift 5
  local run_dir="$out/$name/${mode}_$index"
  rm -rf "$run_dir"
  mkdir -p "$(dirname "$run_dir")"
  local preset=()
  [[ "$name" != bonn* ]] && preset=(--camera-preset freiburg1)
  "$segslam" --log-level warn run --dataset "$dataset" "${preset[@]}" --start-frame "$start" \
    --out "$run_dir" --seed "$index" --no-map "$@" > "$run_dir.log" 2>&1 ||
    bench_fail "segslam run failed: see $run_dir.log"
  "$segslam" eval --json --gt "$dataset/groundtruth.txt" \
    --est "$run_dir/CameraTrajectoryTracked.txt" > "$run_dir/tracked_evaluation.json" ||
    bench_fail "segslam eval failed for $run_dir"
  /usr/bin/python3 - "$run_dir" "$name" "$mode" "$index" >> "$runs_file" << 'PY'
import json, sys
run_dir, name, mode, index = sys.argv[1:]
summary = json.load(open(run_dir + "/summary.json"))
tracked = json.load(open(run_dir + "/tracked_evaluation.json"))
print(json.dumps({"case": name, "mode": mode, "index": int(index),
                  "lost_frames": summary["lost_frames"], "ate_m": summary["ate_rmse_m"],
                  "ate_tracked_m": tracked["ate"]["translational"]["rmse"],
                  "rpe_m": summary["rpe_translational_rmse_m"],
                  "rpe_tracked_m": tracked["rpe"]["translational"]["rmse"]}))
PY
  echo "trajectory_smoothing.sh: $name $mode $index: $(tail -1 "$runs_file" | /usr/bin/python3 -c \
    'import json,sys; r=json.load(sys.stdin); print("ATE %.4f m smoothed, %.4f m tracked" % (r["ate_m"], r["ate_tracked_m"]))')"
}

for entry in "${cases[@]}"; do
  IFS='|' read -r name dataset start composite <<< "$entry"
  if [[ -n "$only" && ",$only," != *",$name,"* ]]; then continue; fi
  for index in $(seq 1 "$runs"); do run_one "$name" "$dataset" "$start" camera_rate "$index"; done
  run_one "$name" "$dataset" "$start" deterministic 1 --deterministic
  if [[ "$composite" == yes ]]; then
    for index in $(seq 1 "$runs"); do
      run_one "$name" "$dataset" "$start" oracle "$index" --seg oracle
    done
  fi
done

commit=$(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet || echo "+changes")
/usr/bin/python3 "$root/bench/trajectory_smoothing_report.py" "$runs_file" --commit "$commit" \
  --markdown "$root/bench/results/trajectory_smoothing.md" \
  --json "$root/bench/results/trajectory_smoothing.json"
echo "trajectory_smoothing.sh: wrote bench/results/trajectory_smoothing.md"
