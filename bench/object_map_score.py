#!/usr/bin/env python3
"""Scores a run's objects (map/objects.json) against a synthetic sequence's ground-truth instances.

    object_map_score.py RUN_DIR DATASET_DIR [--voxel 0.05] [--stride 5]

Ground-truth objects: the instance images of every stride-th frame, back-projected with the
ground truth in the run's frame (RUN_DIR/GroundTruthAligned.txt) into voxels of --voxel metres;
instances of the room (wall, floor, ceiling) are no objects. Static objects are scored against
the instances never dynamic in the sequence, dynamic ones against the people (their whole path).
A map object matches a true object of its label at 3D IoU >= 0.5 on these voxels (one to one,
highest IoU first; a dynamic one when >= 50 % of its voxels lie on the person's path): precision = matched map objects / map objects, recall = matched true
objects / true objects. Fragments per true object: map objects lying mostly (>= 50 % of their
voxels) on it, over the true objects with at least one. Prints one JSON object.
"""
import argparse
import json
import os
import sys

import cv2
import numpy as np

ROOM = {"wall", "floor", "ceiling", "none"}


def read_list(path):
    rows = []
    with open(path) as f:
        for line in f:
            line = line.replace(",", " ").replace("\t", " ").strip()
            if line and not line.startswith("#"):
                rows.append(line.split())
    return rows


def quaternion_matrix(q):
    x, y, z, w = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def read_ply_points(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    count = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    types = {"float": "<f4", "uchar": "u1", "ushort": "<u2", "int": "<i4", "uint": "<u4"}
    fields = [(l.split()[2], types[l.split()[1]]) for l in header if l.startswith("property")]
    vertices = np.frombuffer(data[end:], dtype=np.dtype(fields), count=count)
    return np.stack([vertices["x"], vertices["y"], vertices["z"]], axis=1).astype(np.float64)


def voxels(points, size):
    return set(map(tuple, np.floor(points / size).astype(np.int64)))


def truth_voxels(dataset, run_dir, voxel, stride):
    meta = json.load(open(os.path.join(dataset, "meta.json")))
    camera = meta["camera"]
    classes = {o["instance_id"]: o for o in meta["objects"]}
    poses = {round(float(r[0]), 4): r[1:] for r in read_list(
        os.path.join(run_dir, "GroundTruthAligned.txt"))}
    depth_files = {round(float(r[0]), 4): r[1] for r in read_list(os.path.join(dataset, "depth.txt"))}
    instance_list = read_list(os.path.join(dataset, "instances.txt"))
    v, u = np.mgrid[0:camera["height"], 0:camera["width"]]
    truth = {}
    for timestamp, name in instance_list[::stride]:
        key = round(float(timestamp), 4)
        if key not in poses or key not in depth_files:
            continue
        pose = [float(x) for x in poses[key]]
        rotation, translation = quaternion_matrix(pose[3:7]), np.array(pose[0:3])
        depth = cv2.imread(os.path.join(dataset, depth_files[key]), cv2.IMREAD_UNCHANGED)
        instances = cv2.imread(os.path.join(dataset, name), cv2.IMREAD_UNCHANGED)
        z = depth.astype(np.float64) / camera["depth_factor"]
        valid = (z > 0) & (instances > 0)
        x = (u - camera["cx"]) * z / camera["fx"]
        y = (v - camera["cy"]) * z / camera["fy"]
        points = np.stack([x[valid], y[valid], z[valid]], axis=1) @ rotation.T + translation
        ids = instances[valid]
        for instance in np.unique(ids):
            if classes.get(int(instance), {}).get("class", "none") in ROOM:
                continue
            truth.setdefault(int(instance), set()).update(voxels(points[ids == instance], voxel))
    return {i: {"label": classes[i]["class"], "dynamic": classes[i]["dynamic"], "voxels": s}
            for i, s in truth.items()}


def score(map_objects, true_objects, min_voxels, by_share):
    """by_share: a map object matches by the share of its voxels on the true object (>= 0.5)
    rather than by IoU: for people, whose true voxels sweep their whole path while the map sees
    them only from its keyframes."""
    true_objects = {i: t for i, t in true_objects.items() if len(t["voxels"]) >= min_voxels}
    pairs = []
    fragments = {i: 0 for i in true_objects}
    for m, obj in enumerate(map_objects):
        for i, truth in true_objects.items():
            shared = len(obj["voxels"] & truth["voxels"])
            if not shared:
                continue
            if shared >= 0.5 * len(obj["voxels"]):
                fragments[i] += 1
            if truth["label"] == obj["label"]:
                union = len(obj["voxels"]) if by_share else len(obj["voxels"] | truth["voxels"])
                pairs.append((shared / union, m, i))
    pairs.sort(reverse=True)
    used_map, used_true, matches = set(), set(), []
    for iou, m, i in pairs:
        if iou < 0.5 or m in used_map or i in used_true:
            continue
        used_map.add(m)
        used_true.add(i)
        matches.append({"map": map_objects[m]["id"], "truth": i, "iou": round(iou, 3)})
    seen = [n for n in fragments.values() if n > 0]
    return {
        "map_objects": len(map_objects),
        "true_objects": len(true_objects),
        "matched": len(matches),
        "precision": len(matches) / len(map_objects) if map_objects else 0.0,
        "recall": len(matches) / len(true_objects) if true_objects else 0.0,
        "fragments_per_true_object": sum(seen) / len(seen) if seen else 0.0,
        "missed": sorted(f"{true_objects[i]['label']}#{i}" for i in true_objects if i not in used_true),
        "unmatched": sorted(map_objects[m]["id"] for m in range(len(map_objects)) if m not in used_map),
        "matches": matches,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run_dir")
    parser.add_argument("dataset")
    parser.add_argument("--voxel", type=float, default=0.05)
    parser.add_argument("--stride", type=int, default=5)
    parser.add_argument("--min-voxels", type=int, default=8)
    args = parser.parse_args()
    truth = truth_voxels(args.dataset, args.run_dir, args.voxel, args.stride)
    index = json.load(open(os.path.join(args.run_dir, "map", "objects.json")))["objects"]
    result = {}
    for layer, dynamic in (("static", False), ("dynamic", True)):
        objects = [{"id": o["id"], "label": o["label"],
                    "voxels": voxels(read_ply_points(os.path.join(args.run_dir, "map", o["file"])),
                                     args.voxel)}
                   for o in index if o["dynamic"] == dynamic]
        true_objects = {i: t for i, t in truth.items() if t["dynamic"] == dynamic}
        result[layer] = score(objects, true_objects, args.min_voxels, by_share=dynamic)
    json.dump(result, sys.stdout)
    print()


if __name__ == "__main__":
    main()
