"""Tangential (partial-slip) contact: roughcontact's solve_tangential against its peers, side by side.

What is compared
----------------
Case 1, Cattaneo-Mindlin, monotonic: a smooth sphere (paraboloid, R = 10 mm, E* = 1 GPa) pressed on a
flat by P = 0.5 N, then loaded by Q = 0.5 mu P (mu = 0.3) from a virgin (frictionless-normal) state;
n x n grid over a 4a x 4a free (non-periodic) window (``--sizes``, default 64 128 256). Two problems,
because no one problem suits every peer (both have Dundurs beta = 0: normal and tangential uncoupled):

* [A] nu = 0, sphere and flat of the same material: Cattaneo's c/a = (1 - Q/mu P)^(1/3) is exact.
  ours: ``solve_normal(topo, m, counter_body=m, force=P)``, then ``solve_tangential(normal, m,
  counter_body=m, friction_coefficient=mu, force=[Q])``. aspher ``FrictionSolver(grid_size=n,
  domain_size=L, E_star=E*, nu=0, model=CoulombFriction(mu))`` (free boundary, zero-padded Love/Cerruti,
  uncoupled by design, history): ``set_gap(-h)``, ``step(p_bar=P/L^2, tol_normal=tol)``, then
  ``step(q_bar=(Q/L^2, 0), tol_tangential=tol, tol_normal=tol)``. aspher is not run on [B]: at
  nu = 0.3 and 0.5 its tangential CG did not converge (10^4 iterations, projected residual ~1e-2,
  steps refused or accepted as "local_kkt_near_tolerance"; measured at 32^2 and 64^2).
* [B] nu = 0.5 on a RIGID flat (E = E* (1 - nu^2)). tamaas's frictional solvers use the single body's
  Boussinesq-Cerruti kernel and so always couple normal and tangential unless nu = 0.5. ours as in [A]
  with ``counter_body=None``. tamaas ``PolonskyKeerTan(model, h, tol, mu)`` and ``Condat(model, h,
  tol, mu)`` on a ``surface_2d`` model, ``solve([qx, qy, p])`` (mean tractions): one-shot normal +
  tangential, no history, PERIODIC only (``registerNonPeriodic`` is refused for ``surface_2d``), so
  they run on a window ``--periodic-factor`` (default 2) times wider with the same pixel size (a
  2n x 2n grid, the size of our zero-padded free operator; at 8a the stick radius equals our free
  one), in units a = 1, E* = 1. ``Condat`` solves the associated Coulomb law (its docstring): not the
  same law; reported for completeness. Mindlin's c/a is approximate for nu != 0 (~+0.005 at 64^2).

Matched-accuracy rule. The accuracy is the stick radius c = sqrt(A_stick / pi), A_stick the area of
the contact points with |q| < (1 - 1e-6) mu p (one rule on every code's fields), against Cattaneo's
c/a (a = Hertz radius); each code's c/a error is printed. Every code runs a ladder of its own accuracy
knob: ours and aspher a tolerance (``--tolerances``, normal and tangential alike); tamaas an iteration
cap (``--tamaas-iterations``, ``--condat-iterations``) at tolerance 1e-12, because its stopping test
is unreliable here (at 1e-8 PolonskyKeerTan stopped with the mean tractions 10-45 % off target; below
~3e-9 it stalls and runs to ``max_iter``). A run is valid when its normal and tangential forces are
within 1e-5 of the targets (and the peer says converged, where it says); a code's MATCHED run is its
cheapest valid run whose c/a is within 1e-3 of that of its most accurate valid run (the stick radius
has converged in the solver's knob). Time ratios ours/peer compare matched runs on the same problem
(total: normal + tangential; tamaas cannot split them). Model/solver set-up is timed apart where the
peer separates it (ours builds its operators inside the calls, so they are in its times); solve times
are best of ``--repeats`` (one run when a run takes over 10 s).

Case 2, rough-ball loop (paper 001): a rough ball (``sphere_with_roughness``: R = 5 mm, rms 0.2 um,
H = 0.8, seed 1) at F0 = 1 N, mu = 0.15, driven along the paper's displacement path (``stroke_path``:
0 -> 3 um -> 0, ``--cycles`` 4, ``--steps-per-stroke`` 25, i.e. 200 steps) at 256^2 (and 512^2 with
``--large``) over a 4a window, free boundary. [A] nu = 0 pair with the E* of HDPE on a rigid flat:
ours (``solve_tangential(displacement=path, fields_at="none")``) and aspher's FrictionSolver
(``step(delta_t=(d, 0), tol_tangential=tol, tol_normal=tol)`` per step, history carried between
steps). [P] the paper's pair, HDPE (0.98 GPa, nu = 0.5) on a rigid flat: ours only. tamaas: n/a (no
history, no load path). Reported: ms per tangential step, seconds per loop and in total, iterations per
step, and the largest difference of the [A] force paths over mu F0 (the accuracy check; both codes at
``--loop-tolerance``).

Threads: aspher runs on ``OMP_NUM_THREADS`` threads, set to 1 here unless given (libgomp spinning on a
loaded machine), tamaas's wheel is serial; ours uses its default FFT threads. Peer versions are
printed. ``--quick``: Case 1 at 32^2 and 64^2, Case 2 at 64^2. Ends with one JSON line.

    python benchmarks/tangential.py [--sizes 64 128 256] [--quick] [--large] [--steps-per-stroke 25]
        [--loop-sizes 256 512] [--no-cattaneo] [--no-loop] [--no-peers] [--peers aspher]
        [--problems A P]
"""

