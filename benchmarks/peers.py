"""Adapters to the peer normal-contact solvers, so that they can be run side by side in one benchmark.

Every adapter takes SI inputs and returns a dict with

* ``pressure``: contact pressure (Pa), same shape as ``heights`` (axis 0 = x), positive in compression;
* ``iterations``: the peer's own iteration count (``None`` if it cannot be had);
* ``seconds``: wall time of the solve call only (model, kernel and operator set-up excluded);
* ``approach``: rigid-body approach delta measured from first touch, i.e. the gap is
  ``g = u - h + max(h) - delta >= 0`` (``= 0`` in contact), ``u`` the elastic displacement positive into the
  body and, periodic case, with zero mean (``u(q = 0) = 0``);
* ``converged``: the peer's own verdict, and ``error``: its own convergence measure at exit.

Common conventions: ``heights`` (m) point towards the counter-surface, so the highest point touches first;
``size = (Lx, Ly)`` (m); ``contact_modulus`` is Johnson's E*, 1/E* = sum_i (1 - nu_i^2)/E_i (every peer is
handed E* directly with nu = 0 where it asks for E and nu). Load control: ``mean_pressure`` (Pa) over the
nominal area, or ``force`` (N) for the free-boundary Hertz cases (mean pressure ``force / (Lx Ly)`` over the
window). Every peer is imported lazily: importing this module never needs a peer.

Peers (versions as installed with ``pip install roughcontact[bench]``, checked 2026):

tamaas 2.9.0 (EPFL/LSMS; C++ with pybind11; wheel built with the serial ``cpp`` backend: one thread)
    Solver: ``PolonskyKeerRey`` (Polonsky & Keer 1999 constrained CG, Rey et al. 2017), ``basic_2d`` model.
    Modulus: ``model.E``, ``model.nu``; ``model.E_star = E / (1 - nu^2)``: we set ``E = E*``, ``nu = 0``.
    Periodic kernel: Westergaard, ``u(q) = 2 p(q) / (E* |q|)`` on the collocation grid, mean mode zero: the
    same as ours. Heights: the surface elevation, highest point first (same as ours). Error:
    ``|sum_i p_i g_i| / (sum_i p_i * std(h))``, the complementarity (pressure-weighted mean gap) over the
    rms height; ``solve`` stops once it is <= ``tolerance`` (checked in-loop, before the last update).
    Iterations: only printed by tamaas's logger (stderr, info level); captured here from file descriptor 2.
    Displacement control: ``PolonskyKeerRey(model, h, tol, PolonskyKeerRey.gap, PolonskyKeerRey.gap)`` and
    ``solve(mean_gap)``. Free boundary: ``ModelFactory.registerNonPeriodic(model, name)`` and
    ``solver.setIntegralOperator(name)``; without the latter tamaas silently solves the periodic problem, and
    the operator takes E* when it is registered, so register after setting ``E`` and ``nu``. That free
    operator matched the exact Love-kernel peers to 3e-9 in pressure on a 256^2 Hertz case.

contactmechanics 1.8.3 (``import ContactMechanics``; pure Python on numpy and muGrid FFTs; one thread;
``ContactMechanics.__version__`` reports a git hash, use ``importlib.metadata.version``)
    Solver: ``constrained_conjugate_gradients`` (Polonsky & Keer) on a ``PeriodicFFTElasticHalfSpace`` or
    ``FreeFFTElasticHalfSpace``; it works on pixel forces (N), pressure = force / pixel area.
    Modulus: ``young`` is E* when ``poisson`` is left at 0 (``contact_modulus = young / (1 - poisson^2)``).
    Periodic kernel: ``u(q) = 2 p(q) / (E* |q|)``, collocation; its default ``stiffness_q0=None`` gives the
    mean mode the stiffness of the lowest non-zero wavevector, which shifts the rigid offset (not the pressure
    under load control): we pass ``stiffness_q0=0`` (mean mode zero, as ours). Free kernel: Love's exact
    integral of uniform pressure over each rectangular pixel (Johnson 1985 p. 54), zero-padded to 2N x 2N.
    Heights: the rigid counter-body's profile, highest first; gap ``u - h - offset``; load control with
    ``external_force`` (total force), displacement control with ``offset`` (``delta = max(h) + offset``).
    Error: no single number. Converged when rms and max penetration and the max change of ``u`` per
    iteration are < ``pentol`` (m), the max tensile force < ``forcetol`` (N per pixel), and the relative
    change of the rigid-body position < ``thermotol``. Here ``tolerance`` maps to ``pentol = tolerance *
    std(h)``, ``forcetol = tolerance * mean pixel force``, ``thermotol = tolerance``; the returned
    ``error`` is max penetration / std(h). Iterations: ``result.nit`` (two FFT convolutions each).

aspher 0.1.3.post1 (C++17 with pybind11, built from the sdist: needs a C++ compiler, and Eigen from
``libeigen3-dev``, else its CMake fetches Eigen from the network; OpenMP on every core by default)
    Solver: ``ContactSolver(...).solve`` (Polonsky-Keer projected CG with |q| spectral preconditioner and
    certified stopping) or ``solve_nested`` (coarse-to-fine). Load control only (``p_nominal``, the mean
    pressure); no displacement-controlled normal solve (``solve_bipotential`` is a slow frictional reference).
    Square grids only (``grid_size`` = Ns, one ``domain_size``). Modulus: ``E_star``, Johnson's E*.
    Periodic kernel (``backend="periodic"``): ``u(q) = 2 p(q) / (E* |q|)``, zero mean mode: the same as ours.
    Free kernel (``backend="fft"``): exact Love (Boussinesq over square pixels) influence coefficients by
    zero-padded FFT convolution (``"h2"``, its default elsewhere, is an approximate fast-multipole operator).
    Heights: it takes the initial gap ``g0 = -h``; gap ``u + g0 - approach``, ``delta = max(h) + approach``.
    Error: converged when the Frank-Wolfe gap ``sum_i p_i (v_i - min v) / (sum_i p_i * (max h - min h))``
    (``v = u + g0``) and the max penetration / (max h - min h) are both <= ``tol``, and the load is met to
    1e-12; all recomputed on the returned pressure. It is normalised by the peak-to-valley height (~5 x the
    rms height that tamaas uses), yet the same ``tol`` gave a larger pressure error (table below).
    Iterations: ``result.iterations``. Threads: set ``OMP_NUM_THREADS`` before the first import; on a
    loaded 2-core machine libgomp's spinning made a 256^2 solve ~50x slower than with one thread.

What ``tolerance`` buys: max |p - p_ref| / max p_ref on a 256^2 periodic self-affine surface (H = 0.8,
7 % contact), p_ref = tamaas at 1e-12 (which contactmechanics at 1e-12 matches to 8e-13)::

    tolerance          1e-4     1e-6     1e-8     1e-10    1e-12
    tamaas             4.1e-4   1.4e-6   1.5e-8   1.7e-10  (ref)
    contactmechanics   2.4e-4   1.5e-6   2.2e-8   1.9e-10  8.3e-13
    aspher             1.2e-3   8.7e-6   1.0e-7   6.2e-10  9.2e-12

so tamaas and contactmechanics (mapping above) land at about ``tolerance``, aspher at 5-10 x ``tolerance``:
give aspher a tolerance ~10 x smaller for the same accuracy. tamaas's error stalls near 8e-13 on that
problem: below it ``solve`` runs to ``max_iter``. Every solve here is capped at 10 000 iterations.

Heights are centred (mean removed) before being handed to a peer; ``approach`` does not depend on it.
"""

