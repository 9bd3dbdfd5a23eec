r"""Accelerated projected gradients (Nesterov / FISTA with restart) for one partial-slip increment.

The increment is the convex second-order-cone programme of :mod:`roughcontact.contact._shear_cg`:

.. math::

    \min_q\ f(q) = \tfrac12\, q \cdot C q + q \cdot (e - \delta)
    \quad \text{over the discs } |q_i| \le c_i = \mu p_i

with C the tangential compliance of the pair (symmetric positive semi-definite), e the known
field of the step and delta the rigid tangential displacement, given (displacement control) or
the Lagrange multiplier of the force constraint sum(q) A_px = F (force control, where the
feasible set is the product of discs intersected with that affine plane and the delta term is
constant on it). Its gradient is the slip increment w = C q + e - delta.

Method: Nesterov's accelerated projected gradient::

    y_k     = x_k + beta_k (x_k - x_{k-1})
    x_{k+1} = Proj(y_k - (C y_k + e - delta) / L)

C y_k = (1 + beta_k) C x_k - beta_k C x_{k-1} is a combination of known products, so each
iteration applies C once (two FFT pairs), against two applications per iteration of the
conjugate-gradient solver. Two momentum rules:

- constant momentum beta = (sqrt(kappa) - 1) / (sqrt(kappa) + 1), kappa = L / mu_c, when a
  lower bound mu_c > 0 of C's smallest eigenvalue on the feasible directions is given
  (``strong_convexity``; :func:`kernel_extremes` gives it from the Fourier kernel). This is
  Nesterov's constant-step scheme for strongly convex functions (Nesterov 2004, scheme
  2.2.19; "V-FISTA" in Beck 2017, sec. 10.7.7), with f - f* <= (1 - kappa^(-1/2))^k
  (f(x_0) - f* + mu_c |x_0 - x*|^2 / 2) for a convex feasible set;
- otherwise FISTA's t-sequence (Beck and Teboulle 2009), t_{k+1} = (1 + sqrt(1 + 4 t_k^2))/2,
  beta_{k+1} = (t_k - 1) / t_{k+1}, f - f* = O(L |x_0 - x*|^2 / k^2).

Either way the momentum is reset (one step with beta = 0, and t = 1) by O'Donoghue and
Candes' (2015) adaptive restart: when (y_k - x_{k+1}).(x_{k+1} - x_k) > 0 (gradient restart,
the default: the step goes against the momentum) or f(x_{k+1}) > f(x_k) (function restart).

Measured on a smooth sphere (free 128^2 grid, 4a window, tolerance 1e-8): FISTA with either
adaptive restart needs 470 (nu = 0) and 330-450 (nu = 0.5) iterations, the restart test firing
once or not at all: the error is spread over many modes of the 1/k spectrum, so the iterates
never visibly oscillate and FISTA stays in its O(1/k^2) regime. The constant momentum from the
kernel's mu_c needs 99 and 108 (a fixed restart every 30 iterations, 126). mu_c is close to
the true smallest eigenvalue there (2.819e-15 against 2.823e-15 m/Pa by ARPACK; kappa = 96).

Step 1/L and the bounds. L must bound the largest eigenvalue of C restricted to the contact
set (q vanishes elsewhere). It is computed once per operator and contact set by 20 Lanczos
steps on the restricted operator and cached; the extreme Ritz value converges from below
(against ARPACK: 1e-14 after 10 steps on the smooth sphere, 4e-6 after 10 and 1e-15 after 20
on rough balls), and a 2 % margin is added. The extreme eigenvalues of the 2 x 2 Fourier
kernel over all modes (:func:`kernel_extremes`) bound the restricted operator's spectrum from
both sides, for the zero-padded free operator as well: it is P^T K P with P the isometric zero
padding and K the circulant (checked against the dense matrix in the tests). The lower one is
mu_c (for a periodic surface without the k = 0 mode: under force control the feasible
directions have zero mean); it is tight (within 0.1-6 % of the restricted smallest eigenvalue
on the smooth sphere and on rough balls). The upper one is loose, the norm over the whole
window: 5x the restricted value for a smooth sphere or a rough ball on a 4a window, 42x on
paper 001's sparse contacts (1.5 % of a 160^2 window), and the iteration count grows like
sqrt(L).

Projections (exact):

- displacement control: radial projection of each point onto its disc;
- force control: the projection onto {discs} and {sum_i q_i = F / A_px} is
  q_i = Proj_i(z_i + m) with the 2-vector multiplier m solving sum_i Proj_i(z_i + m) = F / A_px,
  the gradient equation of the convex function sum_i phi_i(z_i + m) - m.F/A_px
  (phi(z) = |z|^2/2 - dist(z, disc)^2/2 has gradient Proj). It is solved by Newton's method
  with the projections' Jacobians (I inside a disc, (c/|z|)(I - u u^T) outside, a 1e-12
  relative ridge against a singular sum) and a backtracking line search on that convex
  function, warm-started from the previous iteration's m, to |sum q - F/A_px| <= 1e-14 sum c.
  The force is therefore met to round-off at every iterate. delta, the force's multiplier in
  the programme, is recovered at each iterate as the mean of C q + e over the points strictly
  inside their disc (stick), as the conjugate-gradient solver does
  (:func:`roughcontact.contact._shear_kernels.interior_mean`).

Residual and result are those of :func:`roughcontact.contact._shear_cg.solve_increment`
(:func:`roughcontact.contact._shear_kernels.classify`: the traction-weighted mean violation of
the stick and slip-direction conditions relative to the step's displacement scale), so a
tolerance means the same for both solvers. |q_i| <= c_i holds to round-off at every iterate.

Convergence assumptions. f is convex with an L-Lipschitz gradient on the feasible set, which
is closed, convex and non-empty (under force control |F| < mu F_0, checked). On the contact set
C is positive definite, its smallest eigenvalue of the order of a pixel's self-compliance,
so f is strongly convex there with kappa of the order of the contact diameter in pixels, and
the iterates converge linearly at about 1 - kappa^(-1/2) per iteration, whatever the
stick-slip pattern: unlike the conjugate-gradient solver's, the rate does not depend on the
slip directions staying fixed. The residual, a measure of the optimality conditions, is not
monotone along the iterates.

Diagonal (Jacobi) scaling, the only preconditioning compatible with the disc projection, does
nothing here: the diagonal of C is the same at every pixel (translation-invariant kernel).

References
----------
Beck, A. and Teboulle, M. (2009). A fast iterative shrinkage-thresholding algorithm for linear
inverse problems. SIAM J. Imaging Sci. 2, 183-202. doi:10.1137/080716542
O'Donoghue, B. and Candes, E. (2015). Adaptive restart for accelerated gradient schemes.
Found. Comput. Math. 15, 715-732. doi:10.1007/s10208-013-9150-3
Nesterov, Y. (2004). Introductory Lectures on Convex Optimization, sec. 2.2. Kluwer.
doi:10.1007/978-1-4419-8853-9
Beck, A. (2017). First-Order Methods in Optimization, sec. 10.7. SIAM. doi:10.1137/1.9781611974997
Vollebregt, E. A. H. (2014). J. Optim. Theory Appl. 162, 931-953 (the convex formulation).
"""

