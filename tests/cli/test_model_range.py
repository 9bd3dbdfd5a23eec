"""Results that leave their model's range say so (issue 15): printed, stored and reported, numbers kept."""

import json

import numpy as np

from roughcontact.contact import solve_normal
from roughcontact.materials import get_material
from roughcontact.topography import Topography, save_topography
from roughcontact.topography.generate import sinusoid, sphere

SU8 = get_material("SU-8")


def test_an_elastic_peak_pressure_beyond_the_small_slope_theory_is_flagged():
    ball = sphere((64, 64), 2e-6, radius=1e-6, kind="paraboloid")
    gentle = solve_normal(ball, SU8, force=1e-6)  # peak 0.03 E*
    steep = solve_normal(ball, SU8, force=1e-4)  # peak 0.13 E* (Hertz p0 0.14 E*)
    # the gentle contact is 9 pixels: flagged as unresolved, not as beyond the small-slope theory
    (unresolved,) = gentle.range_warnings()
    assert "9 pixels" in unresolved and "not resolved" in unresolved
    (warning,) = steep.range_warnings()
    assert "small-slope" in warning and "E*" in warning
    capped = solve_normal(ball, SU8, force=1e-4, hardness=0.1 * gentle.contact_modulus)
    assert capped.range_warnings() == []  # elastic-plastic: the cap is the model


def test_full_contact_is_flagged():
    wave = sinusoid((64, 64), 1e-6, amplitude=1e-9, wavelength=1e-6)
    # Westergaard: full contact above p* = pi E* h / lambda (h the amplitude) = 0.0042 E* here
    full = solve_normal(wave, SU8, mean_pressure=0.02 * 4.8e9, boundary="periodic")
    assert any("full contact" in w for w in full.range_warnings())


def test_the_command_prints_the_warning_and_keeps_it_in_json(run, tmp_path):
    x = np.linspace(-1e-6, 1e-6, 32)
    bump = Topography(-(x[:, None] ** 2 + x[None, :] ** 2) / (2 * 1e-6), 2e-6)
    save_topography(bump, tmp_path / "bump.nc")
    argv = ("contact", tmp_path / "bump.nc", "--material", "SU-8", "--force", "100 uN", "--detrend", "none")
    status, out, err = run(*argv)
    assert status == 0 and "roughcontact: warning: peak pressure" in err
    status, out, _ = run(*argv, "--json")
    assert "small-slope" in json.loads(out)["analyses"][0]["cases"][0]["warnings"][0]


def test_a_scan_outside_1_nm_to_1_m_is_noted(run, tmp_path):
    save_topography(
        Topography(np.random.default_rng(1).normal(size=(16, 16)) * 1e-3, 2.0), tmp_path / "big.nc"
    )
    status, _, err = run("contact", tmp_path / "big.nc", "--material", "SU-8", "--pressure", "1 MPa")
    assert status == 0
    assert "roughcontact: note:" in err and "outside 1 nm to 1 m" in err and "2 m x 2 m" in err


def test_no_warning_in_range(run, tmp_path):
    x = np.linspace(-1e-6, 1e-6, 64)
    bump = Topography(-(x[:, None] ** 2 + x[None, :] ** 2) / (2 * 5e-6), 2e-6)
    save_topography(bump, tmp_path / "bump.nc")
    # Hertz: a = 90 nm (about 26 pixels of 31 nm: resolved), p0 = 0.01 E*
    status, _, err = run("contact", tmp_path / "bump.nc", "--material", "SU-8", "--force", "1 uN")
    assert status == 0 and "warning" not in err
