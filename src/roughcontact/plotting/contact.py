"""Figures of normal contact: contact-area, pressure and gap maps, load-approach curves, von Mises maps.

``plot_*`` draw one :class:`~roughcontact.contact.result.NormalContactResult`; ``*_figure`` draw
a study's figure from several cases (:mod:`roughcontact.plotting.cases`).
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ..cases import branch_points, evenly_chosen, grouped, realisations_of, scalar_series, with_fields
from ..units import format_si, prefixed_scale
from .cases import caption
from .layout import axes_for, legend
from .study import map_length_scale


def _field_map(ax: Axes, result, name: str, unit: str, cmap: str, *, empty: float | None):
    """Draw a result's field on the colour scale of the study figures, ``empty`` in grey.

    The scale runs from 0 to the 99.5th percentile of the nonzero values, so that no single spike
    sets it; the colour bar says so.
    """
    from .layout import colour_scale
    from .study import map_axes

    field = result.to_xarray()[name]
    map_axes(ax, field, name, unit, cmap=cmap, scale=colour_scale(field, from_zero=True), empty=empty)


def plot_pressure(result, ax: Axes | None = None, *, cmap: str = "magma"):
    """Draw the contact pressure map of a 2D NormalContactResult (grey: no contact); returns ``(fig, ax)``."""
    fig, ax = axes_for(ax)
    _field_map(ax, result, "pressure", "Pa", cmap, empty=0.0)
    ax.set_title(f"contact pressure, {100 * result.contact_fraction:.2g} % in contact")
    return fig, ax


def plot_gap(result, ax: Axes | None = None, *, cmap: str = "viridis"):
    """Draw the gap map of a 2D NormalContactResult (contact where the gap is zero); returns ``(fig, ax)``."""
    fig, ax = axes_for(ax)
    _field_map(ax, result, "gap", "m", cmap, empty=None)
    ax.set_title(f"gap, mean {format_si(result.mean_gap, 'm', digits=3)}")
    return fig, ax


def plot_load_approach(curve: dict, ax: Axes | None = None, *, label: str | None = None):
    """Draw force against approach from ``LoadUnloadResult.curve()`` (or any dict with those keys).

    The unloading branch is drawn from the peak, the last point of the loading branch, so that
    the two meet as the path does.
    """
    fig, ax = axes_for(ax)
    approach, force = np.asarray(curve["approach"]), np.asarray(curve["force"])
    a_scale, a_unit = prefixed_scale(float(np.max(np.abs(approach))) or 1e-9, "m")
    f_scale, f_unit = prefixed_scale(float(np.max(np.abs(force))) or 1.0, "N")
    branches = np.asarray(curve.get("branch", ["loading"] * len(force)))
    for branch, style in (("loading", "-o"), ("unloading", "--s")):
        keep = branch_points(branches, branch)
        if keep.size:
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
    ax.set_title(f"von Mises at z = {format_si(float(stress.depths[depth_index]), 'm', digits=3)}")
    return fig, ax


def plot_contact_overview(result) -> Figure:
    """Return a two-panel figure: pressure and gap maps of a NormalContactResult."""
    fig = Figure(figsize=(10.0, 4.2), layout="constrained")
    left, right = fig.subplots(1, 2)
    plot_pressure(result, left)
    plot_gap(result, right)
    return fig


MARKED_BELOW = 0.02
"""Contact fraction below which each contact patch is ringed on the maps and the most loaded one is
shown enlarged: under it the patches are a few pixels each and vanish in a map of the whole scan."""
MARKED_PATCHES = 400
"""At most this many patches are ringed (more rings than that hide the map)."""
ZOOM_SIDE = 1 / 8
"""Side of the enlarged window, as a fraction of the scan's (at least three times the patch)."""


