# Type stub of the hecal Python module (docs/python.md), for editors and type checkers.
# Frames: T_a_b maps coordinates in frame b to frame a. Lengths in metres unless a unit is given
# (results in the robot poses' unit), angles in radians.
import os
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

PathLike = Union[str, os.PathLike]
ArrayLike = npt.ArrayLike
Sigma = Union[str, Tuple[float, float]]  # "MM,DEG" or (mm, deg), per axis

class Error(Exception): ...

class InputError(Error, ValueError):
    source: str  # the file, or the argument / option holding the bad value
    line: int  # 1-based line in the file; 0 when not line-bound
    problem: str
    fix: str

class DegenerateError(Error):
    unobservable: str  # what the data cannot determine

# The OpenCV drop-in (OpenCV 4.6's values; CALIB_HAND_EYE_ML is hecal's and the default).
CALIB_HAND_EYE_TSAI: int
CALIB_HAND_EYE_PARK: int
CALIB_HAND_EYE_HORAUD: int
CALIB_HAND_EYE_ANDREFF: int
CALIB_HAND_EYE_DANIILIDIS: int
CALIB_HAND_EYE_ML: int
CALIB_ROBOT_WORLD_HAND_EYE_SHAH: int
CALIB_ROBOT_WORLD_HAND_EYE_LI: int

def calibrateHandEye(
    R_gripper2base: Union[Sequence[ArrayLike], ArrayLike],
    t_gripper2base: Union[Sequence[ArrayLike], ArrayLike],
    R_target2cam: Union[Sequence[ArrayLike], ArrayLike],
    t_target2cam: Union[Sequence[ArrayLike], ArrayLike],
    R_cam2gripper: Optional[np.ndarray] = None,
    t_cam2gripper: Optional[np.ndarray] = None,
    method: int = ...,
) -> Tuple[np.ndarray, np.ndarray]:
    """X = T_gripper_camera (R 3x3, t 3x1) from T_base_gripper and T_camera_target lists."""

