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

`import hecal as cv2` in an OpenCV script: the two hand-eye functions and their constants are
hecal's; any other public name (cv2.Rodrigues, cv2.solvePnP, cv2.imread, ...) is looked up in
OpenCV's own cv2 module when it is installed (a module __getattr__, PEP 562), so the rest of the
script runs unchanged.
"""
from ._hecal import *  # noqa: F401,F403
from ._hecal import __version__  # noqa: F401
from . import _hecal

__all__ = [name for name in dir(_hecal) if not name.startswith("_")]


def __getattr__(name):
    """OpenCV's cv2.<name> for a public name hecal does not have (see the module docstring)."""
    if name.startswith("_"):
        raise AttributeError(f"module 'hecal' has no attribute {name!r}")
    try:
        import cv2 as opencv
    except ImportError:
        raise AttributeError(
            f"module 'hecal' has no attribute {name!r} (OpenCV's cv2, which hecal forwards other "
            "names to, is not installed)") from None
    try:
        return getattr(opencv, name)
    except AttributeError:
        raise AttributeError(f"module 'hecal' has no attribute {name!r} (nor has cv2)") from None
