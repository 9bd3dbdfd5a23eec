"""Figures of normal contact: pressure and gap maps, load-approach curves, von Mises maps.

``plot_*`` draw one :class:`~roughcontact.contact.result.NormalContactResult`; ``*_figure`` draw
a study's figure from several cases (:mod:`roughcontact.plotting.cases`).
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ..units import format_si, prefixed_scale
from .cases import caption, evenly_chosen, grouped, realisations_of, scalar_series, with_fields
from .layout import axes_for, legend


def _map(ax: Axes, result, values: np.ndarray, label: str, cmap: str):
    fig = ax.figure
    topography = result.topography
    size_scale, size_label = prefixed_scale(max(topography.size), "m")
    x, y = (c / size_scale for c in topography.coordinates())
    image = ax.pcolormesh(x, y, values.T, cmap=cmap, shading="auto", rasterized=True)
    ax.set_aspect("equal")
    ax.set_xlabel(f"x ({size_label})")
    ax.set_ylabel(f"y ({size_label})")
    fig.colorbar(image, ax=ax, label=label)


def plot_pressure(result, ax: Axes | None = None, *, cmap: str = "magma"):
    """Draw the contact pressure map of a 2D NormalContactResult; returns ``(fig, ax)``."""
    fig, ax = axes_for(ax)
    scale, unit = prefixed_scale(float(result.pressure.max()) or 1.0, "Pa")
    _map(ax, result, result.pressure / scale, f"pressure ({unit})", cmap)
    ax.set_title(f"contact pressure, {100 * result.contact_fraction:.2g} % in contact")
    return fig, ax


def plot_gap(result, ax: Axes | None = None, *, cmap: str = "viridis"):
    """Draw the gap map of a 2D NormalContactResult (contact where the gap is zero); returns ``(fig, ax)``."""
    fig, ax = axes_for(ax)
    scale, unit = prefixed_scale(float(np.max(result.gap)) or 1e-9, "m")
    _map(ax, result, result.gap / scale, f"gap ({unit})", cmap)
    ax.set_title(f"gap, mean {result.mean_gap / scale:.3g} {unit}")
    return fig, ax


def plot_load_approach(curve: dict, ax: Axes | None = None, *, label: str | None = None):
    """Draw force against approach from ``LoadUnloadResult.curve()`` (or any dict with those keys)."""
    fig, ax = axes_for(ax)
    approach, force = np.asarray(curve["approach"]), np.asarray(curve["force"])
    a_scale, a_unit = prefixed_scale(float(np.max(np.abs(approach))) or 1e-9, "m")
    f_scale, f_unit = prefixed_scale(float(np.max(np.abs(force))) or 1.0, "N")
    branches = np.asarray(curve.get("branch", ["loading"] * len(force)))
    for branch, style in (("loading", "-o"), ("unloading", "--s")):
        keep = branches == branch
        if keep.any():
            name = branch if label is None else f"{label}, {branch}"
            ax.plot(approach[keep] / a_scale, force[keep] / f_scale, style, ms=3, label=name)
    ax.set_xlabel(f"approach ({a_unit})")
    ax.set_ylabel(f"force ({f_unit})")
    legend(ax)
    ax.grid(True, alpha=0.3)
    return fig, ax


def plot_contact_area(curve: dict, ax: Axes | None = None):
    """Draw real contact area against force from a load curve dict; returns ``(fig, ax)``."""
    fig, ax = axes_for(ax)
    ax.plot(np.asarray(curve["force"]), np.asarray(curve["contact_area"]), "-o", ms=3)
    ax.set_xlabel("force (N)")
    ax.set_ylabel("real contact area (m²)")
    ax.grid(True, alpha=0.3)
    return fig, ax


def plot_von_mises(stress, depth_index: int, ax: Axes | None = None, *, cmap: str = "inferno"):
    """Draw the von Mises stress on the plane ``stress.depths[depth_index]``; returns ``(fig, ax)``."""
    fig, ax = axes_for(ax)
    vm = stress.von_mises()[depth_index]
    scale, unit = prefixed_scale(float(vm.max()) or 1.0, "Pa")
    size_scale, size_label = prefixed_scale(max(stress.size), "m")
    nx, ny = vm.shape
    x = np.arange(nx) * stress.size[0] / nx / size_scale
    y = np.arange(ny) * stress.size[1] / ny / size_scale
    image = ax.pcolormesh(x, y, vm.T / scale, cmap=cmap, shading="auto", rasterized=True)
    ax.set_aspect("equal")
    ax.set_xlabel(f"x ({size_label})")
    ax.set_ylabel(f"y ({size_label})")
    fig.colorbar(image, ax=ax, label=f"von Mises ({unit})")
    d_scale, d_unit = prefixed_scale(float(stress.depths[depth_index]) or 1e-9, "m")
    ax.set_title(f"von Mises at z = {stress.depths[depth_index] / d_scale:.3g} {d_unit}")
    return fig, ax


def plot_contact_overview(result) -> Figure:
    """Return a two-panel figure: pressure and gap maps of a NormalContactResult."""
    fig = Figure(figsize=(10.0, 4.2), layout="constrained")
    left, right = fig.subplots(1, 2)
    plot_pressure(result, left)
    plot_gap(result, right)
    return fig


@caption(
    "Contact pressure (top) and gap (bottom) of up to four cases; each row shares one colour scale, "
    "from 0 to the 99.5th percentile of its nonzero values. Titles give the case and the fraction of "
    "the nominal area in contact. A line scan (plane-strain line contact) is drawn as profiles: "
    "pressure and gap against x, one curve per case."
)
def contact_maps_figure(cases):
    """Draw pressure and gap of up to four cases with fields (profiles for line scans); None without any."""
    from .layout import colour_scale, legend, new_figure, shared_colorbar
    from .study import map_axes, profile_axes

    chosen = evenly_chosen(with_fields(cases), 4)
    fields = [case.dataset() for case in chosen]
    if not chosen:
        return None
    if "y" not in fields[0].dims:
        figure, axes = new_figure(2, 1, width=6.4, height=2.6)
        labels = [
            f"{r.label}: {100 * r.scalars['contact_fraction']:.3g} % in contact" if len(chosen) > 1 else None
            for r in chosen
        ]
        profile_axes(axes[0][0], [data["pressure"] for data in fields], labels, "pressure", "Pa")
        profile_axes(axes[1][0], [data["gap"] for data in fields], labels, "gap", "m")
        if len(chosen) > 1:
            legend(axes[0][0])
        else:
            axes[0][0].set_title(
                f"{chosen[0].label}\n{100 * chosen[0].scalars['contact_fraction']:.3g} % in contact"
            )
        return figure
    figure, axes = new_figure(2, len(chosen), width=3.6 if len(chosen) > 1 else 4.6, height=3.2)
    for row, (name, cmap) in enumerate((("pressure", "magma"), ("gap", "viridis"))):
        unit = "Pa" if name == "pressure" else "m"
        shared = colour_scale(*(data[name] for data in fields), from_zero=True)
        for column, data in enumerate(fields):
            image = map_axes(
                axes[row][column], data[name], name, unit, cmap=cmap, scale=shared, colorbar=False
            )
        shared_colorbar(image, axes[row], name, unit, shared)
    for case, ax in zip(chosen, axes[0], strict=True):
        ax.set_title(f"{case.label}\n{100 * case.scalars['contact_fraction']:.3g} % in contact")
    return figure


def _curve_of_cases(cases, x: str, y: str, scales: tuple[float, float], labels: tuple[str, str, str]):
    """One scalar against another over the cases, a line per sample (None for fewer than 2 cases).

    Cases that differ only in their realisation are one point: the means with their 95 % intervals
    as error bars (both ways), each realisation a small faint dot of the line's colour.
    """
    from ..spread import spread
    from .layout import legend, new_figure

    if len(cases) < 2:
        return None
    figure, axes = new_figure(1, 1)
    ax = axes[0][0]
    groups = grouped(cases)
    for sample, group in groups.items():
        realisations = list(realisations_of(group).values())
        if all(len(r) == 1 for r in realisations):
            abscissa, ordinate = scalar_series(group, x, y)
            ax.plot(abscissa * scales[0], ordinate * scales[1], "o-", label=sample or None)
            continue
        spreads = [
            (spread(float(c.scalars[x]) for c in r), spread(float(c.scalars[y]) for c in r))
            for r in realisations
        ]
        spreads.sort(key=lambda pair: pair[0].mean)
        count = max(sx.n for sx, _ in spreads)
        (line,) = ax.plot(
            [sx.mean * scales[0] for sx, _ in spreads],
            [sy.mean * scales[1] for _, sy in spreads],
            "-",
            label=f"{sample + ': ' if sample else ''}mean ± 95 % CI of {count} realisations",
        )
        ax.errorbar(
            [sx.mean * scales[0] for sx, _ in spreads],
            [sy.mean * scales[1] for _, sy in spreads],
            xerr=[np.nan_to_num(sx.half_width) * scales[0] for sx, _ in spreads],
            yerr=[np.nan_to_num(sy.half_width) * scales[1] for _, sy in spreads],
            fmt="o",
            capsize=3,
            color=line.get_color(),
        )
        abscissa, ordinate = scalar_series(group, x, y)
        ax.plot(abscissa * scales[0], ordinate * scales[1], ".", alpha=0.35, color=line.get_color())
    ax.set_xlabel(labels[0])
    ax.set_ylabel(labels[1])
    ax.set_title(labels[2])
    if ax.get_legend_handles_labels()[1]:  # samples, or what the realisations' marks mean
        legend(ax)
    return figure


@caption(
    "Real contact area as a fraction of the nominal area against the nominal mean pressure, one line "
    "per sample."
)
def area_load_figure(cases):
    """Draw the real contact fraction against the mean pressure over the cases, a line per sample."""
    labels = (
        "nominal mean pressure (MPa)",
        "real contact area (% of nominal)",
        "real contact area against load",
    )
    return _curve_of_cases(cases, "mean_pressure", "contact_fraction", (1e-6, 100.0), labels)


@caption(
    "Normal force (per unit length for a line scan) against the rigid approach counted from the "
    "first touch, one line per sample."
)
def load_approach_figure(cases):
    """Draw the force (per length for a line scan) against the approach over the cases."""
    if cases and "force_per_length" in cases[0].scalars:
        labels = ("approach (nm)", "force per length (N/m)", "load against approach")
        return _curve_of_cases(cases, "approach", "force_per_length", (1e9, 1.0), labels)
    labels = ("approach (nm)", "force (µN)", "load against approach")
    return _curve_of_cases(cases, "approach", "force", (1e9, 1e6), labels)


@caption(
    "Von Mises stress at the first stored depth below the surface for up to four cases, on one colour "
    "scale from 0 to the largest value of all the panels."
)
def von_mises_figure(cases):
    """Draw the von Mises maps at the first stored depth of up to four cases; None without any."""
    from .layout import colour_scale, new_figure, shared_colorbar
    from .study import map_axes

    chosen = evenly_chosen([r for r in cases if "max_von_mises" in r.scalars], 4)
    if not chosen:
        return None
    figure, axes = new_figure(1, len(chosen), width=3.6 if len(chosen) > 1 else 4.6, height=3.2)
    fields = [case.dataset()["von_mises"].isel(depth=0) for case in chosen]
    shared = colour_scale(*fields, from_zero=True, percentiles=(0, 100))  # smooth: the full range
    for column, (case, field) in enumerate(zip(chosen, fields, strict=True)):
        ax = axes[0][column]
        image = map_axes(ax, field, "von Mises stress", "Pa", cmap="inferno", scale=shared, colorbar=False)
        ax.set_title(f"{case.label}\nz = {format_si(float(field.depth), 'm', digits=3)}")
    shared_colorbar(image, axes[0], "von Mises stress", "Pa", shared)
    return figure
