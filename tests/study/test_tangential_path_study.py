"""The ``tangential_path`` study kind and its example (examples/tangential_path.toml), at a reduced size.

The example is shrunk to a 128 px field (8.6 um pixels) and a 40 px window, where paper 001's POM
ball at 25 mN still touches inside the window, so both programmes run in a few seconds.
"""

import numpy as np
import pytest
import xarray as xr

from roughcontact.contact.paths import read_path_csv
from roughcontact.materials import Material
from roughcontact.models import paper001
from roughcontact.study import load_study
from roughcontact.study.config import StudyError
from roughcontact.study.inputs import build_topography
from roughcontact.study.kinds.tangential_path import KIND
from roughcontact.study.run import make_task
from roughcontact.study.store import read_table

FILES = ("tangential_path_displacement.csv", "tangential_path_force.csv")
SMALL = {"shape = 256": "shape = 128", "window = 64": "window = 40"}


def small_study(shrunk, folder):
    return shrunk("tangential_path.toml", folder, SMALL, copy=FILES)


def test_example_runs_both_programmes(cli, shrunk, tmp_path, examples):
    study = small_study(shrunk, tmp_path)
    out = tmp_path / "out"
    status, stdout, stderr = cli("run", study, "-o", out, "--no-progress")
    assert status == 0, stderr
    assert "2 cases run, 0 reused, 0 failed" in stdout
    displacement, force = read_table(out / "results.csv")
    assert (displacement["control"], force["control"]) == ("displacement", "force")

    # displacement control: +-1.35 um slides at both ends; the last loop is analysed as paper 001's
    assert int(displacement["loops"]) == 2 and float(displacement["energy_last_loop [J]"]) > 0
    assert float(displacement["mu_from_loop"]) == pytest.approx(0.108, rel=1e-3)
    assert float(displacement["stroke_from_loop [m]"]) == pytest.approx(2.7e-6, rel=1e-9)
    k = [float(displacement[f"K_L_{p} [N/m]"]) for p in "ABC"]
    assert k[0] > k[1] > k[2] > 0

    # force control: every prescribed force is met, no sliding plateau, so no paper analysis
    programme, _ = read_path_csv(examples / FILES[1])
    assert float(force["last_force_x [N]"]) == pytest.approx(programme[-1, 0], rel=1e-9)
    assert float(force["last_force_y [N]"]) == pytest.approx(programme[-1, 1], rel=1e-9)
    assert force["mu_from_loop"] == force["K_L_A [N/m]"] == ""  # NaN, stored as an empty cell
    assert force["analysis_note"].startswith("force control") and displacement["analysis_note"] == ""
    assert int(force["loops"]) == 2 and float(force["energy_last_loop [J]"]) > 0
    assert 0 < float(force["last_stick_fraction"]) < 1

    datasets = {}
    for path in (out / "cases" / "programmes").glob("*.nc"):
        data = xr.load_dataset(path)
        datasets[data.attrs["control"]] = data
    steps = len(read_path_csv(examples / FILES[0])[0])
    data = datasets["displacement"]
    assert data["delta_x"].size == data["force_x"].size == steps + 1  # from the unloaded start
    assert data["normalised_shear"].shape == (4, 40, 40)  # the last three reversals and the last step
    assert int(data["kept_step"][-1]) == steps
    assert np.nanmax(data["normalised_shear"].values) <= 1 + 1e-5
    for name in ("loops", "stick_slip"):
        assert (out / "figures" / f"programmes_{name}.png").stat().st_size > 10_000


def test_scalars_equal_a_direct_programme_case(shrunk, tmp_path, examples):
    study = load_study(small_study(shrunk, tmp_path))
    case = study.cases[0]
    task = make_task(study, case)
    scalars = KIND.run(task.parameters, task.inputs).scalars
    ball = build_topography(case.topographies["pom_ball"], None)
    programme, control = read_path_csv(examples / FILES[0])
    direct = paper001.programme_case(
        paper001.central_window(ball, 40),
        Material(1.38e9, 0.5, "POM"),
        Material(130e9, 0.28, "wafer"),
        25e-3,
        path=programme,
        control=control,
        friction_coefficient=0.108,
    )
    row = direct.scalars()
    assert scalars["last_force_x"] == pytest.approx(row["last_F_x [N]"], rel=1e-12)
    assert scalars["energy_last_loop"] == pytest.approx(row["energy_per_loop [J]"][-1], rel=1e-12)
    assert scalars["K_L_B"] == pytest.approx(row["K_L_B [N/m]"], rel=1e-12)


def test_a_bad_programme_fails_validation_naming_the_file(shrunk, tmp_path):
    study = small_study(shrunk, tmp_path)
    (tmp_path / FILES[1]).write_text("step,Q_x\n1,0.5\n")
    with pytest.raises(StudyError) as error:
        load_study(study)
    assert "path" in str(error.value) and "'q_x' has no unit" in str(error.value)
    (tmp_path / FILES[1]).unlink()
    with pytest.raises(StudyError, match="not found"):
        load_study(study)


def test_editing_the_programme_changes_the_case_key(shrunk, tmp_path):
    study = small_study(shrunk, tmp_path)
    before = [c.key for c in load_study(study).cases]
    path = tmp_path / FILES[0]
    path.write_text(path.read_text().replace("x [um]", "x [nm]"))
    after = [c.key for c in load_study(study).cases]
    assert after[0] != before[0] and after[1] == before[1]
    assert np.isfinite(read_path_csv(path)[0]).all()
