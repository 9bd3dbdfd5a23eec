"""examples/frictional_programme.toml: a combined normal and tangential programme from a CSV, end to end."""

import csv

import numpy as np
import xarray as xr


def test_the_combined_example_runs_and_meets_every_row(cli, shrunk, tmp_path, examples):
    study = shrunk("frictional_programme.toml", tmp_path, {}, copy=("frictional_programme.csv",))
    out = tmp_path / "out"
    status, stdout, stderr = cli("run", study, "-o", out, "--no-progress")
    assert status == 0, stderr
    assert "0 failed" in stdout
    (row,) = list(csv.DictReader((out / "results.csv").open()))
    assert row["normal_loading"] == "frictional" and row["status"] == "done"
    rows = np.loadtxt(examples / "frictional_programme.csv", delimiter=",", comments="#", skiprows=7)
    data = xr.load_dataset(next((out / "cases" / "combined").glob("*.nc")))
    point = data["programme_point"].values[1:]
    at_rows = np.append(point[1:] != point[:-1], True)
    np.testing.assert_allclose(data["normal_force"].values[1:][at_rows], 1e-3 * rows[:, 1], rtol=1e-8)
    np.testing.assert_allclose(data["delta_x"].values[1:][at_rows], 1e-6 * rows[:, 0], rtol=1e-12, atol=1e-15)
    for name in ("path", "loops", "stick_slip"):
        assert (out / "figures" / f"combined_{name}.png").stat().st_size > 10_000
