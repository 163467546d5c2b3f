#!/usr/bin/env python3
"""Feeds segslam from one's own loop: here the frames come from image files read with OpenCV, as
they would from a camera driver or a ROS 2 callback. The camera comes from its intrinsics, and
each frame's own dynamic mask (from any segmenter of yours) can be handed over with it.

    PYTHONPATH=build/python python3 examples/python/own_loop.py ../shared/data/tum_fr1_xyz_300
"""

import argparse
import pathlib

import cv2
import numpy as np

import segslam


def frames(folder):
    """(timestamp, rgb uint8 HxWx3, raw depth uint16 HxW) of a TUM folder, in order: the colour
    images paired with the depth image listed nearest in time."""
    def listed(name):
        rows = [line.split() for line in (folder / name).read_text().splitlines()
                if line.strip() and not line.startswith("#")]
        return [(float(t), folder / path) for t, path in rows]

    depths = listed("depth.txt")
    depth_times = np.array([t for t, _ in depths])
    for timestamp, rgb_path in listed("rgb.txt"):
        nearest = int(np.argmin(np.abs(depth_times - timestamp)))
        if abs(depth_times[nearest] - timestamp) > 0.02:
            continue
        bgr = cv2.imread(str(rgb_path), cv2.IMREAD_COLOR)
        depth = cv2.imread(str(depths[nearest][1]), cv2.IMREAD_UNCHANGED)
        yield timestamp, cv2.cvtColor(bgr, cv2.COLOR_BGR2RGB), depth


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=pathlib.Path)
    args = parser.parse_args()

    # Freiburg 1 intrinsics; depth images in 1/5000 m.
    camera = segslam.Camera(640, 480, fx=517.306408, fy=516.469215, cx=318.643040,
                            cy=255.313989, distortion=(0.262383, -0.953104, -0.005358, 0.002628,
                                                       1.163314), depth_factor=5000.0)
    with segslam.System(camera, seg="geometric") as system:
        for timestamp, rgb, depth in frames(args.folder):
            # Your own dynamic mask goes here (non-zero = moving); it is added to segslam's.
            own_mask = np.zeros(depth.shape, np.uint8)
            result = system.track(timestamp, rgb, depth, mask=own_mask)
            if result.ok and result.frame_id % 30 == 0:
                x, y, z = result.pose[:3, 3]
                print(f"{timestamp:.3f}  camera at ({x:+.3f}, {y:+.3f}, {z:+.3f}) m, "
                      f"{int(np.count_nonzero(result.mask))} dynamic pixels")
    print(f"{len(system.trajectory())} frames tracked, {system.num_keyframes} keyframes")


if __name__ == "__main__":
    main()
