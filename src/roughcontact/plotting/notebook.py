"""The small figure a notebook shows under a result's table of scalars (:mod:`roughcontact.display_html`)."""

from __future__ import annotations

from io import BytesIO

import matplotlib

from .cases import plotting_function
from .layout import axes_for


def thumbnail(name: str, result, *, size: tuple[float, float] = (3.0, 2.5), dpi: int = 80) -> bytes:
    """Return a small PNG of a result's figure, as a notebook shows it under the result's table.

    Parameters
    ----------
    name : str
        The figure: ``"module.function"`` of this package
        (:func:`~roughcontact.plotting.cases.plotting_function`), drawn as ``function(result, ax=ax)``.
    result : Result
        What it draws.
    size : (float, float)
        Width and height [inch].
    dpi : int
        Resolution [dots per inch].

    Returns
    -------
    bytes
        The PNG file's content.
    """
    with matplotlib.rc_context({"font.size": 7}):
        figure, ax = axes_for(None, figsize=size)
        plotting_function(name)(result, ax=ax)
        buffer = BytesIO()
        figure.savefig(buffer, format="png", dpi=dpi)
    return buffer.getvalue()
