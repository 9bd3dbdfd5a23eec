"""The accelerated projected-gradient increment solver (``method="apg"``) against CG, its bounds and inputs.

Its closed-form checks (Cattaneo-Mindlin, Mindlin-Deresiewicz) are those of
test_tangential_closed_forms.py, which runs them for both methods. Here: apg against the
conjugate-gradient solver on the Cattaneo case and on rough balls (coupled and uncoupled, free and
periodic), the spectral bounds the method's step and momentum rest on, and the refused inputs.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_tangential_closed_forms import FORCE, MU, _case

from roughcontact.contact import ShearSolver, _shear_apg, solve_normal
from roughcontact.contact.tangential import solve_tangential
from roughcontact.elasticity.tangential import TractionCompliance
from roughcontact.errors import InputError
from roughcontact.materials import Material
from roughcontact.topography import generate

FRACTIONS = np.array([0.25, 0.5, 0.75, 0.9])


@pytest.fixture(scope="module")
def cattaneo_64():
    material, normal, a, g_star = _case(64)
    common = dict(
        counter_body=material,
        friction_coefficient=MU,
        force=FRACTIONS * MU * FORCE,
        solver=ShearSolver(tolerance=1e-10),
    )
    apg = solve_tangential(
        normal, material, **(common | {"solver": ShearSolver(tolerance=1e-10, method="apg")})
    )
    cg = solve_tangential(
        normal, material, **(common | {"solver": ShearSolver(tolerance=1e-10, method="cg")})
    )
    return apg, cg, a, g_star


def test_apg_agrees_with_cg_on_cattaneo(cattaneo_64):
    """Both at tolerance 1e-10: delta to 1e-7 relative, tractions to 1e-6 mu p0, the same stick set."""
    apg, cg, a, _ = cattaneo_64
    p0 = 3 * FORCE / (2 * np.pi * a**2)
    assert np.allclose(
        apg.displacement, cg.displacement, rtol=1e-7, atol=1e-7 * np.abs(cg.displacement).max()
    )
    for step in cg.states:
        first, second = apg.states[step], cg.states[step]
        assert np.max(np.abs(first.shear_x - second.shear_x)) < 1e-6 * MU * p0
        assert np.array_equal(first.stick, second.stick)


# ------------------------------------------------------------------------------------------------
# apg against cg on rough balls

ROUGH_N, ROUGH_SIZE, ROUGH_RADIUS, ROUGH_F0, ROUGH_MU = 64, 80e-6, 1e-3, 2e-3, 0.15
# measured differences at tolerance 1e-10: forces 4e-11 mu F0 (free), tractions 1e-9 to 8e-9 mu p_max,
# slips 2e-11 to 1.5e-9 of the largest displacement, identical stick sets
FIELD_TOLERANCE = 1e-6


@pytest.mark.parametrize(
    "label",
    ["incompressible on rigid (uncoupled)", "nu 0.3 on rigid (coupled)", "periodic, force control"],
)
def test_apg_agrees_with_cg_on_a_rough_ball(label):
    """Three steps (loading, further, partly back): forces to 1e-6 mu F0, fields to 1e-6 (see above)."""
    body = Material(1e9, 0.5 if label.startswith("incompressible") else 0.3, "ball")
    periodic = label.startswith("periodic")
    counter = body if periodic else None
    topography = generate.sphere_with_roughness(
        (ROUGH_N, ROUGH_N), (ROUGH_SIZE, ROUGH_SIZE), radius=ROUGH_RADIUS, rms_height=0.1e-6, seed=3
    )
    normal = solve_normal(
        topography,
        body,
        counter_body=counter,
        force=ROUGH_F0,
        tolerance=1e-10,
        boundary="periodic" if periodic else "free",
    )
    if periodic:
        path = {"force": np.array([[0.5, 0.1], [0.9, 0.3], [0.2, -0.1]]) * ROUGH_MU * ROUGH_F0}
    else:
        path = {"displacement": np.array([0.3, 0.6, 0.2]) * 1e-6}
    common = dict(
        counter_body=counter, friction_coefficient=ROUGH_MU, **path, solver=ShearSolver(tolerance=1e-10)
    )
    apg = solve_tangential(normal, body, **(common | {"solver": ShearSolver(tolerance=1e-10, method="apg")}))
    cg = solve_tangential(normal, body, **(common | {"solver": ShearSolver(tolerance=1e-10, method="cg")}))
    assert np.max(np.abs(apg.force - cg.force)) < 1e-6 * ROUGH_MU * ROUGH_F0
    scale_q = ROUGH_MU * normal.pressure.max()
    scale_s = np.abs(cg.displacement).max()
    assert np.max(np.abs(apg.displacement - cg.displacement)) < FIELD_TOLERANCE * scale_s
    for step in cg.states:
        first, second = apg.states[step], cg.states[step]
        assert np.all(np.hypot(first.shear_x, first.shear_y) <= ROUGH_MU * first.pressure * (1 + 1e-12))
        assert np.max(np.abs(first.pressure - second.pressure)) < FIELD_TOLERANCE * normal.pressure.max()
        assert np.max(np.hypot(first.shear_x - second.shear_x, first.shear_y - second.shear_y)) < (
            FIELD_TOLERANCE * scale_q
        )
        assert np.max(np.hypot(first.slip_x - second.slip_x, first.slip_y - second.slip_y)) < (
            FIELD_TOLERANCE * scale_s
        )
        assert np.sum(first.stick != second.stick) <= 1


# ------------------------------------------------------------------------------------------------
# the spectral bounds of the step (L) and the momentum (mu_c)


@pytest.mark.parametrize("boundary", ["free", "periodic"])
@pytest.mark.parametrize("poisson", [0.0, 0.5])
def test_kernel_extremes_bound_the_restricted_operator(boundary, poisson):
    """Dense restricted operator on a disc of a 16^2 grid: kernel min <= its eigenvalues <= kernel max,
    and the Lanczos estimate of the largest one is converged."""
    n = 16
    operator = TractionCompliance((n, n), (1e-5, 1e-5), Material(1e9, poisson, "b"), None, boundary=boundary)
    x = np.arange(n) - (n - 1) / 2
    contact = np.hypot(*np.meshgrid(x, x, indexing="ij")) < 6
    index = np.flatnonzero(contact)
    columns = []
    for component in range(2):
        for i in index:
            q = [np.zeros(n * n), np.zeros(n * n)]
            q[component][i] = 1.0
            sx, sy = operator.shear(q[0].reshape(n, n), q[1].reshape(n, n))
            columns.append(np.concatenate([sx.ravel()[index], sy.ravel()[index]]))
    matrix = np.array(columns).T
    assert np.allclose(matrix, matrix.T, rtol=0, atol=1e-12 * np.abs(matrix).max())
    eigenvalues = np.linalg.eigvalsh(0.5 * (matrix + matrix.T))
    low, high = _shear_apg.kernel_extremes(operator)
    if boundary == "periodic":  # the k = 0 mode left out: bound on zero-mean directions
        mean_free = np.eye(2 * index.size) - np.kron(
            np.eye(2), np.full((index.size, index.size), 1 / index.size)
        )
        basis = np.linalg.svd(mean_free)[0][:, : 2 * index.size - 2]
        eigenvalues_free = np.linalg.eigvalsh(basis.T @ matrix @ basis)
        assert eigenvalues_free.min() >= low * (1 - 1e-9)
    else:
        assert eigenvalues.min() >= low * (1 - 1e-9) and low > 0
    assert eigenvalues.max() <= high * (1 + 1e-9)
    estimate = _shear_apg.restricted_norm(operator.shear, contact)
    assert estimate <= eigenvalues.max() * (1 + 1e-9)
    assert estimate >= eigenvalues.max() * (1 - 1e-6)


# ------------------------------------------------------------------------------------------------
# inputs


@pytest.fixture(scope="module")
def small_normal():
    material, normal, _, _ = _case(32)
    return material, normal


def test_unknown_method_is_refused(small_normal):
    material, normal = small_normal
    with pytest.raises(InputError, match="method"):
        solve_tangential(
            normal,
            material,
            counter_body=material,
            friction_coefficient=MU,
            force=[0.1],
            solver=ShearSolver(method="x"),
        )


def test_apg_refuses_the_fourier_preconditioner(small_normal):
    material, normal = small_normal
    with pytest.raises(InputError, match="precondition"):
        solve_tangential(
            normal,
            material,
            counter_body=material,
            friction_coefficient=MU,
            force=[0.1 * MU * FORCE],
            solver=ShearSolver(method="apg", precondition=True),
        )


def test_apg_refuses_the_sliding_force(small_normal):
    """At mu F0 the contact slides as a whole: refused, the message gives the sliding force."""
    material, normal = small_normal
    with pytest.raises(InputError, match="sliding force"):
        solve_tangential(
            normal,
            material,
            counter_body=material,
            friction_coefficient=MU,
            force=[MU * FORCE],
            solver=ShearSolver(method="apg"),
        )


def test_auto_picks_cg_for_nu_0_and_apg_when_slip_directions_turn(small_normal):
    """method="auto" (the default): cg for nu = 0 pairs (B = 0), apg when a body has nu > 0."""
    material, normal = small_normal
    common = dict(friction_coefficient=MU, force=[0.5 * MU * FORCE], solver=ShearSolver(tolerance=1e-10))
    default = solve_tangential(normal, material, counter_body=material, **common)
    explicit = solve_tangential(
        normal,
        material,
        counter_body=material,
        **(common | {"solver": ShearSolver(tolerance=1e-10, method="cg")}),
    )
    assert default.parameters["method"] == "cg"
    assert np.array_equal(default.states[0].shear_x, explicit.states[0].shear_x)
    assert np.array_equal(default.iterations, explicit.iterations)
    soft = Material(material.youngs_modulus, 0.3, "nu 0.3")
    normal = solve_normal(normal.topography, soft, counter_body=soft, force=FORCE, tolerance=1e-10)
    default = solve_tangential(normal, soft, counter_body=soft, **common)
    explicit = solve_tangential(
        normal, soft, counter_body=soft, **(common | {"solver": ShearSolver(tolerance=1e-10, method="apg")})
    )
    assert default.parameters["method"] == "apg"
    assert np.array_equal(default.states[0].shear_x, explicit.states[0].shear_x)
    preconditioned = solve_tangential(
        normal,
        soft,
        counter_body=soft,
        **(common | {"solver": ShearSolver(tolerance=1e-10, precondition=True)}),
    )
    assert preconditioned.parameters["method"] == "cg"  # the Fourier preconditioner is cg's


@pytest.mark.parametrize("restart", ["gradient", "function"])
@pytest.mark.parametrize("momentum", ["constant", "fista"])
def test_apg_variants_reach_the_same_increment(small_normal, restart, momentum):
    """The restart tests and FISTA's momentum sequence (no strong-convexity bound) give the same answer."""
    material, normal = small_normal
    operator = TractionCompliance(
        normal.topography.shape, normal.topography.size, material, material, boundary="free"
    )
    bound = MU * normal.pressure
    zero = np.zeros_like(bound)
    common = dict(pixel_area=operator.pixel_area, force=(0.5 * MU * FORCE, 0.0), tolerance=1e-10)
    reference = _shear_apg.solve_increment(
        operator.shear,
        bound,
        (zero, zero),
        strong_convexity=_shear_apg.kernel_extremes(operator)[0],
        **common,
    )
    variant = _shear_apg.solve_increment(
        operator.shear,
        bound,
        (zero, zero),
        restart=restart,
        strong_convexity=_shear_apg.kernel_extremes(operator)[0] if momentum == "constant" else None,
        **common,
    )
    assert variant.residual <= 1e-10
    assert np.max(np.abs(variant.qx - reference.qx)) < 1e-6 * bound.max()
    assert np.isclose(variant.delta[0], reference.delta[0], rtol=1e-7)
