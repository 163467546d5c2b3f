#!/usr/bin/env bash
# Measures the object map against the targets of the object issue.
#
#   bench/object_map.sh [--build DIR] [--out DIR]
#
# - Synthetic (`segslam synth`, three scenes: xyz path with two people, a room lap with one, a
#   loop with two): `segslam run --deterministic` with the dataset's ground-truth labels and
#   instances (`--seg oracle`) and with the network's labels (`--seg semantic`); each run's
#   objects scored by bench/object_map_score.py (precision and recall at 3D IoU >= 0.5, map objects
#   per true object).
# - Real frames (tum_fr1_xyz_300, tum_fr1_xyz_300_walker): `--seg semantic --deterministic` and the
#   default camera-rate run; objects per label against the counts read off the frames
#   (TRUE_COUNTS below).
# - Cost: the map's object step (summary.json map.timings.objects_s) against the run's wall time.
# Writes bench/results/object_map.md and object_map.json. Needs ../shared (or SEGSLAM_SHARED_DIR).
set -euo pipefail

source "$(dirname "$0")/common.sh"
out="$root/out/bench_objects"
bench_parse_build_out "$@"
bench_require_segslam
bench_require_dir "$shared/data"
/usr/bin/python3 -c "import cv2" 2>/dev/null ||
  bench_fail "/usr/bin/python3 lacks OpenCV, which object_map_score.py needs (scripts/install_deps.sh)"
mkdir -p "$out/runs" "$root/bench/results"
results="$out/object_map.jsonl"
: > "$results"

# What the frames show (README of ../shared/data and a look at them): four monitors (the one in
# front, one behind it, the grey one on the right, a small one far right), two chairs (an empty
# office chair on the left, the sitting person's, mostly hidden), two joined desks, one person
# sitting still; the walker adds one walking person.
TRUE_COUNTS='{"tum_fr1_xyz_300": {"monitor": 4, "chair": 2, "table": 2, "person (dynamic)": 1},
 "tum_fr1_xyz_300_walker": {"monitor": 4, "chair": 2, "table": 2, "person (dynamic)": 2}}'

synth() {  # name, synth options...
  local name="$1"; shift
  [[ -f "$out/$name/groundtruth.txt" ]] || "$segslam" synth --out "$out/$name" "$@" >/dev/null 2>&1
}

run() {  # kind, name, dataset, run options...
  local kind="$1" name="$2" dataset="$3"; shift 3
  local run_dir="$out/runs/${name}_${kind}"
  echo "== $name ($kind)"
  "$segslam" --log-level warn run --dataset "$dataset" --out "$run_dir" "$@" >/dev/null
  local score='null'
  if [[ -f "$dataset/instances.txt" ]]; then  # ground-truth instances: a synthetic sequence
    score="$(/usr/bin/python3 "$root/bench/object_map_score.py" "$run_dir" "$dataset")"
  fi
  python3 - "$name" "$kind" "$run_dir" "$score" >> "$results" <<'PY'
import json, os, sys
name, kind, run_dir, score = sys.argv[1], sys.argv[2], sys.argv[3], json.loads(sys.argv[4])
summary = json.load(open(os.path.join(run_dir, "summary.json")))
objects = json.load(open(os.path.join(run_dir, "map", "objects.json")))["objects"]
print(json.dumps({"sequence": name, "kind": kind, "score": score,
                  "wall_seconds": summary["wall_seconds"],
                  "objects_seconds": summary["map"]["timings"]["objects_s"],
                  "keyframes": summary["map"]["keyframes"],
                  "objects": [{k: o[k] for k in ("id", "label", "dynamic", "confidence",
                                                  "keyframes", "points")} for o in objects]}))
PY
}

synth synth_xyz_p2_s1 --seed 1 --people 2
synth synth_room_p1_s2 --seed 2 --people 1 --path room --frames 360
synth synth_loop_p2_s3 --seed 3 --people 2 --path loop --frames 300
for name in synth_xyz_p2_s1 synth_room_p1_s2 synth_loop_p2_s3; do
  run oracle "$name" "$out/$name" --seg oracle --deterministic
  run semantic "$name" "$out/$name" --seg semantic --deterministic
done
for name in tum_fr1_xyz_300 tum_fr1_xyz_300_walker; do
  run semantic "$name" "$shared/data/$name" --seg semantic --deterministic
  run default "$name" "$shared/data/$name"
done
python3 "$root/bench/object_map_report.py" "$results" "$TRUE_COUNTS" \
  "$root/bench/results/object_map.md" "$root/bench/results/object_map.json"
