r"""Surface response of two elastic half-spaces to shear and normal tractions (Boussinesq-Cerruti).

Two bodies touch at the plane z = 0; body 1 (the rough one) receives the shear traction
q = (q_x, q_y) and the pressure p, body 2 (the flat) the opposite tractions. The contact
solvers need the *relative* surface displacements: the slip s_t = u_t^(1) - u_t^(2) in the
plane and the normal displacement that opens the gap, u_z = u_z^(1) + u_z^(2). Both are linear
in (q_x, q_y, p); the conventions of :mod:`roughcontact.elasticity.kernels` hold (axis 0 is x,
backward-normalised rfft2, displacement positive into each body).

Point forces on one half-space (shear modulus G, Poisson's ratio nu; Johnson 1985 eqs. 3.19 and
3.86-3.87 at z = 0; X, Y the offset from the force, rho = |(X, Y)|)

.. math::

    Q_x:\quad u_x = \frac{Q}{2\pi G}\Big[\frac{1-\nu}{\rho} + \frac{\nu X^2}{\rho^3}\Big],\quad
    u_y = \frac{Q}{2\pi G}\frac{\nu X Y}{\rho^3},\quad
    u_z = \frac{(1-2\nu) Q}{4\pi G}\frac{X}{\rho^2};\qquad
    P:\quad u_z = \frac{(1-\nu) P}{2\pi G \rho},\quad
    u_x = -\frac{(1-2\nu) P}{4\pi G}\frac{X}{\rho^2}

(the shear force's u_z follows from the pressure's u_x by Betti's reciprocity). For the pair the
compliances add, except the cross terms, which come with the difference of the two bodies'
(1 - 2 nu)/G, since body 2's traction and its inward normal are both reversed. Define

.. math::

    A = \sum_i \frac{1}{G_i},\quad B = \sum_i \frac{\nu_i}{G_i},\quad
    C = \sum_i \frac{1-\nu_i}{G_i} = \frac{2}{E^*},\quad
    D = \frac{1-2\nu_1}{2 G_1} - \frac{1-2\nu_2}{2 G_2}

(a rigid body adds nothing). D = beta C with beta Dundurs' second constant; D = 0 for similar
materials, and then shear and pressure do not interact. The Fourier coefficients of the
displacements of a periodic surface are (k the wavevector; the factors follow from the 2D
transforms of 1/rho, X^2/rho^3, XY/rho^3 and X/rho^2, i.e. 2 pi/k, 2 pi k_y^2/k^3,
-2 pi k_x k_y/k^3 and -2 pi i k_x/k^2, under the exp(-i k.x) convention of the FFT)

.. math::

    \begin{pmatrix} s_x \\ s_y \\ u_z \end{pmatrix} = \frac{1}{k}
    \begin{pmatrix} A - B k_x^2/k^2 & -B k_x k_y/k^2 & i D k_x/k \\
                    -B k_x k_y/k^2 & A - B k_y^2/k^2 & i D k_y/k \\
                    -i D k_x/k & -i D k_y/k & C \end{pmatrix}
    \begin{pmatrix} q_x \\ q_y \\ p \end{pmatrix}

with the k = 0 mode left at zero (a uniform traction moves a half-space by an undetermined
amount; under force control the rigid displacement absorbs it). For a free surface the same
point-force responses are integrated over each pixel in closed form and convolved by zero
padding (DC-FFT, as for the pressure); the pixel integrals of 1/rho, X^2/rho^3, XY/rho^3 and
X/rho^2 have the antiderivatives (d^2F/dX dY = f) X asinh(Y/X) + Y asinh(X/Y), Y asinh(X/|Y|),
-rho and Y ln rho + X arctan(Y/X).

References
----------
Johnson, K. L. (1985). Contact Mechanics, ch. 3 and 5. doi:10.1017/CBO9781139171731
Dundurs, J. (1969). J. Appl. Mech. 36, 650-652 (bimaterial constants).
Liu, S., Wang, Q. and Liu, G. (2000). Wear 243, 101-111 (DC-FFT).
"""

