r"""Fused elementwise passes of the partial-slip increment solver (numba).

Each function does the work of :func:`roughcontact.contact._shear_cg.solve_increment` between
two operator applications in one serial pass over the grid (serial for the reasons given in
:mod:`roughcontact.contact._cg_kernels`: memory-bound work, no competition with the FFT
threads, a fixed summation order). Arrays are 1D C-contiguous float64 views; ``state`` is uint8
with 0 = out of contact, 1 = stick, 2 = slip.
"""

from __future__ import annotations

import math

import numba as nb

_JIT = dict(cache=True, nogil=True)

OUT, STICK, SLIP = 0, 1, 2


@nb.njit(inline="always")
def length(x, y):
    """Return |(x, y)| = sqrt(x^2 + y^2).

    A third of math.hypot's time in these loops; tractions in Pa and displacements in m square far
    inside the float64 range, so hypot's guard against overflow buys nothing here.
    """
    return math.sqrt(x * x + y * y)


@nb.njit(**_JIT)
def interior_mean(qx, qy, c, sx, sy, rim):
    """Return the mean of (s_x, s_y) over contact points inside their disc (all contact points if none)."""
    n_in, ax, ay, n_all, bx, by = 0, 0.0, 0.0, 0, 0.0, 0.0
    for i in range(c.size):
        ci = c[i]
        if ci > 0.0:
            n_all += 1
            bx += sx[i]
            by += sy[i]
            if length(qx[i], qy[i]) < ci * (1.0 - rim):
                n_in += 1
                ax += sx[i]
                ay += sy[i]
    if n_in > 0:
        return ax / n_in, ay / n_in
    if n_all > 0:
        return bx / n_all, by / n_all
    return 0.0, 0.0


@nb.njit(**_JIT)
def classify(qx, qy, c, sx, sy, ex, ey, dx, dy, rim, state, zx, zy, nx, ny, bend):
    """Classify stick/slip, build the restricted gradient z, the rim normals and multipliers.

    ``sx, sy`` hold s + e on entry and w = s + e - delta on return; ``ex, ey`` is e. Returns
    (changed: whether ``state`` changed, weighted violation sum c|z|, sum c, sum |s + e|^2 over
    the contact, sum |s|^2 = |C q|^2 over the contact, contact points, stick points, sum z over
    the stick set (x, y), |z|^2).
    """
    changed = False
    violation, weight, ss, cc = 0.0, 0.0, 0.0, 0.0
    n_contact, n_stick = 0, 0
    zsx, zsy, zz = 0.0, 0.0, 0.0
    for i in range(c.size):
        ci = c[i]
        s_x, s_y = sx[i], sy[i]
        wx, wy = s_x - dx, s_y - dy
        sx[i], sy[i] = wx, wy
        new = OUT
        gx, gy, ux, uy, lam = 0.0, 0.0, 0.0, 0.0, 0.0
        if ci > 0.0:
            n_contact += 1
            ss += s_x * s_x + s_y * s_y
            cx, cy = s_x - ex[i], s_y - ey[i]
            cc += cx * cx + cy * cy
            weight += ci
            norm = length(qx[i], qy[i])
            new = STICK
            if norm >= ci * (1.0 - rim):
                ux, uy = qx[i] / norm, qy[i] / norm
                along = wx * ux + wy * uy
                if along < 0.0:
                    new = SLIP
                    gx, gy = wx - along * ux, wy - along * uy
                    lam = -along / ci
            if new == STICK:
                gx, gy = wx, wy
                ux, uy = 0.0, 0.0
                n_stick += 1
                zsx += gx
                zsy += gy
            violation += ci * length(gx, gy)
            zz += gx * gx + gy * gy
        if state[i] != new:
            changed = True
            state[i] = new
        zx[i], zy[i], nx[i], ny[i], bend[i] = gx, gy, ux, uy, lam
    return changed, violation, weight, ss, cc, n_contact, n_stick, zsx, zsy, zz


@nb.njit(**_JIT)
def remove_stick_mean(zx, zy, state, mx, my):
    """Subtract (m_x, m_y) from z on the stick set (force control); return the new |z|^2."""
    zz = 0.0
    for i in range(zx.size):
        if state[i] == STICK:
            zx[i] -= mx
            zy[i] -= my
        zz += zx[i] * zx[i] + zy[i] * zy[i]
    return zz


@nb.njit(**_JIT)
def update_direction(tx, ty, zx, zy, nx, ny, state, beta):
    """Set t = z + beta t_old (t_old made tangent to the rim on slip points, 0 outside); return z.t."""
    zt = 0.0
    for i in range(tx.size):
        if state[i] == OUT:
            tx[i], ty[i] = 0.0, 0.0
            continue
        ox, oy = tx[i], ty[i]
        if state[i] == SLIP:
            along = ox * nx[i] + oy * ny[i]
            ox -= along * nx[i]
            oy -= along * ny[i]
        tx[i] = zx[i] + beta * ox
        ty[i] = zy[i] + beta * oy
        zt += zx[i] * tx[i] + zy[i] * ty[i]
    return zt


@nb.njit(**_JIT)
def rim_curvature(tx, ty, bend):
    """Return sum lambda |t|^2, the curvature the disc rims add to t.Ct along t (``bend`` = lambda)."""
    total = 0.0
    for i in range(tx.size):
        total += bend[i] * (tx[i] * tx[i] + ty[i] * ty[i])
    return total


@nb.njit(**_JIT)
def step_and_project(qx, qy, tx, ty, tau, c):
    """Step q -= tau t, then project each point radially onto its disc |q| <= c."""
    for i in range(qx.size):
        x = qx[i] - tau * tx[i]
        y = qy[i] - tau * ty[i]
        norm = length(x, y)
        if norm > c[i]:
            scale = c[i] / norm if norm > 0.0 else 0.0
            x *= scale
            y *= scale
        qx[i], qy[i] = x, y


@nb.njit(**_JIT)
def restrict(mx, my, zx, zy, nx, ny, state):
    """Restrict M z like z (0 outside, tangent on slip); return (z.Mz, its sums on stick)."""
    dot, sx, sy = 0.0, 0.0, 0.0
    for i in range(mx.size):
        if state[i] == OUT:
            mx[i], my[i] = 0.0, 0.0
            continue
        if state[i] == SLIP:
            along = mx[i] * nx[i] + my[i] * ny[i]
            mx[i] -= along * nx[i]
            my[i] -= along * ny[i]
        else:
            sx += mx[i]
            sy += my[i]
        dot += zx[i] * mx[i] + zy[i] * my[i]
    return dot, sx, sy
