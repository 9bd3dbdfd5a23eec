"""The normal contact engine on a GPU: periodic self-affine solves from 2048^2 up, beside the CPU engine.

Per grid: a self-affine surface (H = 0.8, rms slope 0.1, the same family as
``benchmarks/normal_contact.py``) drawn on the GPU (spectral synthesis with CuPy: a 32768^2 draw
on the CPU would take longer than its solve), pressed at a mean pressure of 0.005 E* (a few
percent of contact), solved by :func:`roughcontact.contact.solve_normal` with ``device="gpu"``
at ``--tolerance`` (default 1e-8). Columns: the first solve's wall time (cuFFT plans, the
cascade's coarse operators and the kernels' compilation at the first grid included), a second
solve's (what a load path's later steps cost), iterations of the finest level, the peak of
GPU memory held by CuPy's pool during the solve (the pool emptied first), and, where the CPU
engine solves the same surface too (``--cpu-up-to``), its time on all the machine's cores and
the largest pressure difference relative to the peak. ``--single`` grids are solved again with
float32 fields (``precision="single"``) at ``--single-tolerance``; the row gives their time,
memory and the largest difference to the float64 answer. Times are end to end: the host's share
(the separation, the copies to and from the device, the result's fields) is in them.

    python benchmarks/gpu.py [--sizes 2048 4096 8192 16384 32768] [--cpu-up-to 4096]
        [--single 16384 32768] [--tolerance 1e-8] [--json FILE]

Ends with one JSON line (also written to ``--json``). Needs a CUDA GPU and CuPy
(``pip install .[gpu]``).
"""

from __future__ import annotations

import argparse
import gc
import json
import os
import time

import numpy as np

from roughcontact._device import gpu_module
from roughcontact.contact import solve_normal
from roughcontact.errors import ConvergenceError
from roughcontact.topography import Topography

CONTACT_MODULUS = 1e9
RMS_SLOPE = 0.1
HURST = 0.8
SIZE = 1e-4  # m, the side of every grid: finer grids resolve shorter wavelengths
PRESSURE = 0.005 * CONTACT_MODULUS


def surface(n: int, seed: int) -> Topography:
    """Return a periodic self-affine n x n surface (H = 0.8, rms slope 0.1), drawn on the GPU.

    Spectral synthesis: Gaussian Fourier coefficients with the power spectrum q^-2(1+H) above the
    lowest wavevector, the mean mode zero, scaled to the rms slope by the spectral slope sum
    (the same statistics as :func:`roughcontact.topography.generate.self_affine`, not its draw).
    """
    cp = gpu_module().cupy
    rng = cp.random.RandomState(seed)
    q_x = 2 * np.pi * cp.fft.fftfreq(n, d=SIZE / n)[:, None]
    q_y = 2 * np.pi * cp.fft.rfftfreq(n, d=SIZE / n)[None, :]
    q_squared = q_x**2 + q_y**2
    q_squared[0, 0] = 1.0
    amplitude = q_squared ** (-(1 + HURST) / 2)
    amplitude[0, 0] = 0.0
    coefficients = (
        rng.standard_normal(amplitude.shape) + 1j * rng.standard_normal(amplitude.shape)
    ) * amplitude
    del amplitude
    heights = cp.fft.irfft2(coefficients, s=(n, n))
    del coefficients
    dx = SIZE / n
    slope_x = (cp.roll(heights, -1, axis=0) - heights) / dx
    slope_squared = float((slope_x**2).mean())
    del slope_x
    slope_y = (cp.roll(heights, -1, axis=1) - heights) / dx
    slope_squared += float((slope_y**2).mean())
    del slope_y
    heights *= RMS_SLOPE / np.sqrt(slope_squared)
    host = heights.get()
    del heights
    _release()
    return Topography(host, (SIZE, SIZE), periodic=True)


def _release() -> None:
    cp = gpu_module().cupy
    cp.get_default_memory_pool().free_all_blocks()
    cp.fft.config.get_plan_cache().clear()


def _gpu_solve(topography: Topography, tolerance: float, precision: str = "double"):
    """Return (result, seconds, peak GPU bytes held by the pool)."""
    cp = gpu_module().cupy
    _release()
    pool = cp.get_default_memory_pool()
    start = time.perf_counter()
    result = solve_normal(
        topography,
        CONTACT_MODULUS,
        mean_pressure=PRESSURE,
        tolerance=tolerance,
        device="gpu",
        precision=precision,
    )
    cp.cuda.Device().synchronize()
    return result, time.perf_counter() - start, pool.total_bytes()


def _solved(topography, tolerance, precision="double"):
    """Solve at ``tolerance``, or at twice the round-off floor where the solver stalls above it."""
    try:
        return (*_gpu_solve(topography, tolerance, precision), tolerance)
    except ConvergenceError as error:
        floor = error.stalled_at if error.stalled_at is not None else error.residual
        looser = float(f"{2 * floor:.0e}")
        print(f"  {precision} stalled at {floor:.2g} above {tolerance:g}: solved at {looser:g}", flush=True)
        return (*_gpu_solve(topography, looser, precision), looser)


