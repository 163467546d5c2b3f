#!/usr/bin/env bash
# Soak: memory and tracking time over long runs in mapped space (the memory issue's targets).
#
#   bench/soak.sh [--build DIR] [--out DIR] [--sweeps "9 30"] [--lsan]
#
# Sequences (made once into OUT, default out/soak): tum_fr1_xyz_300 swept back and forth N times
# (../shared/tools/long_base.py --passes N: about N x 10 s at 30 Hz), and the same with two real
# people walking through it (../shared/tools/composite.py --people 2 --seed 21), for each N of
# --sweeps, plus a 3-sweep static run whose ATE the longest static run is compared with. Each run
# is the default `segslam run` (camera rate, fused masks, map on) sampled by bench/soak.py: peak
# RSS after the first sweep and at the last frame, its growth per 1000 frames in between, RSS and
# tracking median per tenth, keyframes, map points, dense-map clouds and points. The dense map of
# each 9-sweep run is scored by `segslam eval map` (the static sweep through a copy whose masks say
# nothing moves, so that completeness is computed). --lsan: builds build-asan as
# `test.sh --sanitize` does and runs the 9-sweep sequence with people (--fast) under ASan with
# LeakSanitizer, which fails the run on any leak.
# Writes bench/results/soak.md and soak.json (every run, RSS samples included).
set -euo pipefail

source "$(dirname "$0")/common.sh"
out="$root/out/soak"
sweeps="9 30"
lsan=0
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --sweeps) sweeps="$2"; shift 2 ;;
    --lsan) lsan=1; shift ;;
    *) bench_unknown_option "$1" ;;
  esac
done
bench_require_segslam
bench_require_dir "$shared/data/tum_fr1_xyz_300"
mkdir -p "$out"
out="$(realpath "$out")"  # the masked copy links to the sweep by absolute path
/usr/bin/python3 -c "import cv2" 2>/dev/null ||
  bench_fail "/usr/bin/python3 lacks OpenCV, which ../shared/tools needs (scripts/install_deps.sh)"
mkdir -p "$out/runs" "$root/bench/results"
results="$out/soak.jsonl"
: > "$results"
sweep_frames=300  # the first sweep: the 300 frames of tum_fr1_xyz_300

static_sequence() {  # passes
  local dir="$out/sweeps$1"
  [[ -f "$dir/groundtruth.txt" ]] ||
    /usr/bin/python3 "$shared/tools/long_base.py" "$shared/data/tum_fr1_xyz_300" "$dir" \
      --passes "$1" >/dev/null
}

people_sequence() {  # passes
  local dir="$out/people$1"
  static_sequence "$1"
  [[ -f "$dir/mask.txt" ]] ||
    /usr/bin/python3 "$shared/tools/composite.py" --base "$out/sweeps$1" --out "$dir" --people 2 \
      --seed 21 --jpeg 95 >/dev/null
}

# The static sweep with masks that mark nothing: `segslam eval map` scores completeness only
# where the dataset has masks.
nothing_moves() {  # passes
  local dir="$out/sweeps$1_masked"
  [[ -f "$dir/mask.txt" && -f "$dir/rgb.txt" ]] && return
  rm -rf "$dir"
  mkdir -p "$dir/mask"
  for f in depth depth.txt groundtruth.txt rgb rgb.txt; do ln -sfn "$out/sweeps$1/$f" "$dir/$f"; done
  /usr/bin/python3 - "$dir" <<'PY'
import sys
import cv2
import numpy as np
folder = sys.argv[1]
cv2.imwrite(f"{folder}/mask/static.png", np.zeros((480, 640), np.uint8))
stamps = [line.split()[0] for line in open(f"{folder}/rgb.txt") if not line.startswith("#")]
with open(f"{folder}/mask.txt", "w") as masks:
    masks.write("# dynamic masks: nothing moves\n# timestamp filename\n")
    masks.writelines(f"{t} mask/static.png\n" for t in stamps)
PY
}

soak() {  # name, dataset, eval dataset or "", run options...
  local name="$1" dataset="$2" eval_dataset="$3"; shift 3
  local run_dir="$out/runs/$name"
  echo "== $name"
  local json
  json="$(/usr/bin/python3 "$root/bench/soak.py" --sweep-frames "$sweep_frames" "$segslam" \
    "$dataset" "$run_dir" --camera-preset freiburg1 "$@")"
  local map_eval='null'
  if [[ -n "$eval_dataset" ]]; then
    "$segslam" --log-level warn eval map --run "$run_dir" --dataset "$eval_dataset" >/dev/null
    map_eval="$(cat "$run_dir/map_evaluation.json")"
  fi
  python3 - "$name" "$json" "$map_eval" >> "$results" <<'PY'
import json, sys
run = json.loads(sys.argv[2])
run["name"] = sys.argv[1]
evaluation = json.loads(sys.argv[3])
if evaluation:
    run["map_completeness"] = evaluation.get("completeness")
    run["map_accuracy"] = evaluation.get("accuracy")
print(json.dumps(run))
PY
}

