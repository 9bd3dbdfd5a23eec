"""Figures of one pre-sliding result (paper 001): loops, stick/slip and pressure maps, the path, K_L.

The ``plot_*`` functions of :mod:`roughcontact.plotting.presliding`, which serves them (import
them from there): each draws one result, loop or series on optional axes and returns the figure.
Loops and stiffness are in the paper's fixed units (:data:`LENGTH_UNIT`, :data:`FORCE_UNIT`,
:data:`STIFFNESS_UNIT`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
from matplotlib import colormaps
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.patches import Rectangle

from ..errors import InputError
from ..units import format_si, prefixed_scale, unit_factor
from .layout import axes_for, colour_scale, empty_grey, legend, shared_colorbar

LENGTH_UNIT, FORCE_UNIT, STIFFNESS_UNIT = "µm", "mN", "mN/µm"
"""Fixed units of the loops and K_L, as in paper 001 Figs. 13-15 (K_L's mN/µm is what the tables write)."""

LENGTH_SCALE, FORCE_SCALE, STIFFNESS_SCALE = (
    float(unit_factor(unit)[0]) for unit in (LENGTH_UNIT, FORCE_UNIT, STIFFNESS_UNIT)
)
"""The SI value of one of each fixed unit (divide by it to plot in that unit)."""


POINT_COLOURS = {"A": "tab:red", "B": "tab:blue", "C": "black", "D": "tab:green"}
"""Colours of the points, as in paper 001 Fig. 15 (A red, B blue, C black)."""


MINDLIN_STYLES = {"johnson": "--", "printed": "-."}
"""Line styles of Mindlin's K_L in each reading of equation 12."""


SLIP_LEVEL = 0.999
"""Normalised shear at or above which a point counts as slipping in the maps."""


def _curves(curves, field: str) -> list[tuple[np.ndarray, np.ndarray, str]]:
    out = []
    for item in curves or ():
        try:
            delta, force, label = item
        except (TypeError, ValueError):
            raise InputError(
                field, "expected a list of (displacement, force, label).", "pass [(delta, F, 'label')]."
            ) from None
        delta, force = np.asarray(delta, dtype=float), np.asarray(force, dtype=float)
        if delta.shape != force.shape or delta.ndim != 1:
            raise InputError(
                field, f"curve {label!r}: displacement and force differ in shape.", "give equal 1-D arrays."
            )
        out.append((delta, force, str(label)))
    return out


def plot_hysteresis_loops(
    simulated: Sequence[tuple],
    measured: Sequence[tuple] | None = None,
    *,
    realisations: Sequence[Sequence[tuple]] | None = None,
    ax: Axes | None = None,
    title: str | None = None,
) -> Figure:
    """Draw friction hysteresis loops, friction force vs tangential displacement (figures 13-14).

    Simulated loops are thick solid lines, compared ones (measured, or synthetic: their labels say
    which) thin dashed lines; the paper overlays the loops it measured at five spots on the wafer
    on the simulation. Where a simulated loop is the mean over realisations (stand-in balls of
    the same statistics), each realisation is a thin line of its colour: together they show the
    band the draw of the surface spans.

    Parameters
    ----------
    simulated : list of (delta, F, label)
        Displacement [m] and force [N] arrays and a legend label per loop.
    measured : list of (delta, F, label), optional
        The same for compared loops; the label names their origin.
    realisations : list of list of (delta, F, label), optional
        Per simulated loop, the loops of its realisations (empty for a loop of one).
    ax : matplotlib Axes, optional
        Axes to draw on.
    title : str, optional
        Axes title.

    Returns
    -------
    Figure
    """
    fig, ax = axes_for(ax, figsize=(5.5, 4.0))
    curves = _curves(simulated, "simulated")
    for number, (delta, force, label) in enumerate(curves):
        (line,) = ax.plot(delta / LENGTH_SCALE, force / FORCE_SCALE, "-", linewidth=2.0, label=label)
        for delta_i, force_i, _ in _curves((realisations or [[]] * len(curves))[number], "realisations"):
            ax.plot(
                delta_i / LENGTH_SCALE,
                force_i / FORCE_SCALE,
                "-",
                linewidth=0.6,
                alpha=0.45,
                color=line.get_color(),
            )
    for delta, force, label in _curves(measured, "measured"):
        ax.plot(delta / LENGTH_SCALE, force / FORCE_SCALE, "--", linewidth=1.0, alpha=0.8, label=label)
    ax.axhline(0.0, color="0.7", linewidth=0.5)
    ax.set_xlabel(f"tangential displacement δ_x ({LENGTH_UNIT})")
    ax.set_ylabel(f"friction force F_x ({FORCE_UNIT})")
    if title:
        ax.set_title(title)
    if ax.get_lines():  # below the axes: inside, a loop's box leaves no corner free
        legend(ax, fontsize="small", loc="upper center", bbox_to_anchor=(0.5, -0.15))
    return fig


def _panel_extent(box, label: str) -> tuple[float, float, float, float]:
    try:
        x0, x1, y0, y1 = (float(v) for v in box)
    except (TypeError, ValueError):
        raise InputError("extent", f"{box!r} for {label!r}.", "give (xmin, xmax, ymin, ymax) in m.") from None
    return x0, x1, y0, y1


def _centres(values: np.ndarray, box, scale: float) -> tuple[np.ndarray, np.ndarray]:
    """Pixel-centre coordinates (in the display unit ``scale``) of a map drawn over ``box``."""
    x0, x1, y0, y1 = box
    ny, nx = values.shape
    return (
        x0 / scale + (np.arange(nx) + 0.5) * (x1 - x0) / scale / nx,
        y0 / scale + (np.arange(ny) + 0.5) * (y1 - y0) / scale / ny,
    )


def _outline(ax: Axes, values: np.ndarray, inside: np.ndarray, box, scale: float, colour: str) -> None:
    """Draw the outline of the contact (the pixels ``inside``) as a thin line."""
    if inside.any() and (~inside).any():
        xs, ys = _centres(values, box, scale)
        ax.contour(xs, ys, inside.astype(float), levels=[0.5], colors=colour, linewidths=0.7)


def plot_stick_slip_maps(
    maps: Mapping[str, np.ndarray],
    extent,
    *,
    zoom: tuple[float, float, float, float] | None = None,
    columns: int = 3,
    cmap: str = "viridis",
) -> Figure:
    """Draw maps of the normalised shear sqrt(qx^2 + qy^2)/(mu p) (paper 001 figures 11-12).

    The colour scale is fixed to 0..1 (a perceptually uniform map, so equal steps of stick read
    as equal steps of colour; the paper's rainbow is ``cmap="jet"``): values below 1 stick, 1 is
    slip. The contact's outline is drawn in black and the boundary of the slip zone (values
    within :data:`SLIP_LEVEL` of 1) in white. NaN (outside the contact) is blank. Each panel
    title gives the slip fraction of the contact area.

    Parameters
    ----------
    maps : dict of str to 2-D array
        Label (e.g. ``"25 mN, A"``) to the normalised shear, rows along y, NaN outside contact.
    extent : (xmin, xmax, ymin, ymax) in m, or dict of label to it
        Physical extent of the maps (as ``imshow``'s, ``origin="lower"``).
    zoom : (xmin, xmax, ymin, ymax) in m, optional
        Axis limits of a zoomed-in view (the paper shows 0.2 mm x 0.2 mm).
    columns : int
        Panels per row.
    cmap : str
        Colour map.

    Returns
    -------
    Figure

    Raises
    ------
    InputError
        No maps, a map that is not 2-D, or a missing or malformed extent.
    """
    if not maps:
        raise InputError("maps", "is empty.", "pass {label: 2-D array}.")
    labels = list(maps)
    columns = max(1, min(columns, len(labels)))
    rows = -(-len(labels) // columns)
    fig = Figure(figsize=(3.6 * columns + 0.8, 3.2 * rows), layout="constrained")
    axes = np.atleast_1d(fig.subplots(rows, columns, squeeze=False)).ravel()
    colour_map = colormaps[cmap].with_extremes(bad="white")
    image = None
    for ax, label in zip(axes, labels, strict=False):
        values = np.asarray(maps[label], dtype=float)
        if values.ndim != 2:
            raise InputError("maps", f"map {label!r} has shape {values.shape}.", "give 2-D arrays.")
        box = _panel_extent(extent[label] if isinstance(extent, Mapping) else extent, label)
        x0, x1, y0, y1 = box
        scale, unit = prefixed_scale(max(abs(x1 - x0), abs(y1 - y0)), "m")
        image = ax.imshow(
            np.ma.masked_invalid(values),
            origin="lower",
            extent=(x0 / scale, x1 / scale, y0 / scale, y1 / scale),
            cmap=colour_map,
            vmin=0.0,
            vmax=1.0,
            interpolation="nearest",
        )
        finite = np.isfinite(values)
        slipping = finite & (values >= SLIP_LEVEL)
        _outline(ax, values, finite, box, scale, "black")
        if slipping.any() and (~slipping & finite).any():
            xs, ys = _centres(values, box, scale)
            ax.contour(
                xs, ys, np.where(finite, values, 0.0), levels=[SLIP_LEVEL], colors="white", linewidths=0.6
            )
        fraction = slipping.sum() / max(finite.sum(), 1)
        ax.set_title(f"{label} (slip {100 * fraction:.0f} %)", fontsize="medium")
        ax.set_xlabel(f"x ({unit})")
        ax.set_ylabel(f"y ({unit})")
        if zoom is not None:
            ax.set_xlim(zoom[0] / scale, zoom[1] / scale)
            ax.set_ylim(zoom[2] / scale, zoom[3] / scale)
    for ax in axes[len(labels) :]:
        ax.set_visible(False)
    colourbar = fig.colorbar(image, ax=list(axes[: len(labels)]), shrink=0.9)
    colourbar.set_label("√(q_x² + q_y²) / (μ p)   (1 = slip)")
    fig.suptitle("black: outline of the contact; white: edge of the slip zone", fontsize="small")
    return fig


def plot_pressure_maps(
    maps: Mapping[str, np.ndarray],
    extent,
    *,
    zoom: tuple[float, float, float, float],
    cmap: str = "magma",
) -> Figure:
    """Draw contact pressure maps, the whole field beside a zoomed-in view (paper 001 figures 8-9).

    One row per map: left the whole computed field with the zoomed box drawn on it, right the
    box. Every panel shares one colour scale, from 0 to the 99.5th percentile of the nonzero
    pressures of all the maps (stated on the colour bar), grey where there is no contact, and the
    contact outline is drawn on the zoomed view.

    Parameters
    ----------
    maps : dict of str to 2-D array
        Label (e.g. ``"POM 25 mN"``) to the pressure [Pa], rows along y.
    extent : (xmin, xmax, ymin, ymax) in m, or dict of label to it
        Physical extent of each map.
    zoom : (xmin, xmax, ymin, ymax) in m
        The zoomed-in box (the paper: 0.2 mm x 0.2 mm at the centre).
    cmap : str
        Colour map.

    Returns
    -------
    Figure
    """
    if not maps:
        raise InputError("maps", "is empty.", "pass {label: 2-D array}.")
    shared = colour_scale(*maps.values(), from_zero=True)
    factor, _ = shared.prefixed("Pa")
    fig = Figure(figsize=(7.6, 3.4 * len(maps)), layout="constrained")
    axes = fig.subplots(len(maps), 2, squeeze=False)
    image = None
    grey = empty_grey(cmap)  # no contact: grey, not the map's black
    for (whole, zoomed), (label, values) in zip(axes, maps.items(), strict=True):
        values = np.asarray(values, dtype=float)
        box = _panel_extent(extent[label] if isinstance(extent, Mapping) else extent, label)
        scale, length = prefixed_scale(max(box[1] - box[0], box[3] - box[2]), "m")
        for ax in (whole, zoomed):
            image = ax.imshow(
                np.ma.masked_less_equal(values, 0.0) / factor,
                origin="lower",
                extent=tuple(v / scale for v in box),
                cmap=grey,
                vmin=0.0,
                vmax=shared.high / factor,
                interpolation="nearest",
            )
            ax.set_xlabel(f"x ({length})")
            ax.set_ylabel(f"y ({length})")
        within = (max(zoom[0], box[0]), min(zoom[1], box[1]), max(zoom[2], box[2]), min(zoom[3], box[3]))
        x0, x1, y0, y1 = (v / scale for v in within)  # the zoom, inside the computed field
        whole.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, edgecolor="#2166ac", linewidth=1.0))
        whole.set_title(f"{label}: whole field", fontsize="medium")
        _outline(zoomed, values, values > 0, box, scale, "black")
        zoomed.set_xlim(x0, x1)
        zoomed.set_ylim(y0, y1)
        side = prefixed_scale(within[1] - within[0], "m")
        width, height = (within[1] - within[0]) / side[0], (within[3] - within[2]) / side[0]
        zoomed.set_title(f"zoom {width:.3g} x {height:.3g} {side[1]}", fontsize="medium")
    shared_colorbar(image, list(axes.ravel()), "contact pressure", "Pa", shared, shrink=0.9)
    return fig


