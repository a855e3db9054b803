#!/usr/bin/env python3
"""A typical OpenCV hand-eye script, with hecal as the drop-in for the calibration only.

Eye-to-hand (camera fixed, target on the gripper) with MoveIt Calibration's 50 real samples
(data/moveit-calibration/pose_samples.json: T_base_eef and T_camera_target per sample, metres).
As OpenCV documents for eye-to-hand, the robot poses go in inverted (base2gripper), and the
answer is then T_base_camera. The only change from the OpenCV script is the import:
`import hecal as cv2` instead of `import cv2`. calibrateHandEye, calibrateRobotWorldHandEye and
their constants are hecal's; every other name (cv2.Rodrigues below) is OpenCV's, forwarded.

  PYTHONPATH=build/python /usr/bin/python3 examples/python/drop_in_cv2.py
"""
import json
import os
import sys

import numpy as np

import hecal as cv2  # was: import cv2

here = os.path.dirname(os.path.abspath(__file__))
path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    here, "..", "..", "data", "moveit-calibration", "pose_samples.json")
samples = json.load(open(path))

R_base2gripper, t_base2gripper, R_target2cam, t_target2cam = [], [], [], []
for T_base_eef, T_cam_target in samples:
    T_eef_base = np.linalg.inv(np.array(T_base_eef))  # eye-to-hand: invert the robot poses
    T_cam_target = np.array(T_cam_target)
    R_base2gripper.append(T_eef_base[:3, :3])
    t_base2gripper.append(T_eef_base[:3, 3:4])
    R_target2cam.append(T_cam_target[:3, :3])
    t_target2cam.append(T_cam_target[:3, 3:4])

R, t = cv2.calibrateHandEye(R_base2gripper, t_base2gripper, R_target2cam, t_target2cam,
                            method=cv2.CALIB_HAND_EYE_PARK)
print("PARK: T_base_camera t = (%.4f, %.4f, %.4f) m" % tuple(t.ravel()))
R, t = cv2.calibrateHandEye(R_base2gripper, t_base2gripper, R_target2cam, t_target2cam)
print("ML:   T_base_camera t = (%.4f, %.4f, %.4f) m" % tuple(t.ravel()))
print("R =\n" + np.array2string(R, precision=5, suppress_small=True))
rvec, _ = cv2.Rodrigues(R)  # OpenCV's own function, through the same name
print("rvec = (%.4f, %.4f, %.4f) rad" % tuple(rvec.ravel()))
