#!/usr/bin/env bash
# Loop closure: ATE with loop closing off and on (bag-of-words candidates with the union mask, the
# descriptor vote, and the CNN descriptor with the union mask: `run`'s default when the backbone
# is found, bag of words otherwise), loops accepted and
# whether each agrees with the ground truth, on drifting synthetic room laps and on the sequences
# the issue names. Writes bench/results/loop_closure.md and bench/results/loop_closure.json.
#
#   bench/loop_closure.sh [--build DIR] [--out DIR] [--reuse] [--modes "off bow vote cnn"]
#
# --reuse keeps the runs of an earlier call that finished (their summary.json exists). --modes
# picks the loop detectors compared ("off" is always run: the changes are relative to it); cnn
# needs ../shared/models/tiny_darknet_imagenet.onnx.
#
# Runs `segslam run --deterministic --no-map` (reproducible figures). A loop whose verified
# relative pose is more than 0.1 m or 5 degrees from the ground truth's counts as false.
set -euo pipefail

source "$(dirname "$0")/common.sh"
out="$root/out/bench_loop"
reuse=false
modes="off bow vote cnn"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --reuse) reuse=true; shift ;;
    --modes) modes="off ${2//off/}"; shift 2 ;;
    *) bench_unknown_option "$1" ;;
  esac
done
bench_require_segslam
mkdir -p "$out" "$root/bench/results"

render() {  # name, synth options...
  local name="$1"; shift
  [[ -f "$out/$name/groundtruth.txt" ]] || "$segslam" synth --out "$out/$name" --seed 1 "$@" >/dev/null
}
render room_320 --path room --people 0 --frames 450 --width 320 --height 240 --depth-noise kinect
render room_320_2laps --path room --laps 2 --people 0 --frames 900 --width 320 --height 240 --depth-noise kinect
render room_2laps_people --path room --laps 2 --people 2 --frames 900 --width 320 --height 240 --depth-noise kinect
render room_600 --path room --people 0 --frames 600 --depth-noise kinect
render room_people --path room --people 2 --frames 600 --depth-noise kinect
render xyz_people --path xyz --people 2

# name | dataset | extra run options
configurations=(
  "synthetic room lap 320x240|$out/room_320|--seg none"
  "synthetic room, 2 laps 320x240|$out/room_320_2laps|--seg none"
  "synthetic room, 2 laps 320x240, 2 people, oracle|$out/room_2laps_people|--seg oracle"
  "synthetic room, 2 laps 320x240, 2 people, masks off|$out/room_2laps_people|--seg none"
  "synthetic room lap 640x480|$out/room_600|--seg none"
  "synthetic room lap, 2 people, oracle|$out/room_people|--seg oracle"
  "synthetic xyz, 2 people, oracle|$out/xyz_people|--seg oracle"
  "synthetic xyz, 2 people, masks off|$out/xyz_people|--seg none"
)
if [[ -d "$shared/data" ]]; then
  configurations+=(
    "fr1_xyz_300|$shared/data/tum_fr1_xyz_300|--seg none"
    "fr1_xyz_300_walker oracle|$shared/data/tum_fr1_xyz_300_walker|--seg oracle"
    "fr1_xyz_300_walker masks off|$shared/data/tum_fr1_xyz_300_walker|--seg none"
  )
fi

results="$out/summaries.jsonl"
: > "$results"
for configuration in "${configurations[@]}"; do
  IFS='|' read -r name dataset extra <<< "$configuration"
  for mode in $modes; do
    run_dir="$out/runs/${name//[ ,]/_}_$mode"
    flag="--loop-detector $mode"
    [[ $mode == off ]] && flag="--no-loop-closing"
    echo "== $name, loop closing: $mode"
    # shellcheck disable=SC2086
    [[ $reuse == true && -f "$run_dir/summary.json" ]] ||
      "$segslam" --log-level warn run --deterministic --no-map --dataset "$dataset" --out "$run_dir" \
      $extra $flag >/dev/null
    python3 - "$name" "$mode" "$run_dir/summary.json" >> "$results" <<'PY'
import json, sys
summary = json.load(open(sys.argv[3]))
summary["configuration"], summary["loop_mode"] = sys.argv[1], sys.argv[2]
print(json.dumps(summary))
PY
  done
done

python3 - "$results" "$root/bench/results" "$(uptime)" "$modes" <<'PY'
import json, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
out_dir, load = sys.argv[2], sys.argv[3].strip()
modes = [m for m in sys.argv[4].split() if m != "off"]
by_name = {}
for row in rows:
    by_name.setdefault(row["configuration"], {})[row["loop_mode"]] = row

def loop_figures(run):
    loops = run.get("loop_closing", {}).get("loops", [])
    checked = [l for l in loops if "ground_truth_translation_error_m" in l]
    false_loops = sum(1 for l in checked if l["ground_truth_translation_error_m"] > 0.1
                      or l["ground_truth_rotation_error_deg"] > 5.0)
    worst = max((l["ground_truth_translation_error_m"] for l in checked), default=None)
    return loops, false_loops, worst

def describe_text(run):
    ms = run.get("loop_closing", {}).get("describe_ms_mean", 0.0)
    return f"; CNN {ms:.0f} ms/kf" if ms > 0.5 else ""

def change(on, off):
    return f"{100 * (on - off) / off:+.0f} %" if on is not None and off else "-"

lines = ["# Loop closure", "",
         "`bench/loop_closure.sh`: `segslam run --deterministic --no-map`, loop closing off, on with",
         "bag-of-words candidates and the union mask (`bow`, the default without the backbone), with",
         "the descriptor vote (`vote`) and with the CNN descriptor and the union mask (`cnn`,",
         "tiny_darknet pool2, masked average pooling: the default when the backbone is found).",
         "A loop is false when its verified relative pose is more than 0.1 m or",
         "5 degrees from the ground truth's. Loops: accepted / false, with the worst translation",
         f"error and the query keyframes. Load while measuring: `{load}`.", "",
         "| sequence | keyframes | ATE off (m) | " +
         " | ".join(f"ATE {m} (m) | change | loops {m}" for m in modes) + " |",
         "| --- | --- | --- | " + " | ".join("--- | --- | ---" for _ in modes) + " |"]
for name, runs in by_name.items():
    off = runs["off"]
    cells = [name, str(off.get("keyframes", "-")), f"{off.get('ate_rmse_m', float('nan')):.4f}"]
    for mode in modes:
        run = runs[mode]
        loops, false_loops, worst = loop_figures(run)
        queries = ",".join(str(l["query_keyframe"]) for l in loops)
        worst_text = f", worst {worst:.3f} m" if worst is not None else ""
        cells += [f"{run.get('ate_rmse_m', float('nan')):.4f}",
                  change(run.get("ate_rmse_m"), off.get("ate_rmse_m")),
                  f"{len(loops)} / {false_loops}{worst_text}" + (f" (kf {queries})" if queries else "")
                  + describe_text(run)]
    lines.append("| " + " | ".join(cells) + " |")
open(f"{out_dir}/loop_closure.md", "w").write("\n".join(lines) + "\n")
json.dump(rows, open(f"{out_dir}/loop_closure.json", "w"), indent=1)
print("\n".join(lines))
PY
