"""A study's cases as data: what a case holds, and the helpers that choose, group and crop cases.

A *case* is one run of a model: a study's stored ``CaseRecord``, or a result wrapped for a figure
(:class:`roughcontact.plotting.ResultCase`). Each has what :class:`Case` names: a ``label``, its
``scalars`` and ``parameters`` (SI) and its fields and curves as an ``xarray.Dataset``. The study
layer groups its cases by realisation to report their spread (:func:`realisations_of`), picks the
cases at a load (:func:`at_load`) and crops stored fields (:func:`box_around`); the figures of
:mod:`roughcontact.plotting` draw from the same groups. None of this draws, so it lives below
both: :mod:`roughcontact.study` and :mod:`roughcontact.plotting` import it from here.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any, Protocol

import numpy as np


class Case(Protocol):
    """One case as the figures and the study's summaries read it (a ``CaseRecord``, a ``ResultCase``)."""

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


def evenly_chosen(items: Sequence, count: int) -> list:
    """At most ``count`` items, evenly spread over ``items`` (first and last included)."""
    if len(items) <= count:
        return list(items)
    picks = np.unique(np.linspace(0, len(items) - 1, count).round().astype(int))
    return [items[i] for i in picks]


def grouped(cases: Sequence[Case], key: str = "sample") -> dict[str, list[Case]]:
    """Return the cases grouped by a parameter (default the sample label), in order of first appearance."""
    groups: dict[str, list[Case]] = {}
    for case in cases:
        groups.setdefault(str(case.parameters.get(key, "")), []).append(case)
    return groups


def realisations_of(cases: Sequence[Case]) -> dict[str, list[Case]]:
    """Return the cases grouped by everything but their realisation, each group by its label without it.

    Cases that differ only in ``replicate`` (the realisations of a study's generated surfaces),
    or in a value zipped with it (measured files of one sample, one per replicate), are one group;
    the key is the label of its cases with ``replicate ...`` left out. Swept values count (a grid
    swept in a mesh study makes other groups, :func:`setting_of`). A case without a ``replicate``
    parameter (a result drawn from Python) is a group of its own.
    """
    groups: dict[str, list[Case]] = {}
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


def setting_of(case: Case) -> dict[str, Any]:
    """Return what a case was run with: its parameters and, for a study record, its swept values.

    A swept topography key (``topographies.island.shape``, a mesh study) is not among the case's
    parameters, which name the surface only: without the swept values, cases on different grids
    would look alike.
    """
    data = getattr(case, "data", None)
    axes = data.get("axes") if isinstance(data, dict) else None
    return {**dict(case.parameters), **dict(axes or {})}


def with_fields(cases: Sequence[Case]) -> list[Case]:
    """Return the cases that hold fields and curves."""
    return [case for case in cases if case.has_fields]


def surface_origin(cases: Sequence[Case | None]) -> str:
    """Return where the cases' surfaces come from, as their ``surface_origin`` scalars say.

    ``"measured"`` (a file), ``"synthetic"`` (generated), both joined by "and" where the cases mix
    them; ``""`` where none says (cases stored before the origin was recorded). Missing cases
    (None) are passed over.
    """
    found = {case.scalars.get("surface_origin") for case in cases if case is not None}
    return " and ".join(sorted(o for o in found if o))


def scalar_series(cases: Sequence[Case], *names: str) -> tuple[np.ndarray, ...]:
    """Arrays of the scalars ``names`` over ``cases``, ordered by the first of them."""
    values = np.array([[float(c.scalars[name]) for name in names] for c in cases], dtype=float)
    values = values[np.argsort(values[:, 0], kind="stable")]
    return tuple(values.T)


LOAD_RTOL = 1e-9
"""Relative difference below which two cases' loads count as one (:func:`loads_of`)."""


def load_of(case: Case, key: str = "normal_force") -> float:
    """Return the load of a case: its parameter ``key`` [N]."""
    return float(case.parameters[key])


def loads_of(cases: Sequence[Case], key: str = "normal_force") -> list[float]:
    """Return the distinct loads of the cases, ascending (equal within :data:`LOAD_RTOL`)."""
    distinct: list[float] = []
    for load in sorted(load_of(case, key) for case in cases):
        if not distinct or not math.isclose(load, distinct[-1], rel_tol=LOAD_RTOL):
            distinct.append(load)
    return distinct


def at_load(cases: Sequence[Case], load: float, key: str = "normal_force") -> list[Case]:
    """Return the cases at ``load`` (within :data:`LOAD_RTOL`)."""
    return [case for case in cases if math.isclose(load_of(case, key), load, rel_tol=LOAD_RTOL)]


def by_sample(cases: Sequence[Case], name: str) -> dict[str, list[float]]:
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
