"""Friction-loop analysis (paper 001 sec. 4-5) on loops built from the Mindlin-Deresiewicz Masing rule."""

from pathlib import Path

import numpy as np
import pytest

from roughcontact.analytic.mindlin import (
    dissipated_energy_displacement,
    masing_force,
    sliding_displacement,
)
from roughcontact.errors import InputError, UnitError
from roughcontact.experiment.friction_loop import (
    analyse_loop,
    eq9_force,
    loop_energy,
    read_loop_csv,
    split_branches,
)

MU, P, A, G = 0.153, 25e-3, 40e-6, 0.1e9
ARGS = (MU, P, A, G)
DELTA0 = sliding_displacement(*ARGS)
STROKE = 2.8e-6
LEG = 1501
EXAMPLE = Path(__file__).parents[2] / "examples" / "paper001_measured_loop.csv"


def paper_path(stroke=STROKE, cycles=4, points=LEG):
    """0 -> stroke -> 0, ``cycles`` times (paper 001 Fig. 6)."""
    leg = np.linspace(0.0, stroke, points)
    return np.concatenate([leg] + [leg[::-1][1:], leg[1:]] * (cycles - 1) + [leg[::-1][1:]])


def mindlin_stiffness(distance):
    """K_L on a Masing branch at ``distance`` from the reversal: Q_M'(x/2)."""
    return 1.5 * MU * P / DELTA0 * np.sqrt(1.0 - distance / (2.0 * DELTA0))


@pytest.fixture(scope="module")
def clean():
    path = paper_path()
    force = masing_force(path, *ARGS)
    return path, force, analyse_loop(path, force, P)


def test_stroke_mu_energy_exact(clean):
    path, force, result = clean
    assert result.stroke == pytest.approx(STROKE, rel=1e-12)
    assert result.mu == pytest.approx(MU, rel=1e-5)
    assert result.energy == pytest.approx(dissipated_energy_displacement(STROKE, *ARGS), rel=1e-5)
    assert len(result.reversals) == 7
    assert np.all(np.asarray(result.reversals) % (LEG - 1) == 0)


def test_eq9_fit_is_the_masing_branch(clean):
    _, _, result = clean
    b = result.branch
    assert b.direction == 1
    # Mindlin is exactly of the eq. 9 form: c1 = 2 mu P, c2 = 1/(2 delta_0), n = 3/2
    assert b.c1 == pytest.approx(2 * MU * P, rel=1e-5)
    assert b.c2 == pytest.approx(1 / (2 * DELTA0), rel=1e-5)
    assert b.n == pytest.approx(1.5, rel=1e-5)
    assert b.span == pytest.approx(2 * MU * P, rel=1e-12)
    # K_L at A, B, C within 1e-5 of Mindlin (tolerance stated in docs/presliding_analysis.md)
    assert np.allclose(b.point_stiffness, mindlin_stiffness(b.point_distance), rtol=1e-5)
    # the points lie at 25/50/75 % of the span: Q_M(x/2) * 2 = f * 2 mu P
    change = b.direction * (b.point_force - b.reversal_force)
    assert np.allclose(change, np.array([0.25, 0.5, 0.75]) * 2 * MU * P, rtol=1e-9)
    assert np.allclose(
        b.point_distance, 2 * DELTA0 * (1 - (1 - np.array([0.25, 0.5, 0.75])) ** (2 / 3)), rtol=1e-5
    )
    # point D: start of full sliding at 2 delta_0 (within the plateau tolerance)
    assert b.sliding_distance == pytest.approx(2 * DELTA0, rel=0.02)
    assert set(result.lateral_stiffness) == {"A", "B", "C"}
    scalars = result.scalars()
    assert scalars["K_L_B"] == pytest.approx(b.point_stiffness[1])
    assert {"stroke", "mu", "energy", "c1", "c2", "n", "distance_D"} <= set(scalars)


