r"""Figures of the ``theories`` study: Persson, Bush-Gibson-Thomas and Greenwood-Williamson beside the BEM.

A study of the model ``theories`` runs one case per load and realisation
(:func:`roughcontact.theory.compare_theories` at one load). :func:`sweeps` gathers the cases of one
setting into a :class:`Sweep`: its loads, and each case's scalars as a matrix of realisations by
loads. The figures draw the BEM as the mean over the realisations with Student's 95 % confidence
interval of the mean shaded (a single line for one realisation, a measured scan), and every theory
beside it as the mean of its values on the realisations (each from that surface's own spectrum).
Loads are read as :math:`p_0/(E^* g)`, :math:`g` the spectral rms gradient, and in pascals. From
Python, wrap the results of single-load calls with :func:`~roughcontact.plotting.cases.as_cases`
(each with its ``reduced_pressure`` among its scalars).

Matplotlib loads when a figure is drawn, not with this module (the study's tables use
:func:`sweeps` too).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..cases import setting_of, surface_origin
from ..spread import spread
from ..units import prefixed_scale
from .cases import caption

__all__ = [
    "Sweep",
    "plot_theories",
    "sweeps",
    "theories_area_figure",
    "theories_gap_figure",
    "theories_kappa_figure",
    "theories_magnification_figure",
    "theories_pressure_figure",
]

LOAD_KEYS = ("reduced_pressure", "mean_pressure")
"""The parameters that set a case's load: the cases of one sweep differ in these and ``replicate``."""

BEM = "black"
THEORY_STYLES = {
    "persson": ("Persson", "tab:blue", "-"),
    "bgt": ("Bush-Gibson-Thomas (small load)", "tab:orange", "--"),
    "gw": ("Greenwood-Williamson", "tab:green", "-."),
}
"""Legend name, colour and line style of each theory."""


