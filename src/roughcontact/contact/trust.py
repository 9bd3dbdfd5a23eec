"""How much of a contact rests on points that are not measured surface, on a window's edge, on a few pixels.

A contact computed on a measured scan can look certain and rest on nothing measured:

* **filled points**: heights interpolated where the instrument recorded nothing
  (``Topography.filled``). Harmonic filling is smooth, but its rim follows the measured points
  around it, spikes included (SurfaceTopography's ``frt-2.frt``, 27 % undefined: 81 of the 109
  contact points at 20 MPa are filled ones);
* **specks**: measured points in groups of a few standing alone amid undefined ones
  (``Topography.specks``), often outliers that the filling turns into spikes (the other 28);
* **the edge of a free window**: a scan is a window cut from a larger surface. Solved with a free
  boundary, the window's edge acts as the edge of a punch when the contact reaches it, and the
  pressure there is singular (``sur-2.sur`` at 20 MPa: 1231 of the 1237 points above 200 MPa lie
  within 3 pixels of the edge). Filled points kept out of contact
  (:func:`roughcontact.topography.process.exclude_filled`) leave such an edge inside the window
  too, around them, whatever the boundary.

:func:`contact_shares` measures the share of the load and of the contact area each carries;
:func:`share_warnings` says when one is large enough to change the answer, and the fix.

An area resolved on a handful of pixels is a number of the grid, not of the surface:
:func:`area_resolution` says so for an area below :data:`RESOLVED_PIXELS` pixels, and
:func:`patch_resolution` for patch counts of which more than :data:`ONE_PIXEL_PATCHES` are single
pixels (the next finer scan would split or merge them).

The thresholds are choices, stated here: a share of the load above :data:`INVENTED_SHARE` on
filled points or specks; for the band within :data:`EDGE_PIXELS` of an edge, a share of the load
above :data:`EDGE_SHARE` that is :data:`EDGE_EXCESS` times its share of the contact area or more
(the pressure is concentrated at the edge: a punch edge; ``sur-2.sur`` at 20 MPa, 13 % of the load
on 3 % of the contact), or more than :data:`EDGE_MAJORITY` of the load whatever its pressure (the
contact is decided at the edge of the scan, e.g. a bowed or tilted scan: ``di-3.di`` at 20 MPa,
84 %). A patch that merely lies near the edge (``top-1.top`` at 20 MPa, 10 % of the load on 9 % of
the contact) is not flagged.
"""

from __future__ import annotations

import numpy as np
from scipy import ndimage

from ..units import format_si

__all__ = [
    "EDGE_EXCESS",
    "EDGE_MAJORITY",
    "ONE_PIXEL_PATCHES",
    "RESOLVED_PIXELS",
    "area_resolution",
    "patch_resolution",
    "EDGE_PIXELS",
    "EDGE_SHARE",
    "INVENTED_SHARE",
    "SHARES",
    "contact_shares",
    "edge_band",
    "share_warnings",
]

EDGE_PIXELS = 3
"""Width of the band along a free window's edge whose load is reported [pixels]."""

INVENTED_SHARE = 0.05
"""Share of the load on filled points (or on specks) above which a result warns."""

EDGE_SHARE = 0.1
"""Share of the load in the edge band above which a result warns if it is concentrated (EDGE_EXCESS)."""

EDGE_EXCESS = 2.0
"""Concentrated: the band's share of the load is this many times its share of the contact area or more."""

EDGE_MAJORITY = 0.5
"""Share of the load in the edge band above which a result warns whatever the pressure there."""

RESOLVED_PIXELS = 10
"""Pixels below which a contact (or pull-off) area is said to be unresolved."""

ONE_PIXEL_PATCHES = 0.5
"""Share of one-pixel patches above which a patch count is said to be unresolved (with 4 or more patches)."""

SHARES = {
    "filled_load_share": "share of the load carried by filled (interpolated) points",
    "filled_area_share": "share of the contact area on filled (interpolated) points",
    "speck_load_share": "share of the load carried by specks (isolated measured points)",
    "speck_area_share": "share of the contact area on specks",
    "edge_load_share": f"share of the load within {EDGE_PIXELS} pixels of an edge of the measured surface "
    "(a free window's edge, the rim of filled points kept out of contact)",
    "edge_area_share": f"share of the contact area within {EDGE_PIXELS} pixels of such an edge",
}
"""The scalars :func:`contact_shares` may return, and what each is (all dimensionless)."""


