#!/usr/bin/env python3
"""Runs segslam on a TUM RGB-D sequence from Python and evaluates it, as `segslam run` does.

    PYTHONPATH=build/python python3 examples/python/run_tum.py ../shared/data/tum_fr1_xyz_300
"""

import argparse
import time

import segslam


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dataset", help="folder in the TUM layout (rgb.txt, depth.txt, ...)")
    parser.add_argument("--seg", default="auto", help="auto, none, oracle, semantic, geometric, fused")
    parser.add_argument("--deterministic", action="store_true", help="reproducible, slower")
    parser.add_argument("--out", help="write the camera trajectory here (TUM format)")
    args = parser.parse_args()

    dataset = segslam.TumDataset(args.dataset)
    system = segslam.System(dataset.camera, seg=args.seg, deterministic=args.deterministic)
    print(f"{len(dataset)} frames, camera {dataset.camera_source}, masks {system.mask_source}, "
          f"loop candidates {system.loop_detector}")
    start = time.perf_counter()
    lost = 0
    for frame in dataset:
        # Oracle masks are the dataset's own; the other sources make theirs.
        mask = frame.mask if system.mask_source == "oracle" else None
        result = system.track(frame.timestamp, frame.rgb, frame.depth, mask)
        lost += result.state == segslam.TrackingState.LOST
    system.finish()
    seconds = time.perf_counter() - start

    trajectory = system.trajectory()
    print(f"tracked {len(trajectory)} of {len(dataset)} frames ({lost} lost) in {seconds:.1f} s, "
          f"{system.num_keyframes} keyframes")
    if args.out:
        trajectory.write_tum(args.out)
    if dataset.ground_truth is not None:
        ate = segslam.ate(dataset.ground_truth, trajectory)
        rpe = segslam.rpe(dataset.ground_truth, trajectory)
        print(f"ATE rmse {ate.rmse:.4f} m over {ate.statistics.count} poses; RPE (1 s) "
              f"{rpe.translational.rmse:.4f} m, {rpe.rotational_deg.rmse:.3f} deg rmse")


if __name__ == "__main__":
    main()