from __future__ import annotations

import contextlib
import functools
import importlib
import os
import re
import sys
import tempfile
import time
from collections.abc import Callable, Iterator, Sequence

import numpy as np

_MODULES = {"tamaas": "tamaas", "contactmechanics": "ContactMechanics", "aspher": "aspher"}
_MAX_ITER = 10_000


def available_peers() -> list[str]:
    """Names of the peers that import, in the order tamaas, contactmechanics, aspher."""
    names = []
    for name, module in _MODULES.items():
        try:
            with _silenced_fd(1), _silenced_fd(2):  # tamaas prints its import errors
                importlib.import_module(module)
        except Exception:  # a peer that fails to import is absent
            continue
        names.append(name)
    return names


def solvers(case: str, names: Sequence[str] | None = None) -> dict[str, Callable[..., dict]]:
    """Return {label: solve} of the available peers for ``case`` ("periodic" or "free_hertz").

    ``names`` keeps only those peers (default: all that import). aspher's periodic case comes
    twice: with its full-grid Fourier preconditioner ("aspher") and coarse-to-fine
    ("aspher nested", :func:`aspher_periodic` with ``nested=True``), its fastest mode.
    """
    found = {}
    for name in available_peers():
        if names is not None and name not in names:
            continue
        solve = globals().get(f"{name}_{case}")
        if solve is None:
            continue
        found[name] = solve
        if name == "aspher" and case == "periodic":
            found["aspher nested"] = functools.partial(aspher_periodic, nested=True)
    return found


# --------------------------------------------------------------------------------------------------------
# helpers


def _check(
    heights: np.ndarray, size: Sequence[float], contact_modulus: float, load: float, tolerance: float
) -> tuple[np.ndarray, float, float]:
    h = np.ascontiguousarray(heights, dtype=np.float64)
    if h.ndim != 2 or min(h.shape) < 2:
        raise ValueError(f"heights must be a 2D array of at least 2 x 2 points, got shape {h.shape}")
    if not np.all(np.isfinite(h)):
        raise ValueError("heights must be finite")
    lx, ly = (float(s) for s in size)
    for value, what in ((lx, "size"), (ly, "size"), (contact_modulus, "contact_modulus"), (load, "load")):
        if not (np.isfinite(value) and value > 0):
            raise ValueError(f"{what} must be positive and finite, got {value}")
    if not (np.isfinite(tolerance) and tolerance > 0):
        raise ValueError(f"tolerance must be positive and finite, got {tolerance}")
    # The datum is physically irrelevant (delta is measured from first touch) but not numerically: a large
    # offset costs digits (tamaas and contactmechanics stall at h + 1 m), and contactmechanics's periodic
    # solve with max(h) <= 0 stops after one iteration at a uniform pressure and reports success.
    return h - h.mean(), lx, ly


def _square(h: np.ndarray, lx: float, ly: float, peer: str) -> int:
    if h.shape[0] != h.shape[1] or not np.isclose(lx, ly, rtol=1e-12, atol=0.0):
        raise ValueError(f"{peer} solves square grids of a square domain only, got {h.shape} over {(lx, ly)}")
    return h.shape[0]


@contextlib.contextmanager
def _silenced_fd(fd: int) -> Iterator[None]:
    sys.stdout.flush()
    sys.stderr.flush()
    with open(os.devnull, "w") as null:
        saved = os.dup(fd)
        try:
            os.dup2(null.fileno(), fd)
            yield
        finally:
            os.dup2(saved, fd)
            os.close(saved)


@contextlib.contextmanager
def _captured_stderr() -> Iterator[list[str]]:
    """Collect what native code writes on file descriptor 2 (tamaas's logger); lines land in the list."""
    lines: list[str] = []
    sys.stderr.flush()
    with tempfile.TemporaryFile(mode="w+b") as tmp:
        saved = os.dup(2)
        try:
            os.dup2(tmp.fileno(), 2)
            yield lines
        finally:
            os.dup2(saved, 2)
            os.close(saved)
            tmp.seek(0)
            lines.extend(tmp.read().decode(errors="replace").splitlines())


_ITER_LINE = re.compile(r"^\s*(\d+)\s+\S+\s+\S+\s*$")


def _tamaas_iterations(lines: list[str]) -> int | None:
    for line in reversed(lines):
        match = _ITER_LINE.match(line)
        if match:
            return int(match.group(1))
    return None


def _tamaas_solve(tm, solver, load: float) -> tuple[float, float, int | None]:
    """Run ``solver.solve(load)`` at info log level, timing it and reading the iteration count."""
    level = tm.get_log_level()
    tm.set_log_level(tm.LogLevel.info)
    try:
        with _captured_stderr() as lines:
            start = time.perf_counter()
            error = solver.solve(load)
            seconds = time.perf_counter() - start
    finally:
        tm.set_log_level(level)
    return float(error), seconds, _tamaas_iterations(lines)


# --------------------------------------------------------------------------------------------------------
# tamaas


def _tamaas_model(tm, h: np.ndarray, lx: float, ly: float, contact_modulus: float):
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [lx, ly], list(h.shape))
    model.E = float(contact_modulus)
    model.nu = 0.0
    return model


def tamaas_periodic(
    heights: np.ndarray,
    size: Sequence[float],
    contact_modulus: float,
    mean_pressure: float,
    tolerance: float,
) -> dict:
    """Periodic contact with tamaas's ``PolonskyKeerRey`` under mean-pressure control."""
    h, lx, ly = _check(heights, size, contact_modulus, mean_pressure, tolerance)
    tm = importlib.import_module("tamaas")
    model = _tamaas_model(tm, h, lx, ly, contact_modulus)
    solver = tm.PolonskyKeerRey(model, h, float(tolerance))
    solver.max_iter = _MAX_ITER
    error, seconds, iterations = _tamaas_solve(tm, solver, float(mean_pressure))
    pressure = np.array(model.traction, dtype=np.float64).reshape(h.shape)
    # model.displacement = u + c with zero-mean u and g = u - h + c >= 0, so delta = max(h) - c
    offset = float(np.mean(np.asarray(model.displacement)))
    return {
        "pressure": pressure,
        "iterations": iterations,
        "seconds": seconds,
        "approach": float(h.max()) - offset,
        "converged": error <= tolerance,
        "error": error,
    }


