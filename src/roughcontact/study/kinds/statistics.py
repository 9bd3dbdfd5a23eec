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
from ...units import format_si
from ..kind import CaseOutput, CaseParameters, Kind, caption
from ..schema import TopographyName
from .common import evenly_chosen, grid


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


@caption(
    "Height maps of up to four surfaces about their mean plane, as used (levelled files, generated "
    "surfaces as made); colours clipped to the 0.5-99.5 percentiles of each map, titles give Sq."
)
def _heights(records, context):
    from ...plotting.layout import legend, new_figure
    from ...plotting.study import map_axes

    chosen = evenly_chosen(records, 4)
    fields = [record.dataset() for record in chosen]
    if "y" not in fields[0].dims:
        figure, axes = new_figure(1, 1, width=7.0)
        for record, data in zip(chosen, fields, strict=True):
            axes[0][0].plot(data["x"] * 1e6, data["heights"] * 1e9, label=record.label)
        axes[0][0].set_xlabel("x (µm)")
        axes[0][0].set_ylabel("height (nm)")
        legend(axes[0][0])
        return figure
    figure, axes = new_figure(1, len(chosen), width=3.8, height=3.2)
    for column, (record, data) in enumerate(zip(chosen, fields, strict=True)):
        map_axes(axes[0][column], data["heights"], "height", "m")
        axes[0][column].set_title(f"{record.label}\nSq {format_si(record.scalars['Sq'], 'm', digits=3)}")
    return figure


@caption(
    "Power spectral density C(q) of every surface against the wavevector q = 2π/λ (radially averaged "
    "for maps; normalised so that it integrates to the mean square height, Jacobs et al. 2017)."
)
def _psd(records, context):
    from ...plotting.layout import legend, new_figure

    figure, axes = new_figure(1, 1)
    ax = axes[0][0]
    for record in records:
        data = record.dataset()
        ax.loglog(data["q"], data["psd"], label=record.label)
    ax.set_xlabel("wavevector q (rad/m)")
    ax.set_ylabel(f"PSD ({records[0].dataset()['psd'].attrs['units']})")
    ax.set_title("power spectral density")
    if 1 < len(records) <= 12:
        legend(ax, fontsize="small")
    return figure


KIND = Kind(
    name="statistics",
    summary="roughness statistics, spectral moments (m0, m2, m4) and McCool summit parameters",
    parameters=StatisticsParameters,
    run=run,
    units={"size_x": "m", "size_y": "m"} | {name: unit for name, (unit, _) in SUMMARY.items() if unit},
    figures={"heights": _heights, "psd": _psd},
    headline=("Sq", "Sa", "Rq", "Ra", "rms_slope", "summit_radius"),
    renamed={"surface": "topography"},
)
