"""Hand-eye data sets for the drop-in tests and bench/python_drop_in_bench.py.

opencv_trial: the random trial of OpenCV 4.6's own test (modules/calib3d/test/
test_calibration_hand_eye.cpp, CV_CalibrateHandEyeTest::simulateData), reproduced with NumPy:
cam2gripper a 10-50 deg rotation and 0.05-0.5 m per axis, target2base 5-85 deg and 0.5-3.5 m,
gripper2base 5-45 deg and 0.5-1.5 m, random signs; with noise, target2cam gets N(0, 0.002) rad /
N(0, 0.005) m per Rodrigues / translation component and gripper2base N(0, 0.001) rad / m.
Rotations of target2cam are passed as Rodrigues vectors (as OpenCV's test does).

wide_rotation_case: consecutive stations differ by a 170-179.9 deg rotation (the data that break
OpenCV 4.6's TSAI, HORAUD and DANIILIDIS; src/testing/handeye_cases.h WideRotationCase).
"""
import numpy as np


def rodrigues(rvec):
    """Rotation matrix of a rotation vector (axis * angle, radians)."""
    rvec = np.asarray(rvec, dtype=float).reshape(3)
    theta = np.linalg.norm(rvec)
    if theta < 1e-300:
        return np.eye(3)
    k = rvec / theta
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(theta) * K + (1 - np.cos(theta)) * K @ K


def log_so3(R):
    """Rotation vector of a rotation matrix (angle in [0, pi])."""
    angle = np.arccos(np.clip((np.trace(R) - 1) / 2, -1.0, 1.0))
    if angle < 1e-12:
        return np.zeros(3)
    if angle > np.pi - 1e-6:
        w, v = np.linalg.eigh((R + R.T) / 2)
        return v[:, np.argmax(w)] * angle
    axis = np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    return axis / (2 * np.sin(angle)) * angle


def rotation_angle(Ra, Rb):
    """Angle between two rotations, radians (accurate near 0: |Ra - Rb|_F = 2 sqrt(2) sin(a/2))."""
    return 2 * np.arcsin(min(1.0, np.linalg.norm(Ra - Rb) / (2 * np.sqrt(2))))


def transform(R, t):
    T = np.eye(4)
    T[:3, :3] = R
    T[:3, 3] = np.asarray(t).reshape(3)
    return T


def _pose(rng, min_theta, max_theta, t_range):
    axis = rng.uniform(-1.0, 1.0, 3)
    theta = rng.uniform(min_theta, max_theta) * np.sign(rng.uniform(-1.0, 1.0))
    t = rng.uniform(t_range[0], t_range[1], 3) * np.sign(rng.uniform(-1.0, 1.0, 3))
    return transform(rodrigues(theta * axis), t)


def opencv_trial(rng, n_poses=10, noise=False):
    """(R_gripper2base, t_gripper2base, rvec_target2cam, t_target2cam, T_cam2gripper)."""
    d = np.pi / 180.0
    X = _pose(rng, 10 * d, 50 * d, (0.05, 0.5))  # cam2gripper
    target2base = _pose(rng, 5 * d, 85 * d, (0.5, 3.5))
    R_g, t_g, r_t, t_t = [], [], [], []
    for _ in range(n_poses):
        G = _pose(rng, 5 * d, 45 * d, (0.5, 1.5))  # gripper2base
        B = np.linalg.inv(X) @ np.linalg.inv(G) @ target2base  # target2cam
        if noise:
            B[:3, :3] = rodrigues(log_so3(B[:3, :3]) + rng.normal(0, 0.002, 3))
            B[:3, 3] += rng.normal(0, 0.005, 3)
            G[:3, :3] = rodrigues(log_so3(G[:3, :3]) + rng.normal(0, 0.001, 3))
            G[:3, 3] += rng.normal(0, 0.001, 3)
        R_g.append(G[:3, :3].copy())
        t_g.append(G[:3, 3:4].copy())
        r_t.append(log_so3(B[:3, :3]).reshape(3, 1))
        t_t.append(B[:3, 3:4].copy())
    return R_g, t_g, r_t, t_t, X


def random_rotation(rng):
    q = rng.normal(size=4)
    q /= np.linalg.norm(q)
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def wide_rotation_case(rng, n_poses=10):
    """Noise-free eye-in-hand lists whose consecutive stations differ by 170-179.9 deg.

    Returns (R_gripper2base, t_gripper2base, R_target2cam, t_target2cam, T_cam2gripper)."""
    X = transform(random_rotation(rng), rng.uniform(-0.05, 0.05, 3))
    Z = transform(random_rotation(rng), rng.uniform(-1.0, 1.0, 3))  # T_base_target
    T_target_camera = transform(random_rotation(rng), [0.0, 0.0, -1.0])
    R_g, t_g, R_t, t_t = [], [], [], []
    for i in range(n_poses):
        if i > 0:
            axis = rng.normal(size=3)
            axis /= np.linalg.norm(axis)
            theta = np.radians(rng.uniform(170.0, 179.9))
            T_target_camera[:3, :3] = T_target_camera[:3, :3] @ rodrigues(theta * axis)
            T_target_camera[:3, 3] = rng.uniform(-0.5, 0.5, 3) + [0.0, 0.0, -1.0]
        B = np.linalg.inv(T_target_camera)
        A = Z @ T_target_camera @ np.linalg.inv(X)
        R_g.append(A[:3, :3].copy())
        t_g.append(A[:3, 3:4].copy())
        R_t.append(B[:3, :3].copy())
        t_t.append(B[:3, 3:4].copy())
    return R_g, t_g, R_t, t_t, X


def errors(R, t, T_true):
    """(rotation error rad, translation error m) of an estimate against the truth."""
    return rotation_angle(R, T_true[:3, :3]), float(np.linalg.norm(np.ravel(t) - T_true[:3, 3]))
