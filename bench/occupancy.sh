#!/usr/bin/env bash
# Occupancy maps with people: dev-suite composites (the shared walker and ../shared/tools
# composites of tum_fr1_xyz_300) run as users run them (`segslam run`: 30 Hz, default masks, map
# and occupancy on) N times and once --deterministic, each scored by `segslam eval map` against
# the run of the same frames without people (tum_fr1_xyz_300, in the same mode): ghosts (voxels
# occupied here that the people-free run sees free, and of them those with no occupied voxel of
# it within one voxel), kept (its occupied voxels occupied here within one voxel), occupied voxels
# on people, the point map's completeness and points on people, and the occupancy map's cost
# against the run's wall time. Writes bench/results/occupancy.md and occupancy.json.
#
#   bench/occupancy.sh [--build DIR] [--out DIR] [--runs N]
set -euo pipefail

source "$(dirname "$0")/common.sh"
out="$root/out/bench_occupancy"
runs=2
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    *) bench_unknown_option "$1" ;;
  esac
done
bench_require_segslam
out=$(realpath -m "$out")
base="$shared/data/tum_fr1_xyz_300"
bench_require_dir "$base"
bench_require_dir "$shared/tools"
/usr/bin/python3 -c "import cv2" 2>/dev/null ||
  bench_fail "/usr/bin/python3 lacks OpenCV, which ../shared/tools needs (scripts/install_deps.sh)"
suite="$root/out/dev_suite"
mkdir -p "$suite" "$out" "$root/bench/results"

# name | composite.py options (300 frames of tum_fr1_xyz_300, as bench/camera_rate.sh makes them)
composites=(
  "fr1_p1_s11_near|--people 1 --seed 11 --distance-fraction 0.55"
  "fr1_p2_s12_fast|--people 2 --seed 12 --distance-fraction 0.6,0.8 --speed 0.8:1.2"
  "fr1_p2_s14_far|--people 2 --seed 14 --distance-fraction 0.85,1.0"
)
datasets=("walker|$shared/data/tum_fr1_xyz_300_walker")
for entry in "${composites[@]}"; do
  IFS='|' read -r name options <<< "$entry"
  if [[ ! -f "$suite/$name/mask.txt" ]]; then
    echo "occupancy.sh: making $name"
    # shellcheck disable=SC2086
    /usr/bin/python3 "$shared/tools/composite.py" --out "$suite/$name" --jpeg 95 $options \
      > "$suite/$name.log" 2>&1 || bench_fail "composite.py failed for $name (see $suite/$name.log)"
  fi
  datasets+=("$name|$suite/$name")
done

run() {  # dataset run_dir seed options...
  local dataset=$1 run_dir=$2 seed=$3
  shift 3
  rm -rf "$run_dir"
  mkdir -p "$(dirname "$run_dir")"
  "$segslam" --log-level warn run --dataset "$dataset" --out "$run_dir" --seed "$seed" "$@" \
    > "$run_dir.log" 2>&1 || bench_fail "segslam run failed: see $run_dir.log"
}

# The people-free references, one per mode.
run "$base" "$out/reference/camera_rate" 1
run "$base" "$out/reference/deterministic" 1 --deterministic

runs_file="$out/occupancy.jsonl"
: > "$runs_file"
score() {  # name dataset run_dir mode index
  local name=$1 dataset=$2 run_dir=$3 mode=$4 index=$5
  "$segslam" --log-level warn eval map --run "$run_dir" --dataset "$dataset" \
    --occupancy-reference "$out/reference/$mode" > "$run_dir.eval.log" 2>&1 ||
    bench_fail "segslam eval map failed: see $run_dir.eval.log"
  python3 - "$run_dir" "$name" "$mode" "$index" >> "$runs_file" <<'PY'
import json, os, sys
run_dir, name, mode, index = sys.argv[1:5]
summary = json.load(open(os.path.join(run_dir, "summary.json")))
evaluation = json.load(open(os.path.join(run_dir, "map_evaluation.json")))
print(json.dumps({"sequence": name, "mode": mode, "index": int(index), "summary": summary,
                  "map_evaluation": evaluation}))
PY
  echo "occupancy.sh: $name $mode $index: $(tail -1 "$runs_file" | python3 -c \
    'import json,sys; o=json.load(sys.stdin)["map_evaluation"]["occupancy"]; print("ghosts %.2f %% (%.2f %% beyond a voxel), kept %.1f %%" % (100*o["ghost_share"], 100*o["ghost_beyond_a_voxel_share"], 100*o["kept_share"]))')"
}

for entry in "${datasets[@]}"; do
  IFS='|' read -r name dataset <<< "$entry"
  for index in $(seq 1 "$runs"); do
    run "$dataset" "$out/$name/camera_rate_$index" "$index"
    score "$name" "$dataset" "$out/$name/camera_rate_$index" camera_rate "$index"
  done
  run "$dataset" "$out/$name/deterministic_1" 1 --deterministic
  score "$name" "$dataset" "$out/$name/deterministic_1" deterministic 1
done

commit=$(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet || echo "+changes")
python3 "$root/bench/occupancy_report.py" "$runs_file" --commit "$commit" \
  --markdown "$root/bench/results/occupancy.md" --json "$root/bench/results/occupancy.json"
echo "occupancy.sh: wrote bench/results/occupancy.md"