static_sequence 3
soak static3 "$out/sweeps3" ""
for n in $sweeps; do
  static_sequence "$n"
  people_sequence "$n"
  eval_static="" eval_people=""
  if [[ "$n" == 9 ]]; then
    nothing_moves "$n"
    eval_static="$out/sweeps${n}_masked"
    eval_people="$out/people$n"
  fi
  soak "static$n" "$out/sweeps$n" "$eval_static"
  soak "people$n" "$out/people$n" "$eval_people"
done

lsan_line=""
if [[ "$lsan" == 1 ]]; then
  people_sequence 9
  echo "== LeakSanitizer: people9, --fast, build-asan"
  "$root/scripts/build.sh" build-asan -DSEGSLAM_SANITIZE=ON -DSEGSLAM_BUILD_BENCH=OFF \
    -DSEGSLAM_WERROR=OFF "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" >/dev/null
  if ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 "$root/build-asan/segslam" --log-level warn run \
    --dataset "$out/people9" --camera-preset freiburg1 --fast --out "$out/runs/lsan_people9" \
    >/dev/null 2>"$out/runs/lsan_people9.log"; then
    lsan_line="LeakSanitizer (build-asan, people9 played --fast): no leak, exit 0."
  else
    lsan_line="LeakSanitizer (build-asan, people9 played --fast): FAILED, see $out/runs/lsan_people9.log."
  fi
  echo "$lsan_line"
fi

python3 - "$results" "$root/bench/results" "$lsan_line" <<'PY'
import json, os, sys
runs = [json.loads(line) for line in open(sys.argv[1])]
folder, lsan_line = sys.argv[2], sys.argv[3]
json.dump(runs, open(os.path.join(folder, "soak.json"), "w"))
by_name = {r["name"]: r for r in runs}

def f(value, digits=1):
    return "-" if value is None else f"{value:.{digits}f}"

lines = [
    "# Soak: memory and tracking time over long runs in mapped space", "",
    "`bench/soak.sh`: `segslam run --camera-preset freiburg1` (default: the camera's 30 Hz, fused",
    "masks, map on) on tum_fr1_xyz_300 swept back and forth N times (`long_base.py --passes N`),",
    "static and with two people (`composite.py --people 2 --seed 21`); one run each. Growth: peak",
    "RSS at the last frame minus after the first sweep (300 frames), per 1000 frames (frames placed",
    "in time by the run's progress lines). After tracking: the peak while the dense map is built",
    "and written once at the end. RSS over time: `soak.json`.", "",
    "| run | frames | SLAM keyframes at the end / most at the end of a tenth | map points | dense clouds | dense static points | after 1st sweep / at last frame [MB] | growth [MB / 1000 frames] | peak after tracking [MB] | tracking median 1st / last tenth [ms] | ratio | ATE [m] | map completeness / accuracy |",
    "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
]
for r in runs:
    tenths = r["tracking_median_ms_per_tenth"]
    quality = "-"
    if r.get("map_completeness") is not None:
        quality = f"{100 * r['map_completeness']:.2f} / {100 * r['map_accuracy']:.2f} %"
    lines.append(
        f"| {r['name']} | {r['frames']} | {r['keyframes']} / {max(r['keyframes_per_tenth'])} | "
        f"{r['map_points']} | "
        f"{r['dense_keyframes']} | {r['dense_static_points']} | "
        f"{f(r['rss_mb_after_first_sweep'], 0)} / {f(r['rss_mb_at_last_frame'], 0)} | "
        f"{f(r['rss_growth_mb_per_1000_frames'])} | {f(r['rss_mb_after_tracking'], 0)} | "
        f"{tenths[0]:.1f} / {tenths[-1]:.1f} | "
        f"{tenths[-1] / tenths[0]:.2f} | {f(r['ate_rmse_m'], 4)} | {quality} |")
longest = max((r for r in runs if r["name"].startswith("static")), key=lambda r: r["frames"])
if "static3" in by_name and longest["name"] != "static3":
    ratio = longest["ate_rmse_m"] / by_name["static3"]["ate_rmse_m"]
    lines += ["", f"ATE {longest['name']} / static3: {ratio:.2f}."]
if lsan_line:
    lines += ["", lsan_line]
open(os.path.join(folder, "soak.md"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY
