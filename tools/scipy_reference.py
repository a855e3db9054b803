#!/usr/bin/python3
"""Writes the scipy reference fixtures in tests/data/scipy/ (an independent implementation of
every rotation format hecal converts, used by src/geometry/euler_scipy_test.cc and by the
end-to-end tests of `hecal poses convert`).

Usage (Debian 12: python3-scipy 1.10.1 is the system python's; a pyenv python may lack scipy):
    /usr/bin/python3 tools/scipy_reference.py [OUTPUT_DIR]      # default: tests/data/scipy

Deterministic: a fixed seed, and the poses are built from explicit lists. Re-running with the
same scipy/numpy reproduces the files byte for byte.

What it writes (pose tables in the docs/pose-files.md contract: `#` comment lines, then a header of
named columns, `id` first, `x,y,z` in metres, one rotation group, numbers as %.17g):
  poses_quaternion.csv            input: id,x,y,z,qw,qx,qy,qz (unit Hamilton quaternions)
  expected_rotvec.csv             rx,ry,rz (radians)            scipy as_rotvec
  expected_matrix.csv             r11..r33 (row-major)          scipy as_matrix
  expected_quaternion.csv         qw,qx,qy,qz, canonical sign   scipy as_quat, w ≥ 0
  expected_euler_<mode>_<SEQ>.csv a1,a2,a3 (radians)            scipy as_euler, 24 sequences
  expected_rpy.csv                roll,pitch,yaw (radians)      extrinsic xyz
  expected_kuka.csv               a_deg,b_deg,c_deg             intrinsic ZYX, degrees
  expected_fanuc.csv              w_deg,p_deg,r_deg             extrinsic xyz, degrees
  expected_abb.csv                q1,q2,q3,q4 = w,x,y,z         canonical sign
  expected_ur.csv                 rx,ry,rz (radians)            rotation vector
  gimbal_lock_exact.csv           for every (pose, Euler target) that scipy reports as gimbal
                                  locked: the exact angles under the shared convention (a3 = 0,
                                  middle angle exactly ±π/2, 0 or π) next to scipy's values
  poses_catalog.csv               id,category,sequence,a1,a2,a3: how each pose was built
See tests/data/scipy/README.md for the conventions and the known scipy imprecision at lock.
"""

import math
import os
import sys
import warnings

import numpy as np
import scipy
from scipy.spatial.transform import Rotation

SEED = 20240504
PI = math.pi
AXES = "xyz"


def all_sequences():
    """The 12 axis sequences, each extrinsic (lowercase) and intrinsic (uppercase)."""
    seqs = []
    for a in AXES:
        for b in AXES:
            for c in AXES:
                if a != b and b != c:
                    seqs.append(a + b + c)
    return seqs + [s.upper() for s in seqs]


SEQUENCES = all_sequences()


def euler_file_stem(seq):
    """Case-preserving, case-folding-safe name: euler_intrinsic_ZYX, euler_extrinsic_xyz."""
    return "euler_%s_%s" % ("intrinsic" if seq.isupper() else "extrinsic", seq)


def is_proper(seq):
    return seq[0].lower() == seq[2].lower()


def lock_values(seq):
    return (0.0, PI) if is_proper(seq) else (PI / 2, -PI / 2)


# --- an independent definition, to check scipy's convention before trusting it ----------------
def elementary(axis, angle):
    c, s = math.cos(angle), math.sin(angle)
    if axis == 0:
        return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    if axis == 1:
        return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def composed(seq, angles):
    """Intrinsic XYZ: Rx(a1) Ry(a2) Rz(a3); extrinsic xyz: Rz(a3) Ry(a2) Rx(a1)."""
    e = [elementary(AXES.index(ch.lower()), a) for ch, a in zip(seq, angles)]
    return e[0] @ e[1] @ e[2] if seq.isupper() else e[2] @ e[1] @ e[0]


def check_scipy_convention(rng):
    for seq in SEQUENCES:
        for _ in range(20):
            angles = rng.uniform(-PI, PI, 3)
            err = np.abs(Rotation.from_euler(seq, angles).as_matrix() - composed(seq, angles)).max()
            assert err < 1e-14, (seq, angles, err)


# --- poses ------------------------------------------------------------------------------------
def canonical_wxyz(quat_xyzw):
    """scipy's (x, y, z, w) → (w, x, y, z) with w ≥ 0; at w == 0 the first non-zero of x, y, z
    positive (the sign rule of hecal::CanonicalQuaternion)."""
    q = np.array([quat_xyzw[3], quat_xyzw[0], quat_xyzw[1], quat_xyzw[2]], dtype=float)
    for c in q:
        if c > 0:
            return q
        if c < 0:
            return -q
    return q


