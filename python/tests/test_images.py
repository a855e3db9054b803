"""calibrate_images equals `hecal calibrate --images` byte for byte on rwhe-kuka2's 28 images;
detect gives the camera poses."""
import os
import shutil
import subprocess

import numpy as np
import pytest

import hecal

SOURCE = os.environ.get("HECAL_SOURCE_DIR", ".")
CLI = os.environ.get("HECAL_CLI", os.path.join(SOURCE, "build", "bin", "hecal"))
KUKA = os.path.join(SOURCE, "data", "rwhe-kuka2")

pytestmark = pytest.mark.skipif(not hasattr(hecal, "calibrate_images"),
                                reason="built without the vision layer")


def test_calibrate_images_equals_the_cli(tmp_path):
    out = tmp_path / "k.json"
    subprocess.run([CLI, "calibrate", "--images", os.path.join(KUKA, "images"), "--target",
                    os.path.join(KUKA, "target.yaml"), "--robot",
                    os.path.join(KUKA, "RobotPosesVec.txt"), "--setup", "eye-in-hand",
                    "--output", str(out)], check=True, stdout=subprocess.DEVNULL)
    texts = []
    result = hecal.calibrate_images(os.path.join(KUKA, "images"), os.path.join(KUKA, "target.yaml"),
                                    os.path.join(KUKA, "RobotPosesVec.txt"), setup="eye-in-hand",
                                    log=lambda kind, text: texts.append(kind))
    assert result.to_json() == out.read_text()
    assert "progress" in texts
    assert result.to_dict()["images"]["per_image"][0]["id"] == "im_01"


def test_detect_and_errors(tmp_path):
    folder = tmp_path / "images"
    folder.mkdir()
    for name in sorted(os.listdir(os.path.join(KUKA, "images")))[:6]:  # six views: fast enough
        shutil.copy(os.path.join(KUKA, "images", name), folder / name)
    poses, ids, camera = hecal.detect(folder, os.path.join(KUKA, "target.yaml"))
    assert poses.shape == (6, 4, 4) and ids[0] == "im_01" and camera["width"] == 1920
    assert np.all(poses[:, 2, 3] > 0.2)  # the board in front of the camera, metres
    with pytest.raises(hecal.InputError) as info:
        hecal.detect(str(tmp_path / "nothing"), os.path.join(KUKA, "target.yaml"))
    assert "nothing" in str(info.value)
    with pytest.raises(hecal.InputError, match="not available from images"):
        hecal.calibrate_images(KUKA, "t.yaml", "r.csv", method="all")