def tamaas_free_hertz(
    heights: np.ndarray,
    size: Sequence[float],
    contact_modulus: float,
    force: float,
    tolerance: float,
) -> dict:
    """Free-boundary (non-periodic) contact with tamaas's zero-padded operator under total-force control."""
    h, lx, ly = _check(heights, size, contact_modulus, force, tolerance)
    tm = importlib.import_module("tamaas")
    model = _tamaas_model(tm, h, lx, ly, contact_modulus)
    name = "roughcontact_free"
    tm.ModelFactory.registerNonPeriodic(model, name)  # after E and nu: the operator takes them now
    solver = tm.PolonskyKeerRey(model, h, float(tolerance))
    solver.setIntegralOperator(name)
    solver.max_iter = _MAX_ITER
    error, seconds, iterations = _tamaas_solve(tm, solver, float(force) / (lx * ly))
    pressure = np.array(model.traction, dtype=np.float64).reshape(h.shape)
    displacement = np.zeros_like(pressure)
    model.operators[name](pressure, displacement)  # the true displacement of the free half-space
    contact = pressure > 0
    offset = float(np.mean((displacement - h)[contact])) if contact.any() else float("nan")
    return {
        "pressure": pressure,
        "iterations": iterations,
        "seconds": seconds,
        "approach": float(h.max()) + offset,
        "converged": error <= tolerance,
        "error": error,
    }


# --------------------------------------------------------------------------------------------------------
# contactmechanics


def _contactmechanics_solve(substrate, h: np.ndarray, total_force: float, tolerance: float) -> dict:
    ccg = importlib.import_module("ContactMechanics.Optimization.ConstrainedConjugateGradients")
    area_per_pt = float(np.prod(substrate.physical_sizes)) / h.size
    rms = float(np.std(h))
    start = time.perf_counter()
    result = ccg.constrained_conjugate_gradients(
        substrate,
        h,
        external_force=total_force,
        pentol=tolerance * (rms if rms > 0 else 1.0),
        forcetol=tolerance * total_force / h.size,
        thermotol=tolerance,
        maxiter=_MAX_ITER,
    )
    seconds = time.perf_counter() - start
    pressure = np.array(result.jac, dtype=np.float64).reshape(h.shape) / area_per_pt
    max_pen = float(np.max(result.maxcv["max_pen"])) if hasattr(result, "maxcv") else float("nan")
    return {
        "pressure": pressure,
        "iterations": int(result.nit),
        "seconds": seconds,
        "approach": float(h.max()) + float(result.offset),
        "converged": bool(result.success),
        "error": max_pen / (rms if rms > 0 else 1.0),
    }


def contactmechanics_periodic(
    heights: np.ndarray,
    size: Sequence[float],
    contact_modulus: float,
    mean_pressure: float,
    tolerance: float,
) -> dict:
    """Periodic contact with ContactMechanics's constrained CG under total-force control."""
    h, lx, ly = _check(heights, size, contact_modulus, mean_pressure, tolerance)
    cm = importlib.import_module("ContactMechanics")
    substrate = cm.PeriodicFFTElasticHalfSpace(
        h.shape, float(contact_modulus), physical_sizes=(lx, ly), stiffness_q0=0.0
    )
    return _contactmechanics_solve(substrate, h, float(mean_pressure) * lx * ly, float(tolerance))


def contactmechanics_free_hertz(
    heights: np.ndarray,
    size: Sequence[float],
    contact_modulus: float,
    force: float,
    tolerance: float,
) -> dict:
    """Free-boundary contact with ContactMechanics's zero-padded Love kernel under total-force control."""
    h, lx, ly = _check(heights, size, contact_modulus, force, tolerance)
    cm = importlib.import_module("ContactMechanics")
    substrate = cm.FreeFFTElasticHalfSpace(h.shape, float(contact_modulus), physical_sizes=(lx, ly))
    return _contactmechanics_solve(substrate, h, float(force), float(tolerance))


# --------------------------------------------------------------------------------------------------------
# aspher


def _aspher_result(result, h: np.ndarray, seconds: float) -> dict:
    return {
        "pressure": np.array(result.pressure, dtype=np.float64).reshape(h.shape),
        "iterations": int(result.iterations),
        "seconds": seconds,
        "approach": float(h.max()) + float(result.approach),
        "converged": bool(result.converged),
        "error": max(float(result.fw_error), float(result.penetration_error)),
    }


def aspher_periodic(
    heights: np.ndarray,
    size: Sequence[float],
    contact_modulus: float,
    mean_pressure: float,
    tolerance: float,
    *,
    nested: bool = False,
) -> dict:
    """Periodic contact with aspher's spectral operator under mean-pressure control.

    ``nested=False`` runs ``ContactSolver(backend="periodic").solve`` with the full-grid FFT |q|
    preconditioner; ``nested=True`` runs ``solve_nested`` (coarse-to-fine; the grid side must then be
    64 * 2^k, its time includes its own coarse levels and ``iterations`` counts the finest level only).
    """
    h, lx, ly = _check(heights, size, contact_modulus, mean_pressure, tolerance)
    n = _square(h, lx, ly, "aspher")
    aspher = importlib.import_module("aspher")
    gap = np.ascontiguousarray(-h)
    if nested:
        start = time.perf_counter()
        result = aspher.solve_nested(
            grid_size=n,
            gap=gap.ravel(),
            p_nominal=float(mean_pressure),
            domain_size=lx,
            E_star=float(contact_modulus),
            backend="periodic",
            tol=float(tolerance),
            max_iter=_MAX_ITER,
        )
        return _aspher_result(result, h, time.perf_counter() - start)
    solver = aspher.ContactSolver(
        grid_size=n, domain_size=lx, E_star=float(contact_modulus), backend="periodic"
    )
    start = time.perf_counter()
    result = solver.solve(
        gap, p_nominal=float(mean_pressure), tol=float(tolerance), max_iter=_MAX_ITER, precond="fourier-fft"
    )
    return _aspher_result(result, h, time.perf_counter() - start)


def aspher_free_hertz(
    heights: np.ndarray,
    size: Sequence[float],
    contact_modulus: float,
    force: float,
    tolerance: float,
) -> dict:
    """Free-boundary contact with aspher's exact zero-padded Love operator (``backend="fft"``)."""
    h, lx, ly = _check(heights, size, contact_modulus, force, tolerance)
    n = _square(h, lx, ly, "aspher")
    aspher = importlib.import_module("aspher")
    solver = aspher.ContactSolver(grid_size=n, domain_size=lx, E_star=float(contact_modulus), backend="fft")
    gap = np.ascontiguousarray(-h)
    start = time.perf_counter()
    result = solver.solve(
        gap,
        p_nominal=float(force) / (lx * ly),
        tol=float(tolerance),
        max_iter=_MAX_ITER,
        precond="fourier-fft",
    )
    return _aspher_result(result, h, time.perf_counter() - start)


def tamaas_elastic_plastic(
    heights: np.ndarray,
    size: float,
    *,
    depth: float,
    layers: int,
    youngs_modulus: float,
    poissons_ratio: float,
    yield_strength: float,
    hardening_modulus: float,
    forces: Sequence[float],
    tolerance: float = 1e-7,
) -> dict:
    """Load-unload with tamaas' volume plasticity: ``EPICSolver`` on a ``volume_2d`` model (periodic only).

    tamaas 2.9.0's volume models are periodic (``registerNonPeriodic`` refuses them); the model grid is
    ``[depth, x, y]`` with ``layers`` planes from z = 0 to z = depth inclusive (uniform). Units inside:
    lengths over ``size``, stresses over E* (tamaas' natural units). ``IsotropicHardening`` material,
    ``DFSANECXXSolver`` for the plastic residual (with tamaas' ``ToleranceManager``), ``PolonskyKeerRey``
    for the contact, EPIC relaxation 0.3. EPIC rewrites the surface it is given (it holds h0 - u_res
    after a step), so the original heights are kept here and the approach is rebuilt as
    ``-max(h0 - u_el - u_res)`` with u_el the periodic (zero-mean) elastic displacement of the pressure
    and u_res the Mindlin displacement of the total plastic strain (zero mean).

    Returns ``approach`` [m], ``force`` [N], ``area`` [m^2] and ``seconds`` per step, and ``total``.
    """
    import tamaas as tm
    from tamaas.nonlinear_solvers import DFSANECXXSolver, ToleranceManager

    n = heights.shape[0]
    e_star = youngs_modulus / (1.0 - poissons_ratio**2)
    force_unit = e_star * size**2
    tm.set_log_level(tm.LogLevel.warning)
    model = tm.ModelFactory.createModel(tm.model_type.volume_2d, [depth / size, 1.0, 1.0], [layers, n, n])
    model.E = youngs_modulus / e_star
    model.nu = poissons_ratio
    material = tm.materials.IsotropicHardening(
        model, sigma_y=yield_strength / e_star, hardening=hardening_modulus / e_star
    )
    residual = tm.Residual(model, material)
    plastic = ToleranceManager(1e-5, 1e-9, 1 / 4)(DFSANECXXSolver)(residual)
    h0 = (heights - heights.max()) / size
    surface = h0.copy()
    contact = tm.PolonskyKeerRey(model, surface, 1e-12)
    epic = tm.EPICSolver(contact, plastic, tolerance, 0.3)
    elastic = tm.ModelFactory.createModel(tm.model_type.basic_2d, [1.0, 1.0], [n, n])
    elastic.E, elastic.nu = model.E, poissons_ratio
    out = {"approach": [], "force": [], "area": [], "seconds": []}
    for force in forces:
        start = time.perf_counter()
        if force > 0:
            epic.solve(force / force_unit)
        seconds = time.perf_counter() - start
        pressure = model.traction[..., 2].copy() if force > 0 else np.zeros((n, n))
        strain = np.asarray(model["plastic_strain"])
        eigenstress = np.zeros_like(strain)
        model.operators["hooke"](strain, eigenstress)
        lift = np.zeros(model.displacement.shape)
        model.operators["mindlin"](eigenstress, lift)
        elastic.traction[...] = pressure
        elastic.solveNeumann()
        deformed = h0 - elastic.displacement - lift[0, ..., 2]
        out["approach"].append(float(-deformed.max() * size))
        out["force"].append(float(force))
        out["area"].append(float(np.count_nonzero(pressure > 0) * size**2 / n**2))
        out["seconds"].append(seconds)
    out["total"] = float(np.sum(out["seconds"]))
    return out


