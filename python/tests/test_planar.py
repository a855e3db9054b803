"""Planar robots from Python: fix= gives X's unobservable translation component (docs/planar.md)."""
import numpy as np
import pytest

import hecal


def _rotation(axis, angle):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def _pose(rotation, translation):
    pose = np.eye(4)
    pose[:3, :3] = rotation
    pose[:3, 3] = translation
    return pose


def _scara(stations=15, seed=3):
    """A SCARA flange turning about the base's z only, camera on it (eye-in-hand), noisy."""
    rng = np.random.default_rng(seed)
    X = _pose(_rotation([0.1, 0.2, 1.0], 0.3), [0.03, 0.01, 0.09])
    Z = _pose(_rotation([1, 0, 0], np.pi), [0.45, 0.05, 0.0])
    robot, camera = [], []
    for _ in range(stations):
        A = _pose(_rotation([0, 0, 1], rng.uniform(-1.7, 1.7)) @ _rotation([1, 0, 0], np.pi),
                  [0.45 + rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1), rng.uniform(0.3, 0.4)])
        B = np.linalg.inv(A @ X) @ Z
        A[:3, :3] = A[:3, :3] @ _rotation(rng.normal(size=3), np.radians(0.05))
        A[:3, 3] += rng.normal(0, 2e-4, 3)
        B[:3, :3] = B[:3, :3] @ _rotation(rng.normal(size=3), np.radians(0.1))
        B[:3, 3] += rng.normal(0, 5e-4, 3)
        robot.append(A)
        camera.append(B)
    return np.array(robot), np.array(camera), X


def test_without_fix_the_error_names_the_component():
    robot, camera, _ = _scara()
    with pytest.raises(Exception, match="tz=VALUE"):
        hecal.calibrate(robot, camera, setup="eye-in-hand")


def test_fix_gives_the_component_and_the_rest_comes_back():
    robot, camera, X = _scara()
    r = hecal.calibrate(robot, camera, setup="eye-in-hand", fix="tz=90mm")
    assert abs(r.X[2, 3] - 0.09) < 1e-9
    assert np.linalg.norm(r.X[:2, 3] - X[:2, 3]) < 2e-3
    angle = np.arccos(np.clip((np.trace(X[:3, :3].T @ r.X[:3, :3]) - 1) / 2, -1, 1))
    assert np.degrees(angle) < 0.5


def test_a_bad_fix_is_refused_naming_the_argument():
    robot, camera, _ = _scara()
    with pytest.raises(ValueError, match="fix"):
        hecal.calibrate(robot, camera, setup="eye-in-hand", fix="rz=0.1")
