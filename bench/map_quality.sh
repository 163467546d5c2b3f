#!/usr/bin/env bash
# Measures the dense map against the targets of the map issue and writes bench/results/maps.md
# (tables) and bench/results/maps.json (every run's map summary and evaluation).
#
#   bench/map_quality.sh [--build DIR] [--out DIR] [--runs N]
#
# - quality: `segslam run` (threaded, as users run it) on a rendered synthetic sequence with two
#   walking people and on tum_fr1_xyz_300_walker, each with oracle masks and without masks, then
#   `segslam eval map`: share of static-map points on the moving people (within 3 cm of their
#   ground-truth depth), completeness and accuracy against the ground-truth static surface (2 cm),
#   and on the walker the share within 0.3 m (horizontally, 0-2 m high) of the person's path. The
#   static tum_fr1_xyz_300 run, scored against the walker's path, shows how much of the true scene
#   lies in that band anyway.
# - cost: the walker with oracle masks N times with the map and N times with --no-map
#   (alternating, default 3 each); process wall and CPU time, medians.
# Needs ../shared beside the project (or SEGSLAM_SHARED_DIR).
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
build="$root/build"
out="$root/out/bench_maps"
runs=3
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    *) echo "map_quality.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
done
segslam="$build/segslam"
[[ -x "$segslam" ]] || { echo "map_quality.sh: $segslam not built (run ./setup.sh)" >&2; exit 1; }
shared="${SEGSLAM_SHARED_DIR:-$root/../shared}"
[[ -d "$shared/data" ]] || { echo "map_quality.sh: $shared/data not found (set SEGSLAM_SHARED_DIR)" >&2; exit 1; }
mkdir -p "$out" "$root/bench/results"
walker="$shared/data/tum_fr1_xyz_300_walker"
[[ -f "$out/synth_people/groundtruth.txt" ]] ||
  "$segslam" synth --out "$out/synth_people" --seed 1 --people 2 >/dev/null

results="$out/results.jsonl"
: > "$results"

# Runs segslam and appends {configuration, seconds, summary, evaluation} to the results.
measure() {  # name, dataset, masks, eval dataset ("" = none), extra run options...
  local name="$1" dataset="$2" masks="$3" eval_dataset="$4"; shift 4
  local run_dir="$out/runs/${name// /_}"
  echo "== $name"
  python3 - "$out/timing.json" "$segslam" --log-level warn run --dataset "$dataset" --seg "$masks" \
    --out "$run_dir" "$@" <<'PY'
import json, resource, subprocess, sys, time
start = time.monotonic()
subprocess.run(sys.argv[2:], check=True, stdout=subprocess.DEVNULL)
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
json.dump({"wall": time.monotonic() - start, "cpu": usage.ru_utime + usage.ru_stime},
          open(sys.argv[1], "w"))
PY
  if [[ -n "$eval_dataset" ]]; then
    "$segslam" --log-level warn eval map --run "$run_dir" --dataset "$eval_dataset" >/dev/null
  fi
  python3 - "$name" "$run_dir" "$out/timing.json" >> "$results" <<'PY'
import json, os, sys
name, run_dir, timing = sys.argv[1], sys.argv[2], json.load(open(sys.argv[3]))
row = {"configuration": name, "process_seconds": timing["wall"], "cpu_seconds": timing["cpu"],
       "summary": json.load(open(os.path.join(run_dir, "summary.json")))}
evaluation = os.path.join(run_dir, "map_evaluation.json")
if os.path.exists(evaluation):
    row["evaluation"] = json.load(open(evaluation))
print(json.dumps(row))
PY
}

measure "synth people oracle" "$out/synth_people" oracle "$out/synth_people"
measure "synth people masks off" "$out/synth_people" none "$out/synth_people"
measure "walker oracle" "$walker" oracle "$walker"
measure "walker masks off" "$walker" none "$walker"
measure "fr1_xyz_300 (no person) vs walker path" "$shared/data/tum_fr1_xyz_300" none "$walker"
for run in $(seq 1 "$runs"); do
  measure "cost walker oracle map $run" "$walker" oracle ""
  measure "cost walker oracle no-map $run" "$walker" oracle "" --no-map
done

python3 - "$results" "$root/bench/results" "$runs" <<'PY'
import json, os, statistics, subprocess, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
out_dir, runs = sys.argv[2], int(sys.argv[3])
cpu = subprocess.run(["sh", "-c", "grep -m1 'model name' /proc/cpuinfo | cut -d: -f2"],
                     capture_output=True, text=True).stdout.strip()
def pct(value):
    return "-" if value is None else f"{100 * value:.2f} %"
lines = [
    "# Dense map quality and cost",
    "",
    f"`bench/map_quality.sh --runs {runs}`: `segslam run` in threaded mode (voxel 1 cm), then "
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
with_map = [r for r in rows if r["configuration"].startswith("cost walker oracle map")]
without = [r for r in rows if r["configuration"].startswith("cost walker oracle no-map")]
if with_map and without:
    t_map = statistics.median(r["process_seconds"] for r in with_map)
    t_none = statistics.median(r["process_seconds"] for r in without)
    c_map = statistics.median(r["cpu_seconds"] for r in with_map)
    c_none = statistics.median(r["cpu_seconds"] for r in without)
    keyframe_s = statistics.median(r["summary"]["map"]["keyframe_seconds"] for r in with_map)
    build_s = statistics.median(r["summary"]["map"]["build_seconds"] for r in with_map)
    rss_map = statistics.median(r["summary"]["peak_rss_mb"] for r in with_map)
    rss_none = statistics.median(r["summary"]["peak_rss_mb"] for r in without)
    lines += [
        "",
        f"Cost on `tum_fr1_xyz_300_walker` with oracle masks, median of {runs} runs each "
        "(alternating); process wall time and CPU time (user + system, all threads):",
        "",
        "| | wall time [s] | CPU time [s] | peak RSS [MB] |",
        "| --- | --- | --- | --- |",
        f"| `--no-map` | {t_none:.2f} | {c_none:.2f} | {rss_none:.0f} |",
        f"| `--map` (default) | {t_map:.2f} | {c_map:.2f} | {rss_map:.0f} |",
        f"| overhead | {100 * (t_map / t_none - 1):+.1f} % | {100 * (c_map / c_none - 1):+.1f} % "
        f"| {rss_map - rss_none:+.0f} |",
        "",
        f"With the map: {keyframe_s:.2f} s of keyframe clouds on the map thread during tracking, "
        f"{build_s:.2f} s to assemble, clean, cluster and write the map after tracking.",
    ]
table = "\n".join(lines) + "\n"
open(os.path.join(out_dir, "maps.md"), "w").write(table)
json.dump(rows, open(os.path.join(out_dir, "maps.json"), "w"), indent=1)
print(table)
PY
