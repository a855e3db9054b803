#!/usr/bin/env python3
"""Per-call time of the OpenCV drop-in against OpenCV 4.6 itself, side by side in one run
(docs/bench.md#python-drop-in, docs/python.md#speed).

The same Python lists go to cv2.calibrateHandEye(..., method=cv2.CALIB_HAND_EYE_PARK),
hecal.calibrateHandEye(..., method=hecal.CALIB_HAND_EYE_PARK) and hecal.calibrateHandEye(...)
(default: hecal.CALIB_HAND_EYE_ML): OpenCV's own test protocol with noise
(python/tests/drop_in_cases.py), 15 stations, rotations as 3x3 matrices (gripper2base) and
Rodrigues vectors (target2cam), translations 3x1 — a typical script's lists. Every call includes
parsing the lists. timeit: the best of --repeat runs of --number calls each (wall time; the best
run is the least disturbed by other programs), over --datasets data sets; also the mean error to
the truth of each.

  PYTHONPATH=build/python /usr/bin/python3 bench/python_drop_in_bench.py
"""
import argparse
import os
import sys
import timeit

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python", "tests"))
import cv2  # noqa: E402
import hecal  # noqa: E402
from drop_in_cases import errors, opencv_trial  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--stations", type=int, default=15)
    parser.add_argument("--datasets", type=int, default=5)
    parser.add_argument("--number", type=int, default=200, help="calls per timing run")
    parser.add_argument("--repeat", type=int, default=5, help="timing runs (best is kept)")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()

    rng = np.random.default_rng(args.seed)
    data = [opencv_trial(rng, n_poses=args.stations, noise=True) for _ in range(args.datasets)]
    calls = {
        "cv2 PARK": lambda d: cv2.calibrateHandEye(*d[:4], method=cv2.CALIB_HAND_EYE_PARK),
        "hecal PARK": lambda d: hecal.calibrateHandEye(*d[:4], method=hecal.CALIB_HAND_EYE_PARK),
        "hecal ML": lambda d: hecal.calibrateHandEye(*d[:4]),
    }
    us, err = {}, {}
    for name, call in calls.items():
        per_set = []
        for d in data:
            timer = timeit.Timer(lambda: call(d))
            per_set.append(min(timer.repeat(repeat=args.repeat, number=args.number)) / args.number)
        us[name] = 1e6 * float(np.mean(per_set))
        e = np.array([errors(*call(d), d[4]) for d in data])
        err[name] = (np.degrees(e[:, 0].mean()), 1e3 * e[:, 1].mean())

    print(f"OpenCV {cv2.__version__}, hecal {hecal.__version__}, {args.stations} stations, "
          f"{args.datasets} data sets (OpenCV's test protocol with noise), best of "
          f"{args.repeat} x {args.number} calls")
    print(f"{'call':<12} {'us/call':>9} {'vs cv2 PARK':>12} {'rot err deg':>12} {'trans err mm':>13}")
    for name in calls:
        print(f"{name:<12} {us[name]:9.1f} {us['cv2 PARK'] / us[name]:11.1f}x "
              f"{err[name][0]:12.3f} {err[name][1]:13.2f}")


if __name__ == "__main__":
    main()
