r"""Fused elementwise passes of the constrained conjugate-gradient engine (numba).

One iteration of :func:`roughcontact.contact._constrained_cg.solve` needs, besides its FFTs,
about thirty elementwise numpy passes over the grid (masks, reductions, temporaries, copies
into and out of the FFT buffers); on large grids they are memory-bound and cost as much as
the FFTs. Each function here does the work between two transforms in one pass, reading each
array once, allocating nothing, and writing the field the next transform needs straight into
that transform's input buffer (:meth:`roughcontact.elasticity.halfspace.SurfaceCompliance.staged`).

The loops are serial on purpose: they are limited by memory bandwidth, not arithmetic, and a
numba thread pool competes with the FFT's own threads for the cores, which on a 2-core machine
made whole solves several times slower. Serial loops also sum in a fixed order, so the same
input gives the same iterates, bit for bit, and the kernels are safe to call from several
threads at once (e.g. Dask workers).

Arrays are 2D fields of the grid: the engine's own (C-contiguous float64; the step-set mask
uint8, 1 = in the set) and views into FFT buffers (strided on a zero-padded grid; float64 for
the displacement and the pressure input, float32 for the preconditioner's and the quadratic
form's input and the preconditioned gap). ``cap`` is the pressure cap (``inf`` without one).
Under load control the stored pressure is rescaled lazily: the true pressure is ``scale * p``
and the true displacement ``scale * u`` (u = K p of the stored p), which saves a pass per
iteration.

References
----------
Lam, S. K., Pitrou, A. and Seibert, S. (2015). Numba: a LLVM-based Python JIT compiler.
Proc. LLVM-HPC 2015, 7:1-7:6. doi:10.1145/2833157.2833162
"""

from __future__ import annotations

import numba as nb

_JIT = dict(cache=True, nogil=True)


@nb.njit(**_JIT)
def displacement_statistics(p, u, h0, cap, scale):
    """Return (number of points 0 < p < cap, sum of u + h0 over them, sum u, sum u^2) of the true p, u."""
    count, s_free, s_u, s_uu = 0, 0.0, 0.0, 0.0
    m0, m1 = p.shape
    for i in range(m0):
        for j in range(m1):
            ui = scale * u[i, j]
            if 0.0 < scale * p[i, j] < cap:
                count += 1
                s_free += ui + h0[i, j]
            s_u += ui
            s_uu += ui * ui
    return count, s_free, s_u, s_uu


@nb.njit(**_JIT)
def gap_and_residual(p, u, h0, delta, cap, scale, t, g, g_stage, free, admit_overlap):
    """Write the gap g = u + h0 - delta, the step set and g on it (``g_stage``); return the residual terms.

    The step set ``free`` is the elastic contact 0 < p < cap plus the capped points that want to
    unload (p >= cap and g > 0) and, with ``admit_overlap``, the overlapping points out of contact
    (p = 0 and g < 0); ``g_stage`` (the preconditioner's input) is g there and 0 elsewhere.
    ``t`` (the previous conjugate direction) is only read.

    Returns
    -------
    (sum of p over the elastic contact, sum of p |g| over it, largest overlap -g below the cap,
    largest open gap g at the cap, number of points in the step set, and over the step set the
    sums of g^2, of g, of t and of g t)
    """
    s_p, s_pg, overlap, opened, count = 0.0, 0.0, 0.0, 0.0, 0
    s_gg, s_g, s_t, s_gt = 0.0, 0.0, 0.0, 0.0
    m0, m1 = p.shape
    for i in range(m0):
        for j in range(m1):
            gi = scale * u[i, j] + h0[i, j] - delta
            g[i, j] = gi
            pi = scale * p[i, j]
            if pi < cap:
                overlap = max(overlap, -gi)
                step = pi > 0.0 or (admit_overlap and gi < 0.0)
                if pi > 0.0:
                    s_p += pi
                    s_pg += pi * abs(gi)
            else:
                opened = max(opened, gi)
                step = gi > 0.0
            if step:
                free[i, j] = 1
                g_stage[i, j] = gi
                count += 1
                s_gg += gi * gi
                s_g += gi
                s_t += t[i, j]
                s_gt += gi * t[i, j]
            else:
                free[i, j] = 0
                g_stage[i, j] = 0.0
    return s_p, s_pg, overlap, opened, count, s_gg, s_g, s_t, s_gt


@nb.njit(**_JIT)
def restricted_sums(z, g, free, g_previous):
    """Return sums over the step set for a Polak-Ribiere coefficient; then store g in ``g_previous``.

    Returns
    -------
    (sum z, sum g z, sum g_previous z, sum g_previous) over the step set, with ``g_previous``
    the gap of the iteration before (float32: it only steers the coefficient). Afterwards
    ``g_previous`` holds g at every point.
    """
    s_z, s_gz, s_pz, s_p = 0.0, 0.0, 0.0, 0.0
    m0, m1 = g.shape
    for i in range(m0):
        for j in range(m1):
            gi = g[i, j]
            if free[i, j]:
                zi = float(z[i, j])
                previous = float(g_previous[i, j])
                s_z += zi
                s_gz += gi * zi
                s_pz += previous * zi
                s_p += previous
            g_previous[i, j] = gi
    return s_z, s_gz, s_pz, s_p


@nb.njit(**_JIT)
def update_direction(t, z, shift, beta, free, g, t_stage):
    """Set t = (z - shift) + beta t on the step set and 0 elsewhere, also into ``t_stage``; return sum g t.

    ``z`` may share its memory with ``t_stage`` (a periodic grid's in-place transform): each
    point is read before it is written.
    """
    s_gt = 0.0
    m0, m1 = t.shape
    for i in range(m0):
        for j in range(m1):
            if free[i, j]:
                ti = (float(z[i, j]) - shift) + beta * t[i, j]
                s_gt += g[i, j] * ti
            else:
                ti = 0.0
            t[i, j] = ti
            t_stage[i, j] = ti
    return s_gt


@nb.njit(**_JIT)
def update_pressure(p, t, g, tau, entering_step, cap, admit_overlap, scale, p_stage):
    """Step p -= tau t from the true pressure scale * p, project on [0, cap], store it in p and ``p_stage``.

    Without ``admit_overlap`` overlapping points left at p = 0 enter by -entering_step g and are
    counted; with it they took part in the step, and a point entered when its p rose from 0.

    Returns
    -------
    (number of points that entered, sum of the new p)
    """
    entered, s_p = 0, 0.0
    m0, m1 = p.shape
    for i in range(m0):
        for j in range(m1):
            old = scale * p[i, j]
            pi = min(max(old - tau * t[i, j], 0.0), cap)
            if admit_overlap:
                if old <= 0.0 and pi > 0.0:
                    entered += 1
            elif pi <= 0.0 and g[i, j] < 0.0:
                entered += 1
                pi = min(max(pi - entering_step * g[i, j], 0.0), cap)
            p[i, j] = pi
            p_stage[i, j] = pi
            s_p += pi
    return entered, s_p
