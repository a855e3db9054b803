"""Separate calls are thread-safe and release the GIL: several threads calling hecal.calibrate
and hecal.calibrateHandEye at once get the results of one thread alone."""
import os
import threading

import numpy as np

import hecal
from drop_in_cases import opencv_trial, rodrigues

SOURCE = os.environ.get("HECAL_SOURCE_DIR", ".")


def run_threads(function, count):
    results = [None] * count
    errors = []

    def work(k):
        try:
            results[k] = function(k)
        except Exception as e:  # noqa: BLE001 - reported below
            errors.append(e)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(count)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors
    return results


def test_calibrate_concurrently():
    rng = np.random.default_rng(5)
    R_g, t_g, r_t, t_t, _ = opencv_trial(rng, n_poses=20, noise=True)
    robot = np.array([np.block([[R, t], [np.zeros((1, 3)), 1]]) for R, t in zip(R_g, t_g)])
    camera = np.array([np.block([[rodrigues(r), t], [np.zeros((1, 3)), 1]])
                       for r, t in zip(r_t, t_t)])
    alone = hecal.calibrate(robot, camera, setup="eye-in-hand").to_json()
    results = run_threads(lambda k: hecal.calibrate(robot, camera, setup="eye-in-hand").to_json(), 4)
    assert all(r == alone for r in results)


def test_drop_in_concurrently():
    rng = np.random.default_rng(6)
    data = [opencv_trial(rng, n_poses=15, noise=True) for _ in range(4)]
    alone = [hecal.calibrateHandEye(*d[:4]) for d in data]

    def many(k):
        return [hecal.calibrateHandEye(*data[k][:4]) for _ in range(50)]

    for k, results in enumerate(run_threads(many, 4)):
        for R, t in results:
            assert np.array_equal(R, alone[k][0]) and np.array_equal(t, alone[k][1])

