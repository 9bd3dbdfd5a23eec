"""Boussinesq-Cerruti operators of a pair (roughcontact.elasticity.tangential), periodic and free.

Checks: Betti reciprocity and symmetry, positive definiteness, vanishing coupling for similar or
incompressible pairs, Dundurs' beta, the signs and magnitudes of the point-force solutions of the
module docstring, the normal compliance C = 2/E*, and periodic-vs-free agreement near a load.
"""

from __future__ import annotations

import numpy as np
import pytest

from roughcontact.elasticity import kernels
from roughcontact.elasticity.tangential import PairCompliance, TractionCompliance
from roughcontact.materials import Material, contact_modulus
from roughcontact.materials import dundurs_beta as materials_dundurs_beta

BOUNDARIES = ("periodic", "free")
SHAPE = (32, 24)
SIZE = (3.2e-6, 2.0e-6)  # non-square pixels: dx = 100 nm, dy = 83.3 nm
SOFT = Material(2e9, 0.35, "soft")
HARD = Material(170e9, 0.22, "hard")


def _fields(seed, shape=SHAPE, n=3):
    rng = np.random.default_rng(seed)
    return [rng.normal(size=shape) * 1e6 for _ in range(n)]


def _rel(a, b):
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


@pytest.mark.parametrize("boundary", BOUNDARIES)
@pytest.mark.parametrize("counter", [None, HARD], ids=["rigid", "hard"])
def test_betti_reciprocity_of_the_coupling(boundary, counter):
    op = TractionCompliance(SHAPE, SIZE, SOFT, counter, boundary=boundary, workers=1)
    assert op.coupled
    for seed in range(3):
        p, qx, qy = _fields(seed)
        sx, sy = op.slip_from_pressure(p)
        uz = op.normal_from_shear(qx, qy)
        left = np.vdot(p, uz)
        right = np.vdot(qx, sx) + np.vdot(qy, sy)
        scale = np.linalg.norm(p) * np.linalg.norm(uz) + np.linalg.norm(qx) * np.linalg.norm(sx)
        assert abs(left - right) <= 1e-10 * scale
        assert abs(left) > 1e-3 * scale  # not trivially zero


@pytest.mark.parametrize("boundary", BOUNDARIES)
def test_shear_operator_is_symmetric(boundary):
    op = TractionCompliance(SHAPE, SIZE, SOFT, HARD, boundary=boundary, workers=1)
    ax, ay, bx, by = _fields(7, n=4)
    sax, say = op.shear(ax, ay)
    sbx, sby = op.shear(bx, by)
    one = np.vdot(ax, sbx) + np.vdot(ay, sby)
    two = np.vdot(bx, sax) + np.vdot(by, say)
    scale = np.linalg.norm(np.hypot(ax, ay)) * np.linalg.norm(np.hypot(sbx, sby))
    assert abs(one - two) <= 1e-10 * scale


@pytest.mark.parametrize("boundary", BOUNDARIES)
def test_shear_operator_is_positive_definite(boundary):
    op = TractionCompliance(SHAPE, SIZE, SOFT, None, boundary=boundary, workers=1)
    rng = np.random.default_rng(3)
    for _ in range(5):
        qx, qy = rng.normal(size=SHAPE), rng.normal(size=SHAPE)
        if boundary == "free":
            # also a uniform field: the free surface has no null space
            qx = qx + rng.normal() * 5
        sx, sy = op.shear(qx, qy)
        assert np.vdot(qx, sx) + np.vdot(qy, sy) > 0
    if boundary == "free":
        uniform = np.ones(SHAPE)
        sx, sy = op.shear(uniform, np.zeros(SHAPE))
        assert np.vdot(uniform, sx) > 0


@pytest.mark.parametrize("boundary", BOUNDARIES)
@pytest.mark.parametrize(
    "pair",
    [(SOFT, SOFT), (Material(5e9, 0.5), Material(70e9, 0.5)), (Material(5e9, 0.5), None)],
    ids=["similar", "incompressible", "incompressible-rigid"],
)
def test_coupling_vanishes_exactly(boundary, pair):
    op = TractionCompliance(SHAPE, SIZE, *pair, boundary=boundary, workers=1)
    assert op.pair.D == 0.0
    assert op.coupled is False
    assert op.pair.dundurs_beta == 0.0
    p, qx, qy = _fields(11)
    sx, sy = op.slip_from_pressure(p)
    zeros = np.zeros(SHAPE)
    assert np.array_equal(sx, zeros) and np.array_equal(sy, zeros)
    assert np.array_equal(op.normal_from_shear(qx, qy), zeros)


def _johnson_beta(a, b):
    def terms(m):
        if m is None:
            return 0.0, 0.0
        g = m.youngs_modulus / (2 * (1 + m.poissons_ratio))
        return (1 - 2 * m.poissons_ratio) / g, (1 - m.poissons_ratio) / g

    (m1, c1), (m2, c2) = terms(a), terms(b)
    return (m1 - m2) / (2 * (c1 + c2))


