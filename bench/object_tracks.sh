#!/usr/bin/env bash
# One track per walker (issue 40): person objects of `map/objects.json` after `segslam run` (map
# on) on the dev suite's composites and the held-out ones, each once `--deterministic` and with
# seeds at the camera's rate; two builds alternate run by run when --base is given. Tabulated by
# bench/object_tracks_report.py: dynamic tracks [keyframes each] / still person objects, static
# objects labelled dynamic, and how many runs have as many dynamic tracks as walkers.
#
#   bench/object_tracks.sh [--build DIR] [--base DIR] [--seeds "1 2 3"] [--out DIR]
#                          [--report FILE]
#
# Composites are made once into out/dev_suite/ (as bench/camera_rate.sh makes them).
set -euo pipefail

source "$(dirname "$0")/common.sh"
base=""
seeds="1 2 3"
out="$root/out/bench_object_tracks"
report=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --base) base="$2"; shift 2 ;;
    --seeds) seeds="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --report) report="$2"; shift 2 ;;
    *) bench_unknown_option "$1" ;;
  esac
done
bench_require_segslam
[[ -z "$base" || -x "$base/segslam" ]] || bench_fail "$base/segslam not built"
bench_require_dir "$shared/data/tum_fr1_xyz_300_walker"
bench_require_dir "$shared/tools"
/usr/bin/python3 -c "import cv2" 2>/dev/null ||
  bench_fail "/usr/bin/python3 lacks OpenCV, which ../shared/tools needs (scripts/install_deps.sh)"
suite="$root/out/dev_suite"
mkdir -p "$suite" "$out"
out=$(realpath "$out")

# name | walkers | frames | composite.py options ("" for the shared walker)
sequences=(
  "walker|1|300|"
  "fr1_p1_s11_near|1|300|--people 1 --seed 11 --distance-fraction 0.55"
  "fr1_p2_s12_fast|2|300|--people 2 --seed 12 --distance-fraction 0.6,0.8 --speed 0.8:1.2"
  "fr1_p2_s14_far|2|300|--people 2 --seed 14 --distance-fraction 0.85,1.0"
  "fr1_long_p1_s21_near|1|898|--people 1 --seed 21 --distance-fraction 0.55"
  "fr1_long_p2_s22_far|2|898|--people 2 --seed 22 --distance-fraction 0.85,1.0"
  "fr1_long_p2_s23|2|898|--people 2 --seed 23"
  "h91|1|300|--people 1 --seed 91 --distance-fraction 0.4 --speed 1.0:1.5"
  "h92|2|300|--people 2 --seed 92 --distance-fraction 0.5,0.7 --speed 0.6:1.2 --pause 0.5"
  "h93|2|300|--people 2 --seed 93 --distance-fraction 0.35,0.6 --speed 1.2:1.8"
  "h94|1|300|--people 1 --seed 94 --distance-fraction 0.3 --pause 1.5 --speed 0.4:0.8"
)

builds=("change|$build")
[[ -n "$base" ]] && builds=("base|$base" "change|$build")
: > "$out/walkers.txt"
for entry in "${sequences[@]}"; do
  IFS='|' read -r name walkers frames options <<< "$entry"
  dataset="$shared/data/tum_fr1_xyz_300_walker"
  if [[ -n "$options" ]]; then
    bench_make_composite "$suite" "$name" "$frames" "$options"
    dataset="$suite/$name"
  fi
  echo "$name $walkers" >> "$out/walkers.txt"
  for run in det $seeds; do
    mode=(--seed "$run")
    [[ "$run" == det ]] && mode=(--deterministic)
    for build_entry in "${builds[@]}"; do
      IFS='|' read -r label dir <<< "$build_entry"
      run_dir="$out/${name}__${run}__$label"
      rm -rf "$run_dir"
      "$dir/segslam" --log-level warn run --dataset "$dataset" --camera-preset freiburg1 \
        "${mode[@]}" --out "$run_dir" > "$run_dir.log" 2>&1 ||
        bench_fail "segslam run failed: see $run_dir.log"
      echo "object_tracks.sh: $name $run $label done"
    done
  done
done
if [[ -n "$report" ]]; then
  /usr/bin/python3 "$root/bench/object_tracks_report.py" "$out" > "$report"
  echo "object_tracks.sh: wrote $report"
else
  /usr/bin/python3 "$root/bench/object_tracks_report.py" "$out"
fi
