r"""Statistics of a :class:`~roughcontact.topography.surface.Topography`, in SI units.

Amplitude parameters, slopes, curvatures, spectral moments, McCool asperity parameters, power
spectra, autocorrelation and summits.

All inputs are SI (heights and lengths in metres) and so are all outputs.

Conventions
-----------
* Every amplitude quantity is taken about the mean plane: ``z = heights - heights.mean()``.
  No tilt is removed here; level first (:func:`roughcontact.topography.process.level`).
* Two families of roughness names, as a profilometer and an areal instrument report them
  (:func:`summary`). Areal parameters of ISO 25178-2 (Sa, Sq, Ssk, Sku, Sz, Sdq, Sdr) use every
  point of a map. Profile parameters of ISO 4287 (Ra, Rq, Rsk, Rku, Rt, Rdq) use the profiles
  along x (the first axis), each about its own mean line, pooled over all the profiles of a map
  (:func:`profile_parameters`; the "from profile" convention of SurfaceTopography's ``Rq``). For
  a profile the two readings coincide and only the R names are given. On a map Rq differs from
  Sq: the profile means, and any variation across the profiles, are not in Rq.
* Finite differences. Second derivatives always use the compact centred stencil
  ``(z[i+1] - 2 z[i] + z[i-1]) / h**2`` (O(h^2); for a sinusoid of wavevector k the mean square
  is low by ``(sin(kh/2)/(kh/2))**4 ~ 1 - (kh)**2/6``). Being centred, the x and y terms of the
  Laplacian sit on the same point. First derivatives (``derivative=``):

  ``"forward"`` (default)
      ``(z[i+1] - z[i]) / h``: the slope of the segment between two neighbours, as in
      SurfaceTopography. Its mean square is low by ``(sin(kh/2)/(kh/2))**2 ~ 1 - (kh)**2/12``:
      O(h^2) for the averages used here, 4x smaller than the central error, and it still sees the
      Nyquist wave (0.64 of its slope). It is the default because rough surfaces carry power up to
      the pixel scale: on a self-affine map (H = 0.8, power up to the corners of the grid) the
      central rms slope is 11 % below the forward one (benchmarks/statistics.py).
  ``"central"``
      ``(z[i+1] - z[i-1]) / (2 h)`` (np.gradient in the interior): centred on the grid point, but
      its mean square is low by ``(sin(kh)/(kh))**2 ~ 1 - (kh)**2/3`` and it is blind to the
      Nyquist wave.

  Periodic surfaces wrap around (every point has a derivative); on non-periodic surfaces only
  the points whose whole stencil lies on the grid are averaged (no one-sided edge stencils).
* Power spectra use the wavevector ``q = 2 pi / wavelength`` [rad/m] and the normalisation of
  Jacobs, Junge and Pastewka (2017): ``h~(q) = dx dy sum h exp(-i q.r)`` and
  ``C(q) = |h~(q)|**2 / area``, so that Parseval reads
  ``m0 = sum_q C(q) dqx dqy / (2 pi)**2`` (2D, exact on the grid) and
  ``m0 = sum_q C1D(q) dq / (2 pi)`` over the two-sided spectrum (1D).

References
----------
Nayak, P. R. (1971). Random process model of rough surfaces. J. Lubr. Technol. 93, 398-407.
doi:10.1115/1.3451150

McCool, J. I. (1986). Comparison of models for the contact of rough surfaces. Wear 107, 37-60.
doi:10.1016/0043-1648(86)90045-1

Jacobs, T. D. B., Junge, T. and Pastewka, L. (2017). Quantitative characterization of surface
topography using spectral analysis. Surf. Topogr.: Metrol. Prop. 5, 013001.
doi:10.1088/2051-672X/aa51f8

ISO 25178-2:2012 (areal) and ISO 4287:1997 (profile) surface texture parameters.

Seed paper 002, eqs. 1-5 (spectral moments and McCool parameters of the SU-8 island).

The statistics are in this package's modules: :mod:`.amplitude`, :mod:`.slopes`,
:mod:`.moments` (spectral moments and McCool), :mod:`.spectra` (PSDs, autocorrelation) and
:mod:`.summits`; :func:`summary` gathers them. Import them from here.
"""

from __future__ import annotations

from ...errors import InputError
from ..plausible import is_flat
from ..surface import Topography
from .amplitude import profile_parameters, ra, rku, rq, rsk, rz
from .moments import (
    MCCOOL_MIN_BANDWIDTH as MCCOOL_MIN_BANDWIDTH,
)
from .moments import (
    McCoolParameters,
    SpectralMoments,
    mccool_parameters,
    mccool_parameters_of,
    spectral_moments,
)
from .slopes import DERIVATIVES as DERIVATIVES  # the schemes of derivative=
from .slopes import rms_curvature, rms_slope, sdr
from .spectra import WINDOWS as WINDOWS  # the windows of the power spectra
from .spectra import autocorrelation, psd_1d, psd_2d, psd_radial
from .summits import Summits, summits

