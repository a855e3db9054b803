"""hecal.simulate writes the CLI's CSV files byte for byte (`hecal simulate --summary --output`)."""
import os
import subprocess

import pytest

import hecal

SOURCE = os.environ.get("HECAL_SOURCE_DIR", ".")
CLI = os.environ.get("HECAL_CLI", os.path.join(SOURCE, "build", "bin", "hecal"))


def test_simulate_equals_the_cli(tmp_path):
    subprocess.run([CLI, "simulate", "--stations", "5,10", "--sigma", "0.3,1/0.5", "--trials", "20",
                    "--method", "park-martin,ml", "--setup", "eye-in-hand,eye-to-hand",
                    "--summary", str(tmp_path / "s.csv"), "--output", str(tmp_path / "t.csv")],
                   check=True, stdout=subprocess.DEVNULL)
    result = hecal.simulate(stations=[5, 10], sigmas=[0.3, (1, 0.5)], trials=20,
                            methods=["park-martin", "ml"], setups=["eye-in-hand", "eye-to-hand"])
    assert result["summary_csv"] == (tmp_path / "s.csv").read_text()
    assert result["trials_csv"] == (tmp_path / "t.csv").read_text()
    rows = result["summary"]
    assert len(rows) == 2 * 2 * 2 * 2 and rows[0]["method"] == "park-martin"
    assert rows[0]["stations"] == 5 and rows[0]["rotation_rmse_deg"] > 0


def test_simulate_errors():
    with pytest.raises(hecal.InputError, match="stations"):
        hecal.simulate(stations=[2], trials=1)
    with pytest.raises(hecal.InputError, match="unknown value 'sideways'"):
        hecal.simulate(setups=["sideways"], trials=1)
