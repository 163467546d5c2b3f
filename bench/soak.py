#!/usr/bin/env python3
"""One soak run: `segslam run` on a long sequence with its memory sampled over time.

    soak.py [--sweep-frames N] SEGSLAM DATASET RUN_DIR [run options...]

Samples the process's resident memory (VmRSS) every 0.25 s and prints one JSON object: the run's
frames, ATE, keyframes, map points and dense-map points (summary.json), peak RSS, the peak RSS up
to the end of each tenth of the frames and of the first sweep (N frames; default: the first
tenth), its growth per 1000 frames from the end of the first sweep to the last frame, the median
tracking time of each tenth of the run, and the RSS samples (one per second). The frames are
placed in time by the run's progress lines (stderr, passed through): the first frame when the
first line comes, then at its dataset time after the first frame's when the run plays at the
camera's rate (the default), at its share of the tracking time until the last line with --fast.
What comes after the last frame (the dense map built and written once, the evaluation) is not
growth: its peak is reported on its own ("rss_mb_after_tracking").
"""
import csv
import json
import os
import re
import statistics
import subprocess
import sys
import threading
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


def progress_times(stream, start, times):
    """Passes the run's progress lines through and keeps (seconds since start, frames done)."""
    for line in stream:
        sys.stderr.write(line)
        match = re.search(r"\] +\d+% (\d+)/(\d+)", line)
        if match:
            times.append((time.monotonic() - start, int(match.group(1))))


def main():
    args = sys.argv[1:]
    sweep_frames = None
    if args[:1] == ["--sweep-frames"]:
        sweep_frames = int(args[1])
        args = args[2:]
    segslam, dataset, run_dir = args[:3]
    run_options = args[3:]
    command = [segslam, "--log-level", "warn", "run", "--dataset", dataset, "--out", run_dir,
               *run_options]
    start = time.monotonic()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               text=True)
    progress = []  # (seconds since start, frames done)
    reader = threading.Thread(target=progress_times, args=(process.stderr, start, progress))
    reader.start()
    samples = []  # (seconds since start, MB)
    while process.poll() is None:
        mb = rss_mb(process.pid)
        if mb is not None:
            samples.append((time.monotonic() - start, mb))
        time.sleep(0.25)
    reader.join()
    if process.returncode != 0:
        sys.exit(f"soak.py: {' '.join(command)} failed with {process.returncode}")
    summary = json.load(open(os.path.join(run_dir, "summary.json")))
    with open(os.path.join(run_dir, "frame_log.csv")) as log:
        rows = list(csv.DictReader(log))
    frames = len(rows)
    tenth = max(frames // 10, 1)
    tracking = [float(r["tracking_ms"]) for r in rows]
    medians = [statistics.median(tracking[k * tenth:(k + 1) * tenth]) for k in range(10)]
    ends_of_tenths = [rows[min((k + 1) * tenth, frames) - 1] for k in range(10)]
    if len(progress) < 2:
        sys.exit(f"soak.py: {' '.join(command)} printed no progress lines")
    first_frame_at, tracking_end_at = progress[0][0], progress[-1][0]
    if "--fast" in run_options:
        # Played as fast as tracked: a frame is reached at the share of the tracking time the
        # frames before it took.
        total = max(sum(tracking), 1e-9)
        cumulative = 0.0
        reached = []
        for ms in tracking:
            cumulative += ms
            reached.append(first_frame_at + (tracking_end_at - first_frame_at) * cumulative / total)
    else:
        first = float(rows[0]["timestamp"])
        reached = [first_frame_at + float(r["timestamp"]) - first for r in rows]
    reached[-1] = tracking_end_at

    def peak_until(frame):
        before = [mb for s, mb in samples if s <= reached[frame]]
        return max(before) if before else None

    rss_at = [peak_until(min((k + 1) * tenth, frames) - 1) for k in range(10)]
    first_sweep = min(sweep_frames or tenth, frames) - 1
    rss_first_sweep = peak_until(first_sweep)
    rss_last = peak_until(frames - 1)
    growth = None
    if rss_first_sweep is not None and rss_last is not None and frames - 1 > first_sweep:
        growth = (rss_last - rss_first_sweep) / ((frames - 1 - first_sweep) / 1000.0)
    print(json.dumps({
        "dataset": os.path.basename(dataset.rstrip("/")), "options": run_options,
        "frames": frames, "wall_seconds": summary["wall_seconds"],
        "ate_rmse_m": summary.get("ate_rmse_m"), "lost_frames": summary.get("lost_frames"),
        "keyframes": summary.get("keyframes"), "map_points": summary.get("map_points"),
        "dense_keyframes": summary.get("map", {}).get("keyframes"),
        "dense_static_points": summary.get("map", {}).get("static_points"),
        "peak_rss_mb": max(mb for _, mb in samples) if samples else None,
        "rss_mb_per_tenth": rss_at, "rss_mb_after_first_sweep": rss_first_sweep,
        "rss_mb_at_last_frame": rss_last, "rss_growth_mb_per_1000_frames": growth,
        "rss_mb_after_tracking": max((mb for t, mb in samples if t > tracking_end_at),
                                     default=None),
        "tracking_median_ms_per_tenth": medians,
        "keyframes_per_tenth": [int(r["live_keyframes"]) for r in ends_of_tenths],
        "map_points_per_tenth": [int(r["live_map_points"]) for r in ends_of_tenths],
        "rss_samples": [[round(t, 2), round(mb, 1)] for t, mb in samples[::4]],
    }))


if __name__ == "__main__":
    main()
