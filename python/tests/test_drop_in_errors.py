"""Every malformed input of the OpenCV drop-in raises the named hecal error (where OpenCV 4.6 is
silent or wrong), and every accepted input form gives the same answer."""
import numpy as np
import pytest

import hecal
from drop_in_cases import opencv_trial


@pytest.fixture(scope="module")
def lists():
    R_g, t_g, r_t, t_t, X = opencv_trial(np.random.default_rng(3), n_poses=8, noise=False)
    return R_g, t_g, r_t, t_t, X


def raises_input(match, function, *args, **kwargs):
    with pytest.raises(hecal.InputError, match=match) as info:
        function(*args, **kwargs)
    error = info.value
    assert isinstance(error, ValueError) and isinstance(error, hecal.Error)
    assert str(error).startswith(error.source + ": " + error.problem)
    return error


def test_every_input_form_gives_the_same_answer(lists):
    R_g, t_g, r_t, t_t, X = lists
    R_ref, t_ref = hecal.calibrateHandEye(R_g, t_g, r_t, t_t, method=1)
    forms = [
        (tuple(R_g), tuple(t_g), tuple(r_t), tuple(t_t)),
        (np.stack(R_g), np.stack(t_g)[:, :, 0], np.stack(r_t)[:, :, 0], np.stack(t_t)),
        ([r.ravel() for r in R_g], [t.ravel() for t in t_g], [r.T for r in r_t], [t.T for t in t_t]),
        (np.stack(R_g), [t.tolist() for t in t_g], np.stack(r_t), np.stack(t_t)[:, :, 0]),
        ([np.asfortranarray(R) for R in R_g], t_g, [r.reshape(3) for r in r_t], t_t),
        (np.stack(R_g)[:, :, :], np.stack(t_g)[::1], np.stack(r_t)[:, :, 0].T.copy().T, t_t),
    ]
    forms[2] = (forms[2][0][:0] + R_g, forms[2][1], forms[2][2], forms[2][3])
    for k, (R1, t1, R2, t2) in enumerate(forms):
        R, t = hecal.calibrateHandEye(R1, t1, R2, t2, method=1)
        assert np.abs(R - R_ref).max() < 1e-12 and np.abs(t - t_ref).max() < 1e-12, k
    # float32 input: projected to rotations, the answer within float32 rounding
    R, t = hecal.calibrateHandEye([R.astype(np.float32) for R in R_g], np.float32(np.stack(t_g)),
                                  [r.astype(np.float32) for r in r_t], [t.astype(np.float32) for t in t_t],
                                  method=1)
    assert R.dtype == np.float64 and np.abs(R - R_ref).max() < 1e-5 and np.abs(t - t_ref).max() < 1e-5
    # positional and keyword forms of OpenCV 4.6
    R1, _ = hecal.calibrateHandEye(R_g, t_g, r_t, t_t, None, None, 1)
    R2, _ = hecal.calibrateHandEye(R_gripper2base=R_g, t_gripper2base=t_g, R_target2cam=r_t,
                                   t_target2cam=t_t, method=hecal.CALIB_HAND_EYE_PARK)
    assert np.array_equal(R1, R_ref) and np.array_equal(R2, R_ref)
    # an output array is filled and returned, as OpenCV does
    out_R, out_t = np.zeros((3, 3)), np.zeros((3, 1))
    R3, t3 = hecal.calibrateHandEye(R_g, t_g, r_t, t_t, out_R, out_t, method=1)
    assert R3 is out_R and t3 is out_t and np.array_equal(out_R, R_ref)


def test_wrong_shapes(lists):
    R_g, t_g, r_t, t_t, _ = lists
    raises_input(r"entry 2 has shape \(2, 2\)", hecal.calibrateHandEye,
                 R_g[:2] + [np.eye(2)] + R_g[3:], t_g, r_t, t_t)
    raises_input(r"entry 0 has shape \(4,\)", hecal.calibrateHandEye,
                 R_g, [np.zeros(4)] + t_g[1:], r_t, t_t)
    raises_input(r"has shape \(8, 4, 4\)", hecal.calibrateHandEye,
                 np.zeros((8, 4, 4)), t_g, r_t, t_t)
    raises_input(r"not a list of rotations", hecal.calibrateHandEye, 5, t_g, r_t, t_t)
    raises_input(r"entry 1 is not an array of numbers", hecal.calibrateHandEye,
                 R_g, t_g, [r_t[0], "abc"] + r_t[2:], t_t)


