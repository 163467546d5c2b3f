#!/usr/bin/env python3
"""Helpers of bench/map_sessions.sh.

  map_sessions_score.py score SESSION1_RUN SESSION1_GT SESSION2_RUN SESSION2_GT
      One JSON object: the multi-session ATE (session 2's trajectory mapped onto the ground truth
      with the rigid transform that aligns session 1's, no new alignment), session 2's own ATE
      (its own rigid alignment), and the session figures of session 2's summary.json.
  map_sessions_score.py frames-from SRC DST FIRST
      DST: the TUM sequence SRC from frame FIRST on (image folders linked).
  map_sessions_score.py chair LOADED_MAP AFTER_MAP GROUNDTRUTH
      Points of the map file LOADED_MAP near where the synthetic room's chair_1 stands before it is
      pushed, and how many of them AFTER_MAP still holds (docs/map_file.md for the layout).
"""
import json
import os
import struct
import sys

import numpy as np

# chair_1's place before the push (src/segslam/synth/room_layout.cc, chairPush): world metres,
# z up; points within 0.4 m across the floor and below 1.2 m are the chair's.
CHAIR_XY = np.array([3.175, 1.2])


def read_tum(path):
    poses = {}
    with open(path) as f:
        for line in f:
            fields = line.replace(",", " ").split()
            if not fields or fields[0].startswith("#"):
                continue
            poses[float(fields[0])] = np.array([float(v) for v in fields[1:4]])
    return poses


def associate(estimate, truth, max_difference=0.02):
    truth_times = np.array(sorted(truth))
    pairs = []
    for t in sorted(estimate):
        i = int(np.argmin(np.abs(truth_times - t)))
        if abs(truth_times[i] - t) <= max_difference:
            pairs.append((estimate[t], truth[truth_times[i]]))
    est = np.array([p[0] for p in pairs])
    gt = np.array([p[1] for p in pairs])
    return est, gt


def rigid_alignment(est, gt):
    """R, t minimising |gt - (R est + t)| (Horn / Umeyama without scale)."""
    mu_e, mu_g = est.mean(0), gt.mean(0)
    u, _, vt = np.linalg.svd((gt - mu_g).T @ (est - mu_e))
    d = np.diag([1.0, 1.0, np.sign(np.linalg.det(u @ vt))])
    rotation = u @ d @ vt
    return rotation, mu_g - rotation @ mu_e


def rmse(est, gt, rotation, translation):
    errors = gt - (est @ rotation.T + translation)
    return float(np.sqrt((errors ** 2).sum(1).mean()))


def read_tum_poses(path):
    poses = []
    for line in open(path):
        fields = line.split()
        if not fields or fields[0].startswith("#"):
            continue
        x, y, z, w = (float(v) for v in fields[4:8])
        rotation = np.array([
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
        poses.append((rotation, np.array([float(v) for v in fields[1:4]])))
    return poses


def map_points(path):
    """Map point id -> position of a map file (version 1)."""
    data = open(path, "rb").read()
    offset = 16
    sizes = []
    for _ in range(3):
        _, size = struct.unpack_from("<IQ", data, offset)
        sizes.append(size)
        offset += 12
    offset += 8 + sizes[0] + sizes[1]
    (count,) = struct.unpack_from("<I", data, offset)
    offset += 4
    points = {}
    for _ in range(count):
        (point_id,) = struct.unpack_from("<Q", data, offset)
        points[point_id] = np.array(struct.unpack_from("<3d", data, offset + 20))
        offset += 20 + 24 + 24 + 32 + 16 + 8 + 4 + 4 + 1
        (observations,) = struct.unpack_from("<I", data, offset)
        offset += 4 + 12 * observations
    return points


def chair(loaded_map, after_map, ground_truth):
    rotation, translation = read_tum_poses(ground_truth)[0]  # the map frame: the first camera
    after = map_points(after_map)
    mapped = left = 0
    for point_id, position in map_points(loaded_map).items():
        world = rotation @ position + translation
        if np.linalg.norm(world[:2] - CHAIR_XY) > 0.4 or world[2] > 1.2:
            continue
        mapped += 1
        left += point_id in after
    print(json.dumps({"chair_points": mapped, "chair_points_left": left}))


def frames_from(source, destination, first):
    timestamps = [float(line.split()[0]) for line in open(os.path.join(source, "rgb.txt"))
                  if line.strip() and not line.startswith("#")]
    start = timestamps[first] - 1e-4
    os.makedirs(destination, exist_ok=True)
    for name in os.listdir(source):
        path = os.path.join(source, name)
        target = os.path.join(destination, name)
        if os.path.isdir(path):
            if not os.path.lexists(target):
                os.symlink(os.path.abspath(path), target)
            continue
        keep = []
        for line in open(path).read().splitlines():
            fields = line.split()
            if (name.endswith(".txt") and name != "groundtruth.txt" and fields
                    and not line.startswith("#")):
                try:
                    if float(fields[0]) < start:
                        continue
                except ValueError:
                    pass
            keep.append(line)
        open(target, "w").write("\n".join(keep) + "\n")


def score(run1, truth1, run2, truth2):
    est1, gt1 = associate(read_tum(os.path.join(run1, "CameraTrajectory.txt")), read_tum(truth1))
    rotation, translation = rigid_alignment(est1, gt1)
    est2, gt2 = associate(read_tum(os.path.join(run2, "CameraTrajectory.txt")), read_tum(truth2))
    own_rotation, own_translation = rigid_alignment(est2, gt2)
    summary = json.load(open(os.path.join(run2, "summary.json")))
    session = summary.get("map_file", {})
    first = session.get("first_tracked_frame")
    print(json.dumps({
        "session1_ate_m": rmse(est1, gt1, rotation, translation),
        "multi_session_ate_m": rmse(est2, gt2, rotation, translation),
        "own_ate_m": rmse(est2, gt2, own_rotation, own_translation),
        "poses": len(est2),
        "frames": summary["frames"],
        "first_tracked_frame": first,
        "lost_after_first": None if first is None else summary["lost_frames"] - first,
        "tracking_median_ms": summary["tracking_time"]["median_ms"],
        "keyframes": summary["keyframes"],
        "load_seconds": session.get("load_seconds"),
        "loaded_bytes": session.get("loaded_bytes"),
        "saved_bytes": session.get("saved_bytes"),
        "loaded_points": session.get("loaded_points"),
        "loaded_points_culled": session.get("loaded_points_culled"),
    }))


if __name__ == "__main__":
    command, arguments = sys.argv[1], sys.argv[2:]
    if command == "score":
        score(*arguments)
    elif command == "frames-from":
        frames_from(arguments[0], arguments[1], int(arguments[2]))
    elif command == "chair":
        chair(*arguments)
    else:
        sys.exit(f"map_sessions_score.py: unknown command {command}")