# --------------------------------------------------------------------------------------------------------
# adhesive contact: hard wall plus an exponential attraction, under approach control (see ADHESIVE below)

ADHESIVE = """Adhesive adapters: ``{peer}_adhesive(heights, size, contact_modulus, work_of_adhesion, length,
approaches, tolerance, *, until_detached=True)``.

The problem (the same for every peer): a rigid surface ``heights`` (m, towards the body, periodic grid)
against an elastic half-space (Johnson's E* = ``contact_modulus``), a hard wall ``g >= 0`` and an
exponential attraction of energy per area ``phi(g) = -w exp(-g / rho)`` (``w = work_of_adhesion`` J/m^2,
``rho = length`` m; tension ``(w / rho) exp(-g / rho)``, ``w / rho`` at contact). Approach control:
``g = h0 - delta + u >= 0`` with ``h0 = max(h) - h``, ``u`` the elastic displacement (into the body, zero
mean over the periodic cell), ``delta`` = ``approaches[k]`` at step k (m, from first touch), each step
started from the previous state (the first from ``u = 0``), so the branch is followed through loading and
unloading. Returned dict: ``approach`` (m, the approaches solved), ``force`` (N per step, total over the
cell, compressive positive: the mean elastic pressure times the cell area), ``contact_fraction`` (points
at the wall), ``pull_off_force`` (N, ``-min(force)``: the most tensile force of the steps, no refinement),
``seconds`` (solve calls only), ``iterations`` (total), ``step_iterations``, ``converged`` (every step by
the peer's own verdict), ``step_converged``, ``detached`` and ``steps``. ``until_detached``: the programme
stops after the first step of a decreasing stroke that ends with no point at the wall once contact has
been made (the rest of the programme is out of contact); ``steps`` says how many were solved.

tamaas 2.9.0: ``PolonskyKeerRey(model, h, tolerance, gap, gap)`` (primal and constraint: the gap; hard
wall g >= 0; controlled by the MEAN GAP, ``solve(mean(h0) - delta)``: with the zero-mean periodic kernel
that is exactly approach control) plus ``ExponentialAdhesionFunctional`` added with ``addFunctionalTerm``,
``parameters = {"rho": rho, "surface_energy": w}``. Checked on the installed build: its functional is
``-w sum_i exp(-g_i / rho)`` and its gradient ``(w / rho) exp(-g_i / rho)`` per point (``w`` is the
energy per area at contact, the same w as ours, not 2 gamma), on the same per-point scale as the elastic
functional; ``model.traction`` is then the elastic pressure, equal to ``-(w / rho) exp(-g / rho)`` off
contact to 1e-12. The state (``model["gap"]``, the primal) is kept between solves; tamaas rescales it to
the new mean gap on entry. The first state is set here to the undeformed gap ``max(h0 - delta_0, 0)``:
left alone, tamaas starts from a uniform gap, i.e. a body already moulded on the surface, which sticks at
any approach. Error: tamaas' own, ``<= tolerance`` (the normal adapters' measure). Out of contact (no
point at the wall) that error is undefined (it divides by a vanishing sum) and the solve runs to
``max_iter``: such a step is reported as not converged by tamaas' verdict, though its force is right
(it matches contactmechanics), hence ``until_detached``. Free boundary: not tried with adhesion
(``registerNonPeriodic`` + ``setIntegralOperator`` serve the normal adapters; whether the gap formulation
and the adhesion functional honour them is unchecked), so the benchmark is periodic.

ContactMechanics 1.8.3 + Adhesion 0.93: ``Adhesion.System.BoundedSmoothContactSystem`` (hard wall as the
L-BFGS-B lower bound ``u >= h + offset``, i.e. ``g >= 0``; ``_lbounds_from_heights``) on a
``PeriodicFFTElasticHalfSpace`` with ``Adhesion.Interactions.Exponential(gamma0=w, rho)``, whose energy is
``V(g) = -gamma0 exp(-g / rho)`` (source: ``V(0) = -gamma0``, so ``gamma0`` IS the work of adhesion w,
not w / 2; its quadratic continuation for g < 0 is never used behind the wall). Minimiser: scipy
``L-BFGS-B`` on the displacements (as Adhesion's examples: ``maxcor=3``, ``ftol=0``), ``gtol = tolerance *
(w / rho) * pixel area`` (the largest force imbalance of a pixel relative to the peak tension, ours'
measure). Variable: the displacement, control: the rigid ``offset`` (``gap = u - h - offset``, ``delta =
max(h) + offset - mean(u)``). The mean mode of ``u`` has the stiffness ``stiffness_q0``: 0 would let the
body float (zero total force), and a large one stalls L-BFGS-B (x100 the top stiffness: 5x the
iterations, x1e4: 17x); so it is set to the top mode's stiffness ``pi E* q_max`` and the offset is
corrected for the small mean displacement it leaves (predicted from the previous steps, re-solved when
the approach solved misses the programme by more than ``1e-4 rho``), so the zero-mean convention above
holds. Iterations: L-BFGS-B's ``nit`` (``nfev``, one FFT pair each, also returned). Converged:
``result.success``. Free boundary: Adhesion's own examples pair ``FreeFFTElasticHalfSpace`` with these
systems; not tried here (the benchmark is periodic)."""