def build_poses(rng):
    """Returns a list of (category, sequence, intended angles or None, quaternion wxyz)."""
    poses = []

    def add(category, quat_wxyz, seq="", angles=None):
        q = np.asarray(quat_wxyz, dtype=float)
        poses.append((category, seq, angles, q / np.linalg.norm(q)))

    def add_euler(category, seq, angles):
        xyzw = Rotation.from_euler(seq, angles).as_quat()
        add(category, [xyzw[3], xyzw[0], xyzw[1], xyzw[2]], seq, list(angles))

    add("identity", [1, 0, 0, 0])
    add("pi_about_x", [0, 1, 0, 0])
    add("pi_about_y", [0, 0, 1, 0])
    add("pi_about_z", [0, 0, 0, 1])
    add("pi_about_xyz_diagonal", [0, 1, 1, 1])
    add("half_pi_about_x", [math.cos(PI / 4), math.sin(PI / 4), 0, 0])
    add("half_pi_about_y", [math.cos(PI / 4), 0, math.sin(PI / 4), 0])
    add("half_pi_about_z", [math.cos(PI / 4), 0, 0, math.sin(PI / 4)])
    for angle in (1e-9, 1e-6, PI - 1e-6):
        axis = rng.normal(size=3)
        axis /= np.linalg.norm(axis)
        add("angle_%g_random_axis" % angle, np.r_[math.cos(angle / 2), math.sin(angle / 2) * axis])
    for _ in range(4):  # w < 0 on purpose: the same rotation as −q
        q = rng.normal(size=4)
        q[0] = -abs(q[0])
        add("random_negative_w", q)
    for _ in range(150):
        add("random", rng.normal(size=4))

    for seq in SEQUENCES:
        lo, hi = (0.3, PI - 0.3) if is_proper(seq) else (-1.2, 1.2)
        lock_a, lock_b = lock_values(seq)

        def outer():
            return rng.uniform(-PI, PI)

        add_euler("gimbal_lock", seq, [outer(), lock_a, outer()])
        # Combined angle a1 ± a3 beyond ±π: the locked a1 must wrap into (−π, π].
        add_euler("gimbal_lock_wrap", seq, [PI - 0.25, lock_b, 2.5 if lock_b < 0 else -2.5])
        add_euler("a1_pi", seq, [PI, rng.uniform(lo, hi), outer()])
        add_euler("a3_minus_pi", seq, [outer(), rng.uniform(lo, hi), -PI + 1e-10])
        add_euler("a1_a3_near_pi", seq, [PI - 1e-12, rng.uniform(lo, hi), -PI + 1e-9])
        near = 1e-5 if lock_a == 0.0 else lock_a - 1e-5  # inside the angle range
        add_euler("near_lock_1e-5", seq, [outer(), near, outer()])
        near = PI - 1e-6 if lock_b == PI else lock_b + 1e-6
        add_euler("near_lock_1e-6", seq, [outer(), near, outer()])
    return poses


# --- scipy conversions ------------------------------------------------------------------------
def euler_with_lock_flag(rotation, seq, degrees=False):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        angles = rotation.as_euler(seq, degrees=degrees)
    locked = any("Gimbal lock" in str(w.message) for w in caught)
    return angles, locked


def accurate_middle_angle(seq, m):
    """The middle angle from the geometry of R, accurate everywhere (atan2 of a sine and a
    cosine, unlike scipy 1.10's arccos). Proper: the angle between e_p and R e_p. Tait–Bryan
    intrinsic: e_p · R e_r = s sin(a2); extrinsic: e_r · R e_p = −s sin(a2) (s = +1 for cyclic
    axes p→q)."""
    p, q, r = (AXES.index(ch.lower()) for ch in seq)
    e = np.eye(3)
    if is_proper(seq):
        v = m @ e[p]
        return math.atan2(np.linalg.norm(np.cross(e[p], v)), v[p])
    s = 1.0 if (q - p) % 3 == 1 else -1.0
    if seq.isupper():
        v = m @ e[r]
        return math.atan2(s * v[p], np.linalg.norm(np.cross(e[p], v)))
    v = m @ e[p]
    return math.atan2(-s * v[r], np.linalg.norm(np.cross(e[r], v)))