from __future__ import annotations

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")  # aspher's OpenMP: before its first import

import argparse
import importlib
import importlib.metadata
import json
import platform
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _timing import best_of  # noqa: E402
from roughcontact.analytic import mindlin  # noqa: E402
from roughcontact.contact import (
    ShearSolver,
    solve_normal,  # noqa: E402
)
from roughcontact.contact.paths import stroke_path  # noqa: E402
from roughcontact.contact.tangential import solve_tangential  # noqa: E402
from roughcontact.materials import Material, contact_modulus, johnson_shear_modulus  # noqa: E402
from roughcontact.topography import generate  # noqa: E402

# Case 1
RADIUS, FORCE, MU, FRACTION, CONTACT_MODULUS, WINDOW = 10e-3, 0.5, 0.3, 0.5, 1e9, 4.0
STICK_EPS = 1e-6  # stick: |q| < (1 - STICK_EPS) mu p
FORCE_RTOL = 1e-5  # a run is valid when its forces are this close to the targets
MATCH = 1e-3  # c/a within this of the code's most accurate valid run
TAMAAS_TOL = 1e-12
LONG_RUN = 10.0  # s: no repeats beyond this
# Case 2 (paper 001)
BALL_RADIUS, F0, MU_LOOP, STROKE, RMS = 5e-3, 1.0, 0.15, 3e-6, 0.2e-6


def _module(name):
    try:
        return importlib.import_module(name)
    except Exception:  # an absent peer is reported as such
        return None


def _version(dist: str) -> str | None:
    try:
        return importlib.metadata.version(dist)
    except importlib.metadata.PackageNotFoundError:
        return None


def _timed(function, repeats: int) -> tuple[float, object]:
    """best_of, but a single run when the first takes more than LONG_RUN seconds."""
    seconds, result = best_of(function, 1)
    if repeats > 1 and seconds < LONG_RUN:
        more, result = best_of(function, repeats - 1)
        seconds = min(seconds, more)
    return seconds, result


def _stick_radius(pressure, qx, qy, pixel_area, contact_radius) -> float:
    """c/a with c = sqrt(A_stick / pi); stick: p > 0 and |q| < (1 - STICK_EPS) mu p."""
    stick = (pressure > 0) & (np.hypot(qx, qy) < (1 - STICK_EPS) * MU * pressure)
    return float(np.sqrt(stick.sum() * pixel_area / np.pi) / contact_radius)