def adhesive_solvers(names: Sequence[str] | None = None) -> dict[str, Callable[..., dict]]:
    """Return {label: solve} of the adhesive peers that import (contactmechanics needs Adhesion too)."""
    found = {}
    for name in available_peers():
        if (names is not None and name not in names) or f"{name}_adhesive" not in globals():
            continue
        if name == "contactmechanics":
            try:
                importlib.import_module("Adhesion")
            except Exception:  # ContactMechanics without Adhesion: no adhesive peer
                continue
        found[name] = globals()[f"{name}_adhesive"]
    return found


def _adhesive_inputs(heights, size, contact_modulus, work_of_adhesion, length, approaches, tolerance):
    h, lx, ly = _check(heights, size, contact_modulus, 1.0, tolerance)
    for value, what in ((work_of_adhesion, "work_of_adhesion"), (length, "length")):
        if not (np.isfinite(value) and value > 0):
            raise ValueError(f"{what} must be positive and finite, got {value}")
    programme = np.asarray(approaches, dtype=np.float64).ravel()
    if programme.size == 0 or not np.all(np.isfinite(programme)):
        raise ValueError("approaches must be a non-empty sequence of finite approaches (m)")
    return h, lx, ly, programme


def _detached(programme: np.ndarray, k: int, touching: bool, touched: bool) -> bool:
    """True once a decreasing stroke has left contact (after contact was made)."""
    return touched and not touching and k > 0 and programme[k] < programme[k - 1]


def _adhesive_result(approach, force, contact, seconds, iterations, converged, detached, **extra) -> dict:
    force = np.array(force, dtype=np.float64)
    return {
        "approach": np.array(approach, dtype=np.float64),
        "force": force,
        "contact_fraction": np.array(contact, dtype=np.float64),
        "pull_off_force": float(max(-force.min(), 0.0)),
        "seconds": float(seconds),
        "iterations": int(sum(i for i in iterations if i is not None)),
        "step_iterations": list(iterations),
        "converged": bool(all(converged)),
        "step_converged": list(converged),
        "detached": bool(detached),
        "steps": len(force),
        **extra,
    }


def tamaas_adhesive(
    heights: np.ndarray,
    size: Sequence[float],
    contact_modulus: float,
    work_of_adhesion: float,
    length: float,
    approaches: Sequence[float],
    tolerance: float,
    *,
    until_detached: bool = True,
) -> dict:
    """Periodic adhesive contact with tamaas: ``PolonskyKeerRey`` (gap) + ``ExponentialAdhesionFunctional``.

    See :data:`ADHESIVE` for the problem, the conventions and what is returned.
    """
    h, lx, ly, programme = _adhesive_inputs(
        heights, size, contact_modulus, work_of_adhesion, length, approaches, tolerance
    )
    tm = importlib.import_module("tamaas")
    model = _tamaas_model(tm, h, lx, ly, contact_modulus)
    solver = tm.PolonskyKeerRey(model, h, float(tolerance), tm.PolonskyKeerRey.gap, tm.PolonskyKeerRey.gap)
    solver.max_iter = _MAX_ITER
    adhesion = tm.ExponentialAdhesionFunctional(h)
    adhesion.parameters = {"rho": float(length), "surface_energy": float(work_of_adhesion)}
    solver.addFunctionalTerm(adhesion)
    h0 = h.max() - h
    model["gap"][...] = np.maximum(h0 - programme[0], 0.0)  # start undeformed (u = 0), see ADHESIVE
    pixel_area = lx * ly / h.size
    approach, force, contact, iterations, converged = [], [], [], [], []
    seconds, touched, detached = 0.0, False, False
    for k, delta in enumerate(programme):
        error, step_seconds, step_iterations = _tamaas_solve(tm, solver, float(h0.mean() - delta))
        seconds += step_seconds
        gap = np.asarray(model["gap"])
        touching = bool(np.any(gap <= 0.0))
        approach.append(float(delta))
        force.append(float(np.sum(model.traction)) * pixel_area)
        contact.append(float(np.mean(gap <= 0.0)))
        iterations.append(step_iterations)
        converged.append(bool(error <= tolerance))
        if until_detached and _detached(programme, k, touching, touched):
            detached = True
            break
        touched = touched or touching
    return _adhesive_result(approach, force, contact, seconds, iterations, converged, detached)


