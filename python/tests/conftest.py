"""Shared fixtures of the Python module's tests: where the CLI and ../shared are, and runs of one
sequence through the CLI and through segslam.System, made once per test session."""

import os
import pathlib
import subprocess

import numpy as np
import pytest

import segslam

SOURCE_DIR = pathlib.Path(
    os.environ.get("SEGSLAM_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SHARED_DIR = pathlib.Path(os.environ.get("SEGSLAM_SHARED_DIR", SOURCE_DIR.parent / "shared"))
CLI_PATH = pathlib.Path(os.environ.get("SEGSLAM_CLI_PATH", SOURCE_DIR / "build" / "segslam"))


def shared_dataset(name):
    """A dataset of ../shared/data, or a skip naming what is missing (as the C++ tests do)."""
    path = SHARED_DIR / "data" / name
    if not (path / "rgb.txt").is_file():
        pytest.skip(f"{path} is missing: real data lives in ../shared beside the project")
    return path


@pytest.fixture(scope="session")
def cli():
    if not CLI_PATH.is_file():
        pytest.skip(f"the segslam CLI is not built at {CLI_PATH}")
    return CLI_PATH


def run_cli(cli_path, dataset, out_dir, *options):
    """`segslam run --deterministic` on `dataset` into `out_dir`."""
    subprocess.run([str(cli_path), "run", "--dataset", str(dataset), "--out", str(out_dir),
                    "--deterministic", *options], check=True, capture_output=True)
    return out_dir


def run_python(dataset_path, **options):
    """The same run through segslam.System, frame by frame; returns the finished system."""
    dataset = segslam.TumDataset(dataset_path)
    system = segslam.System(dataset.camera, deterministic=True, **options)
    oracle = options.get("seg") == "oracle"
    for frame in dataset:
        system.track(frame.timestamp, frame.rgb, frame.depth, frame.mask if oracle else None)
    system.finish()
    return system


def max_pose_difference(python_trajectory, cli_trajectory):
    """Largest difference of any pose element, after checking the timestamps pair up (the CLI's
    file keeps timestamps to 1 us, pose values to 1e-9)."""
    assert len(python_trajectory) == len(cli_trajectory)
    np.testing.assert_allclose(python_trajectory.timestamps, cli_trajectory.timestamps,
                               rtol=0, atol=1e-6)
    return float(np.max(np.abs(python_trajectory.poses - cli_trajectory.poses)))