def _matched(runs: list[dict]) -> dict | None:
    """The cheapest valid run whose c/a is within MATCH of the most accurate valid run (the last)."""
    valid = [r for r in runs if r["valid"]]
    if not valid:
        return None
    best = valid[-1]["c_over_a"]
    candidates = [r for r in valid if abs(r["c_over_a"] - best) <= MATCH]
    return min(candidates, key=lambda r: r["total_seconds"])


# --------------------------------------------------------------------------------------------------------
# Case 1: Cattaneo-Mindlin


class Cattaneo:
    def __init__(self, n: int, problem: str):
        """``problem``: "A" (nu = 0, sphere and flat of the same material) or "B" (nu = 0.5, rigid flat)."""
        self.n, self.problem = n, problem
        self.poisson = 0.0 if problem == "A" else 0.5
        scale = 2.0 if problem == "A" else 1.0  # E* = E / (scale (1 - nu^2)) = CONTACT_MODULUS
        self.material = Material(scale * CONTACT_MODULUS * (1 - self.poisson**2), self.poisson, "sphere")
        self.counter = self.material if problem == "A" else None
        self.modulus = contact_modulus(self.material, self.counter)
        self.a = mindlin.hertz_contact_radius(FORCE, RADIUS, self.modulus)
        self.size = WINDOW * self.a
        self.topography = generate.sphere((n, n), (self.size, self.size), radius=RADIUS, kind="paraboloid")
        self.q = FRACTION * MU * FORCE
        self.expected = (1 - FRACTION) ** (1 / 3)

    # ours ------------------------------------------------------------------------------------------------
    def ours(self, tolerance: float, repeats: int) -> dict:
        topo, material, counter = self.topography, self.material, self.counter
        normal_s, normal = _timed(
            lambda: solve_normal(topo, material, counter_body=counter, force=FORCE, tolerance=tolerance),
            repeats,
        )
        tan_s, result = _timed(
            lambda: solve_tangential(
                normal,
                material,
                counter_body=counter,
                friction_coefficient=MU,
                force=[self.q],
                fields_at="last",
                solver=ShearSolver(tolerance=tolerance),
            ),
            repeats,
        )
        state = result.states[0]
        pixel = self.size**2 / self.n**2
        c = _stick_radius(state.pressure, state.shear_x, state.shear_y, pixel, self.a)
        errors = (abs(normal.force / FORCE - 1), abs(result.force[0, 0] / self.q - 1))
        return {
            "knob": f"tol {tolerance:g}",
            "setup_seconds": None,  # inside the calls (kernels, FFT plans)
            "normal_seconds": normal_s,
            "tangential_seconds": tan_s,
            "total_seconds": normal_s + tan_s,
            "iterations": int(normal.iterations) + int(result.iterations.sum()),
            "normal_iterations": int(normal.iterations),
            "tangential_iterations": int(result.iterations.sum()),
            "c_over_a": c,
            "c_error": c - self.expected,
            "own_stick_c_over_a": float(np.sqrt(result.stick_area[0] / np.pi) / self.a),
            "force_error": max(errors),
            "valid": max(errors) <= FORCE_RTOL,
        }

    # tamaas ----------------------------------------------------------------------------------------------
    def tamaas(self, solver_name: str, max_iter: int, repeats: int, factor: int) -> dict:
        """Periodic, window factor * 4a with the same pixels, units a = 1, E* = 1."""
        tm = importlib.import_module("tamaas")
        peers = importlib.import_module("peers")
        n_p = factor * self.n
        window = factor * WINDOW  # in units of a
        start = time.perf_counter()
        topo = generate.sphere((n_p, n_p), (window, window), radius=RADIUS / self.a, kind="paraboloid")
        h = topo.heights - topo.heights.mean()
        model = tm.ModelFactory.createModel(tm.model_type.surface_2d, [window, window], [n_p, n_p])
        model.E = 1.0 - self.poisson**2  # E* = E / (1 - nu^2) = 1
        model.nu = self.poisson
        solver = getattr(tm, solver_name)(model, h, TAMAAS_TOL, MU)
        solver.max_iter = int(max_iter)
        setup = time.perf_counter() - start
        p_scale = self.modulus  # tractions in units of E*
        pz = FORCE / (self.size * factor) ** 2 / p_scale
        target = [FRACTION * MU * pz, 0.0, pz]
        iterations: list = [None]

        def solve():
            model.traction[...] = 0.0  # no warm start between repeats
            model.displacement[...] = 0.0
            level = tm.get_log_level()
            tm.set_log_level(tm.LogLevel.info)
            try:
                with peers._captured_stderr() as lines, peers._silenced_fd(1):  # its header is on stdout
                    error = solver.solve(target)
            finally:
                tm.set_log_level(level)
            iterations[0] = peers._tamaas_iterations(lines)
            return error

        seconds, error = _timed(solve, repeats)
        traction = np.array(model.traction, dtype=np.float64).reshape(n_p, n_p, 3)
        qx, qy, p = traction[..., 0], traction[..., 1], traction[..., 2]
        c = _stick_radius(p, qx, qy, (window / n_p) ** 2, 1.0)
        errors = (abs(p.mean() / pz - 1), abs(qx.mean() / target[0] - 1))
        converged = error is not None and float(error) <= TAMAAS_TOL
        return {
            "knob": f"max_iter {max_iter}",
            "setup_seconds": setup,
            "normal_seconds": None,  # one-shot: normal and tangential together
            "tangential_seconds": None,
            "total_seconds": seconds,
            # the log prints every 100 iterations: the cap when it did not converge
            "iterations": int(max_iter) if not converged else iterations[0],
            "c_over_a": c,
            "c_error": c - self.expected,
            "own_error": None if error is None else float(error),
            "force_error": max(errors),
            "valid": max(errors) <= FORCE_RTOL,
            "boundary": f"periodic, window {window:g} a, {n_p}^2",
        }

    # aspher ----------------------------------------------------------------------------------------------
    def aspher(self, tolerance: float, repeats: int) -> dict:
        aspher = importlib.import_module("aspher")
        n, size = self.n, self.size
        h = self.topography.heights - self.topography.heights.mean()
        gap = np.ascontiguousarray(-h)
        start = time.perf_counter()
        solver = aspher.FrictionSolver(
            grid_size=n,
            domain_size=size,
            E_star=self.modulus,
            nu=self.poisson,
            model=aspher.CoulombFriction(MU),
        )
        solver.set_gap(gap)
        setup = time.perf_counter() - start
        p_bar, q_bar = FORCE / size**2, self.q / size**2

        def normal():
            solver.set_gap(gap)  # resets the history
            return solver.step(p_bar=p_bar, tol_normal=tolerance)

        def both():
            first = normal()
            start = time.perf_counter()
            second = solver.step(q_bar=(q_bar, 0.0), tol_tangential=tolerance, tol_normal=tolerance)
            return time.perf_counter() - start, first, second

        normal_s, first = _timed(normal, repeats)
        tan_s = np.inf  # the normal step re-done before each tangential one is not timed
        for _ in range(max(repeats, 1)):
            seconds, first, second = both()
            tan_s = min(tan_s, seconds)
            if seconds > LONG_RUN:
                break
        pressure = np.asarray(solver.pressure, dtype=np.float64).reshape(n, n)
        qx = np.asarray(second.qx, dtype=np.float64).reshape(n, n)
        qy = np.asarray(second.qy, dtype=np.float64).reshape(n, n)
        c = _stick_radius(pressure, qx, qy, (size / n) ** 2, self.a)
        errors = (abs(pressure.mean() / p_bar - 1), abs(qx.mean() / q_bar - 1))
        ok = bool(first.converged) and bool(second.converged)
        return {
            "knob": f"tol {tolerance:g}",
            "setup_seconds": setup,
            "normal_seconds": normal_s,
            "tangential_seconds": tan_s,
            "total_seconds": normal_s + tan_s,
            "iterations": int(first.normal_iters) + int(second.tangential_iters) + int(second.normal_iters),
            "normal_iterations": int(first.normal_iters),
            "tangential_iterations": int(second.tangential_iters),
            "c_over_a": c,
            "c_error": c - self.expected,
            "converged": ok,
            "force_error": max(errors),
            "valid": ok and max(errors) <= FORCE_RTOL,
        }


