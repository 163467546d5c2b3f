#!/usr/bin/env python3
"""Tables of bench/trajectory_smoothing.sh: per case, the ATE as tracked and smoothed.

    trajectory_smoothing_report.py RUNS.jsonl --commit C --markdown OUT.md --json OUT.json
"""
import statistics

from report_runs import parse_report_arguments, write_report


def summarise(runs, key):
    values = sorted(r[key] for r in runs)
    return {"values": values, "median": statistics.median(values), "worst": values[-1]}


def main():
    args, runs = parse_report_arguments(__doc__.split("\n")[0])
    rows = []
    for case in dict.fromkeys(r["case"] for r in runs):
        by_mode = {m: [r for r in runs if r["case"] == case and r["mode"] == m]
                   for m in ("camera_rate", "deterministic", "oracle")}
        row = {"case": case, "runs": len(by_mode["camera_rate"]),
               "lost_max": max(r["lost_frames"] for r in by_mode["camera_rate"])}
        for key in ("ate_tracked_m", "ate_m"):
            row[key] = summarise(by_mode["camera_rate"], key)
            row["deterministic_" + key] = by_mode["deterministic"][0][key]
            if by_mode["oracle"]:
                oracle = summarise(by_mode["oracle"], key)
                row["oracle_" + key] = oracle
                row["ratio_" + key] = {"median": row[key]["median"] / oracle["median"],
                                       "worst": row[key]["worst"] / oracle["median"]}
        rows.append(row)
    lines = [
        "# Trajectory smoothing",
        "",
        f"`bench/trajectory_smoothing.sh` at {args.commit}: `segslam run --no-map` (30 Hz, default "
        "masks) with seeds 1..N, once `--deterministic`, and for composites `--seg oracle` (exact "
        "masks) seeds 1..N. Each run's ATE RMSE [m] as tracked (CameraTrajectoryTracked.txt) and "
        "smoothed (CameraTrajectory.txt): the same run, so the smoothing alone differs. Ratio: a "
        "default run's ATE over the median of the exact-mask runs, both as tracked or both "
        "smoothed.",
        "",
        "| case | runs | lost max | tracked median / worst | smoothed median / worst | change "
        "of median | deterministic tracked / smoothed | exact masks tracked / smoothed (median) "
        "| ratio median / worst, tracked | ratio median / worst, smoothed |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for row in rows:
        tracked, smoothed = row["ate_tracked_m"], row["ate_m"]
        if "oracle_ate_m" in row:
            oracle = "%.4f / %.4f" % (row["oracle_ate_tracked_m"]["median"],
                                      row["oracle_ate_m"]["median"])
            ratios = ["%.2f / %.2f" % (row[k]["median"], row[k]["worst"])
                      for k in ("ratio_ate_tracked_m", "ratio_ate_m")]
        else:
            oracle, ratios = "-", ["-", "-"]
        lines.append(
            f"| {row['case']} | {row['runs']} | {row['lost_max']} | "
            f"{tracked['median']:.4f} / {tracked['worst']:.4f} | "
            f"{smoothed['median']:.4f} / {smoothed['worst']:.4f} | "
            f"{100 * (smoothed['median'] / tracked['median'] - 1):+.0f} % | "
            f"{row['deterministic_ate_tracked_m']:.4f} / {row['deterministic_ate_m']:.4f} | "
            f"{oracle} | {ratios[0]} | {ratios[1]} |")
    write_report(args, lines, {"cases": rows})


if __name__ == "__main__":
    main()