@caption(
    "Up to four cases, one column each. Top: the real contact area (red) on the nominal area, each "
    "contact patch ringed where less than 2 % of the area is in contact. Then the contact pressure "
    "(grey: no contact) and the gap, each row on one colour scale from 0 to the 99.5th percentile of its "
    "nonzero values (values above it in the top colour). Below 2 % contact, a last row enlarges the "
    "patch that carries the largest load (its window framed on the pressure map). Titles give the case "
    "and the fraction of the nominal area in contact. A line scan (plane-strain line contact) is drawn "
    "as profiles: pressure and gap against x, one curve per case."
)
def contact_maps_figure(cases):
    """Draw contact area, pressure and gap of up to four cases (profiles for line scans); None without any."""
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
    sparse = [float(case.scalars["contact_fraction"]) < MARKED_BELOW for case in chosen]
    rows = 3 + any(sparse)
    wide = fields[0].sizes["x"] > 1.3 * fields[0].sizes["y"]  # colour bars below wide maps, beside tall ones
    figure, axes = new_figure(rows, len(chosen), width=3.6 if len(chosen) > 1 else 4.6, height=3.2)
    for column, (case, data) in enumerate(zip(chosen, fields, strict=True)):
        contact = np.asarray(data["pressure"]) > 0
        ax = axes[0][column]
        _contact_area_axes(ax, data["pressure"], contact, ring=sparse[column])
        ax.set_title(f"{case.label}\n{100 * case.scalars['contact_fraction']:.3g} % in contact")
    location = "bottom" if wide else "right"
    scales = {
        name: colour_scale(*(data[name] for data in fields), from_zero=True) for name in ("pressure", "gap")
    }
    for row, (name, cmap) in enumerate((("pressure", "magma"), ("gap", "viridis")), start=1):
        unit = "Pa" if name == "pressure" else "m"
        shared = scales[name]
        for column, data in enumerate(fields):
            image = map_axes(
                axes[row][column], data[name], name, unit, cmap=cmap, scale=shared, colorbar=False,
                empty=0.0 if name == "pressure" else None,
            )  # fmt: skip
            axes[row][column].set_title(name if name == "gap" else "contact pressure (grey: no contact)")
        shared_colorbar(image, axes[row], name, unit, shared, location=location)
    if rows == 4:
        for column, data in enumerate(fields):
            ax = axes[3][column]
            if not sparse[column]:
                ax.set_axis_off()
                fraction = 100 * chosen[column].scalars["contact_fraction"]
                words = f"{fraction:.2g} % in contact:\nvisible without enlargement"
                ax.text(0.5, 0.5, words, ha="center", va="center", transform=ax.transAxes)
                continue
            window = _most_loaded_window(np.asarray(data["pressure"]))
            image = map_axes(
                ax, data["pressure"][window], "pressure", "Pa", cmap="magma", scale=scales["pressure"],
                colorbar=False, empty=0.0,
            )  # fmt: skip
            ax.set_title("enlarged: the most loaded patch")
            _frame(axes[1][column], data["pressure"], window)
        shared_colorbar(image, axes[3], "pressure", "Pa", scales["pressure"], location=location)
    return figure