def edge_band(topography, boundary: str, pixels: int = EDGE_PIXELS) -> np.ndarray | None:
    """Return True within ``pixels`` of an edge of the measured surface; None where it has none.

    The edges are the window's (both ends of a profile) for a free boundary, and the rim of the
    filled points where they were kept out of contact (``info['filled_excluded']``).
    """
    shape = topography.shape
    band = np.zeros(shape, dtype=bool)
    if boundary == "free":
        for axis, n in enumerate(shape):
            index = [slice(None)] * len(shape)
            width = min(pixels, n)
            index[axis] = slice(0, width)
            band[tuple(index)] = True
            index[axis] = slice(n - width, n)
            band[tuple(index)] = True
    excluded = topography.filled if topography.info.get("filled_excluded") else None
    if excluded is not None:
        rim = ndimage.binary_dilation(excluded, iterations=pixels, border_value=0)
        if boundary == "periodic":
            rim = ndimage.binary_dilation(np.pad(excluded, pixels, mode="wrap"), iterations=pixels)
            rim = rim[tuple(slice(pixels, pixels + n) for n in shape)]
        band |= rim & ~excluded
    elif boundary != "free":
        return None
    return band


def _shares(pressure: np.ndarray, contact: np.ndarray, mask: np.ndarray) -> tuple[float, float]:
    load = float(pressure[contact].sum())
    on_mask = contact & mask
    load_share = float(pressure[on_mask].sum()) / load if load > 0 else 0.0
    count = int(np.count_nonzero(contact))
    return load_share, (int(np.count_nonzero(on_mask)) / count if count else 0.0)


def contact_shares(
    pressure: np.ndarray, topography, boundary: str, contact: np.ndarray | None = None
) -> dict[str, float]:
    """Return the shares of the load and of the contact area on filled points, specks and a free edge.

    Only the shares that apply are returned: ``filled_*`` for a surface with filled points,
    ``speck_*`` for one with specks, ``edge_*`` for a free boundary (see :data:`SHARES`).

    Parameters
    ----------
    pressure : ndarray
        Contact pressure [Pa] on the topography's grid, compressive positive; the contact is
        where it is positive (a tensile, adhesive pressure carries no load here).
    topography : Topography
        The surface solved (its ``filled`` and ``specks`` masks).
    boundary : {"periodic", "free"}
    contact : ndarray of bool, optional
        Where the surfaces touch, for a model that says so by other means than the sign of the
        pressure (an adhesive law's ``in_contact(gap)``: its tail of small tractions far from the
        contact is no contact). Default: where the pressure is positive.

    Returns
    -------
    dict
        Shares in [0, 1]; 0 when nothing is in contact.
    """
    pressure = np.asarray(pressure, dtype=float).reshape(topography.shape)
    contact = pressure > 0 if contact is None else np.asarray(contact, dtype=bool).reshape(topography.shape)
    shares = {}
    for name, mask in (("filled", topography.filled), ("speck", topography.specks)):
        if mask is not None:
            shares[f"{name}_load_share"], shares[f"{name}_area_share"] = _shares(pressure, contact, mask)
    band = edge_band(topography, boundary)
    if band is not None:
        shares["edge_load_share"], shares["edge_area_share"] = _shares(pressure, contact, band)
    return shares


