"""hecal.calibrate equals the CLI: to_json() is the file `hecal calibrate --output` writes, byte
for byte, on the bundled data (MoveIt Calibration's 50 eye-to-hand stations: every method;
Tabb's 88 eye-in-hand stations in mm: the default method), and arrays agree with paths."""
import json
import os
import subprocess

import numpy as np
import pytest

import hecal

SOURCE = os.environ.get("HECAL_SOURCE_DIR", ".")
CLI = os.environ.get("HECAL_CLI", os.path.join(SOURCE, "build", "bin", "hecal"))


def run(*args):
    subprocess.run([CLI, *args], check=True, stdout=subprocess.DEVNULL)


@pytest.fixture(scope="module")
def moveit(tmp_path_factory):
    d = tmp_path_factory.mktemp("moveit")
    run("import", "--format", "moveit", os.path.join(SOURCE, "data/moveit-calibration/pose_samples.json"),
        "--robot", str(d / "r.csv"), "--camera", str(d / "c.csv"))
    return d


@pytest.fixture(scope="module")
def tabb(tmp_path_factory):
    d = tmp_path_factory.mktemp("tabb")
    run("import", "--format", "tabb", os.path.join(SOURCE, "data/tabb-rwhe-dataset1"),
        "--robot", str(d / "r.csv"), "--camera", str(d / "c.csv"))
    return d


def cli_json(d, out, *flags):
    run("calibrate", "--robot", str(d / "r.csv"), "--camera", str(d / "c.csv"), "--output",
        str(d / out), *flags)
    return (d / out).read_text()


def test_every_method_equals_the_cli(moveit):
    expected = cli_json(moveit, "all.json", "--setup", "eye-to-hand", "--method", "all")
    result = hecal.calibrate(str(moveit / "r.csv"), moveit / "c.csv", setup="eye-to-hand",
                             method="all")
    assert result.to_json() == expected
    assert result.to_dict() == json.loads(expected)
    methods = [r.method for r in result.results]
    assert methods[-1] == "ml" and len(methods) + len(result.failures) == 12
    assert result.method == "ml"  # the attributes are the default method's


def test_default_method_and_options_equal_the_cli(moveit):
    expected = cli_json(moveit, "ml.json", "--setup", "eye-to-hand", "--robot-sigma", "2,0.05",
                        "--camera-sigma", "2,0.05", "--keep-outliers")
    result = hecal.calibrate(str(moveit / "r.csv"), str(moveit / "c.csv"), setup="eye-to-hand",
                             robot_sigma="2,0.05", camera_sigma=(2, 0.05), keep_outliers=True)
    assert result.to_json() == expected
    d = json.loads(expected)
    assert np.allclose(result.X, d["X"]["matrix"], rtol=0, atol=1e-15)
    assert np.allclose(result.covariance[:6, :6], d["covariance"]["X"], rtol=1e-15, atol=0)
    sigma = d["covariance"]["sigma"]["X"]
    assert np.allclose(np.degrees(result.sigma[:3, 0]), sigma["rotation_deg"], rtol=1e-12)
    assert np.allclose(result.sigma[3:6, 0], sigma["translation"], rtol=1e-12)
    assert [r["id"] for r in result.residuals] == [r["id"] for r in d["residuals"]["per_station"]]
    assert result.noise["estimated"] is False
    assert result.setup == "eye-to-hand" and result.X_frame == "T_base_camera"


def test_millimetre_files_equal_the_cli(tabb):
    expected = cli_json(tabb, "tabb.json", "--setup", "eye-in-hand")
    result = hecal.calibrate(str(tabb / "r.csv"), str(tabb / "c.csv"), setup="eye-in-hand")
    assert result.to_json() == expected
    assert result.unit == "mm" and [r["id"] for r in result.rejected] == \
        json.loads(expected)["stations"]["rejected"]


def test_arrays_agree_with_paths(moveit, tabb):
    R, ids = hecal.read_poses(moveit / "r.csv")
    C, _ = hecal.read_poses(moveit / "c.csv")
    from_files = hecal.calibrate(str(moveit / "r.csv"), str(moveit / "c.csv"), setup="eye-to-hand")
    from_arrays = hecal.calibrate(R, C, setup="eye-to-hand")
    assert from_arrays.to_json() == from_files.to_json()
    # mm: the arrays went through metres and back, so agreement is to rounding
    R, ids = hecal.read_poses(tabb / "r.csv")
    C, _ = hecal.read_poses(tabb / "c.csv")
    R[:, :3, 3] *= 1000
    C[:, :3, 3] *= 1000
    from_files = hecal.calibrate(str(tabb / "r.csv"), str(tabb / "c.csv"), setup="eye-in-hand")
    from_arrays = hecal.calibrate(R, C, setup="eye-in-hand", unit="mm", station_ids=ids)
    assert np.allclose(from_arrays.X, from_files.X, rtol=0, atol=1e-6)
    assert from_arrays.used_station_ids == from_files.used_station_ids
    assert from_arrays.warnings == from_files.warnings


def test_errors_name_the_source(moveit, tmp_path):
    with pytest.raises(hecal.InputError) as info:
        hecal.calibrate(str(moveit / "r.csv"), str(tmp_path / "missing.csv"), setup="eye-to-hand")
    assert info.value.source.endswith("missing.csv") and "missing.csv" in str(info.value)
    bad = tmp_path / "bad.csv"
    bad.write_text("x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n0,0,abc,1,0,0,0\n")
    with pytest.raises(hecal.InputError) as info:
        hecal.calibrate(str(bad), str(moveit / "c.csv"), setup="eye-to-hand")
    assert info.value.line == 3 and info.value.source == str(bad) and info.value.fix
    R, _ = hecal.read_poses(moveit / "r.csv")
    with pytest.raises(hecal.InputError, match="camera: has shape"):
        hecal.calibrate(R, R[:, :3, :], setup="eye-to-hand")
    with pytest.raises(hecal.InputError, match="unknown method 'foo'"):
        hecal.calibrate(R, R, method="foo")
    with pytest.raises(hecal.InputError, match="unknown setup"):
        hecal.calibrate(R, R, setup="eye-on-hand")
    with pytest.raises(hecal.InputError, match="robot_sigma"):
        hecal.calibrate(R, R, robot_sigma="2")
    with pytest.raises(hecal.InputError, match="eye-to-hand"):
        hecal.calibrate(str(moveit / "r.csv"), str(moveit / "c.csv"), setup="eye-in-hand")
