"""read_poses / write_poses: every rotation form, Euler sequence and vendor preset of the CLI
round-trips; units and degrees; ids; errors name the file and line."""
import numpy as np
import pytest

import hecal
from drop_in_cases import random_rotation

FORMS = ["quaternion", "rotvec", "matrix", "euler:ZYX", "euler:xyz", "euler:ZXZ", "euler:yzy",
         "rpy", "kuka", "fanuc", "abb", "ur"]


@pytest.fixture(scope="module")
def poses():
    rng = np.random.default_rng(8)
    T = np.tile(np.eye(4), (6, 1, 1))
    for k in range(6):
        T[k, :3, :3] = random_rotation(rng)
        T[k, :3, 3] = rng.uniform(-1, 1, 3)
    return T


@pytest.mark.parametrize("form", FORMS)
@pytest.mark.parametrize("units,degrees", [("m", False), ("mm", True)])
def test_every_form_round_trips(tmp_path, poses, form, units, degrees):
    path = tmp_path / "poses.csv"
    ids = [f"s{k}" for k in range(len(poses))]
    hecal.write_poses(path, poses, to=form, units=units, degrees=degrees, ids=ids,
                      comments=["written by test_poses"])
    text = path.read_text()
    assert text.startswith("# written by test_poses")
    back, back_ids = hecal.read_poses(str(path))
    assert back_ids == ids
    assert np.abs(back - poses).max() < 1e-12, form


def test_read_options(tmp_path):
    path = tmp_path / "abc.csv"
    path.write_text("x,y,z,a1,a2,a3\n100,0,0,90,0,0\n")
    T, ids = hecal.read_poses(path, units="mm", degrees=True, euler="ZYX")
    assert ids == ["0"] and np.allclose(T[0, :3, 3], [0.1, 0, 0])
    assert np.allclose(T[0, :3, :3], [[0, -1, 0], [1, 0, 0], [0, 0, 1]], atol=1e-15)
    inverse, _ = hecal.read_poses(path, units="mm", degrees=True, euler="ZYX", invert=True)
    assert np.allclose(inverse[0], np.linalg.inv(T[0]), atol=1e-15)
    with pytest.raises(hecal.InputError, match="euler") as info:
        hecal.read_poses(path, degrees=True)
    assert info.value.source == str(path)


def test_errors(tmp_path, poses):
    with pytest.raises(hecal.InputError) as info:
        hecal.read_poses(tmp_path / "missing.csv")
    assert info.value.source.endswith("missing.csv") and info.value.fix
    bad = tmp_path / "bad.csv"
    bad.write_text("x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n0,0,nan,1,0,0,0\n")
    with pytest.raises(hecal.InputError) as info:
        hecal.read_poses(bad)
    assert info.value.line == 3 and str(info.value).startswith(str(bad) + ":3: ")
    with pytest.raises(hecal.InputError, match="unknown rotation form"):
        hecal.write_poses(tmp_path / "o.csv", poses, to="euler")
    with pytest.raises(hecal.InputError, match="has 2 ids for 6 poses"):
        hecal.write_poses(tmp_path / "o.csv", poses, ids=["a", "b"])
    with pytest.raises(hecal.InputError, match=r"shape \(6, 3, 4\)"):
        hecal.write_poses(tmp_path / "o.csv", poses[:, :3, :])
