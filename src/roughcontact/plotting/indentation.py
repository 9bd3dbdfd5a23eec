"""Figure of a nanoindentation analysis: load-depth curve, unloading fit, tangent (paper 001 Fig. 7)."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes

from .topography import _axes

_SEGMENT_STYLES = {"loading": "C0", "hold": "C2", "unloading": "C1"}


def plot_indentation(result, ax: Axes | None = None):
    """Draw load (mN) against depth (nm) with the fitted unloading power law and the tangent at d_max.

    Parameters
    ----------
    result : IndentationResult
        From :func:`roughcontact.experiment.nanoindentation.oliver_pharr`.
    ax : Axes, optional
        Where to draw.

    Returns
    -------
    (Figure, Axes)
        Lines labelled "loading", "hold", "unloading" (the data), "power-law fit"
        (F = alpha (d - d_f)^m over its fit range, dashed beyond it), "tangent S at d_max" and,
        where the creep correction changed it, "corrected S_e"; a marker "d_max, F_max" and a
        vertical line "contact depth d_c".
    """
    fig, ax = _axes(ax, figsize=(5.5, 4.2))
    curve, segments, fit = result.curve, result.segments, result.unloading_fit
    nm, mn = 1e9, 1e3
    for name, color in _SEGMENT_STYLES.items():
        part = getattr(segments, name)
        ax.plot(curve.depth[part] * nm, curve.load[part] * mn, "-", color=color, lw=1.0, label=name)
    d_max, f_max = result.max_depth, result.max_load
    low, high = fit.fit_range
    depth_fit = np.linspace(fit.final_depth, d_max, 200)
    load_fit = fit.load(depth_fit)
    inside = (load_fit >= low * f_max) & (load_fit <= high * f_max)
    ax.plot(depth_fit[inside] * nm, load_fit[inside] * mn, "k-", lw=1.6, label="power-law fit")
    ax.plot(depth_fit * nm, load_fit * mn, "k:", lw=0.8, label="_power-law fit, extrapolated")
    depth_tangent = np.linspace(d_max - f_max / result.stiffness, d_max, 2)
    ax.plot(
        depth_tangent * nm,
        (f_max + result.stiffness * (depth_tangent - d_max)) * mn,
        "r--",
        lw=1.0,
        label="tangent S at d_max",
    )
    if not np.isclose(result.corrected_stiffness, result.stiffness, rtol=1e-9):
        depth_corrected = np.linspace(d_max - f_max / result.corrected_stiffness, d_max, 2)
        ax.plot(
            depth_corrected * nm,
            (f_max + result.corrected_stiffness * (depth_corrected - d_max)) * mn,
            "m-.",
            lw=1.0,
            label="corrected S_e",
        )
    ax.plot([d_max * nm], [f_max * mn], "ko", ms=5, label="d_max, F_max")
    ax.axvline(result.contact_depth * nm, color="0.5", lw=0.8, ls=":", label="contact depth d_c")
    ax.set_xlabel("depth d (nm)")
    ax.set_ylabel("load F (mN)")
    ax.set_title(
        f"E = {result.youngs_modulus / 1e9:.3g} GPa "
        f"(E_r = {result.reduced_modulus / 1e9:.3g} GPa, rate sign: {result.options['rate_sign']})",
        fontsize="medium",
    )
    ax.set_xlim(left=0.0)
    ax.set_ylim(bottom=0.0)
    ax.legend(fontsize="small", loc="upper left")
    ax.grid(True, alpha=0.3)
    return fig, ax
