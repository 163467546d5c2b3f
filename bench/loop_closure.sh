#!/usr/bin/env bash
# Loop closure: ATE with loop closing on and off, loops accepted and whether each agrees with the
# ground truth, on a drifting synthetic lap and on the sequences the issue names. Writes
# bench/results/loop_closure.md and bench/results/loop_closure.json.
#
#   bench/loop_closure.sh [--build DIR] [--out DIR]
#
# Runs `segslam run --deterministic` (reproducible figures). A loop whose verified relative pose
# is more than 0.1 m or 5 degrees from the ground truth's counts as false.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
build="$root/build"
out="$root/out/bench_loop"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    *) echo "loop_closure.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
done
segslam="$build/segslam"
[[ -x "$segslam" ]] || { echo "loop_closure.sh: $segslam not built (run ./setup.sh)" >&2; exit 1; }
shared="${SEGSLAM_SHARED_DIR:-$root/../shared}"
mkdir -p "$out" "$root/bench/results"

render() {  # name, synth options...
  local name="$1"; shift
  [[ -f "$out/$name/groundtruth.txt" ]] || "$segslam" synth --out "$out/$name" --seed 1 "$@" >/dev/null
}
render room_320 --path room --people 0 --frames 450 --width 320 --height 240 --depth-noise kinect
render room_600 --path room --people 0 --frames 600 --depth-noise kinect
render room_people --path room --people 2 --frames 600 --depth-noise kinect
render xyz_people --path xyz --people 2

# name | dataset | extra run options
configurations=(
  "synthetic room lap 320x240|$out/room_320|--seg none"
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
  for mode in on off; do
    run_dir="$out/runs/${name//[ ,]/_}_$mode"
    flag=""
    [[ $mode == off ]] && flag="--no-loop-closing"
    echo "== $name, loop closing $mode"
    # shellcheck disable=SC2086
    "$segslam" --log-level warn run --deterministic --dataset "$dataset" --out "$run_dir" $extra $flag >/dev/null
    python3 - "$name" "$mode" "$run_dir/summary.json" >> "$results" <<'PY'
import json, sys
summary = json.load(open(sys.argv[3]))
summary["configuration"], summary["loop_mode"] = sys.argv[1], sys.argv[2]
print(json.dumps(summary))
PY
  done
done

python3 - "$results" "$root/bench/results" <<'PY'
import json, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
out_dir = sys.argv[2]
by_name = {}
for row in rows:
    by_name.setdefault(row["configuration"], {})[row["loop_mode"]] = row
lines = ["# Loop closure", "",
         "`bench/loop_closure.sh`: `segslam run --deterministic`, loop closing on and off. A loop is",
         "false when its verified relative pose is more than 0.1 m or 5 degrees from the ground truth's.", "",
         "| sequence | ATE off (m) | ATE on (m) | change | loops accepted | false loops | worst loop error (m) |",
         "| --- | --- | --- | --- | --- | --- | --- |"]
for name, modes in by_name.items():
    on, off = modes["on"], modes["off"]
    loops = on.get("loop_closing", {}).get("loops", [])
    checked = [l for l in loops if "ground_truth_translation_error_m" in l]
    errors = [l["ground_truth_translation_error_m"] for l in checked]
    false_loops = sum(1 for l in checked if l["ground_truth_translation_error_m"] > 0.1
                      or l["ground_truth_rotation_error_deg"] > 5.0)
    ate_on, ate_off = on.get("ate_rmse_m"), off.get("ate_rmse_m")
    change = f"{100 * (ate_on - ate_off) / ate_off:+.0f} %" if ate_on and ate_off else "-"
    worst = f"{max(errors):.3f}" if errors else "-"
    lines.append(f"| {name} | {ate_off:.4f} | {ate_on:.4f} | {change} | {len(loops)} | {false_loops} | {worst} |")
open(f"{out_dir}/loop_closure.md", "w").write("\n".join(lines) + "\n")
json.dump(rows, open(f"{out_dir}/loop_closure.json", "w"), indent=1)
print("\n".join(lines))
PY
