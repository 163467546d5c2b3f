#!/usr/bin/env bash
# Threaded runs on the walker as users run them, in both playback modes, repeated because threaded
# results vary from run to run. Writes bench/results/playback_walker.md and playback_walker.json.
#
#   bench/playback.sh [--build DIR] [--out DIR] [--rounds N] [--dataset DIR]
#
# - fast: frames as fast as they load (`segslam run --fast`): the frame rate with and without the
#   network. "tracked" is the rate from the first frame taken to the last frame tracked; "end to
#   end" adds the setup before (loading the network) and the mapping left to finish after.
# - realtime: frames at the dataset's 30 Hz (`segslam run`, the default), as a camera delivers
#   them: the ATE a robot gets, and how late frames were taken up.
# Each round runs every configuration once, in turn, so that a change in the machine's load
# spreads over all of them. Medians over the rounds, every run listed in the JSON.
set -euo pipefail

source "$(dirname "$0")/common.sh"
out="$root/out/bench_playback"
rounds=3
dataset="$shared/data/tum_fr1_xyz_300_walker"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --rounds) rounds="$2"; shift 2 ;;
    --dataset) dataset="$2"; shift 2 ;;
    *) bench_unknown_option "$1" ;;
  esac
done
bench_require_segslam
bench_require_dir "$dataset"
mkdir -p "$out" "$root/bench/results"

# playback | masks | extra options
configurations=(
  "fast|none|--fast" "fast|semantic|--fast" "fast|fused|--fast"
  "realtime|none|" "realtime|semantic|" "realtime|fused|" "realtime|oracle|"
)

runs="$out/runs.jsonl"
: > "$runs"
for round in $(seq 1 "$rounds"); do
  n=0
  for configuration in "${configurations[@]}"; do
    IFS='|' read -r playback masks extra <<< "$configuration"
    n=$((n + 1))
    run_dir="$out/round${round}_$n"
    # shellcheck disable=SC2086
    "$segslam" --log-level warn run --dataset "$dataset" --out "$run_dir" --seg "$masks" --no-map \
      $extra > "$run_dir.log" 2>&1
    python3 - "$run_dir/summary.json" "$playback" "$masks" "$extra" "$round" >> "$runs" <<'PY'
import json, os, sys
summary, playback, masks, extra, round_ = sys.argv[1:6]
s = json.load(open(summary))
print(json.dumps({"playback": playback, "masks": masks, "options": extra, "round": int(round_),
                  "load_1min": os.getloadavg()[0], "summary": s}))
PY
    echo "playback.sh: round $round: $playback $masks $extra: $(tail -1 "$runs" | python3 -c \
      'import json,sys; s=json.load(sys.stdin)["summary"]; print("%.1f frames/s tracked, ATE %.4f m" % (s["tracking_frames_per_second"], s["ate_rmse_m"]))')"
  done
done

python3 - "$runs" "$root/bench/results" "$rounds" "$(basename "$dataset")" <<'PY'
import json, os, statistics, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
out_dir, rounds, name = sys.argv[2], int(sys.argv[3]), sys.argv[4]
cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
groups = {}
for r in rows:
    groups.setdefault((r["playback"], r["masks"], r["options"]), []).append(r)
fast_none = {key: statistics.median(r["summary"][key] for r in groups[("fast", "none", "--fast")])
             for key in ("tracking_frames_per_second", "frames_per_second")}
lines = [
    f"# Threaded runs on {name}: fast and realtime playback",
    "",
    f"`bench/playback.sh --rounds {rounds}`: `segslam run --no-map` (threaded), every configuration "
    f"once per round, {rounds} rounds. Machine: {cpu}, {os.cpu_count()} cores. Medians over the "
    "rounds; every run's ATE in the last column.",
    "",
    "| playback | masks | frames/s tracked | of fast none | frames/s end to end | of fast none "
    "| tracking median | network runs | frame taken up after arrival, p95 / max | ATE median "
    "| ATE of each run |",
    "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
]
for (playback, masks, _), rs in groups.items():
    med = lambda f: statistics.median(f(r["summary"]) for r in rs)
    fps = {key: med(lambda s: s[key]) for key in fast_none}
    lag = "-"
    if playback == "realtime":
        lag = f"{med(lambda s: s['realtime_lag']['p95_ms']):.0f} / {med(lambda s: s['realtime_lag']['max_ms']):.0f} ms"
    lines.append(
        f"| {playback} | {masks} "
        + "".join(f"| {fps[key]:.1f} | {100 * fps[key] / fast_none[key]:.0f} % " for key in fast_none)
        + f"| {med(lambda s: s['tracking_time']['median_ms']):.1f} ms "
        f"| {med(lambda s: s.get('network_runs', 0)):.0f} | {lag} "
        f"| {med(lambda s: s['ate_rmse_m']):.4f} m "
        f"| {', '.join('%.4f' % r['summary']['ate_rmse_m'] for r in rs)} |")
table = "\n".join(lines) + "\n"
open(os.path.join(out_dir, "playback_walker.md"), "w").write(table)
json.dump(rows, open(os.path.join(out_dir, "playback_walker.json"), "w"), indent=1)
print(table)
PY
