"""The eigenstrain operator of the volume-plasticity solver (roughcontact.elasticity.eigenstrain).

Tolerances: the column is a finite-element discretisation in depth, so its own symmetry (Betti
reciprocity between a surface pressure and a plastic strain) holds to round-off, while its stresses
approach the exact half-space solution as the cells shrink (second order; measured 6.4 %, 3.1 %,
1.0 %, 0.30 % of the peak pressure for 8, 16, 32, 64 cells over half the window).
"""

from __future__ import annotations

import numpy as np
import pytest

from roughcontact.elasticity.eigenstrain import EigenstrainOperator, column, isotropic_stress, lame
from roughcontact.elasticity.stress import subsurface_stress
from roughcontact.errors import InputError
from roughcontact.materials import Material

STEEL = Material(youngs_modulus=200e9, poissons_ratio=0.3)
N, L = 32, 1e-6


def _bump():
    x = np.arange(N) * L / N
    xx, yy = np.meshgrid(x, x, indexing="ij")
    return 1e9 * np.exp(-((xx - L / 2) ** 2 + (yy - L / 2) ** 2) / (0.1 * L) ** 2)


def _random_strain(layers, seed=0):
    strain = np.random.default_rng(seed).normal(size=(6, layers, N, N)) * 1e-3
    strain[:3] -= strain[:3].mean(axis=0)  # plastic strain is deviatoric
    return strain


@pytest.mark.parametrize("boundary", ["periodic", "free"])
def test_reciprocity_between_pressure_and_plastic_strain_holds_to_round_off(boundary):
    """Betti: sum p u_res(eps_p) dA = sum sigma(p) : eps_p dV for the column's own fields.

    The mean mode of the pressure's stress is taken as in a periodic body here (for a free window
    :meth:`traction_stress` sets its mean lateral stress to zero, as an isolated load has).
    """
    cells = column(0.5 * L, 12, STEEL)
    operator = EigenstrainOperator((N, N), (L, L), cells, boundary=boundary)
    pressure, strain = _bump(), _random_strain(12)
    _, lift = operator(strain)
    stress = operator.traction_stress(pressure, periodic_lateral=True)
    weights = strain.copy()
    weights[3:] *= 2.0  # tensor shears counted twice
    work = np.sum(stress * weights * cells.thickness[None, :, None, None])
    assert np.sum(lift * pressure) == pytest.approx(work, rel=1e-10)


def test_pressure_stress_converges_to_the_exact_half_space_solution():
    errors = []
    for layers in (8, 16, 32, 64):
        cells = column(0.5 * L, layers, STEEL)
        operator = EigenstrainOperator((N, N), (L, L), cells)
        pressure = _bump()
        exact = subsurface_stress(pressure, (L, L), cells.centres, poissons_ratio=0.3).components
        errors.append(np.abs(operator.traction_stress(pressure) - exact).max() / pressure.max())
    assert all(b < 0.55 * a for a, b in zip(errors, errors[1:], strict=False))  # >= 1.8x per halving
    assert errors[-1] < 4e-3


def test_thick_film_on_a_different_substrate_tends_to_the_half_space():
    """A film far thicker than the window is the half-space of its material (1e-3 of the peak)."""
    pressure = _bump()
    half = EigenstrainOperator((N, N), (L, L), column(0.25 * L, 16, STEEL)).traction_stress(pressure)
    glass = Material(youngs_modulus=70e9, poissons_ratio=0.2)
    thick = column(0.25 * L, 16, STEEL, film_thickness=60 * L, substrate=glass)
    film = EigenstrainOperator((N, N), (L, L), thick).traction_stress(pressure)
    assert np.abs(film - half).max() < 1e-3 * pressure.max()


