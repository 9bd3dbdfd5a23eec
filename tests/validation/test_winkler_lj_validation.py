"""Validation of the Winkler-Lennard-Jones friction model (paper 000) against closed forms.

Tolerances: quadratures are compared at 1e-10 relative (scipy.quad reaches ~1e-13 on these smooth
integrands); closed forms that the model evaluates with the same arithmetic at 1e-12; the force
balance at 1e-12 of the largest term (brentq stops at a few ulps of the approach); Derjaguin at 1 %
(see the test).
"""

import functools
import math

import numpy as np
import pytest
from scipy import integrate

from roughcontact.contact import lennard_jones as lj
from roughcontact.errors import InputError
from roughcontact.materials import Material, get_material
from roughcontact.topography import Topography
from roughcontact.topography.generate import self_affine, sphere, sphere_with_roughness
from roughcontact.winkler_lj import Readings, WinklerLJOptions, standard_linear_solid, winkler_lj_model

POLY, SIO2 = get_material("polysilicon"), get_material("SiO2")
GAMMA, EPS = 0.1, 2e-9


def paper_like(n=64, seed=3, readings=None, **options):
    size = n * 20e-9
    tip = sphere_with_roughness((n, n), size, radius=1e-6, rms_height=0.3e-9, seed=seed)
    scan = self_affine((n, n), size, hurst=0.8, rms_height=1.8e-9, seed=seed + 1)
    options = {"layer_thickness": 50e-9, "surface_energy": 0.05, **options}
    return winkler_lj_model(
        scan, POLY, SIO2, counter_topography=tip, options=WinklerLJOptions(readings=readings, **options)
    )


def tail_integral(start: float) -> float:
    """Integral of eq. 7 from ``start`` to infinity by quad, in x = eps / l (dl = -eps / x^2 dx)."""
    value, _ = integrate.quad(
        lambda x: lj.attractive_stress(EPS / x, GAMMA, EPS) * EPS / x**2,
        0.0,
        EPS / start,
        epsabs=0,
        epsrel=1e-13,
    )
    return value


def test_force_law_integrates_to_the_work_of_adhesion():
    assert tail_integral(EPS) == pytest.approx(GAMMA, rel=1e-10, abs=0)


@pytest.mark.parametrize("ratio", [0.85, 1.0, 1.2, 2.0, 7.5, 100.0])
def test_eq14_closed_form_matches_quadrature(ratio):
    start = ratio * EPS
    assert lj.separation_energy(start, GAMMA, EPS) == pytest.approx(tail_integral(start), rel=1e-10, abs=0)


def test_force_law_zero_and_peak():
    assert lj.attractive_stress(EPS, GAMMA, EPS) == 0.0
    peak = lj.PEAK_DISTANCE_RATIO * EPS
    assert lj.attractive_stress(peak, GAMMA, EPS) == pytest.approx(
        lj.PEAK_STRESS_FACTOR * GAMMA / EPS, rel=1e-14
    )
    near = lj.attractive_stress(peak * np.array([0.999, 1.001]), GAMMA, EPS)
    assert np.all(near < lj.attractive_stress(peak, GAMMA, EPS))


def test_repulsive_distance_balances_the_stress_to_round_off():
    pressure = np.array([0.0, 1e3, 1e7, 1e9, 1e11])
    distance = lj.repulsive_distance(pressure, GAMMA, EPS)
    assert distance[0] == pytest.approx(EPS, rel=1e-15)
    np.testing.assert_allclose(-lj.attractive_stress(distance, GAMMA, EPS), pressure, rtol=1e-12, atol=1e-6)
    assert np.all(np.diff(distance) < 0)


@pytest.mark.parametrize(
    "readings", [Readings(), Readings(contact="zero_gap"), Readings(adhesion_sign="printed")]
)
@pytest.mark.parametrize("load", [1e-7, 1e-5, 3e-4])
def test_force_balance_residual_is_round_off(readings, load):
    model = paper_like(readings=readings)
    result = model.solve(load)
    area = model.spring_area
    mechanical = result.stress[result.mechanical].sum() * area
    attraction = -result.stress[result.adhesive].sum() * area
    sign = -1.0 if readings.adhesion_sign == "attractive" else 1.0
    assert abs(mechanical + sign * attraction - load) <= 1e-12 * max(mechanical, attraction, load)
    assert result.residual <= 1e-12
    assert model.net_normal_force(result.approach) == pytest.approx(load, rel=1e-12)


