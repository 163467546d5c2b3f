#!/usr/bin/env bash
# Measures tracking accuracy and speed against the targets of the tracking issue and writes
# bench/results/tracking.md (a table) and bench/results/tracking.json (every run's summary).
#
#   bench/tracking_accuracy.sh [--build DIR] [--out DIR] [--runs N]
#
# Runs `segslam run --fast` threaded (tracking and local mapping on their own threads, frames as
# fast as they load), N times per configuration (default 3), and reports the median run
# by ATE. Needs ../shared beside the project (or SEGSLAM_SHARED_DIR) for the real sequences; the
# synthetic ones are rendered by `segslam synth` into the output folder.
set -euo pipefail

source "$(dirname "$0")/common.sh"
out="$root/out/bench_tracking"
runs=3
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    *) bench_unknown_option "$1" ;;
  esac
done
bench_require_segslam
bench_require_dir "$shared/data"
mkdir -p "$out" "$root/bench/results"

render() {  # name, synth options...
  local name="$1"; shift
  [[ -f "$out/$name/groundtruth.txt" ]] || "$segslam" synth --out "$out/$name" --seed 1 "$@" >/dev/null
}
render synth_static --people 0
render synth_people --people 2

# name | dataset | masks
configurations=(
  "fr1_xyz_300|$shared/data/tum_fr1_xyz_300|none"
  "fr1_xyz_300_walker oracle|$shared/data/tum_fr1_xyz_300_walker|oracle"
  "fr1_xyz_300_walker masks off|$shared/data/tum_fr1_xyz_300_walker|none"
  "synth static|$out/synth_static|none"
  "synth people oracle|$out/synth_people|oracle"
  "synth people masks off|$out/synth_people|none"
)

results="$out/summaries.jsonl"
: > "$results"
for configuration in "${configurations[@]}"; do
  IFS='|' read -r name dataset masks <<< "$configuration"
  for run in $(seq 1 "$runs"); do
    run_dir="$out/runs/${name// /_}_$run"
    echo "== $name, run $run/$runs"
    "$segslam" --log-level warn run --dataset "$dataset" --seg "$masks" --out "$run_dir" --fast >/dev/null
    python3 - "$name" "$run_dir/summary.json" >> "$results" <<'EOF'
import json, sys
summary = json.load(open(sys.argv[2]))
summary["configuration"] = sys.argv[1]
print(json.dumps(summary))
EOF
  done
done

python3 - "$results" "$root/bench/results" "$runs" <<'EOF'
import json, os, platform, statistics, subprocess, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
out_dir, runs = sys.argv[2], int(sys.argv[3])
by_name = {}
for row in rows:
    by_name.setdefault(row["configuration"], []).append(row)
cpu = subprocess.run(["sh", "-c", "grep -m1 'model name' /proc/cpuinfo | cut -d: -f2"],
                     capture_output=True, text=True).stdout.strip()
lines = [
    "# Tracking accuracy and speed",
    "",
    f"`bench/tracking_accuracy.sh --runs {runs}`: `segslam run` in threaded mode, {runs} runs per "
    "row; the row shows the run with the median ATE, the ATE column the min-max over all runs.",
    f"Machine: {cpu}, {os.cpu_count()} cores.",
    "",
    "| configuration | ATE rmse [m] | ATE over runs [m] | RPE 1 s [m / deg] | tracking median / p95 [ms] "
    "| frames/s | keyframes | lost | peak RSS [MB] |",
    "| --- | --- | --- | --- | --- | --- | --- | --- | --- |",
]
for name, group in by_name.items():
    group.sort(key=lambda r: r.get("ate_rmse_m", float("inf")))
    median = group[len(group) // 2]
    ates = [r.get("ate_rmse_m", float("nan")) for r in group]
    lines.append(
        f"| {name} | {median['ate_rmse_m']:.4f} | {min(ates):.4f}-{max(ates):.4f} "
        f"| {median['rpe_translational_rmse_m']:.4f} / {median['rpe_rotational_rmse_deg']:.2f} "
        f"| {median['tracking_time']['median_ms']:.1f} / {median['tracking_time']['p95_ms']:.1f} "
        f"| {median['frames_per_second']:.1f} | {median['keyframes']} | {median['lost_frames']} "
        f"| {median['peak_rss_mb']} |")
table = "\n".join(lines) + "\n"
open(os.path.join(out_dir, "tracking.md"), "w").write(table)
json.dump(rows, open(os.path.join(out_dir, "tracking.json"), "w"), indent=1)
print(table)
EOF