from __future__ import annotations

import hashlib
import math
import weakref
from collections.abc import Callable

import numba as nb
import numpy as np

from ..errors import ConvergenceError, InputError
from . import _shear_kernels as kernels
from ._shear_cg import RIM, ShearResult, check_below_sliding, optimality
from ._shear_kernels import length

_JIT = dict(cache=True, nogil=True)

RESTARTS = ("gradient", "function")
LANCZOS_STEPS = 20
"""Lanczos steps of the restricted-norm estimate."""
LIPSCHITZ_MARGIN = 1.02
"""Factor on the Lanczos estimate (a lower bound that converges from below)."""
_FORCE_TOLERANCE = 1e-14
"""Force-control projection: |sum q - F/A_px| <= this times sum c."""
_NEWTON_STEPS = 100

# (operator or callable) -> {contact-mask digest: L}; entries die with the operator.
_NORMS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


# ------------------------------------------------------------------------------------------------
# elementwise passes (numba; serial, as in _shear_kernels)


@nb.njit(**_JIT)
def _extrapolate(qx, qy, px, py, sx, sy, tx, ty, beta, gx, gy, step, yx, yy, zx, zy):
    """Write y = q + beta (q - p) and z = y - step (s_y - g), s_y = s + beta (s - t) (= C y + e)."""
    for i in range(qx.size):
        ax = qx[i] + beta * (qx[i] - px[i])
        ay = qy[i] + beta * (qy[i] - py[i])
        yx[i], yy[i] = ax, ay
        zx[i] = ax - step * (sx[i] + beta * (sx[i] - tx[i]) - gx)
        zy[i] = ay - step * (sy[i] + beta * (sy[i] - ty[i]) - gy)


