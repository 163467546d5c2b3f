#!/usr/bin/env python3
"""Tables of bench/real_starts.sh: per case, the camera-rate runs and the deterministic one.

    real_starts_report.py RUNS.jsonl --commit C --markdown OUT.md --json OUT.json
"""
import statistics

from report_runs import parse_report_arguments, write_report


def main():
    args, runs = parse_report_arguments(__doc__.split("\n")[0])
    cases = list(dict.fromkeys(r["case"] for r in runs))
    rows = []
    for case in cases:
        mine = [r for r in runs if r["case"] == case and r["mode"] == "camera_rate"]
        deterministic = [r for r in runs if r["case"] == case and r["mode"] == "deterministic"]
        ates = sorted(r["ate_m"] for r in mine)
        rows.append({
            "case": case, "frames": mine[0]["frames"] if mine else 0, "runs": len(mine),
            "ates_m": ates,
            "ate_median_m": statistics.median(ates) if ates else None,
            "ate_worst_m": ates[-1] if ates else None,
            "tracked_min_pct": min(100.0 * r["tracked_frames"] / r["frames"] for r in mine),
            "lost_max": max(r["lost_frames"] for r in mine),
            "max_step_error_m": max(r["max_step_error_m"] for r in mine),
            "jumps": sum(r["jumps"] for r in mine),
            "tracking_median_ms": statistics.median(r["tracking_median_ms"] for r in mine),
            "deterministic_ate_m": deterministic[0]["ate_m"] if deterministic else None,
        })
    every = [a for row in rows for a in row["ates_m"]]
    lines = [
        "# Starts among people",
        "",
        f"`bench/real_starts.sh` at {args.commit}: each case run as users run it (`segslam run "
        "--no-map`, 30 Hz, default masks) with seeds 1..N, and once `--deterministic`. ATE RMSE "
        "against the camera's ground truth (a Bonn sequence's markers converted); step error: the "
        "largest distance between an estimated step from one tracked frame to the next and the "
        "true one (aligned as for the ATE); jumps: steps more than 5 cm wrong.",
        "",
        "| case | frames | ATE median | ATE worst | runs (ATE) | tracked min | lost max "
        "| step error max | jumps | tracking median | deterministic |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for row in rows:
        lines.append(
            "| {case} | {frames} | {med:.4f} | {worst:.4f} | {all} | {tracked:.1f} % | {lost} | "
            "{step:.3f} m | {jumps} | {ms:.1f} ms | {det} |".format(
                case=row["case"], frames=row["frames"], med=row["ate_median_m"],
                worst=row["ate_worst_m"], all=" / ".join("%.4f" % a for a in row["ates_m"]),
                tracked=row["tracked_min_pct"], lost=row["lost_max"],
                step=row["max_step_error_m"], jumps=row["jumps"],
                ms=row["tracking_median_ms"],
                det="-" if row["deterministic_ate_m"] is None
                else "%.4f" % row["deterministic_ate_m"]))
    if every:
        lines += ["", f"All camera-rate runs: {len(every)}, median ATE "
                  f"{statistics.median(every):.4f} m, worst {max(every):.4f} m."]
    write_report(args, lines, {"cases": rows})


if __name__ == "__main__":
    main()
