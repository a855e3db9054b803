"""The type stub hecal/__init__.pyi names exactly the module's public names, and the
docstrings read like the CLI's --help (frames, units)."""
import ast
import os

import hecal


def test_stub_matches_module():
    path = os.path.join(os.path.dirname(hecal.__file__), "__init__.pyi")
    tree = ast.parse(open(path).read())
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
    public = {n for n in dir(hecal) if not n.startswith("_") and n != "annotations"}
    public -= {"_hecal"}
    helpers = {"PathLike", "ArrayLike", "Sigma"}
    assert public - names == set()
    assert {n for n in names if not n.startswith("_")} - helpers - public == set()


def test_docstrings_name_frames_and_units():
    assert "T_base_gripper" in hecal.calibrate.__doc__ and "T_camera_target" in hecal.calibrate.__doc__
    assert hecal.calibrate.__doc__.startswith("calibrate(robot, camera")
    assert "T_gripper_camera" in hecal.calibrateHandEye.__doc__
    assert "METRES" in hecal.read_poses.__doc__
