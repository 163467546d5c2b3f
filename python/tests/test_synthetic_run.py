"""A short synthetic sequence (rendered by `segslam synth`, so no data is needed) run through the
CLI and through segslam.System frame by frame: the same deterministic trajectory."""

import json
import subprocess
import threading

import numpy as np
import pytest

import segslam
from conftest import SHARED_DIR, max_pose_difference, run_cli, run_python

# Options both runs share; the loop detector that needs no model keeps the test self-contained.
MASK_SOURCES = ["geometric", "oracle"]


@pytest.fixture(scope="session")
def synthetic_sequence(cli, tmp_path_factory):
    folder = tmp_path_factory.mktemp("synth") / "sequence"
    subprocess.run([str(cli), "synth", "--out", str(folder), "--frames", "40", "--people", "1",
                    "--seed", "1"], check=True, capture_output=True)
    return folder


@pytest.mark.parametrize("seg", MASK_SOURCES)
def test_deterministic_python_run_equals_the_cli_run(cli, synthetic_sequence, tmp_path, seg):
    run = run_cli(cli, synthetic_sequence, tmp_path / "run", "--seg", seg, "--loop-detector",
                  "vote")
    system = run_python(synthetic_sequence, seg=seg, loop_detector="vote")
    assert system.mask_source == seg and system.loop_detector == "vote"
    cli_trajectory = segslam.Trajectory.read_tum(run / "CameraTrajectory.txt")
    assert len(cli_trajectory) > 30
    assert max_pose_difference(system.trajectory(), cli_trajectory) < 1e-7
    cli_keyframes = segslam.Trajectory.read_tum(run / "KeyFrameTrajectory.txt")
    assert max_pose_difference(system.keyframes(), cli_keyframes) < 1e-7


def test_a_map_saved_by_python_is_the_clis_and_both_load_it(cli, synthetic_sequence, tmp_path):
    """Python saves the map the CLI saves of the same run, byte for byte; Python localises in
    it without changing it, and the CLI loads the map Python saved."""
    options = ("--seg", "oracle", "--loop-detector", "vote", "--no-map")
    run_cli(cli, synthetic_sequence, tmp_path / "cli", *options, "--save-map",
            str(tmp_path / "cli.map"))
    system = run_python(synthetic_sequence, seg="oracle", loop_detector="vote", build_map=False)
    python_map = tmp_path / "python.map"
    assert system.save_map(python_map) == python_map.stat().st_size
    assert python_map.read_bytes() == (tmp_path / "cli.map").read_bytes()

    again = run_python(synthetic_sequence, seg="oracle", loop_detector="vote", build_map=False,
                       load_map=python_map, localize_only=True)
    assert again.loaded_points > 100
    assert again.loaded_points_left == again.loaded_points
    assert len(again.trajectory()) > 0.9 * len(segslam.TumDataset(synthetic_sequence))
    run = run_cli(cli, synthetic_sequence, tmp_path / "cli_loaded", *options, "--load-map",
                  str(python_map), "--localize-only")
    summary = json.loads((run / "summary.json").read_text())
    assert summary["map_file"]["loaded_points"] == again.loaded_points
    cli_trajectory = segslam.Trajectory.read_tum(run / "CameraTrajectory.txt")
    assert max_pose_difference(again.trajectory(), cli_trajectory) < 1e-7
    with pytest.raises(ValueError, match="absent.map"):
        segslam.System(segslam.TumDataset(synthetic_sequence).camera, seg="none",
                       loop_detector="vote", load_map=tmp_path / "absent.map")


def test_dataset_frames_are_numpy_with_ground_truth(synthetic_sequence):
    dataset = segslam.TumDataset(synthetic_sequence)
    assert len(dataset) == 40 and dataset.has_masks
    frames = list(dataset)
    assert len(frames) == 40
    first, last = dataset[0], dataset[-1]
    assert first.rgb.dtype == np.uint8 and first.rgb.shape == (480, 640, 3)
    assert first.depth.dtype == np.float32 and first.depth.shape == (480, 640)
    assert set(np.unique(first.mask)) <= {0, 255}
    assert last.timestamp == frames[-1].timestamp == dataset.timestamps[-1]
    assert len(dataset.ground_truth) >= 40
    with pytest.raises(IndexError):
        dataset[40]
    with pytest.raises(ValueError, match="rgb.txt"):
        segslam.TumDataset(synthetic_sequence / "rgb")


def test_trajectory_is_read_while_another_thread_tracks(synthetic_sequence):
    """The GIL is released while C++ works, and a system's calls from several threads take
    turns: a reader thread polls the trajectory while this one tracks."""
    dataset = segslam.TumDataset(synthetic_sequence)
    system = segslam.System(dataset.camera, seg="oracle", loop_detector="vote")
    done = threading.Event()
    lengths = []

    def poll():
        while not done.is_set():
            lengths.append(len(system.trajectory()))

    reader = threading.Thread(target=poll)
    reader.start()
    for frame in list(dataset)[:20]:
        system.track(frame.timestamp, frame.rgb, frame.depth, frame.mask)
    done.set()
    reader.join()
    assert lengths == sorted(lengths) and len(lengths) > 1
    cloud = system.dense_map().static_points
    assert len(cloud) > 1000 and cloud.points.dtype == np.float32
    assert cloud.colours.shape == (len(cloud), 3) and cloud.labels.shape == (len(cloud),)
    assert len(system.trajectory()) > 15


def test_segmenter_gives_mask_and_labels(synthetic_sequence):
    model = SHARED_DIR / "models" / "espnetv2_voc_384.onnx"
    if not model.is_file():
        pytest.skip(f"{model} is missing: models live in ../shared beside the project")
    segmenter = segslam.Segmenter(model=model)
    assert "person" in segmenter.dynamic_classes
    rgb = segslam.TumDataset(synthetic_sequence)[20].rgb
    mask, labels = segmenter.segment(rgb[:240])  # any size
    assert mask.shape == labels.shape == (240, 640) and mask.dtype == labels.dtype == np.uint8
    assert set(np.unique(mask)) <= {0, 255} and labels.max() < len(segmenter.classes)
    with pytest.raises(TypeError, match="uint8"):
        segmenter.segment(rgb.astype(np.float32))
    with pytest.raises(ValueError, match="shape"):
        segmenter.segment(rgb[:, :, :2])


def test_the_occupancy_map_of_a_run_reads_into_numpy(cli, synthetic_sequence, tmp_path):
    run = run_cli(cli, synthetic_sequence, tmp_path / "run", "--seg", "oracle", "--loop-detector",
                  "vote")
    occupancy = segslam.OccupancyMap(run / "map" / "occupancy.bt")
    assert occupancy.resolution == pytest.approx(0.05)
    assert occupancy.occupied.shape[1] == 3 and len(occupancy.occupied) > 100
    assert len(occupancy.free) > len(occupancy.occupied)
    states = occupancy.state(np.vstack([occupancy.occupied[:3], occupancy.free[:3],
                                        [[1e3, 1e3, 1e3]]]))
    assert states.tolist() == [1, 1, 1, 0, 0, 0, -1]
    with pytest.raises(ValueError, match="occupancy.json: not an OctoMap binary occupancy map"):
        segslam.OccupancyMap(run / "map" / "occupancy.json")
