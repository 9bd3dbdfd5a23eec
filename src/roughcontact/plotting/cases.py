"""What a figure of several cases draws from, and the helpers that choose and group cases.

Every figure of a study (``roughcontact run``, ``roughcontact plot OUT/``) is a function of this
package taking a sequence of *cases*, each with what :class:`FigureCase` names: a ``label`` for the
legend, its ``scalars`` and ``parameters`` (SI) and its fields and curves as an
``xarray.Dataset``. A study passes its stored case records; from Python, :func:`as_cases` wraps
results (anything with ``scalars()`` and ``to_xarray()``, the result protocol) so the same figure
is drawn without a study::

    from roughcontact.plotting import adhesion_force_approach_figure, as_cases
    figure = adhesion_force_approach_figure(as_cases([cycle_a, cycle_b], labels=["A", "B"]))

A figure function returns a matplotlib ``Figure``, or None where the cases do not make it (a load
curve of one load); its caption, what a reader needs to read it, is attached with :func:`caption`.
Nothing here imports matplotlib.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol, TypeVar

import numpy as np

_F = TypeVar("_F", bound=Callable[..., Any])


class FigureCase(Protocol):
    """One case as a figure reads it (a study's ``CaseRecord``, or :class:`ResultCase`)."""

    @property
    def label(self) -> str:
        """Legend label."""

    @property
    def scalars(self) -> Mapping[str, Any]:
        """Scalar results (SI)."""

    @property
    def parameters(self) -> Mapping[str, Any]:
        """The case's inputs (SI); ``sample`` groups cases."""

    @property
    def has_fields(self) -> bool:
        """Whether :meth:`dataset` holds fields and curves."""

    def dataset(self) -> Any:
        """Return the fields and curves (``xarray.Dataset``), or None."""


@dataclass(frozen=True)
class ResultCase:
    """A result object as a :class:`FigureCase`: its ``scalars()`` and ``to_xarray()``, with a label.

    Attributes
    ----------
    label : str
        Legend label.
    scalars : mapping
        The result's scalars (SI).
    data : xarray.Dataset or None
        The result's fields and curves.
    parameters : mapping
        Inputs a figure groups or labels by (``sample``); empty by default.
    """

    label: str
    scalars: Mapping[str, Any]
    data: Any = None
    parameters: Mapping[str, Any] = field(default_factory=dict)

    @property
    def has_fields(self) -> bool:
        """Whether the result gave fields and curves."""
        return self.data is not None

    def dataset(self) -> Any:
        """Return the result's ``xarray.Dataset`` (None without one)."""
        return self.data


def as_cases(
    results: Any,
    *,
    labels: Sequence[str] | None = None,
    samples: Sequence[str] | None = None,
) -> list[FigureCase]:
    """Return results as the cases a figure function takes.

    Parameters
    ----------
    results : result or iterable
        A result of the result protocol (``scalars()`` and ``to_xarray()``), several, or cases
        already (returned as they are).
    labels : sequence of str, optional
        Legend labels (default ``case 1``, ``case 2``, ...).
    samples : sequence of str, optional
        Sample labels, for figures that group cases by sample.
    """
    one = hasattr(results, "scalars") or (hasattr(results, "has_fields") and hasattr(results, "dataset"))
    results = [results] if one else list(results)
    labels = list(labels) if labels is not None else [f"case {k + 1}" for k in range(len(results))]
    samples = list(samples) if samples is not None else [""] * len(results)
    if not len(labels) == len(samples) == len(results):
        raise ValueError(f"{len(results)} results, {len(labels)} labels and {len(samples)} samples")
    cases: list[FigureCase] = []
    for result, label, sample in zip(results, labels, samples, strict=True):
        if hasattr(result, "has_fields") and hasattr(result, "dataset"):
            cases.append(result)
            continue
        to_xarray = getattr(result, "to_xarray", None)
        cases.append(
            ResultCase(
                label,
                dict(result.scalars()),
                None if to_xarray is None else to_xarray(),
                {"sample": sample} if sample else {},
            )
        )
    return cases


def caption(text: str) -> Callable[[_F], _F]:
    """Give a figure function the caption printed under its figure (the study report reads it).

    The caption says what is shown, for a reader who has not seen the code: the quantities, the
    cases drawn, the colour scales.

    Examples
    --------
    >>> @caption("Real contact area against load.")
    ... def area(cases): ...
    >>> figure_caption(area)
    'Real contact area against load.'
    """

    def mark(function: _F) -> _F:
        function.caption = text  # type: ignore[attr-defined]
        return function

    return mark


def figure_caption(function: Callable[..., Any]) -> str:
    """Return the caption of a figure function (see :func:`caption`), "" when it has none."""
    return getattr(function, "caption", "")


def plotting_function(name: str) -> Callable[..., Any]:
    """Return the function ``"module.function"`` of :mod:`roughcontact.plotting`, importing its module.

    How a study kind names its figures (``"adhesion.force_approach_figure"``) and a result the
    figure a notebook shows under it (``"contact.plot_pressure"``): matplotlib loads here, when
    the figure is drawn.
    """
    from importlib import import_module

    module, function = name.rsplit(".", 1)
    return getattr(import_module(f".{module}", __package__), function)


def evenly_chosen(items: Sequence, count: int) -> list:
    """At most ``count`` items, evenly spread over ``items`` (first and last included)."""
    if len(items) <= count:
        return list(items)
    picks = np.unique(np.linspace(0, len(items) - 1, count).round().astype(int))
    return [items[i] for i in picks]


def grouped(cases: Sequence[FigureCase], key: str = "sample") -> dict[str, list[FigureCase]]:
    """Return the cases grouped by a parameter (default the sample label), in order of first appearance."""
    groups: dict[str, list[FigureCase]] = {}
    for case in cases:
        groups.setdefault(str(case.parameters.get(key, "")), []).append(case)
    return groups


def realisations_of(cases: Sequence[FigureCase]) -> dict[str, list[FigureCase]]:
    """Return the cases grouped by everything but their realisation, each group by its label without it.

    Cases that differ only in ``replicate`` (the realisations of a study's generated surfaces),
    or in a value zipped with it (measured files of one sample, one per replicate), are one group;
    the key is the label of its cases with ``replicate ...`` left out. Swept values count (a grid
    swept in a mesh study makes other groups, :func:`setting_of`). A case without a ``replicate``
    parameter (a result drawn from Python) is a group of its own.
    """
    groups: dict[str, list[FigureCase]] = {}
    settings = [setting_of(case) for case in cases]
    tied = _tied_to_replicate([s for s in settings if "replicate" in s])
    for number, (case, setting) in enumerate(zip(cases, settings, strict=True)):
        if "replicate" not in case.parameters:
            groups[f"case {number}"] = [case]
            continue
        inputs = {k: v for k, v in setting.items() if k != "replicate" and k not in tied}
        key = repr(sorted(inputs.items(), key=lambda item: item[0]))
        groups.setdefault(key, []).append(case)
    return {
        ", ".join(p for p in group[0].label.split(", ") if not p.startswith("replicate ")): group
        for group in groups.values()
    }


def axis_words(key: str) -> str:
    """Return a swept key or parameter in words: its last dotted part, spaces for underscores.

    ``topographies.island.shape`` -> ``shape``, ``mean_pressure`` -> ``mean pressure``: a legend, a
    title or a methods paragraph is read, not parsed.
    """
    return key.rsplit(".", 1)[-1].replace("_", " ")


def _tied_to_replicate(settings: list[dict[str, Any]]) -> set[str]:
    """Return the keys whose value changes exactly when the replicate does (zipped with it)."""
    tied = set()
    for key in {k for setting in settings for k in setting} - {"replicate"}:
        forward: dict[str, str] = {}
        backward: dict[str, str] = {}
        one_to_one = all(
            forward.setdefault(repr(s.get("replicate")), repr(s.get(key))) == repr(s.get(key))
            and backward.setdefault(repr(s.get(key)), repr(s.get("replicate"))) == repr(s.get("replicate"))
            for s in settings
        )
        if one_to_one and len(forward) > 1:
            tied.add(key)
    return tied


def setting_of(case: FigureCase) -> dict[str, Any]:
    """Return what a case was run with: its parameters and, for a study record, its swept values.

    A swept topography key (``topographies.island.shape``, a mesh study) is not among the case's
    parameters, which name the surface only: without the swept values, cases on different grids
    would look alike.
    """
    data = getattr(case, "data", None)
    axes = data.get("axes") if isinstance(data, dict) else None
    return {**dict(case.parameters), **dict(axes or {})}


def with_fields(cases: Sequence[FigureCase]) -> list[FigureCase]:
    """Return the cases that hold fields and curves."""
    return [case for case in cases if case.has_fields]


def scalar_series(cases: Sequence[FigureCase], *names: str) -> tuple[np.ndarray, ...]:
    """Arrays of the scalars ``names`` over ``cases``, ordered by the first of them."""
    values = np.array([[float(c.scalars[name]) for name in names] for c in cases], dtype=float)
    values = values[np.argsort(values[:, 0], kind="stable")]
    return tuple(values.T)


def panel_per_case(
    cases: Sequence[FigureCase], draw, *, limit: int = 4, width: float = 5.5, height: float = 4.4
):
    """Return a figure of one panel per case with fields (at most ``limit``), or None without any.

    ``draw(case, data, ax)`` draws one case from its scalars and its loaded fields.
    """
    from .layout import new_figure

    chosen = with_fields(cases)[:limit]
    if not chosen:
        return None
    figure, axes = new_figure(1, len(chosen), width=width, height=height)
    for ax, case in zip(axes[0], chosen, strict=True):
        draw(case, case.dataset(), ax)
    return figure


LOAD_RTOL = 1e-9
"""Relative difference below which two cases' loads count as one (:func:`loads_of`)."""


def load_of(case: FigureCase, key: str = "normal_force") -> float:
    """Return the load of a case: its parameter ``key`` [N]."""
    return float(case.parameters[key])


def loads_of(cases: Sequence[FigureCase], key: str = "normal_force") -> list[float]:
    """Return the distinct loads of the cases, ascending (equal within :data:`LOAD_RTOL`)."""
    distinct: list[float] = []
    for load in sorted(load_of(case, key) for case in cases):
        if not distinct or not math.isclose(load, distinct[-1], rel_tol=LOAD_RTOL):
            distinct.append(load)
    return distinct


def at_load(cases: Sequence[FigureCase], load: float, key: str = "normal_force") -> list[FigureCase]:
    """Return the cases at ``load`` (within :data:`LOAD_RTOL`)."""
    return [case for case in cases if math.isclose(load_of(case, key), load, rel_tol=LOAD_RTOL)]


def by_sample(cases: Sequence[FigureCase], name: str) -> dict[str, list[float]]:
    """Return scalar ``name`` of every case, per sample (in order of first appearance)."""
    return {sample: [float(c.scalars[name]) for c in group] for sample, group in grouped(cases).items()}


def box_around(mask: np.ndarray, margin: int) -> tuple[slice, slice] | None:
    """Return the rows and columns of the smallest box around every True of ``mask``, ``margin`` wider.

    Clipped to the grid; None when ``mask`` holds no True. Crops stored or drawn fields to where
    something happens (a contact, the springs that carry friction).
    """
    rows, columns = np.nonzero(mask)
    if rows.size == 0:
        return None
    nx, ny = mask.shape
    return (
        slice(max(int(rows.min()) - margin, 0), min(int(rows.max()) + margin + 1, nx)),
        slice(max(int(columns.min()) - margin, 0), min(int(columns.max()) + margin + 1, ny)),
    )


def branch_points(branches: np.ndarray, branch: str) -> np.ndarray:
    """Return the indices of a branch's points; the unloading branch starts at the peak (the point before)."""
    points = np.flatnonzero(np.asarray(branches) == branch)
    if branch == "unloading" and points.size and points[0] > 0:
        points = np.concatenate([[points[0] - 1], points])
    return points