__all__ = [
    "McCoolParameters",
    "SpectralMoments",
    "Summits",
    "autocorrelation",
    "mccool_parameters",
    "mccool_parameters_of",
    "psd_1d",
    "psd_2d",
    "psd_radial",
    "profile_parameters",
    "ra",
    "rku",
    "rms_curvature",
    "rms_slope",
    "rq",
    "rsk",
    "rz",
    "sdr",
    "spectral_moments",
    "summary",
    "summits",
]


_AREAL = "areal, ISO 25178-2"
_PROFILE = "profiles along x, ISO 4287"

SUMMARY = {
    "Sa": ("m", f"arithmetic mean height ({_AREAL})"),
    "Sq": ("m", f"root mean square height ({_AREAL})"),
    "Ssk": ("", f"skewness ({_AREAL})"),
    "Sku": ("", f"kurtosis ({_AREAL})"),
    "Sz": ("m", f"maximum height, highest peak to lowest pit ({_AREAL})"),
    "Sdq": ("", f"root mean square gradient ({_AREAL})"),
    "Sdr": ("", f"developed interfacial area ratio, 0.01 = 1 % ({_AREAL})"),
    "Ra": ("m", f"arithmetic mean deviation ({_PROFILE})"),
    "Rq": ("m", f"root mean square deviation ({_PROFILE})"),
    "Rsk": ("", f"skewness ({_PROFILE})"),
    "Rku": ("", f"kurtosis ({_PROFILE})"),
    "Rt": ("m", f"total height of the profile ({_PROFILE})"),
    "Rdq": ("", f"root mean square slope ({_PROFILE})"),
    "rms_slope": ("", "rms slope sqrt(2 m2), sqrt(m2) for a profile (paper 002)"),
    "rms_curvature": ("1/m", "rms curvature"),
    "m0": ("m^2", "spectral moment m0 (paper 002 eq. 1)"),
    "m2": ("", "spectral moment m2 (eq. 2)"),
    "m4": ("1/m^2", "spectral moment m4 (eq. 3)"),
    "bandwidth": ("", "bandwidth parameter alpha = m0 m4 / m2^2"),
    "summit_density": ("1/m^2", "summit density eta (McCool; a profile: of the isotropic surface it cuts)"),
    "summit_radius": ("m", "summit radius R_asp (eq. 4)"),
    "summit_height_std": ("m", "summit height deviation sigma_s (eq. 5)"),
}
"""Each entry of :func:`summary`: its SI unit ("" for a dimensionless one) and what it is."""


def summary(topography: Topography) -> dict[str, float]:
    """All scalar statistics of a surface, SI (the entries and units of :data:`SUMMARY`).

    A map gets the areal parameters of ISO 25178-2 (Sa, Sq, Ssk, Sku, Sz, Sdq, Sdr) and the
    profile parameters of ISO 4287 along x (:func:`profile_parameters`); a profile gets the profile
    parameters only. Then the rms slope and curvature, paper 002's spectral moments and McCool's
    summit parameters. Default (forward) first differences.
    Entries that are undefined for this surface are left out rather than set to NaN: the
    skewness and kurtosis of a flat surface, and the McCool entries when the moments give
    alpha < 0.8968 or a zero moment.

    A flat surface (:func:`~roughcontact.topography.plausible.is_flat`: its heights vary by
    round-off of their magnitude at most) has every amplitude, slope, curvature and moment 0 and
    none of the entries that need a roughness (skewness, kurtosis, McCool's summits): computed, its
    round-off would read as a roughness of 1e-25 m with summits of gigametres.

    Parameters
    ----------
    topography : Topography
        Surface (heights [m]).

    Returns
    -------
    dict of str to float
    """
    if is_flat(topography.heights):
        areal = ("Sa", "Sq", "Sz", "Sdq", "Sdr") if topography.dim == 2 else ()
        names = (*areal, "Ra", "Rq", "Rt", "Rdq", "rms_slope", "rms_curvature", "m0", "m2", "m4")
        return dict.fromkeys(names, 0.0)
    result = {}
    slope = rms_slope(topography)
    if topography.dim == 2:
        result = {"Sa": ra(topography), "Sq": rq(topography)}
        try:
            result |= {"Ssk": rsk(topography), "Sku": rku(topography)}
        except InputError:
            pass  # flat surface: skewness and kurtosis undefined, left out as documented
        result |= {"Sz": rz(topography), "Sdq": slope, "Sdr": sdr(topography)}
    result |= profile_parameters(topography)
    result |= {
        "rms_slope": slope,
        "rms_curvature": rms_curvature(topography),
    }
    moments = spectral_moments(topography)
    result |= {"m0": moments.m0, "m2": moments.m2, "m4": moments.m4}
    try:
        mccool = mccool_parameters(m0=moments.m0, m2=moments.m2, m4=moments.m4)
    except InputError:
        return result  # McCool entries undefined for these moments, left out as documented
    return result | {
        "bandwidth": mccool.bandwidth,
        "summit_density": mccool.summit_density,
        "summit_radius": mccool.summit_radius,
        "summit_height_std": mccool.summit_height_std,
    }