def cattaneo_case(n: int, args, available: dict) -> dict:
    """Problem A (nu = 0 pair): ours and aspher; problem B (nu = 0.5, rigid flat): ours and tamaas."""
    case = Cattaneo(n, "A")
    codes: dict[str, list[dict]] = {"ours [A]": [case.ours(t, args.repeats) for t in args.tolerances]}
    if available.get("aspher"):
        runs = []
        for tolerance in args.tolerances:
            try:
                runs.append(case.aspher(tolerance, args.repeats))
            except Exception as error:
                runs.append({"knob": f"tol {tolerance:g}", "failed": repr(error), "valid": False})
        codes["aspher.FrictionSolver [A]"] = runs
    expected = case.expected
    contact_radius_pixels = case.a / (case.size / n)
    case = Cattaneo(n, "B")
    codes["ours [B]"] = [case.ours(t, args.repeats) for t in args.tolerances]
    if available.get("tamaas"):
        for name, ladder in (("PolonskyKeerTan", args.tamaas_iterations), ("Condat", args.condat_iterations)):
            runs = []
            for max_iter in ladder:
                try:
                    runs.append(case.tamaas(name, max_iter, args.repeats, args.periodic_factor))
                except Exception as error:  # report, do not abort the benchmark
                    runs.append({"knob": f"max_iter {max_iter}", "failed": repr(error), "valid": False})
            codes[f"tamaas.{name} [B]"] = runs
    matched = {name: _matched(runs) for name, runs in codes.items()}
    ratios = {}
    for name, run in matched.items():
        ours = matched[f"ours [{name[-2]}]"]
        if not name.startswith("ours") and run is not None and ours is not None:
            ratios[name] = ours["total_seconds"] / run["total_seconds"]
    return {
        "case": f"Cattaneo {n}^2",
        "n": n,
        "contact_radius_pixels": contact_radius_pixels,
        "expected_c_over_a": expected,
        "runs": codes,
        "matched": {k: (None if v is None else v["knob"]) for k, v in matched.items()},
        "time_ratio_ours_over_peer": ratios,
    }


