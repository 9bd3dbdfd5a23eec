r"""Fused elementwise passes of the constrained conjugate-gradient engine (numba).

One iteration of :func:`roughcontact.contact._constrained_cg.solve` needs, besides its FFT
pairs, about thirty elementwise numpy passes over the grid (masks, reductions, temporaries);
on large grids they are memory-bound and cost as much as the FFTs. Each function here does
the work between two operator applications in one pass, reading each array once and
allocating nothing.

The loops are serial on purpose: they are limited by memory bandwidth, not arithmetic, and a
numba thread pool competes with the FFT's own threads (scipy.fft ``workers``) for the cores,
which on a 2-core machine made whole solves several times slower. Serial loops also sum in a
fixed order, so the same input gives the same iterates, bit for bit, and the kernels are safe
to call from several threads at once (e.g. Dask workers).

All arrays are 1D, C-contiguous float64 views of the grid (``ravel()``); ``cap`` is the
pressure cap (``inf`` without one). The step-set mask is uint8 (1 = in the set).

References
----------
Lam, S. K., Pitrou, A. and Seibert, S. (2015). Numba: a LLVM-based Python JIT compiler.
Proc. LLVM-HPC 2015, 7:1-7:6. doi:10.1145/2833157.2833162
"""

from __future__ import annotations

import numba as nb

_JIT = dict(cache=True, nogil=True)


@nb.njit(**_JIT)
def displacement_statistics(p, u, h0, cap):
    """Return (number of elastic points 0 < p < cap, sum of u + h0 over them, sum u, sum u^2)."""
    count, s_free, s_u, s_uu = 0, 0.0, 0.0, 0.0
    for i in range(p.size):
        ui = u[i]
        if 0.0 < p[i] < cap:
            count += 1
            s_free += ui + h0[i]
        s_u += ui
        s_uu += ui * ui
    return count, s_free, s_u, s_uu


@nb.njit(**_JIT)
def gap_and_residual(p, u, h0, delta, cap, t, g, g_free, free, admit_overlap):
    """Write the gap g = u + h0 - delta, the step set and g on it; return the residual terms and sums.

    The step set ``free`` is the elastic contact 0 < p < cap plus the capped points that want to
    unload (p >= cap and g > 0) and, with ``admit_overlap``, the overlapping points out of contact
    (p = 0 and g < 0); ``g_free`` is g there and 0 elsewhere. ``t`` (the previous conjugate
    direction) is only read.

    Returns
    -------
    (sum of p over the elastic contact, sum of p |g| over it, largest overlap -g below the cap,
    largest open gap g at the cap, number of points in the step set, and over the step set the
    sums of g^2, of g and of t)
    """
    s_p, s_pg, overlap, opened, count = 0.0, 0.0, 0.0, 0.0, 0
    s_gg, s_g, s_t = 0.0, 0.0, 0.0
    for i in range(p.size):
        gi = u[i] + h0[i] - delta
        g[i] = gi
        pi = p[i]
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
            free[i] = 1
            g_free[i] = gi
            count += 1
            s_gg += gi * gi
            s_g += gi
            s_t += t[i]
        else:
            free[i] = 0
            g_free[i] = 0.0
    return s_p, s_pg, overlap, opened, count, s_gg, s_g, s_t


@nb.njit(**_JIT)
def restrict_direction(z, g, free):
    """Zero z outside the step set; return (sum z, sum g z) over it."""
    s_z, s_gz = 0.0, 0.0
    for i in range(z.size):
        if free[i]:
            s_z += z[i]
            s_gz += g[i] * z[i]
        else:
            z[i] = 0.0
    return s_z, s_gz


@nb.njit(**_JIT)
def update_direction(t, z, shift, beta, free, g):
    """Set t = (z - shift) + beta t on the step set and 0 elsewhere; return sum g t."""
    s_gt = 0.0
    for i in range(t.size):
        if free[i]:
            ti = (z[i] - shift) + beta * t[i]
            s_gt += g[i] * ti
        else:
            ti = 0.0
        t[i] = ti
    return s_gt


@nb.njit(**_JIT)
def update_pressure(p, t, g, tau, entering_step, cap, admit_overlap):
    """Step p -= tau t and project on [0, cap]; return (number of points that entered, sum of the new p).

    Without ``admit_overlap`` overlapping points left at p = 0 enter by -entering_step g and are
    counted; with it they took part in the step, and a point entered when its p rose from 0.
    """
    entered, s_p = 0, 0.0
    for i in range(p.size):
        old = p[i]
        pi = min(max(old - tau * t[i], 0.0), cap)
        if admit_overlap:
            if old <= 0.0 and pi > 0.0:
                entered += 1
        elif pi <= 0.0 and g[i] < 0.0:
            entered += 1
            pi = min(max(pi - entering_step * g[i], 0.0), cap)
        p[i] = pi
        s_p += pi
    return entered, s_p
