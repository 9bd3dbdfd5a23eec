"""Study kind ``statistics``: roughness statistics of one topography per case.

Scalars from :func:`roughcontact.topography.statistics.summary` (the areal parameters of
ISO 25178-2 for a map: Sa, Sq, Ssk, Sku, Sz, Sdq, Sdr; the profile parameters of ISO 4287 along x:
Ra, Rq, Rsk, Rku, Rt, Rdq; rms slope and curvature, spectral moments m0, m2, m4 of paper 002
eqs. 1-3, and McCool's summit density, radius and height deviation, eqs. 4-5), plus the grid and
physical size. Fields: the heights and
the radially averaged PSD (maps) or the 1D PSD (profiles).

Figures: ``heights`` (height maps of up to four cases), ``psd`` (every case's PSD on one plot).
"""

from __future__ import annotations

import numpy as np

from ...topography.statistics import SUMMARY
from ..kind import CaseOutput, CaseParameters, Kind, figure
from ..schema import TopographyName
from .common import grid


class StatisticsParameters(CaseParameters):
    """Keys of a ``model = "statistics"`` analysis."""

    topography: TopographyName
    """The topography to describe."""


def run(parameters: StatisticsParameters, inputs) -> CaseOutput:
    """Statistics of the surface; the heights and PSD as fields."""
    import xarray as xr

    from ...topography.statistics import psd_1d, psd_radial, summary

    surface = inputs.topography(parameters.topography)
    scalars = {
        "points_x": surface.shape[0],
        "points_y": surface.shape[1] if surface.dim == 2 else 1,
        "size_x": surface.size[0],
        "size_y": surface.size[1] if surface.dim == 2 else 0.0,
    } | summary(surface)
    q, psd = psd_radial(surface) if surface.dim == 2 else psd_1d(surface)
    axes, coordinates = grid(surface)
    dataset = xr.Dataset(
        {
            "heights": (axes, surface.heights, {"units": "m"}),
            "psd": ("q", np.asarray(psd), {"units": "m^4" if surface.dim == 2 else "m^3"}),
        },
        coords=coordinates | {"q": ("q", np.asarray(q), {"units": "rad/m"})},
    )
    return CaseOutput(scalars, dataset)


KIND = Kind(
    name="statistics",
    summary="roughness statistics, spectral moments (m0, m2, m4) and McCool summit parameters",
    parameters=StatisticsParameters,
    run=run,
    units={"size_x": "m", "size_y": "m"} | {name: unit for name, (unit, _) in SUMMARY.items() if unit},
    figures={"heights": figure("topography.heights_figure"), "psd": figure("topography.psd_figure")},
    headline=("Sq", "Sa", "Rq", "Ra", "rms_slope", "summit_radius"),
    renamed={"surface": "topography"},
    references=(
        "paper002",
        "nayak1971",
        "mccool1986",
        "jacobs2017",
    ),
)
