"""Figure of a nanoindentation analysis: load-depth curve, unloading fit, tangent (paper 001 figure 7)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.axes import Axes

from ..units import format_si, unit_factor
from .cases import caption, panel_per_case
from .layout import axes_for, legend

_SEGMENT_STYLES = {"loading": "C0", "hold": "C2", "unloading": "C1"}
_DEPTH_UNIT, _LOAD_UNIT = "nm", "mN"  # the axes fixed, as in paper 001 (Fig. 7); moduli by the unit rule
_DEPTH_SCALE, _LOAD_SCALE = (float(unit_factor(unit)[0]) for unit in (_DEPTH_UNIT, _LOAD_UNIT))


def plot_indentation(result, ax: Axes | None = None):
    """Draw an indentation analysis' result (see :func:`plot_indentation_record`).

    Parameters
    ----------
    result : IndentationResult
        From :func:`roughcontact.experiment.nanoindentation.oliver_pharr`.
    ax : Axes, optional
        Where to draw.

    Returns
    -------
    (Figure, Axes)
    """
    return plot_indentation_record(result.to_xarray(), result.scalars(), ax=ax)


def plot_indentation_record(data, scalars: dict, *, ax: Axes | None = None, title: str | None = None):
    """Draw load (mN) against depth (nm) with the fitted unloading power law and the tangent at d_max.

    Draws from what a study stores (paper 001 Fig. 7), so a report re-draws it without the analysis.

    Parameters
    ----------
    data : xarray.Dataset
        :meth:`IndentationResult.to_xarray`: ``depth``, ``load`` and ``segment`` per sample.
    scalars : dict
        :meth:`IndentationResult.scalars`: the fit (``fit_alpha``, ``fit_final_depth``,
        ``fit_exponent``, ``fit_range_low``, ``fit_range_high``), ``max_depth``, ``max_load``,
        ``stiffness``, ``corrected_stiffness``, ``contact_depth``, the moduli, ``hardness`` (shown in
        the title where the record has it) and ``rate_sign``.
    ax : Axes, optional
        Where to draw.
    title : str, optional
        Put before the moduli and the hardness in the title (e.g. the file's name).

    Returns
    -------
    (Figure, Axes)
        Lines labelled "loading", "hold", "unloading" (the data), "power-law fit"
        (F = alpha (d - d_f)^m over its fit range, dotted beyond it), "tangent S at d_max" and,
        where the creep correction changed it, "corrected S_e"; a marker "d_max, F_max" and a
        vertical line "contact depth d_c".
    """
    fig, ax = axes_for(ax, figsize=(5.5, 4.2))
    depth, load = np.asarray(data["depth"]), np.asarray(data["load"])
    segment = np.asarray(data["segment"]).astype(str)
    nm, mn = _DEPTH_SCALE, _LOAD_SCALE  # SI values of one shown unit
    for name, color in _SEGMENT_STYLES.items():
        part = segment == name
        joined = np.concatenate([[False], part[:-1]]) & ~part  # and the next segment's first sample
        part = part | (joined & (segment != "none"))
        ax.plot(depth[part] / nm, load[part] / mn, "-", color=color, lw=1.0, label=name)
    d_max, f_max = scalars["max_depth"], scalars["max_load"]
    alpha, final, exponent = scalars["fit_alpha"], scalars["fit_final_depth"], scalars["fit_exponent"]
    depth_fit = np.linspace(final, d_max, 200)
    load_fit = alpha * np.clip(depth_fit - final, 0.0, None) ** exponent
    inside = (load_fit >= scalars["fit_range_low"] * f_max) & (load_fit <= scalars["fit_range_high"] * f_max)
    ax.plot(depth_fit[inside] / nm, load_fit[inside] / mn, "k-", lw=1.6, label="power-law fit")
    ax.plot(depth_fit / nm, load_fit / mn, "k:", lw=0.8, label="_power-law fit, extrapolated")
    for stiffness, style, label in (
        (scalars["stiffness"], "r--", "tangent S at d_max"),
        (scalars["corrected_stiffness"], "m-.", "corrected S_e"),
    ):
        if label == "corrected S_e" and np.isclose(stiffness, scalars["stiffness"], rtol=1e-9):
            continue
        depth_tangent = np.linspace(d_max - f_max / stiffness, d_max, 2)
        ax.plot(
            depth_tangent / nm, (f_max + stiffness * (depth_tangent - d_max)) / mn, style, lw=1.0, label=label
        )
    ax.plot([d_max / nm], [f_max / mn], "ko", ms=5, label="d_max, F_max")
    ax.axvline(scalars["contact_depth"] / nm, color="0.5", lw=0.8, ls=":", label="contact depth d_c")
    ax.set_xlabel(f"depth d ({_DEPTH_UNIT})")
    ax.set_ylabel(f"load F ({_LOAD_UNIT})")
    hardness = scalars.get("hardness")  # a record stored before the hardness was reported has none
    moduli = (
        f"E = {format_si(scalars['youngs_modulus'], 'Pa', digits=3)}"
        + ("" if hardness is None else f", H = {format_si(hardness, 'Pa', digits=3)}")
        + f" (E_r = {format_si(scalars['reduced_modulus'], 'Pa', digits=3)}, "
        f"rate sign: {scalars['rate_sign']})"
    )
    ax.set_title(f"{title}\n{moduli}" if title else moduli, fontsize="medium")
    ax.set_xlim(left=0.0)
    ax.set_ylim(bottom=0.0)
    legend(ax, fontsize="small", loc="upper left")
    ax.grid(True, alpha=0.3)
    return fig, ax


@caption(
    "Load-displacement curves (up to four) with the fitted unloading law and its tangent at the start "
    "of unloading, whose slope is the contact stiffness S_e (paper 001 Fig. 7)."
)
def indentation_figure(cases):
    """Draw each curve (up to four) with its fitted unloading law and the tangent S_e (paper 001 figure 7)."""

    def draw(case, data, ax):
        source = case.parameters.get("curve")
        plot_indentation_record(data, case.scalars, ax=ax, title=Path(source).name if source else case.label)

    return panel_per_case(cases, draw)
