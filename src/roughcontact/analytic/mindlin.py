r"""Cattaneo-Mindlin and Mindlin-Deresiewicz: tangential loading of a Hertz contact (sphere on flat).

A Hertz contact of radius a under a constant normal force P is loaded by a tangential force Q
(|Q| < mu P). A central stick disc of radius c is surrounded by a slip annulus (Johnson 1985,
sec. 7.2, eqs. 7.33-7.42):

.. math::

    \frac{c}{a} = \left(1 - \frac{Q}{\mu P}\right)^{1/3}, \qquad
    q(r) = \mu p_0 \sqrt{1 - r^2/a^2} - \frac{c}{a}\,\mu p_0 \sqrt{1 - r^2/c^2}\ (r \le c),

    \delta(Q) = \frac{3 \mu P}{16 a G^*}\left[1 - \left(1 - \frac{Q}{\mu P}\right)^{2/3}\right],
    \qquad \frac{dQ}{d\delta} = 8 a G^* \left(1 - \frac{Q}{\mu P}\right)^{1/3},

with p0 = 3P / (2 pi a^2) and Johnson's composite shear modulus
1/G* = (2 - nu1)/G1 + (2 - nu2)/G2 (a rigid body contributes 0). Gross sliding starts at
delta_0 = 3 mu P / (16 a G*), where Q = mu P.

Cyclic loading follows the Masing rule (Mindlin and Deresiewicz 1953; Johnson 1985, sec. 7.4):
after a reversal at (delta_r, Q_r) the branch is the virgin curve scaled by two,
Q = Q_r + 2 Q_M((delta - delta_r)/2), where Q_M is the odd extension of the monotonic curve.
:func:`masing_force` applies it to an arbitrary displacement path with memory of the
reversals (a branch that reaches the reversal point before the last one closes that inner loop
and continues on the branch it interrupted).

Paper 001 (eqs. 10-12) prints the same solution with its own shear modulus G_s; its reference,
in the textbook reading and as printed, is :func:`roughcontact.papers.paper001.paper001_mindlin`.

All quantities are SI (N, m, Pa, J). Johnson's equation numbers are given as commonly cited (not
re-checked against the book); the formulas themselves are verified by
``tests/validation/test_mindlin_closed_forms.py`` (traction integral, stiffness as derivative,
loop energy by quadrature).

References
----------
K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, sec. 7.2 (eqs. 7.33-7.42,
monotonic tangential loading) and sec. 7.4 (oscillating force, eqs. 7.50-7.59).
doi:10.1017/CBO9781139171731

R. D. Mindlin, "Compliance of elastic bodies in contact", J. Appl. Mech. 16 (1949) 259-268.
doi:10.1115/1.4009973

R. D. Mindlin and H. Deresiewicz, "Elastic spheres in contact under varying oblique forces",
J. Appl. Mech. 20 (1953) 327-344. doi:10.1115/1.4010702

Seed paper 001, "Evaluation of pre-sliding behavior at a rough interface: modeling and
experiment", ASME J. Appl. Mech. (2020), eqs. 10-12. doi:10.1115/1.4045900
"""

from __future__ import annotations

import math

import numpy as np

from .._deprecation import moved, renamed
from ..checks import finite_array, positive
from ..errors import InputError

__all__ = [
    "dissipated_energy",
    "dissipated_energy_displacement",
    "hertz_contact_radius",
    "lateral_stiffness",
    "masing_displacement",
    "masing_force",
    "shear_traction",
    "sliding_displacement",
    "stick_radius",
    "tangential_displacement",
    "tangential_force",
]

# --- moduli ---------------------------------------------------------------------------------------