def row(n: int, args) -> dict:
    """Solve the n x n case; return its row."""
    topography = surface(n, seed=n)
    result, first, memory, tolerance = _solved(topography, args.tolerance)
    second = None
    if n <= args.second_up_to:
        _, second, _ = _gpu_solve(topography, tolerance)
    entry = {
        "n": n,
        "tolerance": tolerance,
        "first_seconds": first,
        "second_seconds": second,
        "iterations": result.iterations,
        "residual": result.residual,
        "contact_fraction": result.contact_area / topography.area,
        "gpu_gb": memory / 1e9,
    }
    if n <= args.cpu_up_to:
        start = time.perf_counter()
        cpu = solve_normal(
            topography, CONTACT_MODULUS, mean_pressure=PRESSURE, tolerance=tolerance, device="cpu"
        )
        entry["cpu_seconds"] = time.perf_counter() - start
        entry["cpu_iterations"] = cpu.iterations
        entry["cpu_difference"] = float(np.abs(cpu.pressure - result.pressure).max() / cpu.pressure.max())
    if n in args.single:
        single, seconds, memory, single_tolerance = _solved(topography, args.single_tolerance, "single")
        entry["single"] = {
            "tolerance": single_tolerance,
            "seconds": seconds,
            "iterations": single.iterations,
            "gpu_gb": memory / 1e9,
            "difference": float(np.abs(single.pressure - result.pressure).max() / result.pressure.max()),
        }
    return entry


def _single_alone(n: int, args) -> dict:
    """Solve the n x n case with float32 fields only (its float64 solve did not fit)."""
    topography = surface(n, seed=n)
    try:
        single, seconds, memory, tolerance = _solved(topography, args.single_tolerance, "single")
    except Exception as error:
        print(f"{n:>6}^2 float32 failed too: {type(error).__name__}: {str(error)[:200]}", flush=True)
        return {"error": f"{type(error).__name__}: {str(error)[:500]}"}
    entry = {
        "tolerance": tolerance,
        "seconds": seconds,
        "iterations": single.iterations,
        "gpu_gb": memory / 1e9,
    }
    print(
        f"{n:>6}^2 float32 fields alone, tolerance {tolerance:.0e}: {seconds:.2f} s, {single.iterations} "
        f"iterations, {memory / 1e9:.1f} GB",
        flush=True,
    )
    return entry


def _timed(function, repeats: int = 5) -> float:
    """Median seconds of ``function`` on the device (synchronised around each call)."""
    cp = gpu_module().cupy
    function()
    times = []
    for _ in range(repeats):
        cp.cuda.Device().synchronize()
        start = time.perf_counter()
        function()
        cp.cuda.Device().synchronize()
        times.append(time.perf_counter() - start)
    return float(np.median(times))


def _profile(n: int, tolerance: float) -> dict:
    """Time the parts of an n x n solve: set-up, the engine alone, one transform and one pass of each kind."""
    from roughcontact.contact import _box
    from roughcontact.contact import _cg_kernels_gpu as passes
    from roughcontact.contact.normal import compliance_for

    cp = gpu_module().cupy
    topography = surface(n, seed=n)
    start = time.perf_counter()
    compliance = compliance_for(topography, CONTACT_MODULUS, device="gpu")
    parts = {"operator_set_up": time.perf_counter() - start}
    start = time.perf_counter()
    separation = cp.asarray(topography.heights.max() - topography.heights)
    parts["separation_to_device"] = time.perf_counter() - start
    force = PRESSURE * topography.area
    solve = dict(pixel_area=topography.pixel_area, force=force, tolerance=tolerance, max_iterations=10_000)
    for name in ("engine_first", "engine_second"):
        start = time.perf_counter()
        engine = _box.solve(compliance, separation, **solve)
        cp.cuda.Device().synchronize()
        parts[name] = time.perf_counter() - start
    parts["engine_iterations"] = engine.iterations
    with compliance.staged() as ops:
        ops.pressure[...] = engine.pressure
        parts["K_p_double_pair"] = _timed(ops.displacement)
        parts["M_g_single_pair"] = _timed(ops.precondition)
        parts["tKt_single_forward"] = _timed(ops.quadratic_form)
        p, g, t = engine.pressure, engine.gap, cp.zeros_like(engine.pressure)
        u = ops.displacement()
        free = cp.ones(p.shape, dtype=np.uint8)
        previous = cp.zeros(p.shape, dtype=np.float32)
        parts["pass_statistics"] = _timed(
            lambda: passes.displacement_statistics(p, u, separation, np.inf, 1.0)
        )
        parts["pass_gap"] = _timed(
            lambda: passes.gap_and_residual(
                p, u, separation, 0.0, np.inf, 1.0, t, g, ops.approximate, free, True
            )
        )
        z = ops.precondition()
        parts["pass_restricted"] = _timed(lambda: passes.restricted_sums(z, g, free, previous))
        parts["pass_direction"] = _timed(
            lambda: passes.update_direction(t, z, 0.0, 0.5, free, g, ops.direction)
        )
        q = p.copy()
        parts["pass_pressure"] = _timed(
            lambda: passes.update_pressure(q, t, g, 0.0, 1.0, np.inf, True, 1.0, ops.pressure)
        )
    steps = ("K_p", "M_g", "tKt", "pass_")
    parts["sum_per_iteration"] = sum(value for key, value in parts.items() if key.startswith(steps))
    parts["engine_per_iteration"] = parts["engine_second"] / max(engine.iterations, 1)
    print(
        f"profile of one {n}^2 solve (s): " + ", ".join(f"{k} {v:.4g}" for k, v in parts.items()), flush=True
    )
    return parts