def contactmechanics_adhesive(
    heights: np.ndarray,
    size: Sequence[float],
    contact_modulus: float,
    work_of_adhesion: float,
    length: float,
    approaches: Sequence[float],
    tolerance: float,
    *,
    until_detached: bool = True,
    approach_tolerance: float | None = None,
) -> dict:
    """Periodic adhesive contact with Adhesion's ``BoundedSmoothContactSystem`` (L-BFGS-B, hard wall bound).

    ``approach_tolerance`` (m, default ``1e-4 * length``): how closely the approach solved must match the
    programme (the mean-mode correction, see :data:`ADHESIVE`). Also returns ``function_evaluations``
    and ``corrections`` (extra solves for the mean mode).
    """
    h, lx, ly, programme = _adhesive_inputs(
        heights, size, contact_modulus, work_of_adhesion, length, approaches, tolerance
    )
    cm = importlib.import_module("ContactMechanics")
    optimize = importlib.import_module("scipy.optimize")
    topography_module = importlib.import_module("SurfaceTopography")
    interactions = importlib.import_module("Adhesion.Interactions")
    systems = importlib.import_module("Adhesion.System")
    nx, ny = h.shape
    q_max = np.hypot(nx / 2 / lx, ny / 2 / ly)  # cycles per metre, as ContactMechanics' kernel
    substrate = cm.PeriodicFFTElasticHalfSpace(
        h.shape, float(contact_modulus), physical_sizes=(lx, ly), stiffness_q0=np.pi * contact_modulus * q_max
    )
    topography = topography_module.Topography(h, (lx, ly), periodic=True)
    interaction = interactions.Exponential(float(work_of_adhesion), float(length))
    system = systems.BoundedSmoothContactSystem(substrate, interaction, topography)
    pixel_area = lx * ly / h.size
    options = {
        "gtol": float(tolerance) * work_of_adhesion / length * pixel_area,
        "ftol": 0.0,
        "maxcor": 3,
        "maxiter": _MAX_ITER,
        "maxfun": 2 * _MAX_ITER,
    }
    if approach_tolerance is None:
        approach_tolerance = 1e-4 * length
    top = float(h.max())
    u = np.zeros(h.shape)
    means: list[float] = []  # mean(u) of the steps solved
    approach, force, contact, iterations, evaluations, converged = [], [], [], [], [], []
    seconds, corrections, touched, detached = 0.0, 0, False, False
    for k, delta in enumerate(programme):
        mean = 2 * means[-1] - means[-2] if len(means) > 1 else (means[-1] if means else 0.0)  # predicted
        step_iterations = step_evaluations = 0
        for attempt in range(6):
            offset = float(delta) - top + mean
            start = time.perf_counter()
            result = optimize.minimize(
                system.objective(offset, gradient=True),
                u.ravel(),
                method="L-BFGS-B",
                jac=True,
                bounds=system._reshape_bounds(system._lbounds_from_heights(offset)),
                options=options,
            )
            seconds += time.perf_counter() - start
            step_iterations += int(result.nit)
            step_evaluations += int(result.nfev)
            u = result.x.reshape(h.shape)
            solved = top + offset - float(u.mean())
            if abs(solved - delta) <= approach_tolerance or attempt == 5:
                break
            corrections += 1
            mean = float(u.mean())
        system._update_state(offset, result)
        means.append(float(u.mean()))
        touching = bool(np.any(system.gap <= 0.0))
        approach.append(solved)
        force.append(float(system.compute_normal_force()))
        contact.append(float(np.mean(system.gap <= 0.0)))
        iterations.append(step_iterations)
        evaluations.append(step_evaluations)
        converged.append(bool(result.success))
        if until_detached and _detached(programme, k, touching, touched):
            detached = True
            break
        touched = touched or touching
    return _adhesive_result(
        approach,
        force,
        contact,
        seconds,
        iterations,
        converged,
        detached,
        function_evaluations=int(sum(evaluations)),
        corrections=corrections,
    )