def share_warnings(shares: dict[str, float], topography, boundary: str) -> list[str]:
    """Return a warning, with its fix, for each share of :func:`contact_shares` that is too large."""
    warnings = []
    filled = shares.get("filled_load_share", 0.0)
    if filled > INVENTED_SHARE:
        count = int(np.count_nonzero(topography.filled))
        warnings.append(
            f"{100 * filled:.3g} % of the load ({100 * shares['filled_area_share']:.3g} % of the contact "
            f"area) rests on filled points, heights interpolated where the file has none ({count} of "
            f"{topography.heights.size} points): that part of the answer is invented. Keep them out of "
            "contact («exclude_filled=true»), or crop the undefined region away."
        )
    specks = shares.get("speck_load_share", 0.0)
    if specks > INVENTED_SHARE:
        count = int(np.count_nonzero(topography.specks))
        warnings.append(
            f"{100 * specks:.3g} % of the load ({100 * shares['speck_area_share']:.3g} % of the contact "
            f"area) rests on specks, {count} measured points standing alone amid undefined ones (often "
            "outliers that the filling turns into spikes). Remove them before filling "
            "(«remove_specks=true»); roughcontact inspect lists them."
        )
    edge, on_edge = shares.get("edge_load_share", 0.0), shares.get("edge_area_share", 0.0)
    concentrated = edge > EDGE_SHARE and edge >= EDGE_EXCESS * on_edge
    if not (concentrated or edge > EDGE_MAJORITY):
        return warnings
    excluded = bool(topography.info.get("filled_excluded"))
    where = (
        f"an edge of the measured surface (the window's{' edge' if boundary == 'free' else ''} or the rim "
        "of the filled points kept out of contact)"
        if excluded
        else "the window's edge"
    )
    said = (
        f"{100 * edge:.3g} % of the load is carried within {EDGE_PIXELS} pixels of {where}, on "
        f"{100 * on_edge:.2g} % of the contact area"
    )
    if concentrated:
        said += (
            ": the pressure is concentrated there, as at the edge of a punch, because the surface "
            "beyond the edge is missing from the problem."
        )
    else:
        said += ": the contact is decided at the edge, by a surface that continues beyond the scan unseen."
    if excluded:
        fix = "Crop the scan to a region without undefined points («crop»), or a lower load."
    else:
        fix = (
            "Use a periodic boundary («boundary=periodic») where the surface may be repeated, a lower "
            "load or a larger scan; a scan bowed by the scanner needs «detrend=curvature»."
        )
    warnings.append(f"{said} {fix}")
    return warnings


def area_resolution(
    what: str,
    area: float,
    pixel_measure: float,
    dim: int = 2,
    fix: str = "Use a scan with smaller pixels over the contact, or a higher load.",
) -> list[str]:
    """Return a warning when ``area`` [m^2] (a profile: length [m]) spans fewer than RESOLVED_PIXELS pixels.

    Parameters
    ----------
    what : str
        The quantity in words (``"the contact area at pull-off"``).
    area : float
        The area [m^2] (contact length [m] of a profile); 0 (no contact) gives no warning.
    pixel_measure : float
        Area of a pixel [m^2] (its length [m] for a profile).
    dim : int
        2 for a map, 1 for a profile.
    fix : str
        What to do about it.
    """
    pixels = area / pixel_measure
    if not 0 < pixels < RESOLVED_PIXELS - 1e-9:
        return []
    unit = "m^2" if dim == 2 else "m"
    count = f"{pixels:.3g} pixel" + ("" if round(pixels) == 1 else "s")
    return [
        f"{what} is {count} ({format_si(area, unit)}): not resolved by the grid (fewer than "
        f"{RESOLVED_PIXELS} pixels), so it is a number of the pixel size ({format_si(pixel_measure, unit)}) "
        f"more than of the surface. {fix}"
    ]


def one_pixel_patches(mask: np.ndarray) -> tuple[int, int]:
    """Return (number of 4-connected patches, number of them that are a single pixel) of ``mask``."""
    labels, count = ndimage.label(mask)
    if count == 0:
        return 0, 0
    sizes = np.bincount(labels.ravel())[1:]
    return int(count), int(np.count_nonzero(sizes == 1))


def patch_resolution(patches: int, single: int, area: str = "contact area") -> list[str]:
    """Return a warning when more than ONE_PIXEL_PATCHES of 4 or more patches are single pixels.

    ``area`` names what to report instead of the patch count (``"contact length"`` for a profile).
    """
    if patches < 4 or single <= ONE_PIXEL_PATCHES * patches:
        return []
    return [
        f"{single} of the {patches} contact patches are single pixels: the patches are not resolved, and "
        f"their number and sizes would change on a finer scan. Report the {area} rather than the "
        "patch count, or use a scan with smaller pixels."
    ]
