#!/usr/bin/env bash
# Rolling-shutter compensation on and off: each sequence run as users run it (`segslam run`: 30 Hz,
# default masks, --no-map) with its preset's readout and with the same camera at readout 0 (a
# camera YAML `preset: P, rolling_shutter_readout: 0`), the two alternating, N seeds; and once
# --deterministic each. Sequences: the shared real ones (rgbd_bonn_crowd_300, tum_fr1_xyz_300,
# tum_fr1_xyz_300_walker) and the composites of the dev suite that exist under out/dev_suite
# (bench/camera_rate.sh makes them). Writes bench/results/rolling_shutter_runs.md.
#
#   bench/rolling_shutter.sh [--build DIR] [--out DIR] [--runs N] [--only NAME[,NAME...]]
set -euo pipefail

source "$(dirname "$0")/common.sh"
out="$root/out/bench_rolling_shutter"
runs=3
bench_parse_runs_only "$@"
bench_require_segslam
out=$(realpath -m "$out")
mkdir -p "$out" "$root/bench/results"

cases=("bonn|$shared/data/rgbd_bonn_crowd_300|bonn"
       "fr1|$shared/data/tum_fr1_xyz_300|freiburg1"
       "walker|$shared/data/tum_fr1_xyz_300_walker|freiburg1")
for dir in "$root"/out/dev_suite/fr1_*; do
  [[ -f "$dir/rgb.txt" ]] && cases+=("$(basename "$dir")|$dir|freiburg1")
done

for preset in bonn freiburg1; do
  printf 'camera:\n  preset: %s\n  rolling_shutter_readout: 0\n' "$preset" > "$out/$preset-global.yaml"
done

run_one() {  # name dataset preset variant mode(seed N | deterministic)
  local name=$1 dataset=$2 preset=$3 variant=$4 mode=$5
  local dir="$out/$variant/${name}_$mode" camera=(--camera-preset "$preset")
  [[ $variant == off ]] && camera=(--camera "$out/$preset-global.yaml")
  local timing=(--seed "$mode")
  [[ $mode == det ]] && timing=(--deterministic)
  "$segslam" run --dataset "$dataset" "${camera[@]}" --no-map "${timing[@]}" --out "$dir" \
    > "$dir.log" 2>&1 || bench_fail "segslam run failed: $dir.log"
}

for entry in "${cases[@]}"; do
  IFS='|' read -r name dataset preset <<< "$entry"
  [[ -n $only && ",$only," != *",$name,"* ]] && continue
  bench_require_dir "$dataset"
  mkdir -p "$out/on" "$out/off"
  for mode in det $(seq 1 "$runs"); do
    for variant in on off; do
      echo "rolling_shutter.sh: $name $variant $mode"
      run_one "$name" "$dataset" "$preset" "$variant" "$mode"
    done
  done
done

/usr/bin/python3 - "$out" "$root/bench/results/rolling_shutter_runs.md" "$runs" <<'PY'
import csv, json, statistics, sys
from pathlib import Path
out, result, runs = Path(sys.argv[1]), Path(sys.argv[2]), int(sys.argv[3])
names = sorted({p.name.rsplit("_", 1)[0] for p in (out / "on").iterdir() if p.is_dir()})
def run(variant, name, mode):
    d = out / variant / f"{name}_{mode}"
    s = json.loads((d / "summary.json").read_text())
    rows = list(csv.DictReader(open(d / "frame_log.csv")))
    return s["ate_rmse_m"], s["lost_frames"], statistics.median(float(r["tracking_ms"]) for r in rows)
lines = ["# Rolling-shutter compensation on / off (`bench/rolling_shutter.sh`)", "",
         f"ATE RMSE [m] (lost frames when any); 30 Hz seeds 1-{runs}, the two variants alternating;",
         "tracking: median per frame [ms] over the 30 Hz runs.", "",
         "| sequence | deterministic on / off | 30 Hz on | 30 Hz off | median on / off | tracking on / off |",
         "| --- | --- | --- | --- | --- | --- |"]
def cell(r): return f"{r[0]:.4f}" + (f" ({r[1]} lost)" if r[1] else "")
for name in names:
    det = [run(v, name, "det") for v in ("on", "off")]
    rate = {v: [run(v, name, m) for m in range(1, runs + 1)] for v in ("on", "off")}
    med = {v: statistics.median(r[0] for r in rate[v]) for v in rate}
    trk = {v: statistics.median(r[2] for r in rate[v]) for v in rate}
    lines.append(f"| {name} | {cell(det[0])} / {cell(det[1])} | {' '.join(cell(r) for r in rate['on'])} | "
                 f"{' '.join(cell(r) for r in rate['off'])} | {med['on']:.4f} / {med['off']:.4f} | "
                 f"{trk['on']:.1f} / {trk['off']:.1f} |")
result.write_text("\n".join(lines) + "\n")
print(result)
PY
