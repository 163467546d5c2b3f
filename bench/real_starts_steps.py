#!/usr/bin/env python3
"""One run of bench/real_starts.sh as a JSON line: its summary figures and the steps between
consecutive tracked frames against the true ones.

    real_starts_steps.py RUN_DIR DATASET --name N --mode M --index I

A step is the camera's motion from one tracked frame to the next frame of the sequence, when that
one is tracked too, as tracking accepted it (CameraTrajectoryTracked.txt, before smoothing). Its error is the distance between the estimated step (the estimate aligned on
the ground truth as for the ATE) and the true one: a pose that jumped where the camera cannot
have gone shows as an error of decimetres. Needs the segslam Python module (PYTHONPATH=build/python)
for the ground truth in the camera's frame (a Bonn sequence's markers converted).
"""
import argparse
import json
import os

import numpy as np

import segslam

JUMP_M = 0.05


def nearest(stamps, t):
    i = int(np.searchsorted(stamps, t))
    candidates = [j for j in (i - 1, i) if 0 <= j < len(stamps)]
    return min(candidates, key=lambda j: abs(stamps[j] - t))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run_dir")
    parser.add_argument("dataset")
    parser.add_argument("--name", required=True)
    parser.add_argument("--mode", required=True)
    parser.add_argument("--index", type=int, required=True)
    args = parser.parse_args()
    summary = json.load(open(os.path.join(args.run_dir, "summary.json")))
    dataset = segslam.TumDataset(args.dataset)
    truth = dataset.ground_truth
    tracked_file = os.path.join(args.run_dir, "CameraTrajectoryTracked.txt")
    if not os.path.exists(tracked_file):  # a run with --no-smoothing
        tracked_file = os.path.join(args.run_dir, "CameraTrajectory.txt")
    tracked = segslam.ate(truth, segslam.Trajectory.read_tum(tracked_file))
    aligned = tracked.aligned_estimate
    frames = dataset.timestamps
    est_stamps, est_positions = aligned.timestamps, aligned.positions
    true_stamps, true_positions = truth.timestamps, truth.positions
    errors, lengths = [], []
    for k in range(len(est_stamps) - 1):
        i = nearest(frames, est_stamps[k])
        if i + 1 >= len(frames) or abs(frames[i + 1] - est_stamps[k + 1]) > 1e-4:
            continue  # the next frame was not tracked
        a, b = nearest(true_stamps, est_stamps[k]), nearest(true_stamps, est_stamps[k + 1])
        if max(abs(true_stamps[a] - est_stamps[k]), abs(true_stamps[b] - est_stamps[k + 1])) > 0.02:
            continue
        step = est_positions[k + 1] - est_positions[k]
        errors.append(float(np.linalg.norm(step - (true_positions[b] - true_positions[a]))))
        lengths.append(float(np.linalg.norm(step)))
    print(json.dumps({
        "case": args.name, "mode": args.mode, "index": args.index,
        "frames": summary["frames"], "tracked_frames": summary["tracked_frames"],
        "lost_frames": summary["lost_frames"], "keyframes": summary["keyframes"],
        "ate_m": summary.get("ate_rmse_m"), "ate_tracked_m": tracked.rmse,
        "tracking_median_ms": summary["tracking_time"]["median_ms"],
        "steps": len(errors), "max_step_m": max(lengths, default=0.0),
        "max_step_error_m": max(errors, default=0.0),
        "jumps": sum(e > JUMP_M for e in errors)}))


if __name__ == "__main__":
    main()
