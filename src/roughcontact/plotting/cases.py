"""What a figure of several cases draws from: results as cases, captions, a figure function by name.

Every figure of a study (``roughcontact run``, ``roughcontact plot OUT/``) is a function of this
package taking a sequence of *cases*, each with what :class:`roughcontact.cases.Case` names: a
``label`` for the legend, its ``scalars`` and ``parameters`` (SI) and its fields and curves as an
``xarray.Dataset``. A study passes its stored case records; from Python, :func:`as_cases` wraps
results (anything with ``scalars()`` and ``to_xarray()``, the result protocol) so the same figure
is drawn without a study::

    from roughcontact.plotting import adhesion_force_approach_figure, as_cases
    figure = adhesion_force_approach_figure(as_cases([cycle_a, cycle_b], labels=["A", "B"]))

A figure function returns a matplotlib ``Figure``, or None where the cases do not make it (a load
curve of one load); its caption, what a reader needs to read it, is attached with :func:`caption`.
Nothing here imports matplotlib. The helpers that choose and group cases without drawing
(:func:`~roughcontact.cases.realisations_of`, :func:`~roughcontact.cases.at_load`, ...) are in
:mod:`roughcontact.cases`, below both the figures and the study layer; their old names here warn
and go in the next release.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, TypeVar

from .._deprecation import moved

if TYPE_CHECKING:
    from ..cases import Case

_F = TypeVar("_F", bound=Callable[..., Any])

_MOVED = dict.fromkeys(
    (
        "LOAD_RTOL",
        "at_load",
        "axis_words",
        "box_around",
        "branch_points",
        "by_sample",
        "evenly_chosen",
        "grouped",
        "load_of",
        "loads_of",
        "realisations_of",
        "scalar_series",
        "setting_of",
        "with_fields",
    ),
    "roughcontact.cases",
)
"""The helpers that draw nothing, moved to :mod:`roughcontact.cases` (kept here one release)."""


def __getattr__(name: str) -> Any:
    return moved(__name__, name, _MOVED)


@dataclass(frozen=True)
class ResultCase:
    """A result object as a case (:class:`roughcontact.cases.Case`): ``scalars()``, ``to_xarray()``, a label.

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
) -> list[Case]:
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
    cases: list[Case] = []
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


def panel_per_case(cases: Sequence[Case], draw, *, limit: int = 4, width: float = 5.5, height: float = 4.4):
    """Return a figure of one panel per case with fields (at most ``limit``), or None without any.

    ``draw(case, data, ax)`` draws one case from its scalars and its loaded fields.
    """
    from ..cases import with_fields
    from .layout import new_figure

    chosen = with_fields(cases)[:limit]
    if not chosen:
        return None
    figure, axes = new_figure(1, len(chosen), width=width, height=height)
    for ax, case in zip(axes[0], chosen, strict=True):
        draw(case, case.dataset(), ax)
    return figure