def _print_cattaneo(row: dict) -> None:
    print(
        f"\n{row['case']}: a = {row['contact_radius_pixels']:.1f} px, "
        f"Cattaneo c/a = {row['expected_c_over_a']:.4f}",
        flush=True,
    )
    print(
        f"  {'code':<28} {'knob':<15} {'setup s':>8} {'normal s':>9} {'tang s':>9} {'total s':>9} "
        f"{'iter':>6} {'c/a':>7} {'c/a err':>8} {'F err':>8}  note"
    )

    def fmt(value, spec):
        return format(value, spec) if value is not None else "-".rjust(len(format(0.0, spec)))

    for name, runs in row["runs"].items():
        for run in runs:
            if "failed" in run:
                print(f"  {name:<28} {run['knob']:<15} FAILED {run['failed']}")
                continue
            note = []
            if row["matched"].get(name) == run["knob"]:
                note.append("MATCHED")
            if not run["valid"]:
                note.append("invalid (forces)" if run.get("converged", True) else "not converged")
            if "boundary" in run:
                note.append(run["boundary"])
            iterations = run["iterations"]
            print(
                f"  {name:<28} {run['knob']:<15} {fmt(run['setup_seconds'], '8.3f')} "
                f"{fmt(run['normal_seconds'], '9.3f')} {fmt(run['tangential_seconds'], '9.3f')} "
                f"{run['total_seconds']:9.3f} {iterations if iterations is not None else '-':>6} "
                f"{run['c_over_a']:7.4f} {run['c_error']:+8.4f} {run['force_error']:8.1e}  {', '.join(note)}"
            )
    text = "  ".join(f"{k}: {v:.3g}" for k, v in row["time_ratio_ours_over_peer"].items())
    print(f"  time ratio ours/peer (matched runs, total): {text or 'n/a'}", flush=True)


