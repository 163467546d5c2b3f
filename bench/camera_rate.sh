#!/usr/bin/env bash
# The dev suite: dynamic sequences made from the shared real frames with ../shared/tools (one and
# two people, near and far paths, several seeds, 300 and 898 frames), each run as users run it
# (`segslam run`: 30 Hz, map on) several times, plus once --deterministic and once --seg oracle as
# references, and the static tum_fr1_xyz_300. Every run's map is scored (`segslam eval map`).
# Writes bench/results/camera_rate.md and camera_rate.json (with --busy: camera_rate_busy.*).
#
#   bench/camera_rate.sh [--build DIR] [--out DIR] [--runs N] [--busy] [--only NAME[,NAME...]]
#
# --busy keeps one of the two cores busy with another process (stress-ng --cpu 1) during the
# camera-rate runs, as on a robot's shared computer; the references are not rerun.
# Sequences are made once into out/dev_suite/ (about 1.2 GB) and reused.
set -euo pipefail

source "$(dirname "$0")/common.sh"
out="$root/out/bench_camera_rate"
runs=5
busy=0
only=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --busy) busy=1; shift ;;
    --only) only="$2"; shift 2 ;;
    *) bench_unknown_option "$1" ;;
  esac
done
bench_require_segslam
out=$(realpath -m "$out")
bench_require_dir "$shared/data/tum_fr1_xyz_300"
bench_require_dir "$shared/tools"
/usr/bin/python3 -c "import cv2" 2>/dev/null ||
  bench_fail "/usr/bin/python3 lacks OpenCV, which ../shared/tools needs (scripts/install_deps.sh)"
suite="$root/out/dev_suite"
mkdir -p "$suite" "$out" "$root/bench/results"

# name | frames | composite.py options (the base: fr1_xyz_300 or three sweeps of it)
sequences=(
  "fr1_p1_s11_near|300|--people 1 --seed 11 --distance-fraction 0.55"
  "fr1_p2_s12_fast|300|--people 2 --seed 12 --distance-fraction 0.6,0.8 --speed 0.8:1.2"
  "fr1_p2_s14_far|300|--people 2 --seed 14 --distance-fraction 0.85,1.0"
  "fr1_long_p2_s23|898|--people 2 --seed 23"
  "fr1_long_p1_s21_near|898|--people 1 --seed 21 --distance-fraction 0.55"
  "fr1_long_p2_s22_far|898|--people 2 --seed 22 --distance-fraction 0.85,1.0"
)

# name | dataset folder | whether it has people (oracle masks, map scoring)
datasets=("walker|$shared/data/tum_fr1_xyz_300_walker|1")
for sequence in "${sequences[@]}"; do
  IFS='|' read -r name frames options <<< "$sequence"
  bench_make_composite "$suite" "$name" "$frames" "$options"
  datasets+=("$name|$suite/$name|1")
done
datasets+=("static_fr1_xyz_300|$shared/data/tum_fr1_xyz_300|0")

label=$([[ $busy == 1 ]] && echo camera_rate_busy || echo camera_rate)
runs_file="$out/$label.jsonl"
: > "$runs_file"
stress_pid=""
stop_stress() { [[ -n "$stress_pid" ]] && kill "$stress_pid" 2>/dev/null; stress_pid=""; }
trap stop_stress EXIT
start_stress() {
  if command -v stress-ng > /dev/null; then
    stress-ng --cpu 1 --quiet & stress_pid=$!
  else
    sh -c 'while :; do :; done' & stress_pid=$!
  fi
}

run_one() {  # name dataset people mode index options...
  local name=$1 dataset=$2 people=$3 mode=$4 index=$5
  shift 5
  local run_dir="$out/$label/$name/${mode}_$index"
  rm -rf "$run_dir"
  mkdir -p "$(dirname "$run_dir")"
  if [[ "$mode" == camera_rate && $busy == 1 ]]; then start_stress; fi
  "$segslam" --log-level warn run --dataset "$dataset" --out "$run_dir" --seed "$index" "$@" \
    > "$run_dir.log" 2>&1 || { stop_stress; bench_fail "segslam run failed: see $run_dir.log"; }
  stop_stress
  if [[ "$people" == 1 ]]; then
    "$segslam" --log-level warn eval map --run "$run_dir" --dataset "$dataset" \
      > "$run_dir.eval.log" 2>&1 || bench_fail "segslam eval map failed: see $run_dir.eval.log"
  fi
  python3 - "$run_dir" "$name" "$mode" "$index" >> "$runs_file" <<'PY'
import json, os, sys
run_dir, name, mode, index = sys.argv[1:5]
summary = json.load(open(os.path.join(run_dir, "summary.json")))
map_file = os.path.join(run_dir, "map_evaluation.json")
map_eval = json.load(open(map_file)) if os.path.exists(map_file) else None
print(json.dumps({"sequence": name, "mode": mode, "index": int(index), "summary": summary,
                  "map_evaluation": map_eval}))
PY
  echo "camera_rate.sh: $name $mode $index: $(tail -1 "$runs_file" | python3 -c \
    'import json,sys; r=json.load(sys.stdin); s=r["summary"]; print("ATE %.4f m, %d lost" % (s.get("ate_rmse_m", float("nan")), s["lost_frames"]))')"
}

for entry in "${datasets[@]}"; do
  IFS='|' read -r name dataset people <<< "$entry"
  if [[ -n "$only" && ",$only," != *",$name,"* ]]; then continue; fi
  for index in $(seq 1 "$runs"); do run_one "$name" "$dataset" "$people" camera_rate "$index"; done
  if [[ $busy == 0 ]]; then
    run_one "$name" "$dataset" "$people" deterministic 1 --deterministic
    [[ "$people" == 1 ]] && run_one "$name" "$dataset" "$people" oracle 1 --seg oracle
  fi
done

commit=$(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet || echo "+changes")
python3 "$root/bench/camera_rate_report.py" "$runs_file" --commit "$commit" \
  --busy "$busy" --references "$out/camera_rate.jsonl" \
  --markdown "$root/bench/results/$label.md" --json "$root/bench/results/$label.json"
echo "camera_rate.sh: wrote bench/results/$label.md"