def test_a_stiffer_substrate_carries_more_of_the_load_at_the_interface():
    """Same pressure, film 0.25 L thick: its base's normal stress grows with the substrate's stiffness."""
    pressure = _bump()
    peaks = []
    for modulus in (20e9, 200e9, 2000e9):
        substrate = Material(youngs_modulus=modulus, poissons_ratio=0.3)
        cells = column(0.25 * L, 16, STEEL, film_thickness=0.25 * L, substrate=substrate)
        stress = EigenstrainOperator((N, N), (L, L), cells).traction_stress(pressure)
        peaks.append(-stress[2, -1].min())
    assert peaks[0] < peaks[1] < peaks[2]


def test_uniform_plastic_layer_leaves_no_normal_or_shear_traction_and_lifts_the_surface():
    """The k = 0 mode: a laterally uniform eps_p in a periodic body, in closed form."""
    cells = column(0.5 * L, 4, STEEL)
    operator = EigenstrainOperator((N, N), (L, L), cells)
    strain = np.zeros((6, 4, N, N))
    e = 1e-3
    strain[0, :2], strain[1, :2], strain[2, :2] = -e / 2, -e / 2, e  # compressed laterally, grown in z
    stress, lift = operator(strain)
    lam, mu = lame(STEEL)
    assert np.abs(stress[2]).max() < 1e-6 * mu * e
    assert np.abs(stress[4:]).max() < 1e-6 * mu * e
    # No lateral strain: eps_zz = 2 mu e / (lam + 2 mu) in the plastic cells; u_z(0) = -int eps_zz dz.
    expected = -2 * mu * e / (lam + 2 * mu) * cells.thickness[:2].sum()
    assert lift == pytest.approx(np.full((N, N), expected), rel=1e-12)
    assert stress[0, 0] == pytest.approx(
        np.full((N, N), lam * 2 * mu * e / (lam + 2 * mu) + mu * e), rel=1e-12
    )
    assert np.abs(stress[:, 2:]).max() < 1e-6 * mu * e


def test_isotropic_stress_is_hookes_law():
    strain = np.zeros((6, 1))
    strain[0] = 1e-3
    lam, mu = lame(STEEL)
    assert isotropic_stress(strain, STEEL)[:3, 0] == pytest.approx(
        [(lam + 2 * mu) * 1e-3, lam * 1e-3, lam * 1e-3]
    )


@pytest.mark.parametrize(
    ("arguments", "field"),
    [
        (dict(depth=0.0, layers=4), "depth"),
        (dict(depth=1e-6, layers=0), "layers"),
        (dict(depth=1e-6, layers=4, film_thickness=1e-7, substrate=STEEL), "film_thickness"),
        (dict(depth=1e-6, layers=4, film_thickness=5e-7, substrate=STEEL), "depth"),
    ],
)
def test_bad_columns_name_the_field(arguments, field):
    with pytest.raises(InputError) as raised:
        column(material=STEEL, **arguments)
    assert raised.value.field == field


def test_column_and_closed_form_film_stresses_agree_and_converge():
    """Two independent film-on-substrate solutions: the FE column and the Airy modes (kernels).

    Measured: 1.05 %, 0.30 %, 0.08 % of p_max for 16, 32, 64 cells through a film 0.25 L thick.
    """
    from roughcontact.elasticity.halfspace import ElasticLayer

    pressure = _bump()
    glass = Material(youngs_modulus=70e9, poissons_ratio=0.2)
    errors = []
    for layers in (16, 32, 64):
        cells = column(0.25 * L, layers, STEEL, film_thickness=0.25 * L, substrate=glass)
        numeric = EigenstrainOperator((N, N), (L, L), cells).traction_stress(pressure)
        layer = ElasticLayer(0.25 * L, STEEL, base=glass)
        exact = subsurface_stress(pressure, (L, L), cells.centres, poissons_ratio=0.3, layer=layer).components
        errors.append(np.abs(numeric - exact).max() / pressure.max())
    assert errors[0] > 3 * errors[1] > 9 * errors[2]
    assert errors[-1] < 1e-3