@nb.njit(**_JIT)
def _project_shifted(zx, zy, c, mx, my, qx, qy, yx, yy):
    """Replace z by Proj_disc(z + m) in place; return (y - z_new).(z_new - q) (restart test)."""
    dot = 0.0
    for i in range(zx.size):
        x = zx[i] + mx
        y = zy[i] + my
        ci = c[i]
        norm = length(x, y)
        if norm > ci:
            scale = ci / norm if norm > 0.0 else 0.0
            x *= scale
            y *= scale
        zx[i], zy[i] = x, y
        dot += (yx[i] - x) * (x - qx[i]) + (yy[i] - y) * (y - qy[i])
    return dot


@nb.njit(**_JIT)
def _force_map(zx, zy, c, mx, my):
    """Return sum Proj(z + m) (x, y), its Jacobian (xx, xy, yy) and sum phi(z + m) over the contact."""
    fx, fy, jxx, jxy, jyy, phi = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    for i in range(zx.size):
        ci = c[i]
        if ci <= 0.0:
            continue
        ax = zx[i] + mx
        ay = zy[i] + my
        r = length(ax, ay)
        if r <= ci:
            fx += ax
            fy += ay
            jxx += 1.0
            jyy += 1.0
            phi += 0.5 * r * r
        else:
            ux, uy = ax / r, ay / r
            s = ci / r
            fx += ci * ux
            fy += ci * uy
            jxx += s * (1.0 - ux * ux)
            jxy -= s * ux * uy
            jyy += s * (1.0 - uy * uy)
            phi += ci * r - 0.5 * ci * ci
    return fx, fy, jxx, jxy, jyy, phi


@nb.njit(**_JIT)
def _force_multiplier(zx, zy, c, target_x, target_y, mx, my, scale, tolerance, max_steps):
    """Solve sum_i Proj_i(z_i + m) = target for m (Newton, backtracking); return (m_x, m_y, |error|).

    Descent on psi(m) = sum phi(z + m) - m.target (convex, gradient sum Proj - target); a step is
    accepted on Armijo's condition or when it reduces |gradient| (near the solution psi's
    decrease is below round-off).
    """
    fx, fy, jxx, jxy, jyy, phi = _force_map(zx, zy, c, mx, my)
    gx, gy = fx - target_x, fy - target_y
    psi = phi - mx * target_x - my * target_y
    for _ in range(max_steps):
        g = length(gx, gy)
        if g <= tolerance * scale:
            break
        ridge = 1e-12 * (jxx + jyy) + 1e-300
        a, b, d = jxx + ridge, jxy, jyy + ridge
        det = a * d - b * b
        dx = -(d * gx - b * gy) / det
        dy = -(a * gy - b * gx) / det
        slope = gx * dx + gy * dy
        fraction = 1.0
        accepted = False
        for _ in range(60):
            nx, ny = mx + fraction * dx, my + fraction * dy
            fx, fy, njxx, njxy, njyy, nphi = _force_map(zx, zy, c, nx, ny)
            ngx, ngy = fx - target_x, fy - target_y
            npsi = nphi - nx * target_x - ny * target_y
            if npsi <= psi + 1e-4 * fraction * slope or length(ngx, ngy) <= (1.0 - 1e-4 * fraction) * g:
                accepted = True
                break
            fraction *= 0.5
        if not accepted:
            break
        mx, my, gx, gy, psi = nx, ny, ngx, ngy, npsi
        jxx, jxy, jyy = njxx, njxy, njyy
    return mx, my, length(gx, gy)


