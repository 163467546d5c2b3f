"""Type stub of the `segslam` extension module (python/*.cc); docs/python.md describes it."""

import enum
import os
import pathlib
from typing import Iterator, List, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, os.PathLike[str]]

__version__: str
SEMANTIC_CLASSES: list[str]

def set_log_level(level: str) -> None: ...

class Camera:
    name: str
    width: int
    height: int
    fx: float
    fy: float
    cx: float
    cy: float
    distortion: list[float]  # k1, k2, p1, p2, k3
    depth_factor: float
    fps: float
    def __init__(self, width: int, height: int, fx: float, fy: float, cx: float, cy: float,
                 distortion: Sequence[float] = ..., depth_factor: float = 5000.0,
                 fps: float = 30.0, name: str = "custom") -> None: ...
    @staticmethod
    def preset(name: str) -> Camera: ...
    @staticmethod
    def presets() -> list[str]: ...
    @staticmethod
    def from_yaml(path: _Path) -> Camera: ...
    def to_yaml(self, path: _Path) -> None: ...
    @property
    def intrinsics(self) -> npt.NDArray[np.float64]: ...

class Trajectory:
    def __init__(self, timestamps: npt.NDArray[np.float64],
                 poses: npt.NDArray[np.float64]) -> None: ...
    @staticmethod
    def read_tum(path: _Path, *, frame: str = "camera") -> Trajectory: ...
    def write_tum(self, path: _Path) -> None: ...
    @property
    def timestamps(self) -> npt.NDArray[np.float64]: ...
    @property
    def poses(self) -> npt.NDArray[np.float64]: ...
    @property
    def positions(self) -> npt.NDArray[np.float64]: ...
    def __len__(self) -> int: ...

class Frame:
    timestamp: float
    rgb: npt.NDArray[np.uint8]
    depth: npt.NDArray[np.float32]
    mask: Optional[npt.NDArray[np.uint8]]

class TumDataset:
    def __init__(self, path: _Path, camera_file: Optional[_Path] = None,
                 camera_preset: Optional[str] = None,
                 max_time_difference: float = 0.02,
                 ground_truth_frame: Optional[str] = None) -> None: ...
    def __len__(self) -> int: ...
    def __getitem__(self, index: int) -> Frame: ...
    def __iter__(self) -> Iterator[Frame]: ...
    @property
    def camera(self) -> Camera: ...
    @property
    def camera_source(self) -> str: ...
    @property
    def folder(self) -> pathlib.Path: ...
    @property
    def timestamps(self) -> npt.NDArray[np.float64]: ...
    @property
    def ground_truth(self) -> Optional[Trajectory]: ...
    @property
    def ground_truth_frame(self) -> str: ...
    @property
    def absent_images(self) -> List[pathlib.Path]: ...
    @property
    def has_masks(self) -> bool: ...

class Segmenter:
    def __init__(self, model_config: _Path = ..., model: Optional[_Path] = None) -> None: ...
    def segment(
        self, rgb: npt.NDArray[np.uint8]
    ) -> tuple[npt.NDArray[np.uint8], npt.NDArray[np.uint8]]: ...
    @property
    def name(self) -> str: ...
    @property
    def classes(self) -> list[str]: ...
    @property
    def dynamic_classes(self) -> list[str]: ...

class OccupancyMap:
    def __init__(self, path: _Path) -> None: ...
    @property
    def resolution(self) -> float: ...
    @property
    def occupied(self) -> npt.NDArray[np.float64]: ...
    @property
    def free(self) -> npt.NDArray[np.float64]: ...
    def state(self, points: npt.ArrayLike) -> npt.NDArray[np.int8]: ...

class Cloud:
    points: npt.NDArray[np.float32]
    colours: npt.NDArray[np.uint8]
    labels: npt.NDArray[np.uint8]
    instances: npt.NDArray[np.uint16]
    def __len__(self) -> int: ...