def plot_displacement_path(
    paths: Mapping[str, np.ndarray],
    *,
    last_loop: tuple[int, int] | None = None,
    points: Mapping[str, int] | None = None,
    normal_force: np.ndarray | None = None,
    positions: Mapping[str, np.ndarray] | None = None,
    ax: Axes | None = None,
) -> Figure:
    """Draw the tangential displacement programme against the step (paper 001 figure 6).

    A combined programme's normal force (``normal_force``, when it varies) is drawn on a second
    axis on the right.

    Parameters
    ----------
    paths : dict of str to 1-D array
        Label to delta_x [m] at each step (step 0 the unloaded start). Cases that share one
        programme need only one entry.
    last_loop : (start, stop), optional
        Steps of the analysed (last) loop of the first path, shaded.
    points : dict of str to int, optional
        Steps of the points A, B, C of the last loop, marked on the first path.
    normal_force : 1-D array, optional
        F_n [N] of the first path at each step (step 0 the start).
    positions : dict of str to 1-D array, optional
        Where each path's steps lie on the axis of the programme's rows (steps inserted by the step
        control between two rows at fractional positions), so programmes of the same rows line up
        whatever steps were inserted; default: the step index.
    ax : matplotlib Axes, optional
        Axes to draw on.

    Returns
    -------
    Figure
    """
    entries = len(paths) + (last_loop is not None) + len(points or {})
    fig, ax = axes_for(ax, figsize=(6.5, 3.6 + 0.25 * -(-entries // 2)))  # legend rows below
    where = {label: np.arange(len(delta)) for label, delta in paths.items()} | dict(positions or {})
    for label, delta in paths.items():
        delta = np.asarray(delta, dtype=float)
        ax.plot(where[label], delta / LENGTH_SCALE, "-", linewidth=1.5, label=label)
    first_label = next(iter(paths))
    at = np.asarray(where[first_label], dtype=float)
    if last_loop is not None:
        whose = "" if len(paths) == 1 else f" of {first_label}"
        ax.axvspan(
            at[last_loop[0]],
            at[last_loop[1] - 1],
            color="0.9",
            zorder=0,
            label=f"last loop{whose} (analysed)",
        )
    first = np.asarray(paths[first_label], dtype=float)
    for name, step in (points or {}).items():
        colour = POINT_COLOURS.get(name, "black")
        where_on_axis = f"row {at[step]:.3g}" if positions else f"step {step}"  # the x axis's own index
        ax.plot(
            at[step], first[step] / LENGTH_SCALE, "o", color=colour, label=f"point {name} ({where_on_axis})"
        )
    ax.set_xlabel("programme row (inserted steps in between)" if positions else "step")
    ax.set_ylabel(f"tangential displacement δ_x ({LENGTH_UNIT})")
    if normal_force is not None and np.ptp(normal_force) > 1e-9 * np.max(normal_force):
        right = ax.twinx()
        right.plot(at, 1e3 * np.asarray(normal_force), "--", color="0.35")
        right.set_ylabel("normal force F_n (mN), dashed", color="0.35")
        right.set_ylim(bottom=0)
        entries += 1
    if len(paths) > 1 or last_loop is not None or points:
        legend(
            ax, fontsize="small", loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=2 if entries > 3 else 1
        )
    return fig


def plot_lateral_stiffness(
    loads,
    simulated: Mapping[str, Sequence[float]] | None = None,
    measured: Mapping[str, Sequence[float]] | None = None,
    mindlin: Mapping[str, Mapping[str, Sequence[float]]] | None = None,
    *,
    interval: Mapping[str, Sequence[float]] | None = None,
    prediction: Mapping[str, tuple[Sequence[float], Sequence[float]]] | None = None,
    realisations: int = 1,
    realisation_word: str = "realisations",
    ax: Axes | None = None,
    title: str | None = None,
) -> Figure:
    """Draw the lateral stiffness at points A, B, C vs normal load (paper 001 figure 15).

    Simulated values are markers, measured ones solid lines, Mindlin's dashed lines, one colour
    per point (A red, B blue, C black). Mindlin curves may be given for both normalisations of
    paper 001 eqs. 10-12 (``"johnson"``: dashed; ``"printed"``, 4x Johnson's: dash-dotted), each
    labelled; see :func:`roughcontact.papers.paper001.paper001_mindlin` and its
    ``point_stiffness``.

    Parameters
    ----------
    loads : array_like
        Normal forces F0 [N].
    simulated, measured : dict of str to array_like, optional
        Point name (``"A"``, ``"B"``, ``"C"``) to K_L [N/m] at each load.
    mindlin : dict of str to dict of str to array_like, optional
        Normalisation (``"johnson"``, ``"printed"``) to {point: K_L [N/m] at each load}.
    interval : dict of str to array_like, optional
        Point name to the half width [N/m] of the 95 % interval of the simulated mean at each load
        (``simulated`` then holds means over ``realisations``): drawn as error bars, those of A
        and C shifted by -1 % and +1 % of the largest load so that the three do not hide each other.
    prediction : dict of str to (array_like, array_like), optional
        Point name to the low and high ends [N/m] of the 95 % prediction interval of one more
        realisation at each load (where one ball falls; ``Spread.prediction`` of :mod:`roughcontact.spread`):
        drawn as thin lines without caps behind the error bars of the mean.
    realisations : int
        Realisations behind each simulated mean (said in the legend).
    realisation_word : str
        What the realisations are, in the legend (``"stand-in balls"`` for paper 001's generated balls).
    ax : matplotlib Axes, optional
        Axes to draw on.
    title : str, optional
        Axes title (e.g. ``"(a) HDPE"``).

    Returns
    -------
    Figure

    Raises
    ------
    InputError
        An array whose length differs from ``loads``, or an unknown normalisation.
    """
    load = np.asarray(loads, dtype=float).ravel()
    fig, ax = axes_for(ax, figsize=(5.5, 4.0))

    def values(series, field, point):
        k = np.asarray(series, dtype=float).ravel()
        if k.shape != load.shape:
            raise InputError(
                field, f"point {point}: {k.size} values for {load.size} loads.", "give one K_L per load."
            )
        return k / STIFFNESS_SCALE

    for point, series in (measured or {}).items():
        colour = POINT_COLOURS.get(point)
        ax.plot(
            load / FORCE_SCALE,
            values(series, "measured", point),
            "-",
            color=colour,
            label=f"{point} measured",
        )
    dodge = 0.01 * float(np.max(load)) / FORCE_SCALE if load.size else 0.0  # bars of A, B, C side by side
    for number, (point, (lows, highs)) in enumerate((prediction or {}).items()):
        low, high = values(lows, "prediction", point), values(highs, "prediction", point)
        ax.vlines(
            load / FORCE_SCALE + (number - 1) * dodge,
            low,
            high,
            color=POINT_COLOURS.get(point),
            linewidth=0.8,
            alpha=0.5,
            label=f"{point} one of the {realisation_word}: 95 % prediction interval",
        )
    for number, (point, series) in enumerate((simulated or {}).items()):
        colour = POINT_COLOURS.get(point)
        if interval is not None and point in interval:
            ax.errorbar(
                load / FORCE_SCALE + (number - 1) * dodge,
                values(series, "simulated", point),
                yerr=values(interval[point], "interval", point),
                fmt="o",
                capsize=3,
                color=colour,
                label=f"{point} simulated, mean ± 95 % CI of the mean ({realisations} {realisation_word})",
            )
            continue
        ax.plot(
            load / FORCE_SCALE,
            values(series, "simulated", point),
            "o",
            linestyle="none",
            color=colour,
            label=f"{point} simulated",
        )
    for normalisation, points in (mindlin or {}).items():
        if normalisation not in MINDLIN_STYLES:
            raise InputError(
                "mindlin",
                f"unknown normalisation {normalisation!r}.",
                f"use keys from {sorted(MINDLIN_STYLES)}.",
            )
        name = "Mindlin (Johnson)" if normalisation == "johnson" else "Mindlin (paper 001 as printed, 4x)"
        for point, series in points.items():
            ax.plot(
                load / FORCE_SCALE,
                values(series, "mindlin", point),
                MINDLIN_STYLES[normalisation],
                color=POINT_COLOURS.get(point),
                linewidth=1.2,
                label=f"{point} {name}",
            )
    ax.set_xlabel(f"normal force F_0 ({FORCE_UNIT})")
    ax.set_ylabel(f"lateral stiffness K_L ({STIFFNESS_UNIT})")
    if title:
        ax.set_title(title)
    if ax.get_lines():
        legend(ax, fontsize="x-small", ncol=2)
    return fig


def plot_loop_analysis(
    data: Mapping[str, np.ndarray],
    scalars: Mapping,
    *,
    title: str = "",
    ax: Axes | None = None,
    record: str = "case",
):
    """Draw a friction loop's analysis: the case, its last loop, both equation 9 fits, the points (figure 10).

    Parameters
    ----------
    data : mapping
        :meth:`~roughcontact.experiment.friction_loop.LoopAnalysis.to_xarray`'s arrays:
        ``displacement``, ``force``, ``in_last_loop`` (per sample), ``fit_displacement``,
        ``fit_force``, ``fit_branch`` (the fitted curves), ``point_displacement``,
        ``point_force``, ``point_stiffness`` and ``point`` (the points' names).
    scalars : mapping
        :meth:`~roughcontact.experiment.friction_loop.LoopAnalysis.scalars` (``mu``, ``stroke``).
    title : str
        Above the figure's own line (mu and the stroke).
    ax : Axes, optional
        Where to draw.
    record : str
        The whole record's legend entry (``"synthetic record"``: its origin, where known).

    Returns
    -------
    Figure
    """
    fig, ax = axes_for(ax, figsize=(5.5, 4.4))
    um, mn = LENGTH_SCALE, FORCE_SCALE
    if "displacement" in data:
        displacement, force = np.asarray(data["displacement"]), np.asarray(data["force"])
        last = np.asarray(data["in_last_loop"]).astype(bool)
        ax.plot(displacement / um, force / mn, "-", color="0.75", lw=0.8, label=record)
        ax.plot(displacement[last] / um, force[last] / mn, "k-", lw=1.0, label="last loop")
    branches = np.asarray(data["fit_branch"])
    for number in np.unique(branches):
        part = branches == number
        ax.plot(
            np.asarray(data["fit_displacement"])[part] / um,
            np.asarray(data["fit_force"])[part] / mn,
            "--",
            color="tab:orange",
            lw=1.6,
            label="eq. 9 fit" if number == branches[0] else "_eq. 9 fit",
        )
    for name, x, y, k in zip(
        np.asarray(data["point"]).astype(str),
        np.asarray(data["point_displacement"]),
        np.asarray(data["point_force"]),
        np.asarray(data["point_stiffness"]),
        strict=True,
    ):
        ax.plot(
            x / um,
            y / mn,
            "o",
            color=POINT_COLOURS.get(name, "k"),
            label=f"{name}: K_L = {format_si(k, 'N/m', digits=3)}",
        )
    mu, stroke = scalars.get("mu"), scalars.get("stroke")
    line = f"μ = {mu:.3g}, stroke {format_si(stroke, 'm', digits=3)}" if mu is not None else ""
    ax.set_title(f"{title}\n{line}" if title else line, fontsize="medium")
    ax.set_xlabel(f"tangential displacement δ_x ({LENGTH_UNIT})")
    ax.set_ylabel(f"friction force F_x ({FORCE_UNIT})")
    ax.grid(True, alpha=0.3)
    legend(ax, fontsize="small", loc="center")  # inside the loop, where nothing is drawn
    return fig
