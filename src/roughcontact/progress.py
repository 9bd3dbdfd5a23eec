"""Progress of the long loops inside one computation, for a person watching a terminal.

A solver wraps its step loop in :func:`tracked` (the tangential programme of a pre-sliding case,
the loads of a load-unload); nothing is shown unless the caller turned it on with :func:`shown`,
as the command line does when standard error is a terminal. Elsewhere (a test, a pipe, a Dask
worker, a library user's script) :func:`tracked` returns the iterable untouched.
"""

from __future__ import annotations

import contextlib
import sys
from collections.abc import Iterable, Iterator
from contextvars import ContextVar
from typing import TypeVar

_SHOWN: ContextVar[bool] = ContextVar("roughcontact_progress_shown", default=False)
T = TypeVar("T")


@contextlib.contextmanager
def shown(enabled: bool = True) -> Iterator[None]:
    """Show the progress of :func:`tracked` loops run inside this block (when ``enabled``)."""
    token = _SHOWN.set(enabled)
    try:
        yield
    finally:
        _SHOWN.reset(token)


def tracked(iterable: Iterable[T], *, total: int | None = None, what: str = "steps") -> Iterable[T]:
    """Return ``iterable``, drawn as a progress bar on standard error inside a :func:`shown` block.

    Parameters
    ----------
    iterable : iterable
        The loop's items.
    total : int, optional
        Their number, where ``len`` cannot tell.
    what : str
        What one item is, for the bar (``"tangential steps"``).
    """
    if not _SHOWN.get():
        return iterable
    from tqdm.auto import tqdm

    bar = {"unit": "step", "file": sys.stderr, "leave": False, "dynamic_ncols": True}
    return tqdm(iterable, total=total, desc=what, **bar)