def _print(entry: dict) -> None:
    second = f"{entry['second_seconds']:8.2f}" if entry["second_seconds"] is not None else f"{'-':>8}"
    cpu = (
        f"{entry['cpu_seconds']:8.2f} {entry['cpu_seconds'] / entry['first_seconds']:7.1f}x "
        f"{entry['cpu_difference']:9.1e}"
        if "cpu_seconds" in entry
        else f"{'-':>8} {'-':>8} {'-':>9}"
    )
    print(
        f"{entry['n']:>6}^2 {entry['tolerance']:8.0e} {entry['first_seconds']:8.2f} {second} "
        f"{entry['iterations']:5d} {entry['contact_fraction']:7.3f} {entry['gpu_gb']:7.1f}  {cpu}",
        flush=True,
    )
    if "single" in entry:
        s = entry["single"]
        print(
            f"{'':>8} float32 fields, tolerance {s['tolerance']:.0e}: {s['seconds']:.2f} s, "
            f"{s['iterations']} iterations, {s['gpu_gb']:.1f} GB, "
            f"max dp/p_max to float64 {s['difference']:.1e}",
            flush=True,
        )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[2048, 4096, 8192, 16384, 32768])
    parser.add_argument("--tolerance", type=float, default=1e-8)
    parser.add_argument("--cpu-up-to", type=int, default=4096, help="largest grid the CPU engine solves too")
    parser.add_argument("--second-up-to", type=int, default=16384, help="largest grid solved a second time")
    parser.add_argument(
        "--single", type=int, nargs="*", default=[16384, 32768], help="grids solved in float32 too"
    )
    parser.add_argument("--single-tolerance", type=float, default=1e-6)
    parser.add_argument("--json", help="write the JSON line to this file too")
    parser.add_argument("--profile", type=int, default=0, help="time the parts of one solve on this grid")
    args = parser.parse_args()
    cp = gpu_module().cupy
    properties = cp.cuda.runtime.getDeviceProperties(0)
    name = properties["name"].decode() if isinstance(properties["name"], bytes) else properties["name"]
    total = cp.cuda.Device().mem_info[1] / 1e9
    start = time.perf_counter()
    solve_normal(surface(256, 0), CONTACT_MODULUS, mean_pressure=PRESSURE, device="gpu")  # compile, plan
    warm = time.perf_counter() - start
    print(
        f"GPU normal contact: {name}, {total:.0f} GB; {os.cpu_count()} CPU cores; warm-up {warm:.1f} s",
        flush=True,
    )
    print(
        f"{'grid':>8} {'tol':>8} {'first s':>8} {'second s':>8} {'iter':>5} {'contact':>7} {'GPU GB':>7}  "
        f"{'CPU s':>8} {'CPU/GPU':>8} {'max dp/p':>9}",
        flush=True,
    )
    rows = []
    for n in args.sizes:
        failure = None
        try:
            rows.append(row(n, args))
        except Exception as error:  # out of memory at the largest grid: say so, try float32 fields alone
            failure = f"{type(error).__name__}: {str(error)[:300]}"
        if failure is None:
            _print(rows[-1])
            continue
        print(f"{n:>6}^2 float64 failed: {failure}", flush=True)  # the traceback's arrays are gone here
        rows.append({"n": n, "error": failure})
        gc.collect()
        _release()
        if n in args.single:
            rows[-1]["single"] = _single_alone(n, args)
        break
    profile = _profile(args.profile, args.tolerance) if args.profile else None
    line = json.dumps(
        {"benchmark": "gpu", "device": name, "device_gb": total, "warm_up_seconds": warm, "rows": rows,
         "profile": profile}
    )  # fmt: skip
    print(line)
    if args.json:
        with open(args.json, "w") as file:
            file.write(line + "\n")


if __name__ == "__main__":
    main()
