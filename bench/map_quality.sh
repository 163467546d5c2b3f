#!/usr/bin/env bash
# Measures the dense map against the targets of the map issue.
#
#   bench/map_quality.sh [--build DIR] [--out DIR] [--runs N] [--part all|quality|cost]
#
# - quality (bench/results/maps.md, maps.json): `segslam run --fast` (threaded) on a
#   rendered synthetic sequence with two walking people and on tum_fr1_xyz_300_walker, each with
#   oracle masks and without masks, then `segslam eval map`: share of static-map points on the
#   moving people (within 3 cm of their ground-truth depth), completeness and accuracy against the
#   ground-truth static surface (2 cm), and on the walker the share within 0.3 m (horizontally,
#   0-2 m high) of the person's path. The static tum_fr1_xyz_300 run, scored against the walker's
#   path, shows how much of the true scene lies in that band anyway.
# - cost (bench/results/map_overhead.md, map_overhead.json): tum_fr1_xyz_300, threaded, N times
#   with the map and N times with --no-map (alternating, default 3 each): process wall and CPU
#   time, peak RSS, medians (played fast), the machine's load average around each run, and where the map's
#   time goes.
# The objects of the map: bench/object_map.sh.
# Needs ../shared beside the project (or SEGSLAM_SHARED_DIR).
set -euo pipefail

source "$(dirname "$0")/common.sh"
out="$root/out/bench_maps"
runs=3
part=all
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --part) part="$2"; shift 2 ;;
    *) bench_unknown_option "$1" ;;
  esac
done
bench_require_segslam
bench_require_dir "$shared/data"
mkdir -p "$out" "$root/bench/results"
walker="$shared/data/tum_fr1_xyz_300_walker"
cpu_name="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"

# Runs segslam and appends {configuration, seconds, load, summary, evaluation} to
# $results.
measure() {  # name, dataset, masks, eval dataset ("" = none), extra run options...
  local name="$1" dataset="$2" masks="$3" eval_dataset="$4"; shift 4
  local run_dir="$out/runs/${name// /_}"
  echo "== $name"
  python3 - "$out/timing.json" "$segslam" --log-level warn run --dataset "$dataset" --seg "$masks" \
    --out "$run_dir" "$@" <<'PY'
import json, os, resource, subprocess, sys, time
load_before = os.getloadavg()[0]
start = time.monotonic()
subprocess.run(sys.argv[2:], check=True, stdout=subprocess.DEVNULL)
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
json.dump({"wall": time.monotonic() - start, "cpu": usage.ru_utime + usage.ru_stime,
           "load": [load_before, os.getloadavg()[0]]}, open(sys.argv[1], "w"))
PY
  if [[ -n "$eval_dataset" ]]; then
    "$segslam" --log-level warn eval map --run "$run_dir" --dataset "$eval_dataset" >/dev/null
  fi
  python3 - "$name" "$run_dir" "$out/timing.json" >> "$results" <<'PY'
import json, os, sys
name, run_dir, timing = sys.argv[1], sys.argv[2], json.load(open(sys.argv[3]))
row = {"configuration": name, "process_seconds": timing["wall"], "cpu_seconds": timing["cpu"],
       "load_average_1min": timing["load"],
       "summary": json.load(open(os.path.join(run_dir, "summary.json")))}
evaluation = os.path.join(run_dir, "map_evaluation.json")
if os.path.exists(evaluation):
    row["evaluation"] = json.load(open(evaluation))
print(json.dumps(row))
PY
}

quality() {
  [[ -f "$out/synth_people/groundtruth.txt" ]] ||
    "$segslam" synth --out "$out/synth_people" --seed 1 --people 2 >/dev/null
  results="$out/quality.jsonl"
  : > "$results"
  measure "synth people oracle" "$out/synth_people" oracle "$out/synth_people" --fast
  measure "synth people masks off" "$out/synth_people" none "$out/synth_people" --fast
  measure "walker oracle" "$walker" oracle "$walker" --fast
  measure "walker masks off" "$walker" none "$walker" --fast
  measure "fr1_xyz_300 (no person) vs walker path" "$shared/data/tum_fr1_xyz_300" none "$walker" --fast
  python3 - "$results" "$root/bench/results" "$cpu_name" <<'PY'
import json, os, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
out_dir, cpu = sys.argv[2], sys.argv[3]
def pct(value):
    return "-" if value is None else f"{100 * value:.2f} %"
lines = [
    "# Dense map quality",
    "",
    "`bench/map_quality.sh --part quality`: `segslam run` in threaded mode (voxel 1 cm), then "
    "`segslam eval map` in the ground-truth frame (the run's camera poses aligned onto the ground truth's).",
    f"Machine: {cpu}, {os.cpu_count()} cores (shared with other work while measured).",
    "",
    "| configuration | static points | dynamic points | on moving people (3 cm) | near person path "
    "(0.3 m horizontal, 0-2 m high) | completeness (2 cm) | accuracy (2 cm) | ATE [m] |",
    "| --- | --- | --- | --- | --- | --- | --- | --- |",
]
for row in rows:
    if "evaluation" not in row:
        continue
    e, m = row["evaluation"], row["summary"].get("map", {})
    lines.append(
        f"| {row['configuration']} | {e['static_points']} | {m.get('dynamic_points', '-')} "
        f"| {pct(e.get('on_dynamic_share'))} | {pct(e.get('near_person_path_share'))} "
        f"| {pct(e.get('completeness'))} | {pct(e.get('accuracy'))} "
        f"| {e['trajectory_ate_rmse_m']:.4f} |")
table = "\n".join(lines) + "\n"
open(os.path.join(out_dir, "maps.md"), "w").write(table)
json.dump(rows, open(os.path.join(out_dir, "maps.json"), "w"), indent=1)
print(table)
PY
}