@pytest.mark.parametrize(
    "readings", [Readings(), Readings(shear="eq12_printed", mechanical_energy="eq16_signed")]
)
def test_flat_on_flat_matches_its_closed_form(readings):
    n, pixel, h, load = 16, 20e-9, 50e-9, 2e-5
    flat = Topography(np.zeros((n, n)), n * pixel)
    model = winkler_lj_model(
        flat, POLY, SIO2, options=WinklerLJOptions(layer_thickness=h, surface_energy=0.05, readings=readings)
    )
    result = model.solve(load)
    area = pixel * pixel
    stiffness = model.contact_modulus / (model.winkler_factor * h)
    stress = load / (n * n * area)  # every spring carries the same stress
    compression = stress / stiffness
    held_at = lj.repulsive_distance(stress, model.work_of_adhesion, EPS)
    energy = lj.separation_energy(held_at, model.work_of_adhesion, EPS)
    if readings.mechanical_energy == "two_stage":
        energy = 2 * model.work_of_adhesion - energy
    height = h - compression
    if readings.shear == "simple_shear":
        q = math.sqrt(2 * model.shear_modulus * area * area * energy / height)
    else:
        c = (height / pixel) / ((height / pixel) ** 2 + 1)
        q = math.sqrt(4 * c * model.shear_modulus * area * area * energy / height)
    assert result.mechanical.all() and not result.adhesive.any()
    assert result.approach == pytest.approx(compression, rel=1e-12)
    assert result.friction == pytest.approx(n * n * q, rel=1e-12)
    assert result.mu == pytest.approx(n * n * q / load, rel=1e-12)
    assert result.adhesive_friction == 0.0


def test_flat_on_flat_closed_form_constants():
    """Eq. 1 composite modulus, eq. 4 factor (uniaxial strain reading) and G with sqrt(nu1 nu2)."""
    model = winkler_lj_model(
        Topography(np.zeros((4, 4)), 80e-9),
        POLY,
        SIO2,
        options=WinklerLJOptions(layer_thickness=5e-8, surface_energy=0.05),
    )
    modulus = 1 / ((1 - 0.22**2) / 110e9 + (1 - 0.17**2) / 70e9)
    s = math.sqrt(0.22 * 0.17)
    assert model.contact_modulus == pytest.approx(modulus, rel=1e-14)
    assert model.winkler_factor == pytest.approx((1 + s) * (1 - 2 * s) / (1 - s), rel=1e-14)
    assert model.shear_modulus == pytest.approx(modulus / (2 * (1 + s)), rel=1e-14)
    assert model.work_of_adhesion == pytest.approx(2 * math.sqrt(0.05 * 0.072), rel=1e-14)


def test_smooth_sphere_pull_off_is_derjaguin():
    """Pull-off of a smooth paraboloid (R = 1 um) against the flat vs Bradley/Derjaguin 2 pi R dgamma.

    The springs are stiff (E/(k h) ~ 1e18 Pa/m against a force-law gradient ~ dgamma/eps^2 ~ 1e16),
    and eq. 2 uses the undeformed gaps, so the model is the rigid Derjaguin sum over the pixels. With
    a paraboloid the Derjaguin integral is exact; what is left is the force-law tail cut at the edge
    of the patch, (4/3)(eps/l_edge)^2 ~ 0.5 % for l_edge = (256 nm)^2/(2R) = 33 nm, and the pixel
    quadrature (2 nm pixels against a 60 nm interaction zone, < 0.1 %). Tolerance 1 %.
    """
    radius, n, pixel = 1e-6, 256, 2e-9
    body = sphere((n, n), n * pixel, radius=radius, kind="paraboloid")
    model = winkler_lj_model(
        body, POLY, SIO2, options=WinklerLJOptions(layer_thickness=50e-9, surface_energy=0.072)
    )
    derjaguin = 2 * math.pi * radius * model.work_of_adhesion
    assert model.pull_off_force() == pytest.approx(derjaguin, rel=1e-2)
    assert model.pull_off_force() < derjaguin  # the cut tail only removes attraction