def exact_lock_angles(seq, m, scipy_angles, degrees):
    """Our shared convention at gimbal lock: a3 = 0, a1 (scipy's, computed by atan2 and accurate
    to rounding) carrying the rotation, and the middle angle computed accurately — exactly the
    singular value (±π/2, 0, π) when it is within 1e-12 of it, as for every pose built at the
    lock; otherwise (a pose inside scipy's 1e-7 lock band, e.g. a 1e-9 rad rotation for a
    proper sequence) the true middle angle."""
    a1, _, a3 = np.radians(scipy_angles) if degrees else scipy_angles
    assert a3 == 0.0, (seq, scipy_angles)
    a2 = accurate_middle_angle(seq, m)
    for lock in lock_values(seq):
        if abs(a2 - lock) < 1e-12:
            a2 = lock
    if a1 <= -PI:  # scipy's range is [−π, π]; ours is (−π, π]
        a1 += 2 * PI
    angles = [a1, a2, 0.0]
    return [math.degrees(a) for a in angles] if degrees else angles


def locked_first_angle(seq, angles):
    """The a1 that carries the rotation when (a1, a2, a3) is at gimbal lock and a3 is set to 0.
    Tait–Bryan: E_q(a2) E_r(a3) = E_p(s sin(a2) a3) E_q(a2) at a2 = ±π/2 (s = +1 for cyclic
    axes p→q), so intrinsic a1 + s sin(a2) a3, extrinsic a1 − s sin(a2) a3. Proper: a1 + a3 at
    a2 = 0 and a1 − a3 at a2 = π, in both modes."""
    a1, a2, a3 = angles
    if is_proper(seq):
        return a1 + math.cos(a2) * a3
    p, q = AXES.index(seq[0].lower()), AXES.index(seq[1].lower())
    s = 1.0 if (q - p) % 3 == 1 else -1.0
    sign = 1.0 if seq.isupper() else -1.0
    return a1 + sign * s * math.sin(a2) * a3


def wrapped_difference(a, b, period=2 * PI):
    d = (a - b) % period
    return min(d, period - d)


def fmt(v):
    return format(float(v), ".17g")


