"""A Bonn RGB-D Dynamic sequence as published: it opens with no options (its absent depth images
left out, the Bonn camera from its name) and its ground truth, the markers' poses, comes out as
the camera's, as `segslam run` and `segslam eval` evaluate it. Skips when ../shared is missing."""

import numpy as np
import pytest

import segslam
from conftest import shared_dataset


@pytest.fixture(scope="module")
def bonn():
    return shared_dataset("rgbd_bonn_crowd_300")


def test_bonn_sequence_opens_as_published(bonn):
    dataset = segslam.TumDataset(bonn)
    assert len(dataset) == 300
    assert dataset.camera_source == "preset bonn (from folder name)"
    assert [path.name for path in dataset.absent_images] == [
        "1548339819.85514.png", "1548339826.76234.png"]


def test_bonn_ground_truth_is_the_cameras(bonn):
    dataset = segslam.TumDataset(bonn)
    assert dataset.ground_truth_frame == "bonn-markers"
    reference = segslam.Trajectory.read_tum(bonn / "groundtruth_camera.txt")
    np.testing.assert_allclose(dataset.ground_truth.positions, reference.positions, atol=2e-6)
    markers = segslam.Trajectory.read_tum(bonn / "groundtruth.txt")
    assert np.abs(markers.positions - reference.positions).max() > 0.5
    converted = segslam.Trajectory.read_tum(bonn / "groundtruth.txt", frame="bonn-markers")
    np.testing.assert_allclose(converted.poses, dataset.ground_truth.poses, atol=1e-12)
    as_published = segslam.TumDataset(bonn, ground_truth_frame="camera")
    np.testing.assert_allclose(as_published.ground_truth.positions, markers.positions)
    with pytest.raises(ValueError, match="unknown ground truth frame 'markers'"):
        segslam.Trajectory.read_tum(bonn / "groundtruth.txt", frame="markers")