def _contact_area_axes(ax: Axes, pressure, contact: np.ndarray, *, ring: bool) -> None:
    """Draw the contact set (red on light grey) of a stored pressure field; ring each patch when ``ring``."""
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch
    from scipy import ndimage

    size_scale, size_unit = map_length_scale(pressure)
    xs, ys = np.asarray(pressure["x"]) / size_scale, np.asarray(pressure["y"]) / size_scale
    colours = ListedColormap(["0.9", "#b2182b"])
    ax.pcolormesh(
        xs, ys, contact.T.astype(float), cmap=colours, vmin=0, vmax=1, shading="auto", rasterized=True
    )
    ax.set_aspect("equal")
    ax.set_xlabel(f"x ({size_unit})")
    ax.set_ylabel(f"y ({size_unit})")
    handles = [Patch(color="#b2182b", label="in contact")]
    labels, count = ndimage.label(contact)
    if ring and 0 < count <= MARKED_PATCHES:
        centres = ndimage.center_of_mass(contact, labels, range(1, count + 1))
        spacing = (xs[1] - xs[0] if xs.size > 1 else 1.0, ys[1] - ys[0] if ys.size > 1 else 1.0)
        least = 0.03 * max(np.ptp(xs), np.ptp(ys))
        extents = ndimage.find_objects(labels)
        sizes = [max(e[0].stop - e[0].start, e[1].stop - e[1].start) * max(spacing) for e in extents]
        ax.scatter(
            [xs[0] + c[0] * spacing[0] for c in centres],
            [ys[0] + c[1] * spacing[1] for c in centres],
            s=[(2.0 * max(size, least) / max(np.ptp(xs), np.ptp(ys)) * 72 * 3.0) ** 2 / 4 for size in sizes],
            facecolors="none",
            edgecolors="#2166ac",
            linewidths=0.8,
        )
        handles.append(
            ax.scatter([], [], s=40, facecolors="none", edgecolors="#2166ac", label=f"{count} patches")
        )
    ax.legend(  # below the map, not beside it: a legend beside widens the column for every row
        handles=handles,
        loc="upper center",
        bbox_to_anchor=(0.5, -0.22),
        ncols=len(handles),
        fontsize="x-small",
        frameon=False,
    )


def _most_loaded_window(pressure: np.ndarray) -> tuple[slice, slice]:
    """Return the window (slices) around the contact patch that carries the largest load."""
    from scipy import ndimage

    labels, count = ndimage.label(pressure > 0)
    if count == 0:
        return slice(None), slice(None)
    loads = ndimage.sum_labels(pressure, labels, range(1, count + 1))
    extent = ndimage.find_objects(labels)[int(np.argmax(loads))]
    window = []
    for part, n in zip(extent, pressure.shape, strict=True):
        side = min(n, max(int(round(ZOOM_SIDE * n)), 3 * (part.stop - part.start), 8))
        start = min(max((part.start + part.stop - side) // 2, 0), n - side)
        window.append(slice(start, start + side))
    return window[0], window[1]


def _frame(ax: Axes, field, window: tuple[slice, slice]) -> None:
    """Frame ``window`` of ``field`` (a map drawn by ``map_axes``) on ``ax``."""
    from matplotlib.patches import Rectangle

    size_scale, _ = map_length_scale(field)
    xs, ys = np.asarray(field["x"])[window[0]] / size_scale, np.asarray(field["y"])[window[1]] / size_scale
    ax.add_patch(
        Rectangle((xs[0], ys[0]), np.ptp(xs), np.ptp(ys), fill=False, edgecolor="#2166ac", linewidth=1.0)
    )


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
    line = bool(cases) and "force_per_length" in cases[0].scalars
    name, unit, label = ("force_per_length", "N/m", "force per length") if line else ("force", "N", "force")
    largest = max((abs(float(c.scalars[name])) for c in cases), default=1.0) or 1.0
    deepest = max((abs(float(c.scalars["approach"])) for c in cases), default=1e-9) or 1e-9
    (f_scale, f_unit), (a_scale, a_unit) = prefixed_scale(largest, unit), prefixed_scale(deepest, "m")
    labels = (f"approach ({a_unit})", f"{label} ({f_unit})", "load against approach")
    return _curve_of_cases(cases, "approach", name, (1 / a_scale, 1 / f_scale), labels)


@caption(
    "Von Mises stress at the first stored depth below the surface for up to four cases, on one colour "
    "scale from 0 to the largest value of all the panels."
)
def von_mises_figure(cases):
    """Draw the von Mises maps at the first stored depth of up to four cases; None without any."""
    from .layout import colour_scale, new_figure, shared_colorbar
    from .study import map_axes

    # a case without load has no stress to show: an empty map under a colour bar says nothing
    chosen = evenly_chosen([r for r in cases if float(r.scalars.get("max_von_mises", 0.0)) > 0], 4)
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