# --------------------------------------------------------------------------------------------------------
# Case 2: rough-ball loop


def _ours_loop(topo, material, counter, path, cycles, tol) -> tuple[dict, np.ndarray]:
    start = time.perf_counter()
    normal = solve_normal(topo, material, counter_body=counter, force=F0, tolerance=tol)
    normal_s = time.perf_counter() - start
    start = time.perf_counter()
    result = solve_tangential(
        normal,
        material,
        counter_body=counter,
        friction_coefficient=MU_LOOP,
        displacement=path,
        fields_at="none",
        solver=ShearSolver(tolerance=tol),
    )
    loop_s = time.perf_counter() - start
    steps = len(path)
    return {
        "normal_seconds": normal_s,
        "total_seconds": loop_s,
        "ms_per_step": 1e3 * loop_s / steps,
        "seconds_per_loop": loop_s / cycles,
        "iterations_per_step": float(np.mean(result.iterations)),
        "max_iterations_step": int(np.max(result.iterations)),
        "coupling_passes_per_step": float(np.mean(result.coupling_iterations)),
        "normal_iterations": int(normal.iterations),
        "contact_fraction": float(normal.contact_fraction),
    }, result.force[:, 0]


def loop_case(n: int, args, available: dict) -> dict:
    """Problem A (nu = 0, ball and flat of one material, E* of HDPE on a rigid flat): ours and aspher;
    problem P (the paper's: HDPE, nu = 0.5, on a rigid flat): ours only (aspher fails at nu != 0)."""
    hdpe = Material(0.98e9, 0.5, "HDPE")
    modulus = contact_modulus(hdpe, None)
    pair = Material(2.0 * modulus, 0.0, "nu = 0 pair")  # E* = E / 2 = modulus
    a = mindlin.hertz_contact_radius(F0, BALL_RADIUS, modulus)
    size = WINDOW * a
    topo = generate.sphere_with_roughness((n, n), (size, size), radius=BALL_RADIUS, rms_height=RMS, seed=1)
    path = stroke_path(STROKE, cycles=args.cycles, steps_per_stroke=args.steps_per_stroke)
    steps, tol = len(path), args.loop_tolerance
    codes = {}
    if "A" in args.problems:
        codes["ours [A]"], ours_force = _ours_loop(topo, pair, pair, path, args.cycles, tol)
    if "P" in args.problems:
        codes["ours [P]"], _ = _ours_loop(topo, hdpe, None, path, args.cycles, tol)
    row = {
        "case": f"rough-ball loop {n}^2",
        "n": n,
        "steps": steps,
        "cycles": args.cycles,
        "tolerance": tol,
        "delta_0_um": 1e6 * mindlin.sliding_displacement(MU_LOOP, F0, a, johnson_shear_modulus(pair, pair)),
        "codes": codes,
    }
    if available.get("tamaas"):
        row["codes"]["tamaas"] = {"n/a": "one-shot solvers without history (no load path)"}
    if available.get("aspher") and "A" in args.problems:
        aspher = importlib.import_module("aspher")
        start = time.perf_counter()
        solver = aspher.FrictionSolver(
            grid_size=n, domain_size=size, E_star=modulus, nu=0.0, model=aspher.CoulombFriction(MU_LOOP)
        )
        h = topo.heights - topo.heights.mean()
        solver.set_gap(np.ascontiguousarray(-h))
        setup = time.perf_counter() - start
        start = time.perf_counter()
        first = solver.step(p_bar=F0 / size**2, tol_normal=tol)
        a_normal_s = time.perf_counter() - start
        forces, iterations, reasons = np.full(steps, np.nan), np.zeros(steps, dtype=int), []
        start = time.perf_counter()
        for i, d in enumerate(path):
            r = solver.step(delta_t=(float(d), 0.0), tol_tangential=tol, tol_normal=tol)
            iterations[i] = int(r.tangential_iters)
            if r.converged:
                forces[i] = float(np.asarray(r.q_mean)[0]) * size**2
            else:
                reasons.append(f"step {i}: {r.status_reason}")
        a_loop_s = time.perf_counter() - start
        # the sign convention may differ (force on the ball or on the flat): align on the first step
        sign = 1.0 if np.nan_to_num(forces[0]) * ours_force[0] >= 0 else -1.0
        difference = (
            float(np.nanmax(np.abs(sign * forces - ours_force)) / (MU_LOOP * F0))
            if len(reasons) < steps
            else None
        )
        row["codes"]["aspher.FrictionSolver [A]"] = {
            "setup_seconds": setup,
            "normal_seconds": a_normal_s,
            "normal_iterations": int(first.normal_iters),
            "total_seconds": a_loop_s,
            "ms_per_step": 1e3 * a_loop_s / steps,
            "seconds_per_loop": a_loop_s / args.cycles,
            "iterations_per_step": float(np.mean(iterations)),
            "max_iterations_step": int(np.max(iterations)),
            "failed_steps": len(reasons),
            "failures": reasons[:5],
            "force_sign": sign,
            "max_force_difference_over_mu_F0": difference,
            "time_ratio_ours_over_peer": codes["ours [A]"]["total_seconds"] / a_loop_s,
        }
    return row