from __future__ import annotations

from dataclasses import dataclass

import numba as nb
import numpy as np
from scipy import fft

from .._backend import RealFFT2, resolve_workers
from ..errors import InputError
from ..materials import Material
from . import kernels


@dataclass(frozen=True)
class PairCompliance:
    """The compliance sums A, B, C, D of the module docstring for a body and a counter-body [1/Pa]."""

    A: float
    B: float
    C: float
    D: float

    @classmethod
    def of(cls, body: Material, counter_body: Material | None = None) -> PairCompliance:
        """Return the sums for ``body`` (receives q and p) against ``counter_body`` (None: rigid)."""

        def terms(material):  # (1/G, nu/G, (1 - nu)/G, (1 - 2 nu)/(2G)); a rigid body adds nothing
            if material is None:
                return np.zeros(4)
            nu, g = material.poissons_ratio, material.shear_modulus
            return np.array([1.0, nu, 1.0 - nu, (1.0 - 2.0 * nu) / 2.0]) / g

        first, second = terms(body), terms(counter_body)
        a, b, c, _ = first + second
        return cls(float(a), float(b), float(c), float(first[3] - second[3]))

    @property
    def dundurs_beta(self) -> float:
        """Dundurs' beta = D / C (0 for similar materials or two incompressible bodies)."""
        return self.D / self.C

    @property
    def contact_modulus(self) -> float:
        """E* = 2 / C [Pa]."""
        return 2.0 / self.C


