#!/usr/bin/env python3
"""Calibrate from the 28 bundled chessboard images of data/rwhe-kuka2 and their KUKA robot
poses (eye-in-hand; intrinsics estimated from the images), and print X = T_gripper_camera with
its 1-sigma per axis (`hecal calibrate --images` in Python; about 5 s on 2 cores).

  PYTHONPATH=build/python /usr/bin/python3 examples/python/calibrate_images.py
"""
import os
import sys

import numpy as np

import hecal

here = os.path.dirname(os.path.abspath(__file__))
data = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "rwhe-kuka2")
result = hecal.calibrate_images(os.path.join(data, "images"), os.path.join(data, "target.yaml"),
                                os.path.join(data, "RobotPosesVec.txt"), setup="eye-in-hand")

X = result.X  # T_gripper_camera, metres (the robot file's unit)
sigma = result.sigma.ravel()  # (rx, ry, rz, tx, ty, tz) of X, then of Z; rad and metres
print(f"{result.method}: X = {result.X_frame}")
print("t = (%.4f, %.4f, %.4f) m" % tuple(X[:3, 3]),
      "+- (%.2f, %.2f, %.2f) mm" % tuple(1e3 * sigma[3:6]))
print("R =\n" + np.array2string(X[:3, :3], precision=5, suppress_small=True),
      "\n+- (%.3f, %.3f, %.3f) deg about the camera's axes" % tuple(np.degrees(sigma[:3])))
print(f"{len(result.used_station_ids)} images used; residual "
      f"{np.degrees(result.rotation_rms):.3f} deg / {1e3 * result.translation_rms:.2f} mm")
