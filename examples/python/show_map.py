#!/usr/bin/env python3
"""Runs a TUM RGB-D sequence and shows its dense map with Open3D (Debian's python3-open3d):
the static points in their colours, the points seen on moving objects in red, the camera path
as a line. Without a display (or with --out), writes the map as PLY instead.

    PYTHONPATH=build/python python3 examples/python/show_map.py ../shared/data/tum_fr1_xyz_300
"""

import argparse
import os

import numpy as np
import open3d as o3d

import segslam


def point_cloud(cloud, colour=None):
    points = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(cloud.points.astype(np.float64)))
    colours = np.tile(colour, (len(cloud), 1)) if colour is not None else cloud.colours / 255.0
    points.colors = o3d.utility.Vector3dVector(colours)
    return points


def camera_path(trajectory):
    positions = trajectory.positions
    lines = [[i, i + 1] for i in range(len(positions) - 1)]
    return o3d.geometry.LineSet(o3d.utility.Vector3dVector(positions),
                                o3d.utility.Vector2iVector(lines))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dataset")
    parser.add_argument("--out", help="write the static map to this PLY file instead of showing it")
    args = parser.parse_args()

    dataset = segslam.TumDataset(args.dataset)
    system = segslam.System(dataset.camera)
    for frame in dataset:
        system.track(frame.timestamp, frame.rgb, frame.depth)
    dense_map = system.dense_map()  # finishes the run: the keyframes' final poses
    static = point_cloud(dense_map.static_points)
    print(f"{len(dense_map.static_points)} static points, {len(dense_map.dynamic_points)} on "
          f"moving objects, {dense_map.voxel_size * 100:.0f} cm voxels")
    if args.out or not os.environ.get("DISPLAY"):
        out = args.out or "map.ply"
        o3d.io.write_point_cloud(out, static)
        print(f"wrote {out}")
        return
    o3d.visualization.draw_geometries(
        [static, point_cloud(dense_map.dynamic_points, [1.0, 0.0, 0.0]),
         camera_path(system.trajectory())], window_name="segslam map")


if __name__ == "__main__":
    main()