def _print_loop(row: dict) -> None:
    print(
        f"\n{row['case']}: {row['steps']} steps ({row['cycles']} cycles), tolerance {row['tolerance']:g}, "
        f"contact fraction {next(iter(row['codes'].values()))['contact_fraction']:.3f}, delta_0 (smooth, A) "
        f"{row['delta_0_um']:.2f} um",
        flush=True,
    )
    print(
        f"  {'code':<28} {'normal s':>9} {'total s':>9} {'ms/step':>9} {'s/loop':>8} {'it/step':>8} "
        f"{'max it':>7}  note"
    )
    for name, code in row["codes"].items():
        if "n/a" in code:
            print(f"  {name:<28} n/a: {code['n/a']}")
            continue
        note = []
        if "max_force_difference_over_mu_F0" in code:
            difference = code["max_force_difference_over_mu_F0"]
            note.append(
                f"max |F - F_ours[A]| / mu F0 = {'n/a' if difference is None else format(difference, '.1e')}"
            )
            note.append(f"failed steps {code['failed_steps']}")
            note.append(f"ratio ours[A]/peer {code['time_ratio_ours_over_peer']:.3g}")
            note.extend(code["failures"][:1])
        print(
            f"  {name:<28} {code['normal_seconds']:9.3f} {code['total_seconds']:9.3f} "
            f"{code['ms_per_step']:9.2f} {code['seconds_per_loop']:8.3f} {code['iterations_per_step']:8.1f} "
            f"{code['max_iterations_step']:7d}  "
            f"{'; '.join(note)}",
            flush=True,
        )


# --------------------------------------------------------------------------------------------------------


PEERS = ("tamaas", "aspher")


