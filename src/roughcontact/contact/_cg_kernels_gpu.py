r"""The constrained conjugate-gradient engine's fused passes on the GPU (CUDA through CuPy).

The same five passes as :mod:`roughcontact.contact._cg_kernels`, with the same arguments and
results, for CuPy arrays: :func:`roughcontact.contact._constrained_cg.solve` takes this module
instead of the numba one when its operator lives on the GPU (``device="gpu"``), and runs the same
iteration. Each pass is one CUDA kernel that reads each array once and returns its sums through
:func:`roughcontact._gpu.reduction` (float64 sums whatever the fields' precision; see that
module for how the blocks combine them).

Fields: the engine's own arrays are C-contiguous (``T``: float64, or float32 with
``precision="single"``); the displacement, the staged inputs and the preconditioned gap are views
into the transforms' buffers, passed with their row stride (a free boundary's buffers are twice
as wide as the grid). The step-set mask is uint8, the preconditioner's fields float32.
"""

from __future__ import annotations

import functools

import numpy as np

from .._gpu import c_type, compile_kernels, reduction, row_stride

_CODE = r"""
// Offset of the k-th grid point (row-major over m0 x m1) in an array whose rows are ld apart:
// k itself for contiguous rows (no division), else row * ld + column (32-bit division: k < 2^32).
#define AT(k, ld) ((ld) == m1 ? (k) : (long long)((unsigned)(k) / (unsigned)m1) * (ld) + \
                                       (long long)((unsigned)(k) % (unsigned)m1))
template <typename T>
__global__ void displacement_statistics(const T* p, const T* u, long long ldu, const T* h0,
                                        double cap, double scale, long long m0, long long m1,
                                        double* out) {
    double count = 0.0, s_free = 0.0, s_u = 0.0, s_uu = 0.0;
    GRID_LOOP(k, m0 * m1) {
        double ui = scale * (double)u[AT(k, ldu)];
        double pi = scale * (double)p[k];
        if (0.0 < pi && pi < cap) {
            count += 1.0;
            s_free += ui + (double)h0[k];
        }
        s_u += ui;
        s_uu += ui * ui;
    }
    add_to(out + 0, count); add_to(out + 1, s_free); add_to(out + 2, s_u); add_to(out + 3, s_uu);
}

template <typename T>
__global__ void gap_and_residual(const T* p, const T* u, long long ldu, const T* h0, double delta,
                                 double cap, double scale, const T* t, T* g, float* g_stage,
                                 long long lds, unsigned char* free_set, int admit_overlap,
                                 long long m0, long long m1, double* out) {
    double s_p = 0.0, s_pg = 0.0, overlap = 0.0, opened = 0.0, count = 0.0;
    double s_gg = 0.0, s_g = 0.0, s_t = 0.0, s_gt = 0.0;
    GRID_LOOP(k, m0 * m1) {
        double gi = scale * (double)u[AT(k, ldu)] + (double)h0[k] - delta;
        g[k] = (T)gi;
        double pi = scale * (double)p[k];
        bool step;
        if (pi < cap) {
            overlap = fmax(overlap, -gi);
            step = pi > 0.0 || (admit_overlap && gi < 0.0);
            if (pi > 0.0) {
                s_p += pi;
                s_pg += pi * fabs(gi);
            }
        } else {
            opened = fmax(opened, gi);
            step = gi > 0.0;
        }
        if (step) {
            double ti = (double)t[k];
            free_set[k] = 1;
            g_stage[AT(k, lds)] = (float)gi;
            count += 1.0;
            s_gg += gi * gi;
            s_g += gi;
            s_t += ti;
            s_gt += gi * ti;
        } else {
            free_set[k] = 0;
            g_stage[AT(k, lds)] = 0.0f;
        }
    }
    add_to(out + 0, s_p); add_to(out + 1, s_pg); max_to(out + 2, overlap); max_to(out + 3, opened);
    add_to(out + 4, count); add_to(out + 5, s_gg); add_to(out + 6, s_g); add_to(out + 7, s_t);
    add_to(out + 8, s_gt);
}

template <typename T>
__global__ void restricted_sums(const float* z, long long ldz, const T* g, const unsigned char* free_set,
                                float* g_previous, long long m0, long long m1, double* out) {
    double s_z = 0.0, s_gz = 0.0, s_pz = 0.0, s_p = 0.0;
    GRID_LOOP(k, m0 * m1) {
        double gi = (double)g[k];
        if (free_set[k]) {
            double zi = (double)z[AT(k, ldz)], previous = (double)g_previous[k];
            s_z += zi;
            s_gz += gi * zi;
            s_pz += previous * zi;
            s_p += previous;
        }
        g_previous[k] = (float)gi;
    }
    add_to(out + 0, s_z); add_to(out + 1, s_gz); add_to(out + 2, s_pz); add_to(out + 3, s_p);
}

template <typename T, typename Z>
__global__ void update_direction(T* t, const Z* z, long long ldz, double shift, double beta,
                                 const unsigned char* free_set, const T* g, float* t_stage,
                                 long long lds, long long m0, long long m1, double* out) {
    double s_gt = 0.0;
    GRID_LOOP(k, m0 * m1) {
        double ti = 0.0;
        if (free_set[k]) {
            ti = ((double)z[AT(k, ldz)] - shift) + beta * (double)t[k];
            s_gt += (double)g[k] * ti;
        }
        t[k] = (T)ti;
        t_stage[AT(k, lds)] = (float)ti;
    }
    add_to(out, s_gt);
}

template <typename T>
__global__ void update_pressure(T* p, const T* t, const T* g, double tau, double entering_step,
                                double cap, int admit_overlap, double scale, T* p_stage,
                                long long lds, long long m0, long long m1, double* out) {
    double entered = 0.0, s_p = 0.0;
    GRID_LOOP(k, m0 * m1) {
        double old = scale * (double)p[k];
        double pi = fmin(fmax(old - tau * (double)t[k], 0.0), cap);
        if (admit_overlap) {
            if (old <= 0.0 && pi > 0.0) entered += 1.0;
        } else if (pi <= 0.0 && (double)g[k] < 0.0) {
            entered += 1.0;
            pi = fmin(fmax(pi - entering_step * (double)g[k], 0.0), cap);
        }
        p[k] = (T)pi;
        p_stage[AT(k, lds)] = (T)pi;
        s_p += (double)(T)pi;
    }
    add_to(out + 0, entered); add_to(out + 1, s_p);
}
"""

