#!/usr/bin/env python3
"""Python's per-frame overhead over the C++ pipeline: segslam.System.track on tum_fr1_xyz_300,
threaded and as fast as frames load (as `segslam run --fast`), default masks and loop detector.
Per frame, the overhead is the wall time of the Python call minus the wall time of the C++
pipeline call inside it (TrackResult.pipeline_ms: tracking, and handing late masks and keyframes
over, which `segslam run` does per frame too): checking the numpy arrays and copying them into
the core's layout (RGB to BGR, depth), releasing and retaking the GIL, building the result. It is
set against the C++ tracking time (TrackResult.tracking_ms, the per-frame figure `segslam run`
reports). Loading the frames is not counted: the CLI loads them too. Measures; asserts nothing.

    /usr/bin/python3 bench/python_overhead.py [--build build] [--dataset DIR] [--out FILE]
"""

import argparse
import datetime
import os
import pathlib
import statistics
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
SHARED = pathlib.Path(os.environ.get("SEGSLAM_SHARED_DIR", ROOT.parent / "shared"))


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", type=pathlib.Path, default=ROOT / "build")
    parser.add_argument("--dataset", type=pathlib.Path,
                        default=SHARED / "data" / "tum_fr1_xyz_300")
    parser.add_argument("--out", type=pathlib.Path,
                        default=ROOT / "bench" / "results" / "python_overhead.md")
    return parser.parse_args()


def import_segslam(build):
    sys.path.insert(0, str(build / "python"))
    try:
        import segslam  # pylint: disable=import-outside-toplevel
    except ImportError as error:
        sys.exit(f"python_overhead.py: segslam is not built in {build / 'python'} ({error})")
    return segslam


def measure(segslam, dataset_path):
    """Per frame: (Python wall ms of track(), C++ pipeline ms, C++ tracking ms)."""
    dataset = segslam.TumDataset(dataset_path)
    system = segslam.System(dataset.camera)
    timings = []
    for frame in dataset:  # loaded outside the timed call: loading is not its overhead
        start = time.perf_counter()
        result = system.track(frame.timestamp, frame.rgb, frame.depth)
        call_ms = (time.perf_counter() - start) * 1000.0
        timings.append((call_ms, result.pipeline_ms, result.tracking_ms))
    system.finish()
    return system, timings


def report(system, timings, dataset_path):
    python_ms = [call for call, _, _ in timings]
    pipeline_ms = [pipeline for _, pipeline, _ in timings]
    tracking_ms = [tracking for _, _, tracking in timings]
    overhead_ms = [call - pipeline for call, pipeline, _ in timings]
    share = statistics.mean(overhead_ms) / statistics.mean(tracking_ms)
    median_share = statistics.median(overhead_ms) / statistics.median(tracking_ms)
    commit = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True, check=False).stdout.strip()
    rows = [
        ("Python call `System.track` (wall)", python_ms),
        ("C++ pipeline call inside it (`pipeline_ms`)", pipeline_ms),
        ("C++ tracking (`tracking_ms`, as `segslam run` reports)", tracking_ms),
        ("Python overhead (call - pipeline)", overhead_ms),
    ]
    lines = [
        "# Python overhead per frame",
        "",
        f"Written by `bench/python_overhead.py` on {datetime.date.today()} at {commit}: "
        f"`segslam.System.track` on `{dataset_path.name}` ({len(timings)} frames, threaded, "
        f"frames as fast as they load, masks `{system.mask_source}`, loop candidates "
        f"`{system.loop_detector}`), {os.cpu_count()} cores, load average "
        f"{os.getloadavg()[0]:.2f} at the end.",
        "",
        "| per frame | mean ms | median ms | p95 ms |",
        "| --- | --- | --- | --- |",
    ]
    for name, values in rows:
        p95 = sorted(values)[int(0.95 * (len(values) - 1) + 0.5)]
        lines.append(f"| {name} | {statistics.mean(values):.3f} | "
                     f"{statistics.median(values):.3f} | {p95:.3f} |")
    lines += [
        "",
        f"Python overhead: **{100.0 * share:.2f} %** of the C++ tracking time (mean over mean; "
        f"median over median {100.0 * median_share:.2f} %; target at most 5 %).",
        "",
    ]
    return "\n".join(lines)


def main():
    args = parse_arguments()
    if not (args.dataset / "rgb.txt").is_file():
        sys.exit(f"python_overhead.py: {args.dataset} not found (set SEGSLAM_SHARED_DIR)")
    segslam = import_segslam(args.build)
    system, timings = measure(segslam, args.dataset)
    text = report(system, timings, args.dataset)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(text)
    print(text)


if __name__ == "__main__":
    main()