@dataclass(frozen=True)
class Sweep:
    """The cases of one setting: loads (columns) by realisations (rows).

    Attributes
    ----------
    label : str
        The setting in words (its sample or its surface).
    cases : list of list
        ``cases[i][j]``: the case of realisation ``i`` at load ``j`` (None where it is missing).
    """

    label: str
    cases: list

    @property
    def realisations(self) -> int:
        """The number of realisations (rows)."""
        return len(self.cases)

    @property
    def origin(self) -> str:
        """The surfaces' origin (``"measured"``: a file; ``"synthetic"``: generated; ``""``: not said)."""
        return surface_origin([case for row in self.cases for case in row])

    @property
    def heading(self) -> str:
        """The start of a figure's title: the setting and its origin (``"surface (measured): "``)."""
        origin = self.origin
        origin = f" ({origin})" if origin else ""
        return f"{self.label}{origin}: " if self.label or origin else ""

    def values(self, name: str) -> np.ndarray:
        """Return the scalar ``name`` of every case, realisations by loads (NaN where missing or left out)."""
        return np.array(
            [
                [
                    math.nan if case is None or case.scalars.get(name) is None else float(case.scalars[name])
                    for case in row
                ]
                for row in self.cases
            ]
        )

    def mean(self, name: str) -> np.ndarray:
        """Return the mean of ``name`` over the realisations at each load (NaN where all are left out)."""
        return np.array([spread(column).mean for column in self.values(name).T])

    def band(self, name: str, bounds=(-math.inf, math.inf)) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Return the mean and the 95 % confidence interval of the mean over the realisations, per load."""
        values = self.values(name)
        found = [spread(values[:, j], bounds=bounds) for j in range(values.shape[1])]
        return tuple(np.array([getattr(s, k) for s in found]) for k in ("mean", "ci95_low", "ci95_high"))

    def attribute(self, name: str) -> float:
        """Return the mean of the scalar ``name`` over every case (a property of the surfaces)."""
        return spread(self.values(name).ravel()).mean

    @property
    def gap_compared(self) -> bool:
        """Whether every case's mean gap is the theories' (periodic surfaces)."""
        return all(bool(case.scalars.get("gap_compared")) for row in self.cases for case in row if case)

    def with_fields(self, load: int) -> list:
        """Return the cases at load ``load`` that hold their curves (one per realisation)."""
        return [row[load] for row in self.cases if row[load] is not None and row[load].has_fields]


class _AtLoad:
    """One load of a swept result (a :class:`~roughcontact.theory.TheoryComparison`) as a case."""

    def __init__(self, case, index: int, realisation: int):
        data = case.dataset()
        self._data, self.index = data, index
        self.label = case.label
        self.parameters = {**dict(case.parameters), "replicate": realisation}
        at = {name: float(data[name].values[index]) for name in _CURVES}
        x = at["reduced_pressure"]
        at |= {
            "area_load_slope": at["contact_fraction_corrected"] / x,
            "area_load_slope_raw": at["contact_fraction"] / x,
            "gap_compared": bool(data.attrs.get("gap_compared", 0)),
        }
        self.scalars = {**dict(case.scalars), **at}
        self.has_fields = True

    def dataset(self):
        return self._data.isel(load=[self.index])


_CURVES = (
    "reduced_pressure",
    "mean_pressure",
    "contact_fraction",
    "contact_fraction_corrected",
    "mean_gap",
    "persson_fraction",
    "bgt_fraction",
    "gw_fraction",
    "persson_mean_gap",
    "gw_mean_gap",
)
"""The curves of a swept result that a sweep reads per load."""


def _per_load(cases) -> list:
    """Return the cases with one load each: a study's as they are, a swept result's one per load.

    A swept result (several loads, from Python) is one realisation: the n-th of them in ``cases``
    is realisation n, unless its parameters name a ``replicate``.
    """
    found, swept = [], 0
    for case in cases:
        if "reduced_pressure" in case.scalars:
            found.append(case)
        elif "kappa_loads" in case.scalars and case.has_fields:
            realisation = int(case.parameters.get("replicate", swept))
            data = case.dataset()
            found += [_AtLoad(case, j, realisation) for j in range(data.sizes["load"])]
            swept += 1
    return found


def _load_key(case, by: str) -> float:
    value = case.parameters.get(by)
    return float(f"{float(case.scalars[by] if value is None else value):.9g}")


def sweeps(cases) -> list[Sweep]:
    """Gather the cases of one setting (all but the load and the realisation) into sweeps.

    Each :class:`Sweep` holds its cases by realisation (``replicate``) and load (ascending
    ``reduced_pressure``, or ``mean_pressure`` where the cases were loaded in pascals). A study's
    cases have one load each; a result of several loads (:func:`~roughcontact.theory.compare_theories`
    from Python, wrapped by :func:`~roughcontact.plotting.cases.as_cases`) is one realisation, the
    n-th such result of a setting realisation n. Cases of other models are left out.
    """
    settings: dict[str, list] = {}
    for case in _per_load(cases):
        setting = {k: v for k, v in setting_of(case).items() if k not in (*LOAD_KEYS, "replicate")}
        settings.setdefault(repr(sorted(setting.items(), key=lambda item: item[0])), []).append(case)
    found = []
    for group in settings.values():
        realisations = sorted({int(case.parameters.get("replicate", 0)) for case in group})
        per_realisation = max(
            sum(int(c.parameters.get("replicate", 0)) == r for c in group) for r in realisations
        )
        by = "reduced_pressure"
        given = group[0].parameters.get("mean_pressure") is not None
        if given or len({_load_key(c, by) for c in group}) > per_realisation:
            by = "mean_pressure"  # loaded in pascals: the reduced loads differ between realisations
        loads = sorted({_load_key(case, by) for case in group})
        table = [[None] * len(loads) for _ in realisations]
        for case in group:
            row = realisations.index(int(case.parameters.get("replicate", 0)))
            table[row][loads.index(_load_key(case, by))] = case
        first = group[0].parameters
        found.append(Sweep(str(first.get("sample") or first.get("topography") or ""), table))
    return found


def _realisations_words(sweep: Sweep) -> str:
    n = sweep.realisations
    return "one realisation" if n == 1 else f"mean and 95 % interval of the mean over {n} realisations"


def _title(sweep: Sweep, what: str) -> str:
    window = "" if sweep.gap_compared else ", free window"
    return f"{sweep.heading}{what}{window}\n({_realisations_words(sweep)})"


def _bem_line(ax, x, sweep: Sweep, name: str, scale: float, label: str, *, style="-", bounds=(0.0, math.inf)):
    mean, low, high = sweep.band(name, bounds)
    ax.plot(x, mean * scale, style, color=BEM, marker="o", markersize=3.5, label=label)
    if sweep.realisations > 1:
        ax.fill_between(x, low * scale, high * scale, color=BEM, alpha=0.18, linewidth=0)


def _theory_lines(ax, x, sweep: Sweep, suffix: str, scale: float = 1.0, keys=("persson", "bgt", "gw")):
    for key in keys:
        name, colour, style = THEORY_STYLES[key]
        values = sweep.mean(f"{key}{suffix}") * scale
        if key == "bgt":  # its small-load law, shown where it is a small area
            values = np.where(values <= 0.5, values, np.nan)
        ax.plot(x, values, style, color=colour, label=name)


def plot_theories(result, ax=None):
    """Draw a :class:`~roughcontact.theory.TheoryComparison`: A/A0 against p0/(E* g), BEM and theories.

    The BEM's corrected area (solid, dots) and pixel count (dashed), Persson's, BGT's (up to
    A/A0 = 0.5) and GW's, on logarithmic axes. Returns ``(figure, axes)``.
    """
    from .layout import axes_for, legend

    figure, ax = axes_for(ax)
    x = result.reduced_pressure
    ax.plot(x, result.contact_fraction_corrected, "-o", color=BEM, markersize=3, label="BEM, corrected area")
    ax.plot(x, result.contact_fraction, "--", color=BEM, linewidth=1.0, label="BEM, pixel count")
    for key in ("persson", "bgt", "gw"):
        name, colour, style = THEORY_STYLES[key]
        values = getattr(result, f"{key}_fraction")
        ax.plot(
            x,
            np.where(values <= 0.5, values, np.nan) if key == "bgt" else values,
            style,
            color=colour,
            label=name,
        )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("reduced pressure p0 / (E* g)")
    ax.set_ylabel("relative contact area A / A0")
    legend(ax, fontsize="x-small", loc="upper left")
    return figure, ax


def _new_figure(rows: int, columns: int, width: float, height: float):
    from .layout import new_figure

    return new_figure(rows, columns, width=width, height=height)


def _legend(ax, **keywords):
    from .layout import legend

    legend(ax, **keywords)


def _against_load(cases, what: str, legend_at: str, draw):
    """Draw a row per sweep: a quantity against the reduced load (left) and the nominal one (right).

    ``draw(ax, x, sweep, side)`` draws the quantity on one panel (``side`` 0: against p0/(E* g), 1:
    against p0 in the prefix of its largest value) with its y axis; both share the logarithmic x
    axis, its label, the grid, the row's title (``what``) and the legend (at ``legend_at``, left).
    None without cases.
    """
    found = sweeps(cases)
    if not found:
        return None
    figure, axes = _new_figure(len(found), 2, 5.2, 4.2)
    for row, sweep in zip(axes, found, strict=True):
        reduced, pressure = sweep.mean("reduced_pressure"), sweep.mean("mean_pressure")
        scale, unit = prefixed_scale(float(np.nanmax(pressure)), "Pa")
        for side, (ax, x, xlabel) in enumerate(
            (
                (row[0], reduced, "reduced pressure p0 / (E* g)"),
                (row[1], pressure / scale, f"nominal pressure p0 ({unit})"),
            )
        ):
            draw(ax, x, sweep, side)
            ax.set_xscale("log")
            ax.set_xlabel(xlabel)
            ax.grid(True, which="major", alpha=0.3)
        row[0].set_title(_title(sweep, what), fontsize="medium")
        _legend(row[0], fontsize="small", loc=legend_at)
    return figure


@caption(
    "Relative contact area A/A0 against the reduced pressure p0/(E* g) (left; g the surface's spectral rms "
    "gradient) and against the nominal pressure (right), logarithmic axes. BEM: the area corrected for its "
    "pixelated perimeter (Yastrebov et al. 2017; solid, dots) and the raw pixel count (dashed), the mean "
    "over the realisations with the 95 % confidence interval of the mean shaded; beside it Persson's "
    "erf(sqrt(2) p0/(E* g)), Bush-Gibson-Thomas's small-load sqrt(2 pi) p0/(E* g) (drawn up to A/A0 = 0.5) "
    "and Greenwood-Williamson's from the spectral moments, each the mean of its values on the realisations."
)
def theories_area_figure(cases):
    """Draw the relative contact area of the BEM and of every theory against the load; None without cases."""

    def draw(ax, x, sweep: Sweep, side: int) -> None:
        _bem_line(ax, x, sweep, "contact_fraction_corrected", 1.0, "BEM, corrected area", bounds=(0, 1))
        ax.plot(x, sweep.mean("contact_fraction"), "--", color=BEM, linewidth=1.0, label="BEM, pixel count")
        _theory_lines(ax, x, sweep, "_fraction")
        ax.set_yscale("log")
        ax.set_ylabel("relative contact area A / A0")

    return _against_load(cases, "contact area", "upper left", draw)


@caption(
    "Mean gap between the surface and the flat against the reduced pressure p0/(E* g) (left, over the rms "
    "height) and against the nominal pressure (right). BEM: the mean of the gap field, mean over the "
    "realisations with its 95 % interval shaded; Persson's (2007) mean separation (gamma = 0.4) and "
    "Greenwood-Williamson's separation of the flat from the surface's mean plane. A free window's BEM "
    "gap (dotted) holds the half-space's settlement under the window and is not the theories' quantity."
)
def theories_gap_figure(cases):
    """Draw the mean gap of the BEM and of Persson's and GW's theories against the load (None: no cases)."""

    def draw(ax, x, sweep: Sweep, side: int) -> None:
        if side == 0:
            scale, ylabel = 1 / sweep.attribute("rms_height"), "mean gap / rms height"
        else:
            g_scale, g_unit = prefixed_scale(float(np.nanmax(np.abs(sweep.mean("persson_mean_gap")))), "m")
            scale, ylabel = 1 / g_scale, f"mean gap ({g_unit})"
        if sweep.gap_compared:
            _bem_line(ax, x, sweep, "mean_gap", scale, "BEM", bounds=(0.0, math.inf))
        else:
            label = "BEM, free window (not compared)"
            ax.plot(x, sweep.mean("mean_gap") * scale, ":", color=BEM, label=label)
        _theory_lines(ax, x, sweep, "_mean_gap", scale, keys=("persson", "gw"))
        ax.set_ylabel(ylabel)
        ax.axhline(0.0, color="0.6", linewidth=0.8)

    return _against_load(cases, "mean gap", "upper right", draw)


@caption(
    "Distribution of contact pressures per nominal area, against sigma/(E* g) (bottom axis) and in "
    "pascals (top axis, at the mean E* g of the realisations), at the smallest, a middle and the largest "
    "load: the BEM's histogram (mean over the realisations, 95 % interval shaded) and Persson's P(sigma) "
    "with P(0) = 0. Each integrates to the area in contact; the rest of the nominal area carries no "
    "pressure."
)
def theories_pressure_figure(cases):
    """Draw the BEM's and Persson's distributions of contact pressure at three loads; None without curves."""
    found = [s for s in sweeps(cases) if s.with_fields(0)]
    if not found:
        return None
    sweep = found[0]
    loads = sweep.mean("reduced_pressure")
    chosen = [j for j in sorted({0, len(loads) // 2, len(loads) - 1}) if sweep.with_fields(j)]
    figure, axes = _new_figure(1, len(chosen), 4.4, 3.8)
    unit_pressure = sweep.attribute("contact_modulus") * sweep.attribute("rms_gradient")
    scale, unit = prefixed_scale(unit_pressure, "Pa")
    for ax, j in zip(axes[0], chosen, strict=True):
        datasets = [case.dataset() for case in sweep.with_fields(j)]
        centres = np.asarray(datasets[0]["pressure_bin"].values, dtype=float)
        bem = np.array([np.asarray(d["bem_pressure_density"].values[0], dtype=float) for d in datasets])
        persson = np.mean(
            [np.asarray(d["persson_pressure_density"].values[0], dtype=float) for d in datasets], axis=0
        )
        ax.step(centres, bem.mean(axis=0), where="mid", color=BEM, label="BEM")
        if len(datasets) > 1:
            bands = [spread(bem[:, k], bounds=(0, math.inf)) for k in range(bem.shape[1])]
            ax.fill_between(
                centres,
                [s.ci95_low for s in bands],
                [s.ci95_high for s in bands],
                step="mid",
                color=BEM,
                alpha=0.18,
                linewidth=0,
            )
        ax.plot(centres, persson, color=THEORY_STYLES["persson"][1], label="Persson")
        ax.set_xlabel("contact pressure sigma / (E* g)")
        ax.set_ylabel("density per nominal area (per unit sigma / (E* g))")
        ax.set_title(f"p0 / (E* g) = {loads[j]:.3g}", fontsize="medium")
        ax.set_xlim(0.0, float(centres[-1]))
        ax.set_ylim(bottom=0.0)
        top = ax.secondary_xaxis(
            "top", functions=(lambda s: s * unit_pressure / scale, lambda p: p * scale / unit_pressure)
        )
        top.set_xlabel(f"sigma ({unit})")
        ax.grid(True, alpha=0.3)
    _legend(axes[0][0], fontsize="small")
    figure.suptitle(_title(sweep, "contact pressures"), fontsize="medium")
    return figure


def fitted_kappa(sweep: Sweep, name: str = "contact_fraction_corrected") -> np.ndarray:
    r"""Return :math:`\kappa` of each realisation of ``sweep`` (:func:`~roughcontact.theory.kappa_fit`).

    The loads of the fit are those whose corrected area is at most the cases' ``kappa_max_fraction``
    (NaN for a realisation with none); ``name`` the area fitted (the corrected one, or
    ``contact_fraction`` for the raw count over the same loads).
    """
    from ..theory.comparison import KAPPA_MAX_FRACTION, kappa_fit

    reduced, area = sweep.values("reduced_pressure"), sweep.values(name)
    select = sweep.values("contact_fraction_corrected")
    limits = [
        float(case.parameters.get("kappa_max_fraction", KAPPA_MAX_FRACTION))
        for row in sweep.cases
        for case in row
        if case
    ]
    limit = min(limits) if limits else KAPPA_MAX_FRACTION
    return np.array(
        [
            kappa_fit(reduced[i], area[i], max_fraction=limit, select=select[i])[0]
            for i in range(sweep.realisations)
        ]
    )


@caption(
    "The area-load slope A/A0 / (p0/(E* g)) at each load: the BEM's corrected area (solid, dots; 95 % "
    "interval of the mean shaded) and raw pixel count (dashed), Persson's (tends to sqrt(8/pi) = 1.596 at "
    "small load), Bush-Gibson-Thomas's sqrt(2 pi) = 2.507 and Greenwood-Williamson's. The shaded strip "
    "marks the loads of the fit of kappa (corrected area at most kappa_max_fraction); the fitted kappa, "
    "with its 95 % interval over the realisations, is in the title."
)
def theories_kappa_figure(cases):
    """Draw the area-load slope of the BEM and of every theory at each load; None without cases."""
    found = sweeps(cases)
    if not found:
        return None
    figure, axes = _new_figure(1, len(found), 5.4, 4.2)
    for ax, sweep in zip(axes[0], found, strict=True):
        x = sweep.mean("reduced_pressure")
        _bem_line(ax, x, sweep, "area_load_slope", 1.0, "BEM, corrected area")
        ax.plot(
            x, sweep.mean("area_load_slope_raw"), "--", color=BEM, linewidth=1.0, label="BEM, pixel count"
        )
        reduced = sweep.values("reduced_pressure")
        for key in ("persson", "bgt", "gw"):
            name, colour, style = THEORY_STYLES[key]
            ax.plot(
                x,
                np.nanmean(sweep.values(f"{key}_fraction") / reduced, axis=0),
                style,
                color=colour,
                label=name,
            )
        limits = [float(c.parameters.get("kappa_max_fraction", 0.1)) for row in sweep.cases for c in row if c]
        limit = min(limits, default=0.1)
        used = x[np.nanmax(sweep.values("contact_fraction_corrected"), axis=0) <= limit]
        if used.size:
            ax.axvspan(
                float(np.nanmin(x)) / 1.2,
                float(used.max()) * 1.1,
                color="0.9",
                zorder=0,
                label=f"loads of the BEM's kappa (A/A0 <= {limit:.3g})",
            )
        summary = spread(fitted_kappa(sweep), bounds=(0, math.inf))
        said = (
            f"kappa = {summary.mean:.3g}"
            if summary.n < 2
            else f"kappa = {summary.mean:.3g} [{summary.ci95_low:.3g}, {summary.ci95_high:.3g}]"
        )
        ax.set_xscale("log")
        ax.set_xlabel("reduced pressure p0 / (E* g)")
        ax.set_ylabel("A / A0 over p0 / (E* g)")
        ax.set_ylim(bottom=0.0)
        ax.grid(True, alpha=0.3)
        ax.set_title(_title(sweep, f"area-load slope, BEM {said}"), fontsize="medium")
        _legend(ax, fontsize="small", loc="best")
    return figure


@caption(
    "Persson's relative contact area against the magnification zeta = q/q0, the roughness resolved "
    "from the lowest wavevector q0 up to zeta q0, at each load (first realisation): the area falls as "
    "shorter wavelengths are resolved and ends at the value the area figure shows."
)
def theories_magnification_figure(cases):
    """Draw Persson's area against magnification at each load of the first realisation (None: no curves)."""
    found = [s for s in sweeps(cases) if s.with_fields(0)]
    if not found:
        return None
    import matplotlib

    sweep = found[0]
    row = [case for case in sweep.cases[0] if case is not None and case.has_fields]
    figure, axes = _new_figure(1, 1, 5.2, 4.2)
    ax = axes[0][0]
    colours = matplotlib.colormaps["viridis"](np.linspace(0.0, 0.9, len(row)))
    for case, colour in zip(row, colours, strict=True):
        data = case.dataset()
        zeta = np.asarray(data["magnification"].values, dtype=float)
        reduced = float(data["reduced_pressure"].values[0])
        values = np.asarray(data["persson_fraction_magnified"].values[0], dtype=float)
        ax.plot(zeta, values, color=colour, label=f"p0 / (E* g) = {reduced:.3g}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("magnification zeta = q / q0")
    ax.set_ylabel("Persson's A(zeta) / A0")
    ax.grid(True, which="major", alpha=0.3)
    which = "" if sweep.realisations == 1 else f" (first of {sweep.realisations} realisations)"
    ax.set_title(f"{sweep.heading}Persson's area as the roughness is resolved{which}", fontsize="medium")
    _legend(ax, fontsize="small", loc="lower left")
    return figure
