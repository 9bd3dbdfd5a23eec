"""Immutable result of a normal contact solve, with its derived quantities and ``to_xarray()``."""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import Any, ClassVar

import numpy as np
from scipy import ndimage

from ..display_html import NotebookDisplay
from ..messages import as_messages
from ..results import levelling_of
from ..topography import Topography
from .area import corrected_contact_count, perimeter_switches
from .trust import area_resolution, contact_shares, one_pixel_patches, patch_resolution, share_warnings


def count_patches(mask: np.ndarray, *, periodic: bool) -> int:
    """Count 4-connected contact patches; patches joined across a periodic edge count once."""
    labels, count = ndimage.label(mask)
    if not periodic or count == 0:
        return int(count)
    parent = np.arange(count + 1)

    def root(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    pairs = [(labels[0, :], labels[-1, :])]
    if labels.shape[1] > 1:
        pairs.append((labels[:, 0], labels[:, -1]))
    for first, last in pairs:
        for a, b in zip(first, last, strict=True):
            if a and b:
                ra, rb = root(int(a)), root(int(b))
                if ra != rb:
                    parent[max(ra, rb)] = min(ra, rb)
    return len({root(i) for i in range(1, count + 1)})


@dataclass(frozen=True)
class NormalContactResult(NotebookDisplay):
    """Converged normal contact of a surface against a rigid flat (all SI).

    Attributes
    ----------
    topography : Topography
        The surface that was solved (for two rough bodies: their composite).
    pressure : ndarray
        Contact pressure [Pa], >= 0 (<= hardness for elastic-plastic contact).
    gap : ndarray
        Gap between the deformed surface and the flat [m]; 0 in elastic contact, < 0 only where
        the pressure is at the hardness (the overlap that became plastic deformation).
    displacement : ndarray
        Elastic surface displacement into the body [m].
    approach : float
        Rigid-body approach of the flat [m], from the first touch of the undeformed surface
        (periodic half-space: with the mean elastic displacement taken as zero).
    contact_modulus : float
        E* [Pa] (of the layered body when a layer was given).
    boundary : str
        "periodic" or "free".
    iterations : int
        Conjugate-gradient iterations on the whole grid and on the box around the contact (not
        those of the coarse levels that warm-start a solve, :mod:`roughcontact.contact._box`);
        under load control with a hardness, of all the displacement-controlled solves of the
        root search for the approach.
    residual : float
        Scale-free residual at the returned iterate (see ``roughcontact.contact._constrained_cg``).
    tolerance : float
        The tolerance it met.
    hardness : float or None
        Pressure cap [Pa] of elastic-perfectly-plastic contact.
    parameters : dict
        What was asked for (load or approach, options) and the package version.
    """

    topography: Topography
    pressure: np.ndarray
    gap: np.ndarray
    displacement: np.ndarray
    approach: float
    contact_modulus: float
    boundary: str
    iterations: int
    residual: float
    tolerance: float
    hardness: float | None = None
    parameters: dict[str, Any] = field(default_factory=dict)

    FIGURE = "contact.plot_pressure"
    """The figure a notebook shows under the table of scalars (:mod:`roughcontact.display_html`)."""

    UNITS: ClassVar[dict[str, str]] = {
        "force": "N",
        "mean_pressure": "Pa",
        "approach": "m",
        "contact_area": "m^2",
        "contact_area_corrected": "m^2",
        "mean_gap": "m",
        "max_pressure": "Pa",
        "contact_modulus": "Pa",
        "force_per_length": "N/m",
        "contact_length": "m",
    }
    """SI unit of each dimensional scalar of :meth:`scalars`. A line scan (plane-strain line contact)
    reports ``force_per_length`` and ``contact_length`` instead of ``force`` and ``contact_area``, and no
    corrected area (:mod:`roughcontact.contact.area` corrects maps)."""

    def __post_init__(self):
        for name in ("pressure", "gap", "displacement"):
            getattr(self, name).setflags(write=False)

    @property
    def converged(self) -> bool:
        """Always True: unconverged solves raise instead of returning."""
        return bool(self.residual <= self.tolerance)

    @property
    def force(self) -> float:
        """Total normal force [N] (for a line scan: per unit length [N/m])."""
        return float(self.pressure.sum() * self._pixel_measure)

    @property
    def _pixel_measure(self) -> float:
        return self.topography.pixel_area if self.topography.dim == 2 else self.topography.spacing[0]

    @property
    def mean_pressure(self) -> float:
        """Force over the nominal area [Pa]."""
        return float(self.pressure.mean())

    @property
    def contact_mask(self) -> np.ndarray:
        """True where the pressure is positive."""
        return self.pressure > 0

    @property
    def contact_fraction(self) -> float:
        """Real over nominal contact area [-]."""
        return float(np.count_nonzero(self.contact_mask) / self.pressure.size)

    @property
    def contact_area(self) -> float:
        """Real contact area [m^2] (for a line scan: contact length [m])."""
        return float(np.count_nonzero(self.contact_mask) * self._pixel_measure)

    @cached_property
    def perimeter_switches(self) -> int:
        """Contact/no-contact switches along the grid lines (across the period when periodic); maps only.

        The perimeter of the contact in pixels, :func:`roughcontact.contact.area.perimeter_switches`.
        """
        return perimeter_switches(self.contact_mask, periodic=self.boundary == "periodic")

    @property
    def contact_fraction_corrected(self) -> float:
        """Real over nominal contact area corrected for the pixelated perimeter [-] (maps only).

        :math:`(N_a - c M)/N^2` of Yastrebov et al. (2017), :mod:`roughcontact.contact.area`: the raw
        :attr:`contact_fraction` less ``c = (pi - 1 + ln 2)/24`` pixel per perimeter switch.
        """
        return (
            corrected_contact_count(self.contact_mask, periodic=self.boundary == "periodic")
            / self.pressure.size
        )

    @property
    def contact_area_corrected(self) -> float:
        """Real contact area corrected for the pixelated perimeter [m^2] (maps only, see above)."""
        return self.contact_fraction_corrected * self.topography.area

    @cached_property
    def number_of_patches(self) -> int:
        """Number of connected contact patches (4-connectivity, periodic wrap when periodic).

        Cached: the labelling is the costliest scalar, and ``scalars()`` and ``to_xarray()`` both ask.
        """
        mask = self.contact_mask if self.contact_mask.ndim == 2 else self.contact_mask[:, None]
        return count_patches(mask, periodic=self.boundary == "periodic")

    @cached_property
    def one_pixel_patches(self) -> int:
        """Number of contact patches that are a single pixel (none joined across a periodic edge)."""
        mask = self.contact_mask if self.contact_mask.ndim == 2 else self.contact_mask[:, None]
        return one_pixel_patches(mask)[1]

    @property
    def mean_gap(self) -> float:
        """Mean gap over the whole surface [m]."""
        return float(self.gap.mean())

    @property
    def plastic_mask(self) -> np.ndarray:
        """True where the pressure is at the hardness (all False for elastic contact)."""
        if self.hardness is None:
            return np.zeros(self.pressure.shape, dtype=bool)
        return self.pressure >= self.hardness

    @property
    def plastic_deformation(self) -> np.ndarray:
        """Plastic flow depth [m]: the overlap -gap where the pressure is at the hardness."""
        return np.where(self.plastic_mask, np.maximum(-self.gap, 0.0), 0.0)

    @cached_property
    def shares(self) -> dict[str, float]:
        """Shares of the load and the contact area on filled points, specks and a free window's edge.

        See :func:`roughcontact.contact.trust.contact_shares`; only those that apply.
        """
        return contact_shares(self.pressure, self.topography, self.boundary)

    def scalars(self) -> dict[str, float]:
        """Return the scalar results as a flat dictionary (SI), the :attr:`shares` last.

        A surface read from a file says how it was levelled: ``levelling`` (``"plane"``, ``"none"``,
        ..., :func:`roughcontact.results.levelling_of`).

        A line contact (1D) says what its numbers are: ``force_per_length`` [N/m] and
        ``contact_length`` [m] in place of ``force`` and ``contact_area``. A map reports beside the
        raw pixel count its area corrected for the pixelated perimeter, ``contact_fraction_corrected``
        and ``contact_area_corrected``, and the ``perimeter_switches`` the correction rests on
        (:mod:`roughcontact.contact.area`).
        """
        line = self.topography.dim == 1
        return (
            {
                "force_per_length" if line else "force": self.force,
                "mean_pressure": self.mean_pressure,
                "approach": self.approach,
                "contact_fraction": self.contact_fraction,
                "contact_length" if line else "contact_area": self.contact_area,
            }
            | (
                {}
                if line
                else {
                    "contact_fraction_corrected": self.contact_fraction_corrected,
                    "contact_area_corrected": self.contact_area_corrected,
                    "perimeter_switches": self.perimeter_switches,
                }
            )
            | {
                "number_of_patches": self.number_of_patches,
                "one_pixel_patches": self.one_pixel_patches,
                "mean_gap": self.mean_gap,
                "max_pressure": float(self.pressure.max()),
                "iterations": int(self.iterations),
                "residual": float(self.residual),
                "contact_modulus": self.contact_modulus,
            }
            | levelling_of(self.topography)
            | self.shares
        )

    @as_messages
    def range_warnings(self, *, slope_pressure: float = 0.1, advise_hardness: bool = True) -> list[str]:
        """Say where this solution leaves the range of the model that produced it (empty when it does not).

        * Elastic contact with a peak pressure above ``slope_pressure * E*``: the half-space
          (Boussinesq) solution assumes small surface slopes; a local pressure of order E* means
          local slopes of order one (p ~ E* ``|grad h|`` / 2 for a wedge), where the linear theory
          and the material's elasticity both fail. The usual remedies are a hardness (plastic cap)
          or a coarser, instrument-limited scan.
        * Full contact (every point touching): the answer no longer depends on the roughness,
          and a free (non-periodic) surface is then carried at its edges.
        * A large share of the load on filled points, on specks or at a free window's edge
          (:func:`roughcontact.contact.trust.share_warnings`).
        * A contact area of fewer than ten pixels, or patches most of which are single pixels
          (:func:`roughcontact.contact.trust.area_resolution`, ``patch_resolution``).

        Parameters
        ----------
        slope_pressure : float
            Largest peak pressure over E* that counts as small-slope (default 0.1).
        advise_hardness : bool
            Name a hardness as the remedy of large slopes (False where the caller compares elastic
            models and takes none, as :func:`roughcontact.theory.compare_theories` does).
        """
        notes = []
        peak = float(self.pressure.max())
        if self.hardness is None and peak > slope_pressure * self.contact_modulus:
            remedy = "give a «hardness» for elastic-plastic contact, or " if advise_hardness else ""
            notes.append(
                f"peak pressure {peak / self.contact_modulus:.2g} E* (over {slope_pressure:g} E*): "
                f"local slopes beyond the small-slope elastic theory; {remedy}treat the peak values as "
                "indicative only."
            )
        if self.contact_fraction >= 1.0:
            notes.append("full contact: every point touches, so the roughness no longer matters.")
        notes += area_resolution(
            "the contact area", self.contact_area, self._pixel_measure, self.topography.dim
        )
        notes += patch_resolution(self.number_of_patches, self.one_pixel_patches)
        return notes + share_warnings(self.shares, self.topography, self.boundary)

    def to_xarray(self):
        """Return an ``xarray.Dataset``: fields on x (and y) coordinates, scalars as attributes."""
        import xarray as xr

        coords = {name: ("x", "y")[i] for i, name in enumerate(("x", "y")[: self.topography.dim])}
        axes = tuple(coords.values())
        grid = dict(zip(axes, self.topography.coordinates(), strict=True))
        units = {"pressure": "Pa", "gap": "m", "displacement": "m", "heights": "m"}
        fields = {
            "pressure": self.pressure,
            "gap": self.gap,
            "displacement": self.displacement,
            "heights": self.topography.heights,
        }
        data = {name: (axes, np.asarray(values), {"units": units[name]}) for name, values in fields.items()}
        attributes = {k: v for k, v in self.scalars().items()}
        attributes.update(
            boundary=self.boundary,
            tolerance=self.tolerance,
            hardness=np.nan if self.hardness is None else self.hardness,
        )
        attributes.update({f"parameter_{k}": str(v) for k, v in self.parameters.items()})
        return xr.Dataset(data, coords={a: (a, c, {"units": "m"}) for a, c in grid.items()}, attrs=attributes)