def warm_up() -> float:
    """A 32^2 normal + tangential solve: numba compilation is not timed in the first case."""
    start = time.perf_counter()
    for problem in "AB":
        Cattaneo(32, problem).ours(1e-8, 1)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[64, 128, 256], help="Case 1 grids")
    parser.add_argument("--quick", action="store_true", help="Case 1 at 32^2 and 64^2, Case 2 at 64^2")
    parser.add_argument("--large", action="store_true", help="Case 2 at 512^2 too")
    parser.add_argument("--loop-sizes", type=int, nargs="+", default=None, help="Case 2 grids (default 256)")
    parser.add_argument("--steps-per-stroke", type=int, default=25)
    parser.add_argument("--cycles", type=int, default=4)
    parser.add_argument("--tolerances", type=float, nargs="+", default=[1e-4, 1e-6, 1e-8, 1e-10])
    parser.add_argument("--tamaas-iterations", type=int, nargs="+", default=[100, 300, 1000])
    parser.add_argument("--condat-iterations", type=int, nargs="+", default=[300, 1000, 3000])
    parser.add_argument("--periodic-factor", type=int, default=2, help="tamaas window / our window")
    parser.add_argument("--loop-tolerance", type=float, default=1e-8)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--no-peers", action="store_true")
    parser.add_argument("--peers", nargs="+", choices=PEERS, help="only these peers (default: both)")
    parser.add_argument("--no-loop", action="store_true")
    parser.add_argument("--problems", nargs="+", choices=("A", "P"), default=["A", "P"], help="Case 2: A, P")
    parser.add_argument("--no-cattaneo", action="store_true", help="skip Case 1")
    args = parser.parse_args()
    sizes = [] if args.no_cattaneo else [32, 64] if args.quick else args.sizes
    loop_sizes = args.loop_sizes or ([64] if args.quick else [256] + ([512] if args.large else []))
    available = {}
    if not args.no_peers:
        available = {name: _module(name) is not None for name in args.peers or PEERS}
    versions = {
        "roughcontact": _version("roughcontact"),
        "tamaas": _version("tamaas"),
        "aspher": _version("aspher"),
        "numpy": np.__version__,
    }
    warm_up_seconds = warm_up()
    print(
        f"tangential contact, {os.cpu_count()} CPUs, {platform.processor() or platform.machine()}; "
        f"OMP_NUM_THREADS={os.environ.get('OMP_NUM_THREADS')}; warm-up (JIT) {warm_up_seconds:.2f} s",
        flush=True,
    )
    print("versions: " + ", ".join(f"{k} {v}" for k, v in versions.items()), flush=True)
    print(
        f"Case 1: Cattaneo-Mindlin, smooth sphere, Q = {FRACTION} mu P, mu = {MU}; [A] nu = 0, same material "
        "(exact Cattaneo; ours, aspher), [B] nu = 0.5 on a rigid flat (ours, tamaas: periodic); "
        f"c/a from |q| < (1 - {STICK_EPS:g}) mu p; MATCHED = cheapest run with forces within "
        f"{FORCE_RTOL:g} and "
        f"c/a within {MATCH:g} of the code's most accurate run",
        flush=True,
    )
    cattaneo_rows = []
    for n in sizes:
        cattaneo_rows.append(cattaneo_case(n, args, available))
        _print_cattaneo(cattaneo_rows[-1])
    loop_rows = []
    if not args.no_loop:
        print(
            f"\nCase 2: rough ball (R = {BALL_RADIUS * 1e3:g} mm, rms {RMS * 1e6:g} um), E* of HDPE on a "
            f"rigid flat, F0 = {F0:g} N, mu = {MU_LOOP}, stroke {STROKE * 1e6:g} um (paper 001 path), "
            "free boundary; "
            "[A] nu = 0 pair (ours, aspher), [P] HDPE nu = 0.5 on a rigid flat (ours)",
            flush=True,
        )
        for n in loop_sizes:
            loop_rows.append(loop_case(n, args, available))
            _print_loop(loop_rows[-1])
    print(
        json.dumps(
            {
                "benchmark": "tangential",
                "versions": versions,
                "cpus": os.cpu_count(),
                "omp_num_threads": os.environ.get("OMP_NUM_THREADS"),
                "warm_up_seconds": warm_up_seconds,
                "cattaneo": cattaneo_rows,
                "loop": loop_rows,
            },
            default=lambda o: o.item() if hasattr(o, "item") else str(o),  # numpy scalars
        )
    )


if __name__ == "__main__":
    main()