def test_paper001_point_stiffness_matches_loop_analysis():
    from roughcontact.materials import Material
    from roughcontact.papers.paper001 import paper001_mindlin

    m = paper001_mindlin(
        friction_coefficient=MU,
        normal_force=P,
        radius=5e-3,
        material=Material(0.98e9, 0.5),
        counter_body=Material(130e9, 0.28),
    )
    path = paper_path(stroke=8 * m.sliding_distance, cycles=2)
    force = masing_force(path, m.friction_coefficient, m.normal_force, m.contact_radius, m.shear_modulus)
    result = analyse_loop(path, force, P)
    assert np.allclose(result.branch.point_stiffness, m.point_stiffness(), rtol=1e-5)


def test_both_branches_and_other_fractions(clean):
    path, force, _ = clean
    result = analyse_loop(path, force, P, branch="decreasing", fractions=(0.1, 0.9))
    assert result.branch.direction == -1
    assert result.point_names == ("A", "B")
    assert np.allclose(
        result.branch.point_stiffness, mindlin_stiffness(result.branch.point_distance), rtol=1e-5
    )


def test_symmetric_cycles():
    leg = np.linspace(-1.0, 1.0, 1201) * 4 * DELTA0
    path = np.concatenate([np.linspace(0, 4 * DELTA0, 301), leg[::-1][1:], leg[1:], leg[::-1][1:], leg[1:]])
    force = masing_force(path, *ARGS)
    result = analyse_loop(path, force, P)
    assert result.stroke == pytest.approx(8 * DELTA0, rel=1e-12)
    assert result.mu == pytest.approx(MU, rel=1e-5)
    assert result.energy == pytest.approx(dissipated_energy_displacement(8 * DELTA0, *ARGS), rel=1e-4)


def test_noise_robustness(clean):
    path, force, exact = clean
    rng = np.random.default_rng(3)
    noisy_force = force + 0.01 * MU * P * rng.standard_normal(force.size)  # 1 % of the sliding force
    noisy_path = path + 0.01 * DELTA0 * rng.standard_normal(path.size)
    result = analyse_loop(noisy_path, noisy_force, P)
    # reversal detection still right (within a few samples of the true turning points)
    assert len(result.reversals) == len(exact.reversals)
    assert np.all(np.abs(np.asarray(result.reversals) - np.asarray(exact.reversals)) <= 5)
    assert result.mu == pytest.approx(MU, rel=2e-3)
    assert result.stroke == pytest.approx(STROKE, rel=2e-3)
    assert np.allclose(result.branch.point_stiffness, exact.branch.point_stiffness, rtol=0.1)
    assert result.energy == pytest.approx(exact.energy, rel=0.02)


def test_split_branches_ignores_noise_below_threshold():
    rng = np.random.default_rng(0)
    x = np.concatenate([np.linspace(0, 1, 200), np.linspace(1, 0, 200)[1:]]) + 0.01 * rng.standard_normal(399)
    branches = split_branches(x)
    assert len(branches) == 2
    assert abs(branches[0][1] - 199) <= 5


