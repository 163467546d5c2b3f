#!/usr/bin/env python3
"""Tables of bench/camera_rate.sh: per sequence, the camera-rate runs against the references.

    camera_rate_report.py RUNS.jsonl --commit C --busy 0|1 --references REF.jsonl
                          --markdown OUT.md --json OUT.json

RUNS.jsonl has one line per run ({"sequence", "mode", "index", "summary", "map_evaluation"}).
The references (--deterministic and --seg oracle runs) come from RUNS.jsonl itself, or with
--busy 1 from REF.jsonl, the unloaded pass.
"""
import argparse
import json
import os
import platform
import statistics


def cpu_name():
    try:
        with open("/proc/cpuinfo") as cpuinfo:
            for line in cpuinfo:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def load(path):
    if not path or not os.path.exists(path):
        return []
    with open(path) as lines:
        return [json.loads(line) for line in lines if line.strip()]


def on_moving_pct(run):
    evaluation = run.get("map_evaluation")
    return None if evaluation is None else 100.0 * evaluation["on_dynamic_share"]


def fmt(value, pattern):
    return "-" if value is None else pattern % value


def summarise(sequence, runs, references):
    mine = [r for r in runs if r["sequence"] == sequence and r["mode"] == "camera_rate"]
    ates = sorted(r["summary"]["ate_rmse_m"] for r in mine)
    moving = [m for m in (on_moving_pct(r) for r in mine) if m is not None]

    def reference(mode):
        found = [r for r in references if r["sequence"] == sequence and r["mode"] == mode]
        return found[0] if found else None

    deterministic, oracle = reference("deterministic"), reference("oracle")
    row = {
        "sequence": sequence,
        "frames": mine[0]["summary"]["frames"] if mine else 0,
        "runs": len(mine),
        "ate_median_m": statistics.median(ates) if ates else None,
        "ate_worst_m": ates[-1] if ates else None,
        "ate_each_m": [r["summary"]["ate_rmse_m"] for r in mine],
        "lost_frames_worst": max((r["summary"]["lost_frames"] for r in mine), default=None),
        "on_moving_median_pct": statistics.median(moving) if moving else None,
        "on_moving_worst_pct": max(moving) if moving else None,
        "tracking_median_ms": statistics.median(
            r["summary"]["tracking_time"]["median_ms"] for r in mine) if mine else None,
        "network_runs_median": statistics.median(
            r["summary"].get("network_runs", 0) for r in mine) if mine else None,
        "deterministic_ate_m": deterministic["summary"]["ate_rmse_m"] if deterministic else None,
        "deterministic_on_moving_pct": on_moving_pct(deterministic) if deterministic else None,
        "oracle_ate_m": oracle["summary"]["ate_rmse_m"] if oracle else None,
    }
    if row["oracle_ate_m"] and row["ate_median_m"] is not None:
        row["median_over_oracle"] = row["ate_median_m"] / row["oracle_ate_m"]
        row["worst_over_oracle"] = row["ate_worst_m"] / row["oracle_ate_m"]
    return row


def markdown(rows, args, title):
    lines = [f"# {title}", "",
             f"`bench/camera_rate.sh{' --busy' if args.busy else ''}` at commit {args.commit}, "
             f"{cpu_name()}, {os.cpu_count()} cores. `segslam run` as users run it (30 Hz, fused "
             "masks, map on), each sequence several times; references once each: "
             "`--deterministic` and `--seg oracle`. ATE RMSE in metres; \"on moving\" = share of "
             "the static map's points within 3 cm of a moving person (`segslam eval map`).", ""]
    if args.busy:
        lines += ["One core is kept busy by `stress-ng --cpu 1` during every run.", ""]
    lines += ["| sequence | frames | runs | ATE median | ATE worst | median / oracle | "
              "worst / oracle | lost (worst run) | on moving, median / worst | deterministic: "
              "ATE, on moving | oracle ATE | tracking median | network runs |",
              "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        lines.append(
            f"| {r['sequence']} | {r['frames']} | {r['runs']} | {fmt(r['ate_median_m'], '%.4f')} | "
            f"{fmt(r['ate_worst_m'], '%.4f')} | {fmt(r.get('median_over_oracle'), '%.2f')} | "
            f"{fmt(r.get('worst_over_oracle'), '%.2f')} | {fmt(r['lost_frames_worst'], '%d')} | "
            f"{fmt(r['on_moving_median_pct'], '%.2f')} / {fmt(r['on_moving_worst_pct'], '%.2f')} % | "
            f"{fmt(r['deterministic_ate_m'], '%.4f')}, "
            f"{fmt(r['deterministic_on_moving_pct'], '%.2f')} % | {fmt(r['oracle_ate_m'], '%.4f')} | "
            f"{fmt(r['tracking_median_ms'], '%.1f')} ms | {fmt(r['network_runs_median'], '%.0f')} |")
    lines += ["", "Every camera-rate run's ATE (m):", ""]
    for r in rows:
        lines.append(f"- {r['sequence']}: " + ", ".join("%.4f" % a for a in r["ate_each_m"]))
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("runs")
    parser.add_argument("--commit", required=True)
    parser.add_argument("--busy", type=int, default=0)
    parser.add_argument("--references")
    parser.add_argument("--markdown", required=True)
    parser.add_argument("--json", required=True)
    args = parser.parse_args()
    runs = load(args.runs)
    references = load(args.references) if args.busy else runs
    sequences = list(dict.fromkeys(r["sequence"] for r in runs))
    rows = [summarise(s, runs, references) for s in sequences]
    title = ("Camera-rate runs on the dev suite, one core busy" if args.busy
             else "Camera-rate runs on the dev suite")
    with open(args.markdown, "w") as out:
        out.write(markdown(rows, args, title))
    with open(args.json, "w") as out:
        json.dump({"commit": args.commit, "cpu": cpu_name(), "cores": os.cpu_count(),
                   "busy_core": bool(args.busy), "sequences": rows}, out, indent=1)
        out.write("\n")


if __name__ == "__main__":
    main()
