"""hecal: hand-eye calibration with honest uncertainty (docs/python.md).

The compiled module hecal._hecal holds everything; this package re-exports it.

  hecal.calibrateHandEye / hecal.calibrateRobotWorldHandEye  OpenCV 4.6's functions, drop-in
  hecal.calibrate          robot and camera poses (arrays or pose files) -> X, Z, covariance
  hecal.calibrate_images   a folder of target images + robot poses -> X, Z, covariance
  hecal.detect             target images -> camera poses T_camera_target
  hecal.read_poses / hecal.write_poses   pose tables in every form the CLI reads and writes

Conventions: T_a_b maps coordinates in frame b to frame a; lengths in metres unless a unit is
given, angles in radians; covariances of right perturbations (rx, ry, rz, tx, ty, tz) per pose.
Errors: hecal.InputError (a ValueError) and hecal.DegenerateError, both hecal.Error.
"""
from ._hecal import *  # noqa: F401,F403
from ._hecal import __version__  # noqa: F401
from . import _hecal

__all__ = [name for name in dir(_hecal) if not name.startswith("_")]