def test_csv_unit_invariance(tmp_path, clean):
    path, force, _ = clean
    micro = tmp_path / "loop_um_mN.csv"
    si = tmp_path / "loop_m_N.txt"
    micro.write_text(
        "# comment\ndisplacement [um],force [mN]\n"
        + "".join(f"{d * 1e6:.17g},{f * 1e3:.17g}\n" for d, f in zip(path, force, strict=True))
    )
    si.write_text(
        "".join(
            f"{t:.17g}\t{d:.17g}\t{f:.17g}\n"
            for t, d, f in zip(np.arange(path.size) * 0.1, path, force, strict=True)
        )
    )
    a = read_loop_csv(micro)
    b = read_loop_csv(si, displacement_unit="m", force_unit="N", time_unit="s")
    assert b.time is not None and a.time is None
    assert read_loop_csv(si, displacement_unit="m", force_unit="N").time is None  # no unit: not read
    ra, rb = analyse_loop(a, None, P), analyse_loop(b, None, P)
    assert ra.branch.point_stiffness == pytest.approx(rb.branch.point_stiffness, rel=1e-9)
    assert ra.stroke == pytest.approx(rb.stroke, rel=1e-12)
    assert ra.mu == pytest.approx(rb.mu, rel=1e-12)
    with pytest.raises(InputError) as info:
        read_loop_csv(micro, displacement_unit="nm")
    assert info.value.field == "displacement_unit"
    assert (
        "'displacement [um]'" in info.value.problem
        and "leave --displacement-unit out" in info.value.fix_in("cli")
    )
    # the same unit as the header's, typed, is no contradiction
    same = read_loop_csv(micro, displacement_unit="µm", force_unit="mN")
    np.testing.assert_array_equal(same.displacement, a.displacement)
    np.testing.assert_array_equal(same.force, a.force)


def _nm_newton_rows(path, force) -> str:
    return "".join(f"{d * 1e9:.17g},{f:.17g}\n" for d, f in zip(path, force, strict=True))


def test_no_unit_is_assumed_for_a_loop(tmp_path, clean):
    """A loop in nm and N reads right when its header or the caller says so, and is refused otherwise."""
    path, force, _ = clean
    rows = _nm_newton_rows(path, force)
    labelled, bare, plain = tmp_path / "labelled.csv", tmp_path / "bare.csv", tmp_path / "plain.csv"
    labelled.write_text("displacement [nm],force [N]\n" + rows)
    bare.write_text(rows)
    plain.write_text("displacement,force\n" + rows)
    expected = analyse_loop(path, force, P).mu
    assert analyse_loop(read_loop_csv(labelled), None, P).mu == pytest.approx(expected, rel=1e-12)
    assert analyse_loop(read_loop_csv(bare, "nm", "N"), None, P).mu == pytest.approx(expected, rel=1e-12)
    assert analyse_loop(read_loop_csv(plain, "nm", "N"), None, P).mu == pytest.approx(expected, rel=1e-12)
    with pytest.raises(InputError) as info:
        read_loop_csv(bare)
    assert info.value.field == "displacement_unit"
    assert "no header" in info.value.problem and "displacement and force" in info.value.problem
    assert "--displacement-unit um --force-unit mN" in info.value.fix_in("cli")
    with pytest.raises(InputError) as info:
        read_loop_csv(plain, displacement_unit="nm")
    assert info.value.field == "force_unit" and "'force'" in info.value.problem
    assert info.value.fix_in("study").endswith('force_unit = "mN".')
    with pytest.raises(InputError) as info:
        read_loop_csv(labelled, force_unit="mN")  # a typed unit that contradicts the header
    assert info.value.field == "force_unit"
    assert (
        info.value.problem
        == f"'mN' contradicts the header cell 'force [N]' of {labelled.name}, which gives [N]."
    )


@pytest.mark.parametrize(
    ("header", "fields"),
    [
        ("displacement (nm);force (N)", {}),
        ("delta/nm;F/N", {}),
        ("displacement in nm;force in N", {}),
        ("displacement [nm];force", {"force_unit": "N"}),
    ],
)
def test_header_units_in_every_form(tmp_path, clean, header, fields):
    path, force, _ = clean
    file = tmp_path / "loop.csv"
    file.write_text(header + "\n" + _nm_newton_rows(path, force).replace(",", ";"))
    loop = read_loop_csv(file, **fields)
    np.testing.assert_allclose(loop.displacement, path, rtol=1e-12, atol=1e-21)
    np.testing.assert_allclose(loop.force, force, rtol=1e-12, atol=0)