def hertz_contact_radius(normal_force: float, radius: float, contact_modulus: float) -> float:
    r"""Hertz contact radius, paper 001 equation 11 (Johnson equation 4.22) [m].

    .. math:: a^3 = \frac{3 F_0 R}{4 E_s}, \qquad \frac{1}{E_s} = \sum \frac{1 - \nu_i^2}{E_i}

    Parameters
    ----------
    normal_force : float
        F0 [N], positive.
    radius : float
        Ball radius R [m], positive.
    contact_modulus : float
        E_s (Hertz E*) [Pa], positive; see :func:`roughcontact.materials.contact_modulus`.

    Returns
    -------
    float
        a [m].
    """
    positive(normal_force, "normal_force", example="0.025", unit="N")
    positive(radius, "radius", example="5e-3", unit="m")
    positive(contact_modulus, "contact_modulus", example="1.3e9", unit="Pa")
    return (3.0 * normal_force * radius / (4.0 * contact_modulus)) ** (1.0 / 3.0)


# --- checks ---------------------------------------------------------------------------------------


def _check_contact(friction_coefficient, normal_force, contact_radius, shear_modulus=None) -> float:
    """Validate the common parameters; return mu P [N]."""
    positive(friction_coefficient, "friction_coefficient", example="0.15")
    positive(normal_force, "normal_force", example="0.025", unit="N")
    positive(contact_radius, "contact_radius", example="20e-6", unit="m")
    if shear_modulus is not None:
        positive(shear_modulus, "shear_modulus", example="0.1e9", unit="Pa")
    return float(friction_coefficient) * float(normal_force)


def _force_ratio(force, mu_p: float, field: str = "force") -> np.ndarray:
    """|Q| / (mu P), checked to lie in [0, 1] (with a rounding allowance)."""
    ratio = np.abs(finite_array(force, field)) / mu_p
    if np.any(ratio > 1.0 + 1e-12):
        raise InputError(
            field,
            f"|Q| reaches {ratio.max():.6g} mu P; partial slip needs |Q| <= mu P.",
            "keep the tangential force at or below the sliding force mu * normal_force.",
        )
    return np.minimum(ratio, 1.0)


def _as_output(array: np.ndarray, like) -> float | np.ndarray:
    return float(array) if np.ndim(like) == 0 else array


# --- monotonic loading (Cattaneo-Mindlin) -----------------------------------------------------------


@renamed(mu="friction_coefficient")
def stick_radius(force, friction_coefficient: float, normal_force: float, contact_radius: float):
    r"""Radius of the stick disc, c = a (1 - |Q|/(mu P))^(1/3) [m] (Johnson equation 7.39).

    Parameters
    ----------
    force : float or array
        Tangential force Q [N], |Q| <= mu P.
    friction_coefficient : float
        Coefficient of friction [-].
    normal_force : float
        P [N].
    contact_radius : float
        Hertz radius a [m].

    Returns
    -------
    float or ndarray
        c [m]: a at Q = 0, 0 at |Q| = mu P.
    """
    mu_p = _check_contact(friction_coefficient, normal_force, contact_radius)
    return _as_output(contact_radius * np.cbrt(1.0 - _force_ratio(force, mu_p)), force)


@renamed(mu="friction_coefficient")
def shear_traction(r, force, friction_coefficient: float, normal_force: float, contact_radius: float):
    r"""Cattaneo-Mindlin shear traction q(r) [Pa] (Johnson equations 7.36-7.39), in the sense of Q.

    .. math::

        q(r) = \mu p_0 \sqrt{1 - r^2/a^2} - \frac{c}{a} \mu p_0 \sqrt{1 - r^2/c^2}\quad (r \le c),
        \qquad q(r) = \mu p_0 \sqrt{1 - r^2/a^2}\quad (c < r \le a),

    with p0 = 3P / (2 pi a^2); q = 0 outside the contact.

    Parameters
    ----------
    r : float or array
        Distance from the centre [m].
    force : float
        Tangential force Q [N], |Q| <= mu P (the sign of Q gives the sign of q).
    friction_coefficient, normal_force, contact_radius : float
        As in :func:`stick_radius`.

    Returns
    -------
    float or ndarray
        q [Pa].
    """
    mu_p = _check_contact(friction_coefficient, normal_force, contact_radius)
    if np.ndim(force) != 0:
        raise InputError("force", "expected one tangential force.", "call once per force value.")
    ratio = float(_force_ratio(force, mu_p))
    a = float(contact_radius)
    c_over_a = math.cbrt(1.0 - ratio)
    c = a * c_over_a
    p0 = 3.0 * normal_force / (2.0 * math.pi * a**2)
    rr = np.abs(finite_array(r, "r"))
    full = friction_coefficient * p0 * np.sqrt(np.clip(1.0 - (rr / a) ** 2, 0.0, None))
    if c > 0:
        full = full - c_over_a * friction_coefficient * p0 * np.sqrt(np.clip(1.0 - (rr / c) ** 2, 0.0, None))
    return _as_output(math.copysign(1.0, force) * full, r)