def test_mismatched_lengths(lists):
    R_g, t_g, r_t, t_t, _ = lists
    e = raises_input("has 7 translations but R_gripper2base has 8", hecal.calibrateHandEye,
                     R_g, t_g[:7], r_t, t_t)
    assert e.source == "t_gripper2base" and e.line == 0 and e.fix
    raises_input("R_target2cam: has 6 poses but R_gripper2base has 8", hecal.calibrateHandEye,
                 R_g, t_g, r_t[:6], t_t[:6])


def test_nan_and_inf(lists):
    R_g, t_g, r_t, t_t, _ = lists
    bad = [t.copy() for t in t_t]
    bad[4][1] = np.nan
    raises_input("entry 4 is not finite", hecal.calibrateHandEye, R_g, t_g, r_t, bad)
    bad = [R.copy() for R in R_g]
    bad[0][0, 0] = np.inf
    raises_input("R_gripper2base: entry 0 is not finite", hecal.calibrateHandEye, bad, t_g, r_t, t_t)


def test_too_few_poses(lists):
    R_g, t_g, r_t, t_t, _ = lists
    raises_input("has 2 poses; hand.eye calibration needs at least 3", hecal.calibrateHandEye,
                 R_g[:2], t_g[:2], r_t[:2], t_t[:2])
    raises_input("needs at least 3", hecal.calibrateRobotWorldHandEye,
                 r_t[:2], t_t[:2], R_g[:2], t_g[:2])


def test_unknown_method(lists):
    R_g, t_g, r_t, t_t, _ = lists
    e = raises_input("unknown method 7", hecal.calibrateHandEye, R_g, t_g, r_t, t_t, method=7)
    assert e.source == "method" and "CALIB_HAND_EYE_TSAI" in e.fix
    raises_input("unknown method 2", hecal.calibrateRobotWorldHandEye, r_t, t_t, R_g, t_g, method=2)
    raises_input("not an integer", hecal.calibrateHandEye, R_g, t_g, r_t, t_t, method="park")
    raises_input("not an integer", hecal.calibrateHandEye, R_g, t_g, r_t, t_t, method=1.0)


def test_method_in_an_output_slot(lists):
    """opencv#27625: calibrateHandEye(R, t, R, t, cv2.CALIB_HAND_EYE_PARK) puts the method into
    the R_cam2gripper output and OpenCV silently runs TSAI."""
    R_g, t_g, r_t, t_t, _ = lists
    e = raises_input("R_cam2gripper: is an output but got the integer 1", hecal.calibrateHandEye,
                     R_g, t_g, r_t, t_t, hecal.CALIB_HAND_EYE_PARK)
    assert "opencv#27625" in e.problem and "method=" in e.fix
    raises_input("R_base2world: is an output but got the integer 0",
                 hecal.calibrateRobotWorldHandEye, r_t, t_t, R_g, t_g, 0)
    raises_input("t_cam2gripper: is an output but got a str", hecal.calibrateHandEye,
                 R_g, t_g, r_t, t_t, None, "x")


def test_not_a_rotation(lists):
    R_g, t_g, r_t, t_t, _ = lists
    scaled = [R.copy() for R in R_g]
    scaled[3] *= 1.01
    raises_input("R_gripper2base: entry 3 is not a rotation matrix", hecal.calibrateHandEye,
                 scaled, t_g, r_t, t_t)
    mirrored = [R.copy() for R in R_g]
    mirrored[1] = -mirrored[1]
    raises_input(r"det R = -1", hecal.calibrateHandEye, mirrored, t_g, r_t, t_t)


def test_parallel_rotation_axes_are_degenerate():
    """Every robot rotation about one axis: X's translation along it cannot be observed."""
    X = np.eye(4)
    X[:3, 3] = [0.05, 0.02, 0.1]
    Z = np.eye(4)
    Z[:3, 3] = [1.0, 0.0, 0.0]
    R_g, t_g, R_t, t_t = [], [], [], []
    for i in range(6):
        c, s = np.cos(0.4 * i), np.sin(0.4 * i)
        A = np.eye(4)
        A[:3, :3] = [[c, -s, 0], [s, c, 0], [0, 0, 1]]
        A[:3, 3] = [0.1 * i, 0.05 * i * i, 0.3]
        B = np.linalg.inv(A @ X) @ Z
        R_g.append(A[:3, :3]), t_g.append(A[:3, 3]), R_t.append(B[:3, :3]), t_t.append(B[:3, 3])
    for method in (hecal.CALIB_HAND_EYE_PARK, hecal.CALIB_HAND_EYE_ML):
        with pytest.raises(hecal.DegenerateError, match="cannot observe") as info:
            hecal.calibrateHandEye(R_g, t_g, R_t, t_t, method=method)
        assert isinstance(info.value, hecal.Error) and info.value.unobservable