def test_a_header_unit_of_the_wrong_kind_is_refused_naming_the_cell(tmp_path, clean):
    path, force, _ = clean
    file = tmp_path / "loop.csv"
    file.write_text("displacement [nm],force [mm]\n" + _nm_newton_rows(path, force))
    with pytest.raises(UnitError) as info:
        read_loop_csv(file)
    assert info.value.field == "force_unit" and "'force [mm]'" in info.value.problem
    assert "'force [mN]'" in info.value.fix


def test_example_csv_reproduces_table1():
    loop = read_loop_csv(EXAMPLE)
    assert loop.time is not None
    result = analyse_loop(loop, None, 25e-3)
    assert result.stroke == pytest.approx(2.805e-6, rel=5e-3)
    assert result.mu == pytest.approx(0.153, rel=5e-3)
    header = EXAMPLE.read_text().splitlines()[:2]
    assert header[0] == "# origin: synthetic" and "SYNTHETIC" in header[1]
    # the header's origin travels with the loop: it is never taken for a measurement
    assert loop.origin.word == "synthetic" and loop.origin.declared and not loop.origin.is_measured


def test_a_loop_file_says_its_origin(tmp_path, clean):
    """A loop is measured unless its header says otherwise; an unknown origin word is refused."""
    path, force, _ = clean
    rows = "".join(f"{d * 1e6:.17g},{f * 1e3:.17g}\n" for d, f in zip(path, force, strict=True))
    plain, synthetic, odd = tmp_path / "plain.csv", tmp_path / "synthetic.csv", tmp_path / "odd.csv"
    plain.write_text("displacement [um],force [mN]\n" + rows)
    synthetic.write_text(
        "# origin: synthetic\n# by construction: Mindlin's loop\ndisplacement [um],force [mN]\n" + rows
    )
    odd.write_text("# origin: simulated\ndisplacement [um],force [mN]\n" + rows)
    assert read_loop_csv(plain).origin.is_measured and not read_loop_csv(plain).origin.declared
    made = read_loop_csv(synthetic).origin
    assert (made.word, made.by_construction) == ("synthetic", "Mindlin's loop")
    with pytest.raises(InputError, match="origin: simulated"):
        read_loop_csv(odd)


def test_loop_energy_of_rectangle():
    assert loop_energy([0, 2, 2, 0], [-1, -1, 1, 1]) == pytest.approx(4.0)
    assert eq9_force(10.0, 2.0, 1.0, 1.5) == pytest.approx(2.0)  # saturated beyond 1/c2


@pytest.mark.parametrize(
    "displacement, force, field",
    [
        (np.r_[np.linspace(0, 1, 20), np.nan], np.zeros(21), "displacement"),
        (np.linspace(0, 1, 20), np.r_[np.zeros(19), np.inf], "force"),
        (np.linspace(0, 1, 5), np.zeros(5), "displacement"),
        (np.linspace(0, 1, 50), np.linspace(0, 1, 50), "displacement"),  # no reversal
    ],
)
def test_bad_input(displacement, force, field):
    with pytest.raises(InputError) as info:
        analyse_loop(displacement, force, P)
    assert info.value.field == field


def test_bad_options(clean, tmp_path):
    path, force, _ = clean
    for kwargs, field in (
        ({"fractions": (0.5, 1.2)}, "fractions"),
        ({"branch": "up"}, "branch"),
        ({"plateau_tolerance": 0.9}, "plateau_tolerance"),
    ):
        with pytest.raises(InputError) as info:
            analyse_loop(path, force, P, **kwargs)
        assert info.value.field == field
    with pytest.raises(InputError) as info:
        analyse_loop(path, force, -1.0)
    assert info.value.field == "normal_force"
    with pytest.raises(InputError):
        read_loop_csv(tmp_path / "missing.csv")
    bad = tmp_path / "bad.csv"
    bad.write_text("position,load\n1,2\n")
    with pytest.raises(InputError, match="displacement and force"):
        read_loop_csv(bad)