PAIRS = [
    (SOFT, None),
    (Material(1e9, 0.0), None),
    (SOFT, HARD),
    (HARD, SOFT),
    (Material(3e9, 0.4), Material(3e9, 0.1)),
]


@pytest.mark.parametrize("a, b", PAIRS)
def test_compliance_sums_match_their_definitions(a, b):
    pair = PairCompliance.of(a, b)
    terms = [(m.shear_modulus, m.poissons_ratio) for m in (a, b) if m is not None]
    assert pair.A == pytest.approx(sum(1 / g for g, _ in terms), rel=1e-14)
    assert pair.B == pytest.approx(sum(nu / g for g, nu in terms), rel=1e-14)
    assert pair.C == pytest.approx(2 / contact_modulus(a, b), rel=1e-13)
    assert pair.contact_modulus == pytest.approx(contact_modulus(a, b), rel=1e-13)
    # D = 2 beta C would say beta = D/(2C); Johnson/Dundurs: D = beta C with beta as below
    assert pair.D == pytest.approx(_johnson_beta(a, b) * pair.C, rel=1e-13)


@pytest.mark.parametrize("a, b", PAIRS)
def test_dundurs_beta_matches_dundurs_formula(a, b):
    expected = _johnson_beta(a, b)
    assert expected == pytest.approx(materials_dundurs_beta(a, b), rel=1e-13)
    assert PairCompliance.of(a, b).dundurs_beta == pytest.approx(expected, rel=1e-12)


def test_rigid_counter_body_adds_nothing():
    alone = PairCompliance.of(SOFT)
    with_rigid = PairCompliance.of(SOFT, None)
    assert alone == with_rigid
    assert alone.D == pytest.approx((1 - 2 * 0.35) / (2 * SOFT.shear_modulus), rel=1e-14)


# -- point forces on one pixel of a free grid (body nu = 0.3 on a rigid flat) -----------------

N_POINT = 64
H = 1e-7
NU = 0.3
BODY = Material(1e9, NU, "body")
G = BODY.shear_modulus


@pytest.fixture(scope="module")
def point_operator():
    return TractionCompliance(
        (N_POINT, N_POINT), (N_POINT * H, N_POINT * H), BODY, None, boundary="free", workers=1
    )


def test_pressure_pulls_surface_points_toward_the_load(point_operator):
    c = N_POINT // 2
    p = np.zeros((N_POINT, N_POINT))
    p[c, c] = 1e6
    force = 1e6 * H * H
    sx, sy = point_operator.slip_from_pressure(p)
    r = np.arange(1, 30)
    assert np.all(sx[c + r, c] < 0) and np.all(sx[c - r, c] > 0)
    assert np.all(sy[c, c + r] < 0) and np.all(sy[c, c - r] > 0)
    far = np.arange(5, 30)
    expected = -(1 - 2 * NU) / (4 * np.pi * G) * force / (far * H)
    assert np.allclose(sx[c + far, c], expected, rtol=0.02, atol=0)
    assert np.allclose(sx[c - far, c], -expected, rtol=0.02, atol=0)
    assert np.allclose(sy[c, c + far], expected, rtol=0.02, atol=0)
    # on the axis there is no transverse component
    assert np.max(np.abs(sy[c + far, c])) <= 1e-10 * np.max(np.abs(expected))


def test_shear_point_force_matches_cerruti(point_operator):
    c = N_POINT // 2
    q = np.zeros((N_POINT, N_POINT))
    q[c, c] = 1e6
    force = 1e6 * H * H
    ux, uy = point_operator.shear(q, np.zeros_like(q))
    uz = point_operator.normal_from_shear(q, np.zeros_like(q))
    far = np.arange(5, 30)
    r = far * H
    along_x = force / (2 * np.pi * G * r)  # (1 - nu + nu) / r
    along_y = force * (1 - NU) / (2 * np.pi * G * r)
    assert np.allclose(ux[c + far, c], along_x, rtol=0.02, atol=0)
    assert np.allclose(ux[c - far, c], along_x, rtol=0.02, atol=0)
    assert np.allclose(ux[c, c + far], along_y, rtol=0.02, atol=0)
    assert np.allclose(ux[c, c - far], along_y, rtol=0.02, atol=0)
    # u_z ~ +X / rho^2: positive ahead of the force, negative behind
    uz_expected = (1 - 2 * NU) * force / (4 * np.pi * G * r)
    assert np.allclose(uz[c + far, c], uz_expected, rtol=0.02, atol=0)
    assert np.allclose(uz[c - far, c], -uz_expected, rtol=0.02, atol=0)
    # u_y along the diagonal: nu X Y / rho^3 > 0 in the first quadrant
    d = np.arange(4, 20)
    rho = np.sqrt(2) * d * H
    uy_expected = force / (2 * np.pi * G) * NU * (d * H) ** 2 / rho**3
    assert np.allclose(uy[c + d, c + d], uy_expected, rtol=0.02, atol=0)
    assert np.allclose(uy[c - d, c + d], -uy_expected, rtol=0.02, atol=0)