@renamed(mu="friction_coefficient")
def sliding_displacement(
    friction_coefficient: float, normal_force: float, contact_radius: float, shear_modulus: float
) -> float:
    r"""Tangential displacement at the onset of gross sliding, delta_0 = 3 mu P / (16 a G*) [m].

    Parameters
    ----------
    friction_coefficient, normal_force, contact_radius : float
        As in :func:`stick_radius`.
    shear_modulus : float
        Johnson's G* [Pa] (:func:`roughcontact.materials.johnson_shear_modulus`).

    Returns
    -------
    float
        delta_0 [m].
    """
    mu_p = _check_contact(friction_coefficient, normal_force, contact_radius, shear_modulus)
    return 3.0 * mu_p / (16.0 * contact_radius * shear_modulus)


@renamed(mu="friction_coefficient")
def tangential_displacement(
    force, friction_coefficient: float, normal_force: float, contact_radius: float, shear_modulus: float
):
    r"""Monotonic (virgin) tangential displacement delta(Q) [m] (Mindlin 1949; Johnson equation 7.42).

    .. math:: \delta(Q) = \frac{3\mu P}{16 a G^*}\left[1 - \left(1 - \frac{Q}{\mu P}\right)^{2/3}\right]

    Odd in Q (a negative force gives a negative displacement).

    Parameters
    ----------
    force : float or array
        Q [N], |Q| <= mu P.
    friction_coefficient, normal_force, contact_radius, shear_modulus : float
        As in :func:`sliding_displacement`.

    Returns
    -------
    float or ndarray
        delta [m]; delta_0 at |Q| = mu P.
    """
    delta0 = sliding_displacement(friction_coefficient, normal_force, contact_radius, shear_modulus)
    ratio = _force_ratio(force, friction_coefficient * normal_force)
    sign = np.sign(np.asarray(force, dtype=float))
    return _as_output(sign * delta0 * (1.0 - (1.0 - ratio) ** (2.0 / 3.0)), force)


def _virgin_force(delta: np.ndarray, mu_p: float, delta0: float) -> np.ndarray:
    """Odd, saturated virgin curve Q_M(delta)."""
    x = np.minimum(np.abs(delta) / delta0, 1.0)
    return np.sign(delta) * mu_p * (1.0 - (1.0 - x) ** 1.5)


@renamed(mu="friction_coefficient")
def tangential_force(
    displacement,
    friction_coefficient: float,
    normal_force: float,
    contact_radius: float,
    shear_modulus: float,
):
    r"""Inverse of :func:`tangential_displacement`: Q(delta) [N], with Q = mu P beyond delta_0.

    .. math:: Q(\delta) = \mu P \left[1 - \left(1 - \frac{\delta}{\delta_0}\right)^{3/2}\right],
              \qquad |\delta| \le \delta_0 = \frac{3 \mu P}{16 a G^*}

    Odd in delta; |Q| = mu P (gross sliding) for |delta| >= delta_0.

    Parameters
    ----------
    displacement : float or array
        delta [m] from the unloaded state.
    friction_coefficient, normal_force, contact_radius, shear_modulus : float
        As in :func:`sliding_displacement`.

    Returns
    -------
    float or ndarray
        Q [N].
    """
    delta0 = sliding_displacement(friction_coefficient, normal_force, contact_radius, shear_modulus)
    delta = finite_array(displacement, "displacement")
    return _as_output(_virgin_force(delta, friction_coefficient * normal_force, delta0), displacement)