@functools.cache
def sphere_composite(radius: float, full: int = 512) -> np.ndarray:
    """A self-affine scan (rms 1.8 nm) plus a rough paraboloid tip, 20 nm pixels, apex at the centre."""
    size = full * 20e-9
    scan = self_affine((full, full), size, hurst=0.8, rms_height=1.8e-9, seed=11)
    tip = sphere_with_roughness((full, full), size, radius=radius, rms_height=0.3e-9, seed=12)
    return scan.heights + tip.heights


def central_window(heights: np.ndarray, n: int) -> Topography:
    start = (heights.shape[0] - n) // 2
    return Topography(heights[start : start + n, start : start + n].copy(), n * 20e-9)


def window_result(heights: np.ndarray, n: int, readings: Readings | None = None):
    model = winkler_lj_model(
        central_window(heights, n),
        POLY,
        SIO2,
        options=WinklerLJOptions(layer_thickness=50e-9, surface_energy=0.05, readings=readings),
    )
    return model.solve(1e-5)


@pytest.mark.parametrize("radius", [1e-6, 5e-6])
def test_mu_converges_with_the_scan_size(radius):
    """The same sphere-on-scan contact, modelled on 128^2, 256^2 and 512^2 central windows (20 nm).

    Default readings: only springs bonded within the Dugdale zone (l_ia <= 1.974 eps, a ring of
    ~0.1-0.3 um around the contact) add adhesive friction, so once the window holds the zone mu can
    change only through eq. 2's attraction of the far springs, whose tail falls like (eps/l)^3: the
    model meets 1e-7 (R = 1 um) and 5e-6 (R = 5 um) at 128^2 against 512^2. Tolerance 0.1 %. Contrast:
    the earlier ``all_springs`` sum grows like the log of the window (Q ~ eps / l), > 10 % per doubling.
    """
    heights = sphere_composite(radius)
    default = {n: window_result(heights, n) for n in (128, 256, 512)}
    assert default[512].bonded.sum() > 0 and default[512].adhesive_friction > 0
    assert default[256].mu == pytest.approx(default[512].mu, rel=1e-3)
    assert default[128].mu == pytest.approx(default[512].mu, rel=1e-3)
    earlier = Readings(adhesive_range="all_springs")
    every = [window_result(heights, n, earlier).mu for n in (256, 512)]
    assert every[1] > 1.1 * every[0]