# -- normal compliance C = 2/E*: the tangential kernels reduce to the pressure kernel at nu = 0


@pytest.mark.parametrize("boundary", BOUNDARIES)
def test_nu_zero_shear_kernel_equals_normal_kernel(boundary):
    """For nu = 0 (rigid flat): A = C = 1/G = 2/E*, B = 0, so s_x(q_x) uses the pressure's kernel."""
    body = Material(3e9, 0.0)
    op = TractionCompliance(SHAPE, SIZE, body, None, boundary=boundary, workers=1)
    e_star = contact_modulus(body)
    assert op.pair.C == pytest.approx(2 / e_star, rel=1e-14)
    assert op.pair.B == 0.0
    if boundary == "periodic":
        normal = kernels.periodic_halfspace_kernel(SHAPE, SIZE, e_star)
    else:
        normal = kernels.free_halfspace_kernel(SHAPE, SIZE, e_star)
    assert np.allclose(op._k["xx"], normal, rtol=1e-10, atol=1e-12 * np.abs(normal).max())
    assert np.allclose(op._k["yy"], normal, rtol=1e-10, atol=1e-12 * np.abs(normal).max())


def test_periodic_kernels_match_the_fourier_matrix():
    body, counter = SOFT, HARD
    op = TractionCompliance(SHAPE, SIZE, body, counter, boundary="periodic", workers=1)
    pair = op.pair
    kx, ky = kernels.wavevectors(SHAPE, SIZE)
    kx, ky = np.broadcast_arrays(kx, ky)
    k = np.hypot(kx, ky)
    m = (k > 0) & (np.abs(kx) < np.abs(kx).max()) & (ky < ky.max())  # away from k = 0 and Nyquist
    k = np.where(k > 0, k, 1.0)
    assert np.allclose(op._k["xx"][m], ((pair.A - pair.B * kx**2 / k**2) / k)[m], rtol=1e-12)
    assert np.allclose(op._k["xy"][m], (-pair.B * kx * ky / k**3)[m], rtol=1e-12)
    assert np.allclose(op._k["xz"][m], (pair.D * kx / k**2)[m], rtol=1e-12)
    # normal compliance of the same pair: C / k = 2 / (E* k)
    normal = kernels.periodic_halfspace_kernel(SHAPE, SIZE, contact_modulus(body, counter))
    assert np.allclose((pair.C / k)[m], normal[m], rtol=1e-12)


# -- periodic vs free near a smooth localized traction --------------------------------------


@pytest.fixture(scope="module")
def bump_operators():
    n = 128
    size = (n * H, n * H)
    ops = {b: TractionCompliance((n, n), size, SOFT, HARD, boundary=b, workers=1) for b in BOUNDARIES}
    x = (np.arange(n) - n / 2) * H
    xx, yy = np.meshgrid(x, x, indexing="ij")
    # Zero net force: the periodic operator drops the k = 0 mode, i.e. adds a uniform counter
    # traction over the cell, whose coupled field is linear in position (uniform pressure on a
    # disc: u_r = -(1 - 2 nu) p r / (4 G), Johnson 3.4) and would differ from the free answer by
    # ~ pi r^2 / L^2 (5 % at r = 16 px on 128 px). A Gaussian minus a twice-wider one of equal
    # integral has no mean. Width 5 px: the free (piecewise-constant) discretisation differs from
    # the spectral one by O((h/w)^2) (measured 1.8 % at 3 px, 1.0 % at 4 px, 0.6 % at 5 px).
    width = 5 * H

    def gauss(w):
        return np.exp(-(xx**2 + yy**2) / (2 * w**2))

    bump = 1e6 * (gauss(width) - gauss(2 * width) / 4)
    assert abs(bump.sum()) < 1e-6 * np.abs(bump).sum()
    return ops, bump, n


def _near_differences(field, n, radius=12):
    c = n // 2
    window = field[c - radius : c + radius + 1, c - radius : c + radius + 1]
    return window - field[c, c]


@pytest.mark.parametrize("which", ["shear_x", "shear_y", "slip_from_pressure", "normal_from_shear"])
def test_periodic_and_free_agree_near_the_load(bump_operators, which):
    ops, bump, n = bump_operators
    zero = np.zeros_like(bump)
    out = {}
    for boundary, op in ops.items():
        if which == "shear_x":
            out[boundary] = op.shear(bump, zero)
        elif which == "shear_y":
            out[boundary] = op.shear(zero, bump)
        elif which == "slip_from_pressure":
            out[boundary] = op.slip_from_pressure(bump)
        else:
            out[boundary] = (op.normal_from_shear(bump, 0.5 * bump),)
    for periodic, free in zip(out["periodic"], out["free"], strict=True):
        dp, df = _near_differences(periodic, n), _near_differences(free, n)
        assert np.max(np.abs(dp - df)) <= 0.01 * np.max(np.abs(df))
        assert np.max(np.abs(df)) > 0