cost() {
  results="$out/cost.jsonl"
  : > "$results"
  for run in $(seq 1 "$runs"); do
    measure "cost map $run" "$shared/data/tum_fr1_xyz_300" none "" --fast
    measure "cost no-map $run" "$shared/data/tum_fr1_xyz_300" none "" --fast --no-map
  done
  python3 - "$results" "$root/bench/results" "$runs" "$cpu_name" <<'PY'
import json, os, statistics, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
out_dir, runs, cpu = sys.argv[2], int(sys.argv[3]), sys.argv[4]
with_map = [r for r in rows if r["configuration"].startswith("cost map")]
without = [r for r in rows if r["configuration"].startswith("cost no-map")]
def median(rows, value):
    return statistics.median(value(r) for r in rows)
def loads(rows):
    return ", ".join(f"{r['load_average_1min'][0]:.1f}-{r['load_average_1min'][1]:.1f}" for r in rows)
wall = [median(rs, lambda r: r["process_seconds"]) for rs in (without, with_map)]
cpu_s = [median(rs, lambda r: r["cpu_seconds"]) for rs in (without, with_map)]
tracking = [median(rs, lambda r: r["summary"]["wall_seconds"]) for rs in (without, with_map)]
rss = [median(rs, lambda r: r["summary"]["peak_rss_mb"]) for rs in (without, with_map)]
step = lambda key: median(with_map, lambda r: r["summary"]["map"]["timings"][key])
build = median(with_map, lambda r: r["summary"]["map"]["build_seconds"])
m = with_map[0]["summary"]["map"]
lines = [
    "# Dense map cost",
    "",
    f"`bench/map_quality.sh --part cost --runs {runs}`: `segslam run` (threaded, `--seg none`, "
    "voxel 1 cm) on `tum_fr1_xyz_300` with the map and with `--no-map`, alternating; medians of "
    f"{runs} runs each. Machine: {cpu}, {os.cpu_count()} cores, shared with other work: 1-minute "
    "load average before-after each run in the last column.",
    "",
    "| | process wall [s] | tracking loop wall [s] | CPU time [s] | peak RSS [MB] | load |",
    "| --- | --- | --- | --- | --- | --- |",
    f"| `--no-map` | {wall[0]:.2f} | {tracking[0]:.2f} | {cpu_s[0]:.2f} | {rss[0]:.0f} | {loads(without)} |",
    f"| map (default) | {wall[1]:.2f} | {tracking[1]:.2f} | {cpu_s[1]:.2f} | {rss[1]:.0f} | {loads(with_map)} |",
    f"| overhead | {100 * (wall[1] / wall[0] - 1):+.1f} % | {100 * (tracking[1] / tracking[0] - 1):+.1f} % "
    f"| {100 * (cpu_s[1] / cpu_s[0] - 1):+.1f} % | {rss[1] - rss[0]:+.0f} | |",
    "",
    f"Where the map's time goes (medians; {m['keyframes']} keyframes, {m['static_points']} static "
    "points): CPU time of the keyframe clouds, mostly on the low-priority map thread beside "
    f"tracking: back-projection {step('back_projection_cpu_s'):.2f} s, voxelising "
    f"{step('keyframe_voxels_cpu_s'):.2f} s; after tracking ({build:.2f} s in all, writing "
    f"included): merging {step('merging_s'):.2f} s, outlier removal "
    f"{step('outlier_removal_s'):.2f} s, objects {step('objects_s'):.2f} s.",
]
table = "\n".join(lines) + "\n"
open(os.path.join(out_dir, "map_overhead.md"), "w").write(table)
json.dump(rows, open(os.path.join(out_dir, "map_overhead.json"), "w"), indent=1)
print(table)
PY
}

case "$part" in
  quality) quality ;;
  cost) cost ;;
  all) quality; cost ;;
  *) echo "map_quality.sh: unknown part '$part' (all, quality, cost)" >&2; exit 2 ;;
esac