@pytest.mark.parametrize("n", [32, 64])
def test_flat_face_beyond_the_adhesive_range_adds_no_adhesive_friction(n):
    """A flat face 100 nm (50 eps) below a 2 x 2 pillar that carries the load, against the flat.

    Sliding two parallel faces 100 nm apart changes no bond: default readings give zero adhesive
    friction (exactly), while the face's attraction still enters eq. 2. The earlier ``all_springs``
    sum gives every face spring the same Q, so its adhesive friction scales with the face area.
    """
    heights = np.full((n, n), -100e-9)
    heights[n // 2 : n // 2 + 2, n // 2 : n // 2 + 2] = 0.0
    surface = Topography(heights, n * 20e-9)
    options = {"layer_thickness": 50e-9, "surface_energy": 0.05}
    result = winkler_lj_model(surface, POLY, SIO2, options=WinklerLJOptions(**options)).solve(1e-6)
    assert result.mechanical.sum() == 4 and result.adhesive.sum() == n * n - 4
    assert not result.bonded.any() and result.adhesive_friction == 0.0
    assert result.adhesive_force > 0  # attraction still in eq. 2
    assert result.friction == result.mechanical_friction > 0
    every = winkler_lj_model(
        surface,
        POLY,
        SIO2,
        options=WinklerLJOptions(readings=Readings(adhesive_range="all_springs"), **options),
    )
    face = every.solve(1e-6).lateral_force[~result.mechanical]
    assert face.sum() > 0
    np.testing.assert_allclose(face, face[0], rtol=1e-6)  # one gap, one Q: the sum grows with the area


def test_mu_rises_with_surface_energy():
    mus = [paper_like(surface_energy=g).solve(1e-5).mu for g in (0.01, 0.03, 0.05, 0.1, 0.2)]
    assert np.all(np.diff(mus) > 0)


def solve_in_units(readings, length, force):
    """Paper-like case in a unit system of ``length`` and ``force`` units per metre and newton."""
    n = 48
    tip = sphere_with_roughness((n, n), n * 20e-9, radius=1e-6, rms_height=0.3e-9, seed=5)
    scan = self_affine((n, n), n * 20e-9, hurst=0.8, rms_height=1.5e-9, seed=6)
    pressure = force / length**2

    def material(m):
        return Material(m.youngs_modulus * pressure, m.poissons_ratio, m.name)

    def scaled(t):
        return Topography(t.heights * length, tuple(s * length for s in t.size))

    model = winkler_lj_model(
        scaled(scan),
        material(POLY),
        material(SIO2),
        counter_topography=scaled(tip),
        options=WinklerLJOptions(
            layer_thickness=50e-9 * length,
            epsilon=2e-9 * length,
            surface_energy=0.05 * force / length,
            counter_surface_energy=0.072 * force / length,
            readings=readings,
        ),
    )
    return model.solve(1e-5 * force)


@pytest.mark.parametrize("readings", [Readings(), Readings(shear="eq12_printed", cuboid_height="printed")])
def test_results_do_not_depend_on_the_unit_system(readings):
    """Nanometres and nanonewtons: lengths x 1e9, forces x 1e9, pressures x 1e-9, energy per area x 1."""
    si, nano = solve_in_units(readings, 1.0, 1.0), solve_in_units(readings, 1e9, 1e9)
    assert nano.mu == pytest.approx(si.mu, rel=1e-9)
    assert nano.friction == pytest.approx(si.friction * 1e9, rel=1e-9)
    assert nano.separation == pytest.approx(si.separation * 1e9, rel=1e-9)
    np.testing.assert_array_equal(nano.mechanical, si.mechanical)


@pytest.mark.parametrize(
    "readings", [Readings(balance_terms="pressures_printed"), Readings(energy_area="printed")]
)
def test_printed_unit_mixtures_depend_on_the_unit_system(readings):
    """Documented: stresses summed against a force, or energy per area as energy, are not unit invariant."""
    si, nano = solve_in_units(readings, 1.0, 1.0), solve_in_units(readings, 1e9, 1e9)
    assert abs(nano.mu / si.mu - 1) > 0.01


def test_hold_time_uses_the_relaxed_modulus():
    relaxation = standard_linear_solid(110e9, 60e9, 2.0)
    held = paper_like(relaxation=relaxation, hold_time=1e3)
    relaxed = winkler_lj_model(
        paper_like().topography,
        Material(60e9, 0.22, "relaxed"),
        SIO2,
        options=WinklerLJOptions(layer_thickness=50e-9, surface_energy=0.05),
    )
    assert held.contact_modulus == pytest.approx(relaxed.contact_modulus, rel=1e-12)
    assert held.solve(1e-5).mu == pytest.approx(relaxed.solve(1e-5).mu, rel=1e-10)
    assert paper_like(relaxation=relaxation, hold_time=0.0).contact_modulus == pytest.approx(
        paper_like().contact_modulus, rel=1e-12
    )


def test_crossover_load_separates_adhesive_and_mechanical_dominance():
    model = paper_like()
    crossover = model.crossover_load()
    assert crossover is not None
    below, above = model.solve(crossover * 0.98), model.solve(crossover * 1.02)
    assert below.adhesive_friction > below.mechanical_friction
    assert above.mechanical_friction > above.adhesive_friction


def test_load_the_layer_cannot_carry_is_refused():
    model = paper_like()
    with pytest.raises(InputError, match="load") as error:
        model.solve(2 * model.load_capacity())
    assert error.value.field == "normal_force"