def calibrateRobotWorldHandEye(
    R_world2cam: Union[Sequence[ArrayLike], ArrayLike],
    t_world2cam: Union[Sequence[ArrayLike], ArrayLike],
    R_base2gripper: Union[Sequence[ArrayLike], ArrayLike],
    t_base2gripper: Union[Sequence[ArrayLike], ArrayLike],
    R_base2world: Optional[np.ndarray] = None,
    t_base2world: Optional[np.ndarray] = None,
    R_gripper2cam: Optional[np.ndarray] = None,
    t_gripper2cam: Optional[np.ndarray] = None,
    method: int = ...,
) -> Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(R_base2world, t_base2world, R_gripper2cam, t_gripper2cam): T_world_base, T_camera_gripper."""

class CalibrationResult:
    setup: str  # "eye-in-hand" | "eye-to-hand"
    method: str
    unit: str  # "m" | "mm": every length of the result
    X: np.ndarray  # 4x4 T_gripper_camera (eye-in-hand) | T_base_camera (eye-to-hand)
    Z: np.ndarray  # 4x4 T_base_target (eye-in-hand) | T_gripper_target (eye-to-hand)
    X_frame: str
    Z_frame: str
    covariance: Optional[np.ndarray]  # 12x12, right perturbation (rx,ry,rz,tx,ty,tz) of X then Z
    sigma: Optional[np.ndarray]  # 12x1 sqrt of its diagonal (rad, unit)
    residuals: List[Dict[str, object]]  # id, rotation (rad), translation, whitened, outlier
    rotation_rms: float  # rad
    translation_rms: float  # unit
    rejected: List[Dict[str, object]]  # id, rotation, translation, whitened
    station_ids: List[str]
    used_station_ids: List[str]
    noise: Dict[str, object]  # robot_sigma, camera_sigma (rad, unit), estimated, student_t_dof
    model_check: Optional[Dict[str, object]]
    warnings: List[str]
    seed: Optional[int]
    results: List["CalibrationResult"]  # one per method with method="all"
    failures: Dict[str, str]  # method="all": methods that refused the data
    def to_json(self) -> str:
        """The result file of `hecal calibrate --output out.json` (docs/result-file.md)."""
    def to_yaml(self) -> str: ...
    def to_dict(self) -> dict: ...

def calibrate(
    robot: Union[PathLike, ArrayLike],
    camera: Union[PathLike, ArrayLike],
    *,
    setup: Optional[str] = None,
    method: str = "ml",
    robot_sigma: Optional[Sigma] = None,
    camera_sigma: Optional[Sigma] = None,
    units: Optional[str] = None,
    unit: Optional[str] = None,
    robot_unit: Optional[str] = None,
    camera_unit: Optional[str] = None,
    degrees: bool = False,
    euler: Optional[str] = None,
    robot_inverse: bool = False,
    camera_inverse: bool = False,
    keep_outliers: bool = False,
    all_methods: bool = False,
    robust: str = "none",
    covariance: Optional[str] = None,
    covariance_samples: int = 5000,
    seed: int = 1,
    threads: int = 0,
    station_ids: Optional[Sequence[str]] = None,
    fix: Optional[str] = None,
) -> CalibrationResult:
    """robot T_base_gripper, camera T_camera_target: (N,4,4) arrays or pose files."""

def calibrate_images(
    images: PathLike,
    target: PathLike,
    robot: PathLike,
    *,
    setup: Optional[str] = None,
    method: str = "ml",
    intrinsics: Optional[PathLike] = None,
    pixel_sigma: Optional[float] = None,
    refine_intrinsics: bool = False,
    robot_sigma: Optional[Sigma] = None,
    camera_sigma: Optional[Sigma] = None,
    units: Optional[str] = None,
    degrees: bool = False,
    euler: Optional[str] = None,
    robot_inverse: bool = False,
    keep_outliers: bool = False,
    robust: str = "none",
    covariance: Optional[str] = None,
    covariance_samples: int = 5000,
    seed: int = 1,
    threads: int = 0,
    log: Optional[Callable[[str, str], None]] = None,
) -> CalibrationResult: ...

def detect(
    images: PathLike,
    target: PathLike,
    *,
    intrinsics: Optional[PathLike] = None,
    threads: int = 0,
    log: Optional[Callable[[str, str], None]] = None,
) -> Tuple[np.ndarray, List[str], Dict[str, object]]:
    """(T_camera_target (N,4,4) metres, ids, camera intrinsics)."""

def read_poses(
    path: PathLike,
    *,
    units: str = "m",
    degrees: bool = False,
    euler: Optional[str] = None,
    invert: bool = False,
) -> Tuple[np.ndarray, List[str]]:
    """(poses (N,4,4) in metres, ids)."""

def write_poses(
    path: PathLike,
    poses: ArrayLike,
    *,
    to: str = "quaternion",
    units: str = "m",
    degrees: bool = False,
    ids: Optional[Sequence[str]] = None,
    stamps: Optional[Sequence[float]] = None,
    comments: Sequence[str] = ...,
) -> None:
    """poses (N,4,4) in metres; to: quaternion|rotvec|matrix|euler:SEQ|rpy|kuka|fanuc|abb|ur."""

def simulate(
    *,
    stations: Sequence[int] = ...,
    sigmas: Sequence[Union[float, Tuple[float, float]]] = ...,
    setups: Sequence[str] = ...,
    noise_on: Sequence[str] = ...,
    noise: Sequence[str] = ...,
    outliers: Sequence[int] = ...,
    robot_scales: Sequence[float] = ...,
    methods: Union[str, Sequence[str]] = "all",
    trials: int = 200,
    seed: int = 1,
    threads: int = 0,
    covariance: Optional[str] = None,
    covariance_samples: int = 1000,
    reject_outliers: bool = False,
    estimate_noise: bool = False,
) -> Dict[str, object]:
    """The thesis study: {"summary": [dict], "summary_csv": str, "trials_csv": str, "seed": int}."""

# `import hecal as cv2`: any other public name is OpenCV's cv2.<name> (forwarded at run time).
def __getattr__(name: str) -> Any: ...
