"""Why the normal solver's iterations grow with the grid: the spectrum of its preconditioned operator.

At the solution of a periodic self-affine contact (the statistics of ``normal_contact.py``: H = 0.8,
rms slope 0.1, ~10 % contact, the same physical pixel size at every grid) the conjugate-gradient
iteration of :mod:`roughcontact.contact._constrained_cg` works, once the contact set I is found,
on the operator K restricted to I, preconditioned by the Fourier inverse M = K^{-1} restricted to I,
on the directions that sum to zero over I (load control). This script forms both matrices densely
from the operators' kernels and prints the generalised eigenvalues of (M_II) K_II on that
subspace: their range (kappa = largest / smallest), quantiles, and, for the extreme eigenvectors,
the mean distance of their weight to the edge of the contact (1 = an edge pixel).

Because M_II - (K_II)^{-1} = M_IJ (M_JJ)^{-1} M_JI >= 0 (J: out of contact), every eigenvalue is at
least 1; the large ones belong to the contact's edge pixels. Two corrections are printed beside:
the exact Schur-complement correction over the band B of out-of-contact pixels next to the contact,
M_II - M_IB (M_BB)^{-1} M_BI (needs a solve on the band each iteration), and its first-order form
with the diagonal of M_BB (two more transforms per iteration).

    python benchmarks/preconditioner_spectrum.py [--sizes 64 128] [--band]

Dense: 128^2 takes seconds, 256^2 about 5 minutes and 3 GB. Ends with one JSON line.
"""

from __future__ import annotations

import argparse
import json

import numpy as np
from scipy import linalg, ndimage

from roughcontact.contact import solve_normal
from roughcontact.contact.normal import compliance_for
from roughcontact.topography.generate import self_affine

CONTACT_MODULUS = 1e9


def _dense(rows: np.ndarray, columns: np.ndarray, kernel: np.ndarray) -> np.ndarray:
    """The block of the circulant operator with real-space ``kernel`` between two sets of pixels."""
    n0, n1 = kernel.shape
    r, c = np.unravel_index(rows, kernel.shape), np.unravel_index(columns, kernel.shape)
    return kernel[(r[0][:, None] - c[0][None, :]) % n0, (r[1][:, None] - c[1][None, :]) % n1]


def spectrum(n: int, band: bool) -> dict:
    """Eigenvalues of the preconditioned restricted operator at the solution on an n x n grid."""
    surface = self_affine((n, n), (1e-4 * n / 256, 1e-4 * n / 256), hurst=0.8, rms_slope=0.1, seed=n + 1)
    operator = compliance_for(surface, CONTACT_MODULUS)
    load = 0.05 * CONTACT_MODULUS * 0.1  # mean pressure [Pa], as normal_contact.py
    solution = solve_normal(surface, compliance=operator, mean_pressure=load, tolerance=1e-10)
    contact = solution.pressure > 0
    inside = np.flatnonzero(contact.ravel())
    compliance = np.fft.irfft2(operator.kernel, s=(n, n))
    stiffness = np.fft.irfft2(operator.inverse_kernel(), s=(n, n))
    k_ii, m_ii = _dense(inside, inside, compliance), _dense(inside, inside, stiffness)
    m = inside.size
    basis = np.linalg.qr(np.vstack([np.ones(m), np.eye(m)[:-1]]).T)[0][:, 1:]  # zero sum over I
    k_zero = basis.T @ k_ii @ basis

    def eigenvalues(preconditioner):
        p_zero = basis.T @ preconditioner @ basis
        return linalg.eigh(k_zero, np.linalg.inv(p_zero))

    values, vectors = eigenvalues(m_ii)
    distance = ndimage.distance_transform_edt(contact).ravel()[inside]
    weight = (basis @ vectors) ** 2
    weight /= weight.sum(axis=0)
    row = {
        "n": n,
        "contact_pixels": int(m),
        "smallest": float(values[0]),
        "largest": float(values[-1]),
        "kappa": float(values[-1] / values[0]),
        "quantiles": {str(q): float(np.quantile(values, q)) for q in (0.5, 0.9, 0.99)},
        "edge_distance_of_largest": float(weight[:, -1] @ distance),
        "edge_distance_of_smallest": float(weight[:, 0] @ distance),
    }
    if band:
        ring = np.flatnonzero((ndimage.binary_dilation(contact) & ~contact).ravel())
        m_ib, m_bb = _dense(inside, ring, stiffness), _dense(ring, ring, stiffness)
        exact = eigenvalues(m_ii - m_ib @ np.linalg.solve(m_bb, m_ib.T))[0]
        first = eigenvalues(m_ii - m_ib @ (m_ib.T / np.diag(m_bb)[:, None]))[0]
        row["band_exact_kappa"] = float(exact[-1] / exact[0])
        row["band_diagonal_kappa"] = float(first[-1] / first[0])
    return row


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[64, 128])
    parser.add_argument("--band", action="store_true", help="also the band Schur-complement corrections")
    args = parser.parse_args()
    rows = []
    print("grid   contact  lambda min  lambda max   kappa  median  q0.99  edge dist (max/min)", end="")
    print("  band: exact  diagonal" if args.band else "")
    for n in args.sizes:
        r = spectrum(n, args.band)
        rows.append(r)
        band = f"{r['band_exact_kappa']:11.2f} {r['band_diagonal_kappa']:9.2f}" if args.band else ""
        print(
            f"{n:4d}^2 {r['contact_pixels']:8d} {r['smallest']:11.3f} {r['largest']:11.3f} {r['kappa']:7.2f}"
            f" {r['quantiles']['0.5']:7.3f} {r['quantiles']['0.99']:6.3f}"
            f"   {r['edge_distance_of_largest']:5.2f} / {r['edge_distance_of_smallest']:5.2f}      {band}",
            flush=True,
        )
    print(json.dumps({"benchmark": "preconditioner_spectrum", "rows": rows}))


if __name__ == "__main__":
    main()
