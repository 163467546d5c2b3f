"""Numpy in and out of the module without any data: round trips, and bad input that must raise
TypeError or ValueError with a clear message instead of crashing the interpreter."""

import numpy as np
import pytest

import segslam


def small_camera():
    return segslam.Camera(64, 48, 50.0, 50.0, 31.5, 23.5, depth_factor=1000.0)


def rigid_poses(count, seed=0):
    rng = np.random.default_rng(seed)
    poses = np.tile(np.eye(4), (count, 1, 1))
    for pose in poses:
        q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        pose[:3, :3] = q * np.sign(np.linalg.det(q))
        pose[:3, 3] = rng.normal(size=3)
    return poses


@pytest.fixture
def system():
    return segslam.System(small_camera(), seg="none", loop_closing=False, build_map=False,
                          deterministic=True)


def frame_images(camera):
    rgb = np.zeros((camera.height, camera.width, 3), np.uint8)
    depth = np.ones((camera.height, camera.width), np.float32)
    return rgb, depth


def test_camera_presets_yaml_and_intrinsics_round_trip(tmp_path):
    assert "freiburg1" in segslam.Camera.presets()
    fr1 = segslam.Camera.preset("freiburg1")
    fr1.to_yaml(tmp_path / "camera.yaml")
    again = segslam.Camera.from_yaml(tmp_path / "camera.yaml")
    assert (again.fx, again.cy, again.distortion) == (fr1.fx, fr1.cy, fr1.distortion)
    camera = small_camera()
    np.testing.assert_array_equal(camera.intrinsics,
                                  [[50.0, 0.0, 31.5], [0.0, 50.0, 23.5], [0.0, 0.0, 1.0]])
    assert camera.depth_factor == 1000.0 and "width=64" in repr(camera)


def test_bad_cameras_are_value_errors():
    with pytest.raises(ValueError, match="preset"):
        segslam.Camera.preset("freiburg9")
    with pytest.raises(ValueError):
        segslam.Camera(-1, 48, 50.0, 50.0, 31.5, 23.5)
    with pytest.raises(ValueError):
        segslam.Camera.from_yaml("/nonexistent/camera.yaml")


def test_trajectory_round_trips_through_numpy_and_tum_files(tmp_path):
    poses = rigid_poses(5)
    stamps = np.arange(5) * 0.5 + 1.0
    trajectory = segslam.Trajectory(stamps, poses)
    assert len(trajectory) == 5
    np.testing.assert_array_equal(trajectory.timestamps, stamps)
    np.testing.assert_array_equal(trajectory.poses, poses)
    np.testing.assert_array_equal(trajectory.positions, poses[:, :3, 3])
    trajectory.write_tum(tmp_path / "t.txt")
    read = segslam.Trajectory.read_tum(tmp_path / "t.txt")
    np.testing.assert_allclose(read.poses, poses, atol=1e-8)


def test_bad_trajectories_are_rejected():
    poses = rigid_poses(3)
    stamps = np.array([0.0, 1.0, 2.0])
    with pytest.raises(TypeError, match="float64"):
        segslam.Trajectory(stamps.astype(np.float32), poses)
    with pytest.raises(TypeError, match="float64"):
        segslam.Trajectory(stamps, poses.astype(np.float32))
    with pytest.raises(ValueError, match=r"\(3, 4, 4\)"):
        segslam.Trajectory(stamps, poses[:2])
    with pytest.raises(ValueError, match="increase"):
        segslam.Trajectory(np.array([0.0, 2.0, 1.0]), poses)
    with pytest.raises(ValueError, match="not finite"):
        segslam.Trajectory(np.array([0.0, np.nan, 1.0]), poses)
    scaled = poses.copy()
    scaled[1, :3, :3] *= 2.0
    with pytest.raises(ValueError, match=r"poses\[1\]'s rotation"):
        segslam.Trajectory(stamps, scaled)
    with pytest.raises(TypeError):
        segslam.Trajectory("not an array", poses)


def test_ate_and_rpe_of_a_moved_copy():
    poses = rigid_poses(50, seed=3)
    stamps = np.arange(50) * 0.1
    ground_truth = segslam.Trajectory(stamps, poses)
    moved = poses.copy()
    moved[:, 0, 3] += 5.0  # a translation of the whole estimate: SE(3) alignment removes it
    ate = segslam.ate(ground_truth, segslam.Trajectory(stamps, moved))
    assert ate.rmse < 1e-9 and ate.statistics.count == 50 and ate.errors.shape == (50,)
    np.testing.assert_allclose(ate.alignment[:3, 3], [-5.0, 0.0, 0.0], atol=1e-9)
    rpe = segslam.rpe(ground_truth, ground_truth)
    assert rpe.translational.rmse < 1e-12 and rpe.pairs > 0
    with pytest.raises(ValueError, match="alignment"):
        segslam.ate(ground_truth, ground_truth, alignment="affine")
    with pytest.raises(ValueError, match="delta_unit"):
        segslam.rpe(ground_truth, ground_truth, delta_unit="years")
    with pytest.raises(ValueError):  # no pose matches in time
        segslam.ate(ground_truth, segslam.Trajectory(stamps + 100.0, poses))


