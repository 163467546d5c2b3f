#!/usr/bin/env python3
"""One soak run: `segslam run` on a long sequence with its memory sampled over time.

    soak.py SEGSLAM DATASET RUN_DIR [run options...]

Samples the process's resident memory (VmRSS) every 0.25 s and prints one JSON object: the run's
frames, ATE, keyframes, map points and dense-map points (summary.json), peak RSS, the RSS after
each tenth of the frames (from the time the frame log says each frame was reached), its growth
per 1000 frames after the first tenth, and the median tracking time of each tenth of the run.
"""
import csv
import json
import os
import statistics
import subprocess
import sys
import time


def rss_mb(pid):
    try:
        with open(f"/proc/{pid}/status") as status:
            for line in status:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1]) / 1024.0
    except OSError:
        return None
    return None


def main():
    segslam, dataset, run_dir = sys.argv[1:4]
    command = [segslam, "--log-level", "warn", "run", "--dataset", dataset, "--out", run_dir,
               *sys.argv[4:]]
    start = time.monotonic()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL)
    samples = []  # (seconds since start, MB)
    while process.poll() is None:
        mb = rss_mb(process.pid)
        if mb is not None:
            samples.append((time.monotonic() - start, mb))
        time.sleep(0.25)
    if process.returncode != 0:
        sys.exit(f"soak.py: {' '.join(command)} failed with {process.returncode}")
    summary = json.load(open(os.path.join(run_dir, "summary.json")))
    with open(os.path.join(run_dir, "frame_log.csv")) as log:
        rows = list(csv.DictReader(log))
    frames = len(rows)
    tenth = max(frames // 10, 1)
    tracking = [float(r["tracking_ms"]) for r in rows]
    medians = [statistics.median(tracking[k * tenth:(k + 1) * tenth]) for k in range(10)]
    # The frames were played as fast as tracked: the k-th tenth ends at the share of the
    # tracking time its frames took, after the start-up before the first frame.
    setup = samples[0][0] if samples else 0.0
    loop = summary["tracking_seconds"]
    cumulative = [sum(tracking[:(k + 1) * tenth]) for k in range(10)]
    rss_at = []
    for k in range(10):
        t = setup + loop * cumulative[k] / max(cumulative[-1], 1e-9)
        before = [mb for s, mb in samples if s <= t]
        rss_at.append(max(before) if before else None)
    growth = None
    if rss_at[0] is not None and rss_at[-1] is not None and frames > tenth:
        growth = (rss_at[-1] - rss_at[0]) / ((frames - tenth) / 1000.0)
    print(json.dumps({
        "dataset": os.path.basename(dataset.rstrip("/")), "options": sys.argv[4:],
        "frames": frames, "wall_seconds": summary["wall_seconds"],
        "ate_rmse_m": summary.get("ate_rmse_m"), "lost_frames": summary.get("lost_frames"),
        "keyframes": summary.get("keyframes"), "map_points": summary.get("map_points"),
        "dense_keyframes": summary.get("map", {}).get("keyframes"),
        "dense_static_points": summary.get("map", {}).get("static_points"),
        "peak_rss_mb": max(mb for _, mb in samples) if samples else None,
        "rss_mb_per_tenth": rss_at, "rss_growth_mb_per_1000_frames": growth,
        "tracking_median_ms_per_tenth": medians,
        "rss_samples": samples[::4],
    }))


if __name__ == "__main__":
    main()