def periodic_kernels(shape, size, pair: PairCompliance) -> dict[str, np.ndarray]:
    """Fourier kernels ``xx, xy, yy`` (real) and ``xz`` (imaginary part, s from p) of a periodic pair.

    ``zx`` (u_z from q) is ``-xz``, ``yz`` is ``xz`` with k_y for k_x (returned as ``yz``). All on
    the rfft2 half-spectrum, 0 at k = 0 and the coupling 0 on Nyquist lines (odd kernels have no
    real Nyquist coefficient).
    """
    qx, qy = kernels.wavevectors(shape, size)
    k = np.sqrt(qx**2 + qy**2)
    inv = np.zeros_like(k)
    inv[k > 0] = 1.0 / k[k > 0]
    out = {
        "xx": (pair.A - pair.B * (qx * inv) ** 2) * inv,
        "yy": (pair.A - pair.B * (qy * inv) ** 2) * inv,
        "xy": -pair.B * qx * qy * inv**3,
        "xz": pair.D * qx * inv**2,
        "yz": pair.D * qy * inv**2,
    }
    if shape[0] % 2 == 0:
        out["xz"][shape[0] // 2, :] = 0.0
        out["yz"][shape[0] // 2, :] = 0.0
    if shape[1] % 2 == 0:
        out["xz"][:, -1] = 0.0
        out["yz"][:, -1] = 0.0
    return {name: np.broadcast_to(value, k.shape).copy() for name, value in out.items()}


def _log_x_plus_rho(x, y, rho):
    """ln(x + rho) without cancellation for x < 0 (there x + rho = y^2 / (rho - x))."""
    with np.errstate(divide="ignore"):
        return np.where(x >= 0, np.log(x + rho), np.log(y**2) - np.log(rho - x))


def _antiderivatives(x: np.ndarray, y: np.ndarray) -> dict[str, np.ndarray]:
    """F with d^2F/dx dy = f for f = 1/rho, x^2/rho^3, xy/rho^3, x/rho^2, y/rho^2 (x, y never 0)."""
    rho = np.hypot(x, y)
    return {
        "one": x * _log_x_plus_rho(y, x, rho) + y * _log_x_plus_rho(x, y, rho),
        "xx": y * _log_x_plus_rho(x, y, rho),
        "yy": x * _log_x_plus_rho(y, x, rho),
        "xy": -rho,
        "x": y * np.log(rho) + x * np.arctan(y / x),
        "y": x * np.log(rho) + y * np.arctan(x / y),
    }


def free_influence_coefficients(shape, spacing) -> dict[str, np.ndarray]:
    """Pixel integrals of 1/rho, X^2/rho^3, Y^2/rho^3, XY/rho^3, X/rho^2, Y/rho^2 on a wrap-around grid.

    Entry [i, j] is the integral over the pixel centred at the origin seen from the point at
    offset (i dx, j dy) (upper half of each axis: negative offsets); divide by the moduli of the
    module docstring to get displacements per unit traction [m/Pa].
    """
    dx, dy = spacing
    x = fft.fftfreq(shape[0], d=1.0 / shape[0])[:, None] * dx
    y = fft.fftfreq(shape[1], d=1.0 / shape[1])[None, :] * dy
    x, y = np.broadcast_arrays(x, y)
    a, b = dx / 2.0, dy / 2.0
    corners = [(+1.0, x + a, y + b), (-1.0, x + a, y - b), (-1.0, x - a, y + b), (+1.0, x - a, y - b)]
    total: dict[str, np.ndarray] = {}
    for sign, cx, cy in corners:
        for name, value in _antiderivatives(cx, cy).items():
            total[name] = total.get(name, 0.0) + sign * value
    return total


def free_kernels(shape, size, pair: PairCompliance) -> dict[str, np.ndarray]:
    """Kernels as :func:`periodic_kernels` for a free surface, on the zero-padded grid (2 nx, 2 ny).

    ``xz`` and ``yz`` are returned as the imaginary parts (their real parts vanish: the
    influence coefficients are odd), the others as real parts.
    """
    spacing = (size[0] / shape[0], size[1] / shape[1])
    padded = (2 * shape[0], 2 * shape[1])
    i = free_influence_coefficients(padded, spacing)
    two_pi = 2.0 * np.pi
    # u_x per unit q_x: A' (1-nu)/rho + nu X^2/rho^3 summed over bodies = ((A-B)/rho + B X^2/rho^3) / 2pi
    real_space = {
        "xx": ((pair.A - pair.B) * i["one"] + pair.B * i["xx"]) / two_pi,
        "yy": ((pair.A - pair.B) * i["one"] + pair.B * i["yy"]) / two_pi,
        "xy": pair.B * i["xy"] / two_pi,
        # s_x per unit p: -(1-2nu)/(4 pi G) X/rho^2 summed with the bodies' signs = -D X/rho^2 / 2pi
        "xz": -pair.D * i["x"] / two_pi,
        "yz": -pair.D * i["y"] / two_pi,
    }
    out = {}
    for name, value in real_space.items():
        spectrum = fft.rfft2(value)
        out[name] = spectrum.imag if name in ("xz", "yz") else spectrum.real
    return out


class TractionCompliance:
    """Linear maps between surface tractions [Pa] and relative surface displacements [m] of a pair.

    Parameters
    ----------
    shape, size : (int, int), (float, float)
        Grid and physical size [m] (the period for a periodic surface).
    body, counter_body : Material
        The body receiving q and p (the rough one) and the counter-body (None: rigid).
    boundary : {"periodic", "free"}
    workers : int, optional
        FFT threads (default: all cores).

    Notes
    -----
    :meth:`shear` costs two forward and two inverse transforms (of the padded grid for a free
    boundary); :meth:`slip_from_pressure` one forward and two inverse; :meth:`normal_from_shear`
    two forward and one inverse. The coupling maps are zero (and skipped) when D = 0.
    """

    def __init__(
        self,
        shape,
        size,
        body: Material,
        counter_body: Material | None = None,
        *,
        boundary: str = "periodic",
        workers: int | None = None,
    ):
        if boundary not in kernels.BOUNDARIES:
            raise InputError("boundary", f"unknown boundary {boundary!r}.", "use 'periodic' or 'free'.")
        self.shape = (int(shape[0]), int(shape[1]))
        self.size = (float(size[0]), float(size[1]))
        self.boundary = boundary
        self.pair = PairCompliance.of(body, counter_body)
        if boundary == "periodic":
            fft_shape, built = self.shape, periodic_kernels(self.shape, self.size, self.pair)
        else:
            fft_shape, built = (
                (2 * self.shape[0], 2 * self.shape[1]),
                free_kernels(self.shape, self.size, self.pair),
            )
        self._k = built
        self._bodies, self._workers = (body, counter_body), workers
        self._windows: dict[tuple[int, int], TractionCompliance] = {}
        self._prepared = {}  # multipliers divided by the transform size, made on first use
        self._spectrum = None  # work spectrum of _symmetric_multiplier
        self.coupled = self.pair.D != 0.0
        self._fft = RealFFT2(fft_shape, resolve_workers(workers), input_shape=self.shape)

    @property
    def pixel_area(self) -> float:
        """Area of one pixel [m^2]."""
        return self.size[0] * self.size[1] / (self.shape[0] * self.shape[1])

    def window(self, shape) -> TractionCompliance:
        """Return this pair's operator on a ``shape`` sub-grid of this free surface (same pixels).

        Exact on the sub-grid (:func:`~roughcontact.elasticity.kernels.sub_grid_operator`): a contact that
        covers a quarter of the grid is solved with transforms a quarter the size. Built once per
        shape (the last :data:`~roughcontact.elasticity.kernels.SUB_GRIDS_KEPT` are kept); raises
        :class:`~roughcontact.errors.InputError` on a periodic surface.
        """
        return kernels.sub_grid_operator(
            self,
            self._windows,
            shape,
            lambda shape, size: TractionCompliance(
                shape, size, *self._bodies, boundary="free", workers=self._workers
            ),
        )

    def shear(self, qx: np.ndarray, qy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Relative tangential displacements (s_x, s_y) [m] of the shear tractions alone."""
        if "shear" not in self._prepared:
            self._prepared["shear"] = {name: self._fft.prepared(self._k[name]) for name in ("xx", "xy", "yy")}
        return self._symmetric_multiplier(self._prepared["shear"], qx, qy)

    def shear_energy(self, tx: np.ndarray, ty: np.ndarray) -> float:
        """Return t . C t [Pa m] of a traction field t = (t_x, t_y) [Pa] (C = :meth:`shear`).

        Computed in Fourier space by Parseval's theorem (the multiplier is real and symmetric):
        two forward transforms, against the four transforms and a product of
        ``np.vdot(t, shear(t))``; equal to it to round-off.
        """
        if "energy" not in self._prepared:
            weights = {name: self._fft.quadratic_form_weights(self._k[name]) for name in ("xx", "xy", "yy")}
            self._prepared["energy"] = weights
        weights = self._prepared["energy"]
        fft = self._fft
        with fft.staged() as staged:
            fx = self._forward_into_work(staged, tx)
            staged[...] = ty
            return _symmetric_power(weights["xx"], weights["xy"], weights["yy"], fx, fft.forward_staged())

    def _forward_into_work(self, staged: np.ndarray, field: np.ndarray) -> np.ndarray:
        """rfft2 of ``field`` into the operator's work spectrum (inside ``self._fft.staged()``)."""
        if self._spectrum is None:
            self._spectrum = np.empty(self._fft.spectrum_shape, dtype=complex)
        staged[...] = field
        self._spectrum[...] = self._fft.forward_staged()
        return self._spectrum

    def inverse_shear(self, sx: np.ndarray, sy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Apply the mode-wise inverse of the 2 x 2 shear kernel: tractions [Pa] of displacements [m].

        Exact for a periodic surface except the undetermined k = 0 mode, which gets the stiffness
        of the longest wavelength; for a free surface the inverse of the zero-padded operator
        (an approximate inverse, used as a preconditioner).
        """
        if "inverse" not in self._prepared:
            k = self._k
            det = k["xx"] * k["yy"] - k["xy"] ** 2
            regular = det > 0
            safe = np.where(regular, det, 1.0)
            inverse = {"xx": k["yy"] / safe, "yy": k["xx"] / safe, "xy": -k["xy"] / safe}
            stiffest_long = float(np.min(inverse["xx"][regular]))
            for name, value in inverse.items():
                value[~regular] = stiffest_long if name != "xy" else 0.0
            self._prepared["inverse"] = {name: self._fft.prepared(value) for name, value in inverse.items()}
        return self._symmetric_multiplier(self._prepared["inverse"], sx, sy)

    def _symmetric_multiplier(
        self, matrix: dict, ax: np.ndarray, ay: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray]:
        """Return (M_xx a_x + M_xy a_y, M_xy a_x + M_yy a_y) for a real symmetric 2 x 2 multiplier M.

        ``matrix`` holds M / N (:meth:`RealFFT2.prepared <roughcontact._backend.RealFFT2.prepared>`).
        Two forward and two inverse transforms on the operator's own buffers, the 2 x 2 product
        in one pass over the spectra (no temporaries).
        """
        fft = self._fft
        with fft.staged() as staged:
            fx = self._forward_into_work(staged, ax)
            staged[...] = ay
            fy = fft.forward_staged()
            _mix_symmetric(matrix["xx"], matrix["xy"], matrix["yy"], fx, fy)  # fy <- x result, fx <- y result
            sx = np.array(fft.backward_staged(fy))
            sy = np.array(fft.backward_staged(fx))
        return sx, sy

    def slip_from_pressure(self, pressure: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Relative tangential displacements [m] caused by the pressure (zero when D = 0)."""
        if not self.coupled:
            return np.zeros(self.shape), np.zeros(self.shape)
        fp = self._fft.forward(pressure)
        return self._fft.inverse(1j * self._k["xz"] * fp), self._fft.inverse(1j * self._k["yz"] * fp)

    def normal_from_shear(self, qx: np.ndarray, qy: np.ndarray) -> np.ndarray:
        """Gap-opening normal displacement [m] caused by the shear tractions (zero when D = 0)."""
        if not self.coupled:
            return np.zeros(self.shape)
        fx, fy = self._fft.forward(qx), self._fft.forward(qy)
        _odd_sum(self._k["xz"], self._k["yz"], fx, fy)
        return self._fft.inverse(fx)


@nb.njit(cache=True, nogil=True)
def _mix_symmetric(xx, xy, yy, fx, fy):
    """In place, mode by mode: fy <- xx fx + xy fy and fx <- xy fx + yy fy (real xx, xy, yy)."""
    a, b = fx.ravel(), fy.ravel()
    mxx, mxy, myy = xx.ravel(), xy.ravel(), yy.ravel()
    for i in range(a.size):
        x, y = a[i], b[i]
        b[i] = mxx[i] * x + mxy[i] * y
        a[i] = mxy[i] * x + myy[i] * y


@nb.njit(cache=True, nogil=True)
def _odd_sum(kx, ky, fx, fy):
    """In place, mode by mode: fx <- -i (kx fx + ky fy) (real kx, ky: the odd coupling kernels)."""
    a, b = fx.ravel(), fy.ravel()
    mx, my = kx.ravel(), ky.ravel()
    for i in range(a.size):
        s = mx[i] * a[i] + my[i] * b[i]
        a[i] = complex(s.imag, -s.real)


@nb.njit(cache=True, nogil=True)
def _symmetric_power(wxx, wxy, wyy, fx, fy):
    """Return sum wxx |fx|^2 + 2 wxy Re(conj(fx) fy) + wyy |fy|^2 over the modes."""
    a, b = fx.ravel(), fy.ravel()
    mxx, mxy, myy = wxx.ravel(), wxy.ravel(), wyy.ravel()
    total = 0.0
    for i in range(a.size):
        x, y = a[i], b[i]
        cross = x.real * y.real + x.imag * y.imag
        total += mxx[i] * (x.real * x.real + x.imag * x.imag) + 2.0 * mxy[i] * cross
        total += myy[i] * (y.real * y.real + y.imag * y.imag)
    return total