def write_table(path, comment_lines, columns, ids, positions, values):
    with open(path, "w", newline="\n") as f:
        for line in comment_lines:
            f.write("# %s\n" % line)
        f.write(",".join(["id", "x", "y", "z"] + columns) + "\n")
        for i, p, v in zip(ids, positions, values):
            f.write(",".join([str(i)] + [fmt(c) for c in p] + [fmt(c) for c in v]) + "\n")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "tests", "data", "scipy")
    os.makedirs(out, exist_ok=True)
    rng = np.random.default_rng(SEED)
    check_scipy_convention(rng)

    poses = build_poses(rng)
    ids = list(range(len(poses)))
    positions = rng.uniform(-2.0, 2.0, size=(len(poses), 3))
    quats = [p[3] for p in poses]  # (w, x, y, z), unit
    rotations = [Rotation.from_quat([q[1], q[2], q[3], q[0]]) for q in quats]
    origin = "generated by tools/scipy_reference.py (seed %d) with scipy %s, numpy %s" % (
        SEED, scipy.__version__, np.__version__)

    write_table(os.path.join(out, "poses_quaternion.csv"),
                [origin, "input poses: unit Hamilton quaternions, positions in metres"],
                ["qw", "qx", "qy", "qz"], ids, positions, quats)
    with open(os.path.join(out, "poses_catalog.csv"), "w", newline="\n") as f:
        f.write("# %s\n# how each pose of poses_quaternion.csv was built (angles in radians)\n"
                % origin)
        f.write("id,category,sequence,a1,a2,a3\n")
        for i, (category, seq, angles, _) in zip(ids, poses):
            a = [fmt(v) for v in angles] if angles is not None else ["", "", ""]
            f.write(",".join([str(i), category, seq] + a) + "\n")

    matrices = [r.as_matrix() for r in rotations]
    for r, m in zip(rotations, matrices):
        assert np.abs(m @ m.T - np.eye(3)).max() < 1e-14
    write_table(os.path.join(out, "expected_matrix.csv"), [origin, "scipy Rotation.as_matrix()"],
                ["r%d%d" % (i, j) for i in (1, 2, 3) for j in (1, 2, 3)], ids, positions,
                [m.reshape(9) for m in matrices])
    canonical = [canonical_wxyz(r.as_quat()) for r in rotations]
    write_table(os.path.join(out, "expected_quaternion.csv"),
                [origin, "scipy Rotation.as_quat(), sign made canonical: w >= 0"],
                ["qw", "qx", "qy", "qz"], ids, positions, canonical)
    write_table(os.path.join(out, "expected_abb.csv"),
                [origin, "abb preset: q1..q4 = w,x,y,z (scipy as_quat, canonical sign w >= 0)"],
                ["q1", "q2", "q3", "q4"], ids, positions, canonical)
    rotvecs = [r.as_rotvec() for r in rotations]
    for v in rotvecs:
        assert np.linalg.norm(v) <= PI + 1e-15
    write_table(os.path.join(out, "expected_rotvec.csv"), [origin, "scipy Rotation.as_rotvec()"],
                ["rx", "ry", "rz"], ids, positions, rotvecs)
    write_table(os.path.join(out, "expected_ur.csv"),
                [origin, "ur preset: rotation vector rx,ry,rz in radians (scipy as_rotvec)"],
                ["rx", "ry", "rz"], ids, positions, rotvecs)

    # Euler targets: every sequence, and the three Euler presets.
    targets = [(euler_file_stem(s), s, False, ["a1", "a2", "a3"],
                "sequence %s (%s), radians" % (s, "intrinsic" if s.isupper() else "extrinsic"))
               for s in SEQUENCES]
    targets += [
        ("rpy", "xyz", False, ["roll", "pitch", "yaw"], "rpy preset: extrinsic xyz, radians"),
        ("kuka", "ZYX", True, ["a_deg", "b_deg", "c_deg"], "kuka preset: intrinsic ZYX, degrees"),
        ("fanuc", "xyz", True, ["w_deg", "p_deg", "r_deg"], "fanuc preset: extrinsic xyz, degrees"),
    ]
    lock_rows = []
    band_rows = []  # locked by scipy's 1e-7 tolerance but not exactly at the lock
    max_lock_error = 0.0
    for stem, seq, degrees, columns, what in targets:
        values = []
        for i, (r, m, pose) in enumerate(zip(rotations, matrices, poses)):
            angles, locked = euler_with_lock_flag(r, seq, degrees)
            values.append(angles)
            rad = np.radians(angles) if degrees else angles
            if not locked:
                err = np.abs(composed(seq, rad) - m).max()
                assert err < 1e-9, (stem, i, angles, err)
                continue
            exact = exact_lock_angles(seq, m, list(angles), degrees)
            exact_rad = np.radians(exact) if degrees else exact
            err = np.abs(composed(seq, exact_rad) - m).max()
            # Exact at the lock; inside the band off the lock by δ, a3 = 0 costs O(δ |a3|).
            at_lock = exact_rad[1] in lock_values(seq)
            assert err < (1e-14 if at_lock else 1e-8), (stem, i, exact, err)
            if not at_lock:
                band_rows.append((i, stem))
            max_lock_error = max(max_lock_error, abs(angles[1] - exact[1]) *
                                 (PI / 180 if degrees else 1.0))
            _, built_seq, built, _ = pose
            if built_seq == seq and not degrees:  # compare with the angles the pose came from
                a1, a2, a3 = built
                assert abs(a2 - exact[1]) < 1e-15, (stem, i, built, exact)
                assert wrapped_difference(exact[0], locked_first_angle(seq, built)) < 1e-12, (
                    stem, i, built, exact)
            lock_rows.append((i, stem, "deg" if degrees else "rad", exact, list(angles)))
        write_table(os.path.join(out, "expected_%s.csv" % stem),
                    [origin, "scipy Rotation.as_euler(%r%s): %s" % (
                        seq, ", degrees=True" if degrees else "", what),
                     "angles in [%s] (scipy's range; hecal's is (%s]); gimbal-locked rows: "
                     "see gimbal_lock_exact.csv" % (("-180, 180", "-180, 180") if degrees else
                                                    ("-pi, pi", "-pi, pi"))],
                    columns, ids, positions, values)

    with open(os.path.join(out, "gimbal_lock_exact.csv"), "w", newline="\n") as f:
        f.write("# %s\n" % origin)
        f.write("# rows where scipy reports gimbal lock (middle angle within 1e-7 rad of the lock)"
                "; unit per row (rad or deg)\n")
        f.write("# a1,a2,a3: exact angles under the shared convention: a3 = 0, a1 carries the "
                "rotation, a2 exactly +-pi/2, 0 or pi (or, for a pose inside the band but not at "
                "the lock, its accurate value); scipy_a1..3: scipy's output\n")
        f.write("id,target,unit,a1,a2,a3,scipy_a1,scipy_a2,scipy_a3\n")
        for i, stem, unit, exact, raw in lock_rows:
            f.write(",".join([str(i), stem, unit] + [fmt(v) for v in exact] +
                             [fmt(v) for v in raw]) + "\n")

    print("wrote %d poses, %d Euler targets, %d gimbal-locked (pose, target) pairs to %s" %
          (len(poses), len(targets), len(lock_rows), os.path.normpath(out)))
    print("%d locked (pose, target) pairs inside the band but not at the lock, poses %s" %
          (len(band_rows), sorted({i for i, _ in band_rows})))
    print("largest scipy middle-angle error at gimbal lock: %.3g rad" % max_lock_error)


if __name__ == "__main__":
    main()