def test_track_rejects_wrong_dtypes_shapes_and_sizes(system):
    camera = system.camera
    rgb, depth = frame_images(camera)
    with pytest.raises(TypeError, match="rgb must be a numpy array of dtype uint8, not float32"):
        system.track(0.0, rgb.astype(np.float32), depth)
    with pytest.raises(ValueError, match=r"rgb must have shape \(height, width, 3\), not \(48, 64\)"):
        system.track(0.0, rgb[:, :, 0], depth)
    with pytest.raises(ValueError, match="camera's images are 64x48"):
        system.track(0.0, np.zeros((40, 64, 3), np.uint8), depth)
    with pytest.raises(TypeError, match="uint16.*float32.*not float64"):
        system.track(0.0, rgb, depth.astype(np.float64))
    with pytest.raises(ValueError, match="depth must have shape"):
        system.track(0.0, rgb, np.ones((48, 64, 1), np.float32))
    with pytest.raises(TypeError, match="mask"):
        system.track(0.0, rgb, depth, mask=np.zeros((48, 64), np.int32))
    with pytest.raises(TypeError, match="mask"):
        system.track(0.0, rgb, depth, mask=[[0]])
    with pytest.raises(ValueError, match="mask is 32x48"):
        system.track(0.0, rgb, depth, mask=np.zeros((48, 32), np.uint8))
    with pytest.raises(TypeError):
        system.track(0.0, "rgb", depth)
    with pytest.raises(ValueError, match="finite"):
        system.track(float("nan"), rgb, depth)


def test_track_takes_views_raw_depth_and_bool_masks_and_checks_time(system):
    camera = system.camera
    rgb, depth = frame_images(camera)
    # A non-contiguous view (every other column of a wider image) is copied, not misread.
    wide = np.zeros((camera.height, camera.width * 2, 3), np.uint8)
    mask = np.zeros((camera.height, camera.width), bool)
    mask[:10, :10] = True
    result = system.track(0.0, wide[:, ::2], depth, mask=mask)
    assert result.frame_id == 0 and isinstance(result.state, segslam.TrackingState)
    assert result.mask.dtype == np.uint8 and result.mask.shape == (48, 64)
    assert int(np.count_nonzero(result.mask)) == 100 and result.mask[0, 0] == 255
    raw = np.full((camera.height, camera.width), 1000, np.uint16)
    assert system.track(0.1, rgb, raw).frame_id == 1
    with pytest.raises(ValueError, match="timestamps must increase"):
        system.track(0.1, rgb, depth)
    system.finish()
    assert system.finished
    with pytest.raises(ValueError, match="finish"):
        system.track(0.2, rgb, depth)


def test_bad_system_options_are_value_errors():
    camera = small_camera()
    with pytest.raises(ValueError, match="unknown mask source 'magic'"):
        segslam.System(camera, seg="magic")
    with pytest.raises(ValueError, match="loop_detector"):
        segslam.System(camera, seg="none", loop_detector="psychic")
    with pytest.raises(ValueError, match="features"):
        segslam.System(camera, seg="none", features=5)
    with pytest.raises(ValueError):
        segslam.System(camera, seg="semantic", model="/nonexistent/net.onnx")
    with pytest.raises(TypeError):
        segslam.System(camera, "none")  # options are keyword-only
    with pytest.raises(ValueError, match="build_map"):
        segslam.System(camera, seg="none", build_map=False).dense_map()


def test_segmenter_rejects_bad_images_and_models():
    with pytest.raises(ValueError):
        segslam.Segmenter(model="/nonexistent/net.onnx")
    with pytest.raises(ValueError):
        segslam.Segmenter(model_config="/nonexistent/model.yaml")


def test_log_levels_and_module_help():
    segslam.set_log_level("warn")
    with pytest.raises(ValueError, match="known"):
        segslam.set_log_level("loud")
    assert "numpy" in segslam.__doc__.lower() and "rgb" in segslam.System.track.__doc__
    assert segslam.SEMANTIC_CLASSES[0] == "none"
