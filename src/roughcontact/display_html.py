"""Results that show themselves in a notebook: a table of their scalars with units, a small figure.

Jupyter (and VS Code, and every front end of IPython) shows an object through its
``_repr_html_``, as it shows xarray's. Every public result inherits :class:`NotebookDisplay`,
whose display is :func:`html_summary`: the class and the first line of its docstring, one row per
scalar of ``scalars()`` in engineering units (:func:`roughcontact.units.shown`, the rule of the
commands' printed summaries, so notebook and terminal agree), how the solver ended, where the result
leaves its model's range (``range_warnings()``, what the commands print as warnings), and, where the
class names a figure of :mod:`roughcontact.plotting` in ``FIGURE``, a thumbnail of it: matplotlib
is imported when a notebook shows the result, never when the result's module is imported. The
study's answer shows its cases through :func:`html_table`. ``repr()`` stays the dataclass's text.

The HTML stands alone: every text escaped, a little inline style, no script, no external file.
"""

from __future__ import annotations

import base64
import html
import re
from collections.abc import Callable, Sequence
from typing import Any, ClassVar

import numpy as np

from .results import SolverResult, units_of
from .units import shown

MISSING_CELL = "—"
"""What a notebook's table shows for a value that is not there (None, NaN)."""

_CELL = "padding:1px 8px;text-align:{}"
_ROLE = re.compile(r":[a-z]+:`~?([^`]*)`|``([^`]*)``")
"""A Sphinx role (``:func:`name```) or literal (````x````) of a docstring, read as its plain text."""


def html_table(
    titles: Sequence[str], cells: Sequence[Sequence[str]], *, title: str = "", caption: str = ""
) -> str:
    """Return an HTML table of text cells, every text escaped here.

    Parameters
    ----------
    titles : sequence of str
        The column headers.
    cells : sequence of sequence of str
        One sequence per row, one text per column; the first column is aligned left, the others
        right (numbers).
    title, caption : str
        Above the table: ``title`` in bold, then ``caption``; neither, no caption.
    """

    def row(texts: Sequence[str], tag: str) -> str:
        joined = "".join(
            f'<{tag} style="{_CELL.format("right" if i else "left")}">{html.escape(str(t))}</{tag}>'
            for i, t in enumerate(texts)
        )
        return f"<tr>{joined}</tr>"

    head = ""
    if title or caption:
        bold = f"<strong>{html.escape(title)}</strong> " if title else ""
        head = f'<caption style="text-align:left">{bold}{html.escape(caption)}</caption>'
    body = "".join(row(texts, "td") for texts in cells)
    return (
        f'<table style="border-collapse:collapse">{head}<thead>{row(titles, "th")}</thead>'
        f"<tbody>{body}</tbody></table>"
    )


def value_text(value: Any, unit: str | None) -> str:
    """Return a scalar as a notebook shows it: :func:`~roughcontact.units.shown`, a yes/no, or '—'."""
    if isinstance(value, bool | np.bool_):
        return "yes" if value else "no"
    return shown(value, unit, MISSING_CELL)


def solver_line(result: Any) -> str:
    """Return how a result's solver ended ("converged in 13 iterations, residual 8.6e-09"); "" for none.

    A result of several steps (per-step ``iterations`` and ``residual``) says the iterations of all
    its steps and the largest residual.
    """
    if not isinstance(result, SolverResult):
        return ""
    steps = int(np.size(result.iterations))
    over = f" over {steps} steps" if steps > 1 else ""
    iterations = f"{int(np.sum(result.iterations))} iterations{over}"
    residual = value_text(float(np.max(result.residual)), None)
    largest = "largest residual" if steps > 1 else "residual"
    if result.converged:
        return f"converged in {iterations}, {largest} {residual}"
    return f"did not converge: {iterations}, {largest} {residual}"


def summary_of(cls: type) -> str:
    """Return the first line of a class's docstring, its Sphinx markup read as plain text."""
    lines = (cls.__doc__ or "").strip().splitlines()
    return _ROLE.sub(lambda match: match.group(1) or match.group(2), lines[0]) if lines else ""


_THUMBNAIL: Callable[[str, Any], bytes] | None = None
"""What draws a result's thumbnail (``thumbnail(name, result) -> PNG bytes``); None: no figure.

Registered from above (:func:`draw_thumbnails_with`): the package ``roughcontact`` registers
:func:`roughcontact.plotting.notebook.thumbnail`, loaded on first use, so that this module, a floor
below the figures, never imports them.
"""


def draw_thumbnails_with(thumbnail: Callable[[str, Any], bytes] | None) -> None:
    """Register the function that draws a result's thumbnail (None: show tables without figures)."""
    global _THUMBNAIL
    _THUMBNAIL = thumbnail


def figure_html(result: Any) -> str:
    """Return a thumbnail of the result's ``FIGURE`` as an ``<img>`` (base64 PNG); "" without one.

    A figure that cannot be drawn (a result of one dimension where the figure draws a map) leaves
    the display without a figure, never without its table.
    """
    name = getattr(result, "FIGURE", None)
    if not name or _THUMBNAIL is None:
        return ""
    try:
        png = _THUMBNAIL(name, result)
    except Exception:  # a notebook shows the table whatever the figure does
        return ""
    data = base64.b64encode(png).decode("ascii")
    return f'<img alt="{html.escape(name)}" src="data:image/png;base64,{data}">'


def range_html(result: Any) -> str:
    """Return where the result leaves its model's range (its ``range_warnings()``) as a list; "" if nowhere.

    What the commands print as warnings after a result is shown here under its table, so that a
    number outside its model's validity says so where it is read.
    """
    find = getattr(result, "range_warnings", None)
    lines = find() if callable(find) else []
    if not lines:
        return ""
    items = "".join(f"<li>{html.escape(line)}</li>" for line in lines)
    said = '<p style="color:#a40000;margin-bottom:0"><strong>outside the model\'s range:</strong></p>'
    return f"{said}<ul>{items}</ul>"


def html_summary(result: Any) -> str:
    """Return a result as HTML: its class, its scalars with units, its solver, its range, its figure.

    Parameters
    ----------
    result : Result
        Anything with the result protocol (:mod:`roughcontact.results`): ``scalars()`` and ``UNITS``.

    Returns
    -------
    str
        A ``<div>`` that stands alone (no script, no external file).
    """
    units = units_of(result)
    cells = [(name, value_text(value, units.get(name))) for name, value in result.scalars().items()]
    kind = type(result)
    table = html_table(("scalar", "value"), cells, title=kind.__name__, caption=summary_of(kind))
    solver = solver_line(result)
    ended = f"<p>{html.escape(solver)}</p>" if solver else ""
    return f"<div>{table}{ended}{range_html(result)}{figure_html(result)}</div>"


class NotebookDisplay:
    """What makes a result show itself in a notebook: ``_repr_html_`` is :func:`html_summary`.

    Attributes
    ----------
    FIGURE : str or None
        The figure of the result a notebook shows under its table: ``"module.function"`` of
        :mod:`roughcontact.plotting`, drawn as ``function(result, ax=ax)``; None for none.
    """

    FIGURE: ClassVar[str | None] = None

    def _repr_html_(self) -> str:
        return html_summary(self)