class MapObject:
    id: str
    label: str
    instance: int
    dynamic: bool
    confidence: float
    keyframes: int
    points: Cloud
    centroid: npt.NDArray[np.float32]
    bbox_min: npt.NDArray[np.float32]
    bbox_max: npt.NDArray[np.float32]
    box_centre: npt.NDArray[np.float32]
    box_extent: npt.NDArray[np.float32]
    box_axes: npt.NDArray[np.float32]

class DenseMap:
    voxel_size: float
    static_points: Cloud
    dynamic_points: Cloud
    objects: List[MapObject]

class TrackingState(enum.Enum):
    NOT_INITIALISED = 0
    OK = 1
    LOST = 2

class TrackResult:
    frame_id: int
    timestamp: float
    state: TrackingState
    pose: Optional[npt.NDArray[np.float64]]
    mask: Optional[npt.NDArray[np.uint8]]
    labels: Optional[npt.NDArray[np.uint8]]
    keyframe: bool
    keypoints: int
    matches: int
    tracking_ms: float
    mask_ms: float
    pipeline_ms: float
    @property
    def ok(self) -> bool: ...

class System:
    def __init__(self, camera: Camera, *, seg: str = "auto", loop_detector: str = "auto",
                 deterministic: bool = False, loop_closing: bool = True, features: int = 1000,
                 mask_dilation: int = 10, build_map: bool = True, seed: int = 0,
                 model_config: _Path = ..., model: Optional[_Path] = None,
                 vocabulary: Optional[_Path] = None, backbone_config: _Path = ...,
                 backbone_model: Optional[_Path] = None, network_interval: int = 5,
                 network_latency: int = 0, camera_motion: str = "rigid",
                 load_map: Optional[_Path] = None, localize_only: bool = False) -> None: ...
    def track(self, timestamp: float, rgb: npt.NDArray[np.uint8],
              depth: Union[npt.NDArray[np.uint16], npt.NDArray[np.float32]],
              mask: Optional[npt.NDArray[Union[np.uint8, np.bool_]]] = None) -> TrackResult: ...
    def finish(self) -> None: ...
    def trajectory(self) -> Trajectory: ...
    def tracked_trajectory(self) -> Trajectory: ...
    def keyframes(self) -> Trajectory: ...
    def dense_map(self) -> DenseMap: ...
    def objects(self) -> List[MapObject]: ...
    def save_map(self, path: _Path) -> int: ...
    def __enter__(self) -> System: ...
    def __exit__(self, *args: object) -> None: ...
    @property
    def finished(self) -> bool: ...
    @property
    def num_keyframes(self) -> int: ...
    @property
    def num_map_points(self) -> int: ...
    @property
    def loaded_points(self) -> int: ...
    @property
    def loaded_points_left(self) -> int: ...
    @property
    def camera(self) -> Camera: ...
    @property
    def mask_source(self) -> str: ...
    @property
    def loop_detector(self) -> str: ...

class ErrorStatistics:
    count: int
    rmse: float
    mean: float
    median: float
    std: float
    min: float
    max: float

class AteResult:
    statistics: ErrorStatistics
    aligned_estimate: Trajectory
    @property
    def rmse(self) -> float: ...
    @property
    def errors(self) -> npt.NDArray[np.float64]: ...
    @property
    def alignment(self) -> npt.NDArray[np.float64]: ...

class RpeResult:
    translational: ErrorStatistics
    rotational_deg: ErrorStatistics
    @property
    def pairs(self) -> int: ...

def ate(ground_truth: Trajectory, estimate: Trajectory, *, max_difference: float = 0.02,
        offset: float = 0.0, scale: float = 1.0, alignment: str = "se3") -> AteResult: ...
def rpe(ground_truth: Trajectory, estimate: Trajectory, *, delta: float = 1.0,
        delta_unit: str = "s", fixed_delta: bool = True, max_pairs: int = 10000,
        offset: float = 0.0, scale: float = 1.0, seed: int = 0) -> RpeResult: ...