@renamed(mu="friction_coefficient")
def lateral_stiffness(
    force, friction_coefficient: float, normal_force: float, contact_radius: float, shear_modulus: float
):
    r"""Tangential (lateral) stiffness of the virgin curve, dQ/d delta = 8 a G* (1 - |Q|/(mu P))^(1/3) [N/m].

    Parameters
    ----------
    force : float or array
        Q [N], |Q| <= mu P.
    friction_coefficient, normal_force, contact_radius, shear_modulus : float
        As in :func:`sliding_displacement`.

    Returns
    -------
    float or ndarray
        K [N/m]; 8 a G* at Q = 0, 0 at gross sliding.

    References
    ----------
    Johnson (1985), sec. 7.2 (derivative of eq. 7.42). On a Masing branch after a reversal at Q_r,
    the stiffness is this function evaluated at (Q_r - Q)/2.
    """
    mu_p = _check_contact(friction_coefficient, normal_force, contact_radius, shear_modulus)
    ratio = _force_ratio(force, mu_p)
    return _as_output(8.0 * contact_radius * shear_modulus * np.cbrt(1.0 - ratio), force)


# --- cyclic loading (Mindlin-Deresiewicz, Masing rule) ------------------------------------------------


@renamed(mu="friction_coefficient")
def masing_displacement(
    force,
    force_amplitude: float,
    friction_coefficient: float,
    normal_force: float,
    contact_radius: float,
    shear_modulus: float,
    *,
    branch: str = "unloading",
):
    r"""Displacement on a force-controlled Mindlin-Deresiewicz loop between -Q* and +Q* [m].

    .. math::

        \text{unloading from } Q^*: \quad
        \delta = \delta_M(Q^*) - 2\,\delta_M\!\left(\frac{Q^* - Q}{2}\right),

        \text{reloading from } -Q^*: \quad
        \delta = -\delta_M(Q^*) + 2\,\delta_M\!\left(\frac{Q^* + Q}{2}\right),

    where delta_M is :func:`tangential_displacement` (Johnson eqs. 7.50-7.53).

    Parameters
    ----------
    force : float or array
        Q [N] in [-Q*, Q*].
    force_amplitude : float
        Q* [N], 0 < Q* <= mu P.
    friction_coefficient, normal_force, contact_radius, shear_modulus : float
        As in :func:`sliding_displacement`.
    branch : {"unloading", "reloading"}
        Which half of the loop.

    Returns
    -------
    float or ndarray
        delta [m].
    """
    if branch not in ("unloading", "reloading"):
        raise InputError("branch", f"unknown branch {branch!r}.", "choose 'unloading' or 'reloading'.")
    mu_p = _check_contact(friction_coefficient, normal_force, contact_radius, shear_modulus)
    positive(force_amplitude, "force_amplitude", example="0.5 * mu * normal_force")
    _force_ratio(force_amplitude, mu_p, "force_amplitude")
    q = finite_array(force, "force")
    if np.any(np.abs(q) > force_amplitude * (1.0 + 1e-12)):
        raise InputError("force", "lies outside [-Q*, Q*].", "keep |force| <= force_amplitude.")
    q = np.clip(q, -force_amplitude, force_amplitude)
    args = (friction_coefficient, normal_force, contact_radius, shear_modulus)
    d_star = tangential_displacement(force_amplitude, *args)
    if branch == "unloading":
        delta = d_star - 2.0 * np.asarray(tangential_displacement((force_amplitude - q) / 2.0, *args))
    else:
        delta = -d_star + 2.0 * np.asarray(tangential_displacement((force_amplitude + q) / 2.0, *args))
    return _as_output(np.asarray(delta, dtype=float), force)