# ------------------------------------------------------------------------------------------------
# step length


def kernel_extremes(operator) -> tuple[float, float]:
    """Smallest and largest eigenvalue of the 2 x 2 shear kernel of ``operator`` over its modes [m/Pa].

    They bound the spectrum of :meth:`TractionCompliance.shear
    <roughcontact.elasticity.tangential.TractionCompliance.shear>` restricted to any set of
    points, for either boundary (the free operator restricts the padded circulant). The k = 0
    mode of a periodic operator (zero: the mean displacement is undetermined) is left out of
    the smallest one, which then bounds the directions with zero mean (force control). A
    smallest value <= 0 (an indefinite padded kernel) is no bound of strong convexity.
    """
    k = operator._k
    a, b, d = k["xx"], k["xy"], k["yy"]
    half = 0.5 * (a + d)
    radius = np.sqrt((0.5 * (a - d)) ** 2 + b**2)
    low, high = half - radius, half + radius
    if operator.boundary == "periodic":
        low = low.copy()
        low[0, 0] = np.inf
    return float(np.min(low)), float(max(np.max(high), -np.min(half - radius)))


def restricted_norm(
    shear: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]],
    contact: np.ndarray,
    steps: int = LANCZOS_STEPS,
) -> float:
    """Largest eigenvalue of ``shear`` restricted to the points of ``contact`` (Lanczos, ``steps`` steps).

    A Ritz value, so a lower bound that converges from below; cached per operator (the object a
    bound method belongs to, else the callable) and contact set.
    """
    owner = getattr(shear, "__self__", shear)
    digest = hashlib.blake2b(np.ascontiguousarray(contact).tobytes(), digest_size=16).digest()
    digest += repr(contact.shape).encode()
    try:
        cached = _NORMS.setdefault(owner, {})
    except TypeError:  # not weakly referenceable: no cache
        cached = {}
    if digest in cached:
        return cached[digest]
    rng = np.random.default_rng(20150715)
    mask = np.asarray(contact, dtype=bool)
    v = np.where(mask, rng.standard_normal((2, *mask.shape)), 0.0)
    v /= np.linalg.norm(v)
    v_old = np.zeros_like(v)
    alphas, betas = [], []
    beta = 0.0
    for _ in range(min(steps, 2 * int(mask.sum()))):
        wx, wy = shear(v[0], v[1])
        w = np.where(mask, np.stack([wx, wy]), 0.0)
        alpha = float(np.vdot(w, v))
        w -= alpha * v + beta * v_old
        alphas.append(alpha)
        beta = float(np.linalg.norm(w))
        if beta <= 1e-12 * abs(alpha):
            break
        betas.append(beta)
        v_old, v = v, w / beta
    if not alphas:
        value = 0.0
    else:
        n = len(alphas)
        tridiagonal = np.diag(alphas) + np.diag(betas[: n - 1], 1) + np.diag(betas[: n - 1], -1)
        value = float(np.linalg.eigvalsh(tridiagonal)[-1])
    cached[digest] = value
    return value


# ------------------------------------------------------------------------------------------------