_PASSES = ("displacement_statistics", "gap_and_residual", "restricted_sums", "update_pressure")


@functools.cache
def _kernels():
    names = [f"{name}<{t}>" for name in _PASSES for t in ("double", "float")]
    # z: the preconditioned gap (float32), or the gap itself (plain Polonsky-Keer, the fields' type)
    names += [
        f"update_direction<{t}, {z}>"
        for t, z in (("double", "float"), ("float", "float"), ("double", "double"))
    ]
    return compile_kernels(_CODE, tuple(names))


def _kernel(name: str, *fields):
    return _kernels()[f"{name}<{', '.join(c_type(field.dtype) for field in fields)}>"]


def _grid(field) -> tuple[int, np.int64, np.int64]:
    m0, m1 = field.shape
    return m0 * m1, np.int64(m0), np.int64(m1)


def displacement_statistics(p, u, h0, cap, scale):
    """Return (number of points 0 < p < cap, sum of u + h0 over them, sum u, sum u^2) of the true p, u."""
    n, m0, m1 = _grid(p)
    arguments = (p, u, row_stride(u), h0, np.float64(cap), np.float64(scale), m0, m1)
    count, s_free, s_u, s_uu = reduction(_kernel("displacement_statistics", p), n, arguments, 4)
    return int(round(count)), float(s_free), float(s_u), float(s_uu)


def gap_and_residual(p, u, h0, delta, cap, scale, t, g, g_stage, free, admit_overlap):
    """Write g, the step set and g on it; return the residual terms (as the numba pass does)."""
    n, m0, m1 = _grid(p)
    arguments = (
        p, u, row_stride(u), h0, np.float64(delta), np.float64(cap), np.float64(scale), t, g,
        g_stage, row_stride(g_stage), free, np.int32(bool(admit_overlap)), m0, m1,
    )  # fmt: skip
    sums = reduction(_kernel("gap_and_residual", p), n, arguments, 9)
    s_p, s_pg, overlap, opened, count, s_gg, s_g, s_t, s_gt = (float(value) for value in sums)
    return s_p, s_pg, overlap, opened, int(round(count)), s_gg, s_g, s_t, s_gt


def restricted_sums(z, g, free, g_previous):
    """Return (sum z, sum g z, sum g_previous z, sum g_previous) over the step set; store g in g_previous."""
    n, m0, m1 = _grid(g)
    arguments = (z, row_stride(z), g, free, g_previous, m0, m1)
    return tuple(float(value) for value in reduction(_kernel("restricted_sums", g), n, arguments, 4))


def update_direction(t, z, shift, beta, free, g, t_stage):
    """Set t = (z - shift) + beta t on the step set and 0 elsewhere, also into ``t_stage``; return sum g t."""
    n, m0, m1 = _grid(t)
    arguments = (
        t, z, row_stride(z), np.float64(shift), np.float64(beta), free, g, t_stage, row_stride(t_stage),
        m0, m1,
    )  # fmt: skip
    return float(reduction(_kernel("update_direction", t, z), n, arguments, 1)[0])


def update_pressure(p, t, g, tau, entering_step, cap, admit_overlap, scale, p_stage):
    """Step p -= tau t, project on [0, cap], store in p and ``p_stage``; return (entered, sum of new p)."""
    n, m0, m1 = _grid(p)
    arguments = (
        p, t, g, np.float64(tau), np.float64(entering_step), np.float64(cap), np.int32(bool(admit_overlap)),
        np.float64(scale), p_stage, row_stride(p_stage), m0, m1,
    )  # fmt: skip
    entered, s_p = reduction(_kernel("update_pressure", p), n, arguments, 2)
    return int(round(entered)), float(s_p)