@renamed(mu="friction_coefficient")
def masing_force(
    displacement_path,
    friction_coefficient: float,
    normal_force: float,
    contact_radius: float,
    shear_modulus: float,
) -> np.ndarray:
    r"""Tangential force along a prescribed displacement path (Masing rule with memory) [N].

    The contact starts unloaded (Q = 0) at ``displacement_path[0]``; displacements are taken
    relative to it. The virgin curve is Q_M(delta) = mu P [1 - (1 - delta/delta_0)^(3/2)]
    (odd, saturated at mu P, :func:`tangential_force`). After a reversal at (delta_r, Q_r),
    the branch is (Mindlin and Deresiewicz 1953; Johnson 1985, sec. 7.4)

    .. math:: Q = Q_r + 2\,Q_M\!\left(\frac{\delta - \delta_r}{2}\right),

    which reaches the opposite sliding force after 2 delta_0 and then stays there (gross
    sliding). Memory: the reversal points are kept on a stack; when a branch reaches the
    reversal point before the last one, the inner loop is closed and wiped from memory and the
    force continues on the branch it interrupted; the first branch after the virgin curve rejoins
    the virgin curve at the mirror image (-delta_1, -Q_1) of the first reversal. This is exact
    for the Mindlin contact at constant normal force (the slip annuli of older reversals are
    wiped out once a newer one passes them). The paper's path 0 -> stroke -> 0 -> stroke ...
    and symmetric +/- cycles are special cases.

    Parameters
    ----------
    displacement_path : array_like
        delta [m] at each step, piecewise monotonic; reversals are where the sign of the
        increment changes (repeated values are allowed).
    friction_coefficient, normal_force, contact_radius, shear_modulus : float
        As in :func:`sliding_displacement`.

    Returns
    -------
    ndarray
        Q [N] at every point of the path.
    """
    delta0 = sliding_displacement(friction_coefficient, normal_force, contact_radius, shear_modulus)
    mu_p = friction_coefficient * normal_force
    path = finite_array(displacement_path, "displacement_path")
    if path.ndim != 1 or path.size == 0:
        raise InputError(
            "displacement_path", "expected a non-empty 1-D array.", "pass a sequence of displacements [m]."
        )
    delta = path - path[0]
    force = np.zeros_like(delta)
    stack: list[tuple[float, float]] = []  # reversal points (delta_r, Q_r)
    direction = 0.0

    def virgin(x: float) -> float:  # scalar Q_M, as _virgin_force
        ratio = min(abs(x) / delta0, 1.0)
        return math.copysign(mu_p * (1.0 - (1.0 - ratio) ** 1.5), x)

    def branch(x: float) -> float:
        if not stack:
            return virgin(x)
        d_r, q_r = stack[-1]
        return q_r + 2.0 * virgin((x - d_r) / 2.0)

    values = delta.tolist()
    for k in range(1, len(values)):
        step = values[k] - values[k - 1]
        if step == 0.0:
            force[k] = force[k - 1]
            continue
        new_direction = math.copysign(1.0, step)
        if direction != 0.0 and new_direction != direction:
            stack.append((values[k - 1], float(force[k - 1])))
        direction = new_direction
        while stack:
            target = stack[-2][0] if len(stack) >= 2 else -stack[-1][0]
            if direction * (values[k] - target) < 0.0:
                break
            del stack[-2 if len(stack) >= 2 else -1 :]
        force[k] = branch(values[k])
    return force