def solve_increment(
    shear: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]],
    bound: np.ndarray,
    offset: tuple[np.ndarray, np.ndarray],
    *,
    pixel_area: float,
    displacement: tuple[float, float] | None = None,
    force: tuple[float, float] | None = None,
    initial: tuple[np.ndarray, np.ndarray] | None = None,
    tolerance: float = 1e-8,
    max_iterations: int = 10_000,
    solver: str = "solve_tangential",
    preconditioner: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]] | None = None,
    lipschitz: float | None = None,
    restart: str = "gradient",
    strong_convexity: float | None = None,
) -> ShearResult:
    """Solve the increment of the module docstring by accelerated projected gradients.

    Same arguments, result and errors as :func:`roughcontact.contact._shear_cg.solve_increment`
    (``iterations`` counts iterations of this method, one application of ``shear`` each; the
    Lanczos estimate of L adds up to 20 applications per operator and contact set).

    Parameters
    ----------
    shear : callable
        (q_x, q_y) [Pa] -> (s_x, s_y) [m], the tangential compliance of the pair.
    bound : ndarray
        c = mu p [Pa] (0 outside the contact).
    offset : (ndarray, ndarray)
        The known field e [m].
    pixel_area : float
        [m^2]; the force is pixel_area * sum(q).
    displacement, force : (float, float)
        Exactly one: rigid displacement (delta_x, delta_y) [m] or total force (F_x, F_y) [N].
    initial : (ndarray, ndarray), optional
        Warm start (projected onto the feasible set first).
    tolerance, max_iterations, solver
        Stop criterion, iteration limit (then :class:`ConvergenceError`), name for messages.
    preconditioner : None
        Accepted for the common signature; only None: a non-diagonal preconditioner does not
        commute with the disc projection.
    lipschitz : float, optional
        The step is 1/lipschitz [Pa/m]; it must bound the largest eigenvalue of ``shear`` on the
        contact set (default: :func:`restricted_norm` times :data:`LIPSCHITZ_MARGIN`).
    restart : {"gradient", "function"}
        O'Donoghue and Candes' restart test.
    strong_convexity : float, optional
        mu_c [Pa/m], a lower bound of the smallest eigenvalue of ``shear`` on the feasible
        directions (e.g. the first of :func:`kernel_extremes`): constant momentum from
        kappa = L / mu_c. Without it (or if not in (0, L)), FISTA's momentum sequence.
    """
    if preconditioner is not None:
        raise InputError(
            "preconditioner",
            "the accelerated projected-gradient solver takes no preconditioner (it would not commute "
            "with the projection onto the discs).",
            "pass None, or use the conjugate-gradient solver.",
        )
    if lipschitz is not None and not lipschitz > 0:
        raise InputError("lipschitz", f"must be positive, got {lipschitz!r}.", None)
    if restart not in RESTARTS:
        raise InputError("restart", f"got {restart!r}.", f"use one of {RESTARTS}.")
    shape = bound.shape
    c = np.array(bound, dtype=float)
    c_flat = c.ravel()
    contact = c > 0
    ex = np.ascontiguousarray(offset[0], dtype=float)
    ey = np.ascontiguousarray(offset[1], dtype=float)
    load_control = force is not None
    capacity_sum = float(c.sum())
    target = (0.0, 0.0)
    if load_control:
        check_below_sliding(force, c, pixel_area)
        target = (float(force[0]) / pixel_area, float(force[1]) / pixel_area)
    multiplier = [0.0, 0.0]

    def project(zx, zy, qx, qy, yx, yy):
        """Project z onto the feasible set in place; return the restart product (y - z).(z - q)."""
        if load_control:
            mx, my, error = _force_multiplier(
                zx.ravel(), zy.ravel(), c_flat, target[0], target[1], multiplier[0], multiplier[1],
                capacity_sum, _FORCE_TOLERANCE, _NEWTON_STEPS,
            )  # fmt: skip
            if error > 1e3 * _FORCE_TOLERANCE * capacity_sum:
                raise ConvergenceError(f"{solver} (force projection)", error / capacity_sum, _NEWTON_STEPS, 0)
            multiplier[:] = (mx, my)
        return _project_shifted(
            zx.ravel(), zy.ravel(), c_flat, multiplier[0], multiplier[1],
            qx.ravel(), qy.ravel(), yx.ravel(), yy.ravel(),
        )  # fmt: skip

    # x_0: the warm start projected onto the feasible set
    qx, qy = np.zeros(shape), np.zeros(shape)
    if initial is not None:
        qx[...] = np.where(contact, initial[0], 0.0)
        qy[...] = np.where(contact, initial[1], 0.0)
    project(qx, qy, qx.copy(), qy.copy(), qx.copy(), qy.copy())
    given = (0.0, 0.0) if load_control else (float(displacement[0]), float(displacement[1]))
    delta = given

    sx, sy = shear(qx, qy)
    sx += ex
    sy += ey
    px, py, tx, ty = qx.copy(), qy.copy(), sx.copy(), sy.copy()
    yx, yy, zx, zy, wx, wy = (np.empty(shape) for _ in range(6))
    flat = {name: np.zeros(c.size) for name in ("zx", "zy", "nx", "ny", "bend")}
    state = np.full(c.size, 255, dtype=np.uint8)
    step = None
    momentum = None
    theta, beta = 1.0, 0.0
    energy_old = np.inf
    residual = np.inf
    for iteration in range(max_iterations + 1):
        if load_control:
            delta = kernels.interior_mean(qx.ravel(), qy.ravel(), c_flat, sx.ravel(), sy.ravel(), RIM)
        np.copyto(wx, sx)
        np.copyto(wy, sy)
        residual = optimality(qx, qy, c_flat, wx, wy, delta, state, flat, (ex, ey)).residual
        if residual <= tolerance:
            stick = (state == kernels.STICK).reshape(shape)
            return ShearResult(qx, qy, wx, wy, delta, stick, iteration, float(residual))
        if iteration == max_iterations:
            break
        if step is None:
            norm = lipschitz if lipschitz is not None else LIPSCHITZ_MARGIN * restricted_norm(shear, contact)
            step = 1.0 / norm
            if strong_convexity is not None and 0.0 < strong_convexity < norm:
                root = math.sqrt(norm / strong_convexity)
                momentum = (root - 1.0) / (root + 1.0)
        if restart == "function":
            # f(q) = q.(Cq)/2 + q.(e - delta_given) = q.(s + e)/2 - q.delta_given (s = Cq + e)
            energy = 0.5 * (np.vdot(qx, sx + ex) + np.vdot(qy, sy + ey))
            energy -= given[0] * qx.sum() + given[1] * qy.sum()
            if energy > energy_old:
                theta, beta = 1.0, 0.0
            energy_old = energy
        # the gradient's constant part: the given delta, or the current estimate of the multiplier
        _extrapolate(
            qx.ravel(), qy.ravel(), px.ravel(), py.ravel(), sx.ravel(), sy.ravel(), tx.ravel(), ty.ravel(),
            beta, delta[0], delta[1], step, yx.ravel(), yy.ravel(), zx.ravel(), zy.ravel(),
        )  # fmt: skip
        against = project(zx, zy, qx, qy, yx, yy)
        if restart == "gradient" and against > 0.0:
            theta, beta = 1.0, 0.0
        elif momentum is not None:
            beta = momentum
        else:
            theta_next = 0.5 * (1.0 + math.sqrt(1.0 + 4.0 * theta * theta))
            beta = (theta - 1.0) / theta_next
            theta = theta_next
        # rotate: p <- q <- z (the new iterate), t <- s <- C z + e
        px, py, qx, qy, zx, zy = qx, qy, zx, zy, px, py
        tx, ty = sx, sy
        sx, sy = shear(qx, qy)
        sx += ex
        sy += ey
    raise ConvergenceError(solver, float(residual), iteration, tolerance)