@renamed(mu="friction_coefficient")
def dissipated_energy(
    force_amplitude: float,
    friction_coefficient: float,
    normal_force: float,
    contact_radius: float,
    shear_modulus: float,
) -> float:
    r"""Energy dissipated per force-controlled cycle between -Q* and +Q* [J].

    .. math::

        W = \frac{9 \mu^2 P^2}{10\, a G^*}\left\{1 - \left(1 - \frac{Q^*}{\mu P}\right)^{5/3}
            - \frac{5 Q^*}{6 \mu P}\left[1 + \left(1 - \frac{Q^*}{\mu P}\right)^{2/3}\right]\right\}

    Verified: this is exactly the area of the Masing loop of :func:`masing_displacement`,
    W = 4 Q* delta_M(Q*) - 8 int_0^Q* delta_M(u) du (integrated in closed form, and checked
    against numerical quadrature in ``tests/validation/test_mindlin_closed_forms.py``). It is
    Johnson's eq. 7.59 with (2 - nu)/G there read as 1/G* = sum (2 - nu_i)/G_i. For small
    amplitudes W ~ Q*^3 / (36 mu P a G*) (cubic in Q*); at Q* = mu P, W = (4/5) mu P delta_0.

    Parameters
    ----------
    force_amplitude : float
        Q* [N], 0 < Q* <= mu P.
    friction_coefficient, normal_force, contact_radius, shear_modulus : float
        As in :func:`sliding_displacement`.

    Returns
    -------
    float
        W [J] per cycle.

    References
    ----------
    Mindlin and Deresiewicz (1953); Johnson (1985), sec. 7.4, eq. 7.59.
    """
    mu_p = _check_contact(friction_coefficient, normal_force, contact_radius, shear_modulus)
    positive(force_amplitude, "force_amplitude", example="0.5 * mu * normal_force")
    x = float(_force_ratio(force_amplitude, mu_p, "force_amplitude"))
    prefactor = 9.0 * mu_p**2 / (10.0 * contact_radius * shear_modulus)
    return prefactor * (1.0 - (1.0 - x) ** (5.0 / 3.0) - 5.0 * x / 6.0 * (1.0 + (1.0 - x) ** (2.0 / 3.0)))


@renamed(mu="friction_coefficient")
def dissipated_energy_displacement(
    displacement_range: float,
    friction_coefficient: float,
    normal_force: float,
    contact_radius: float,
    shear_modulus: float,
) -> float:
    r"""Energy dissipated per displacement-controlled cycle of total range ``displacement_range`` [J].

    With half-range D = displacement_range / 2 the steady loop is the Masing loop of amplitude
    Q* = Q_M(D) (:func:`tangential_force`) when D <= delta_0, so W = :func:`dissipated_energy`
    (Q*). Beyond it, gross sliding adds a parallelogram of height 2 mu P:

    .. math:: W = \frac{4}{5}\mu P \delta_0 + 4 \mu P (D - \delta_0), \qquad D > \delta_0.

    This applies to any cycle between two displacement limits (e.g. the paper's 0 -> stroke),
    once the first cycle has set the loop (Masing).

    Parameters
    ----------
    displacement_range : float
        max - min of the displacement over the cycle (the stroke d_s) [m], positive.
    friction_coefficient, normal_force, contact_radius, shear_modulus : float
        As in :func:`sliding_displacement`.

    Returns
    -------
    float
        W [J] per cycle.
    """
    positive(displacement_range, "displacement_range", example="2.8e-6", unit="m")
    delta0 = sliding_displacement(friction_coefficient, normal_force, contact_radius, shear_modulus)
    half = displacement_range / 2.0
    mu_p = friction_coefficient * normal_force
    if half <= delta0:
        amplitude = float(_virgin_force(np.asarray(half), mu_p, delta0))
        return dissipated_energy(amplitude, friction_coefficient, normal_force, contact_radius, shear_modulus)
    return 0.8 * mu_p * delta0 + 4.0 * mu_p * (half - delta0)


def __getattr__(name: str):
    """Serve paper 001's reference, which moved to :mod:`roughcontact.papers.paper001`, with a warning."""
    homes = dict.fromkeys(
        ("NORMALISATIONS", "Paper001Mindlin", "paper001_mindlin"), "roughcontact.papers.paper001"
    )
    return moved(__name__, name, homes)
