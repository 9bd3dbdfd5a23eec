"""Names of release 0.1 that moved or were renamed: kept one release, with a DeprecationWarning.

:func:`moved` serves a module's ``__getattr__`` (a name now defined elsewhere), :func:`moved_module`
stands in for a whole module that moved, :func:`folded` takes keywords that became one option object;
:func:`renamed`
wraps a function whose keyword arguments were respelled (``counter=`` is now ``counter_body=``).
"""

from __future__ import annotations

import functools
import sys
import warnings
from collections.abc import Callable, Mapping
from importlib import import_module
from typing import Any


def moved(module: str, name: str, homes: Mapping[str, str]) -> Any:
    """Return ``name`` from its new module (``homes[name]``) with a warning; AttributeError otherwise.

    Use as ``def __getattr__(name): return moved(__name__, name, {"old": "roughcontact.new"})``.
    """
    if name not in homes:
        raise AttributeError(f"module {module!r} has no attribute {name!r}")
    warnings.warn(
        f"{module}.{name} has moved to {homes[name]}.{name}; import it from there "
        "(the old place goes in the next release).",
        DeprecationWarning,
        stacklevel=3,
    )
    return getattr(import_module(homes[name]), name)


def moved_module(module: str, home: str) -> None:
    """Make the module ``module`` (a kept old place) the module ``home``, with a warning.

    Use as the whole body of the old module: ``moved_module(__name__, "roughcontact.new.place")``;
    ``import old`` and ``from old import name`` then give the new module's names.
    """
    import sys

    warnings.warn(
        f"{module} has moved to {home}; import it from there (the old place goes in the next release).",
        DeprecationWarning,
        stacklevel=3,
    )
    sys.modules[module] = import_module(home)


def _outside() -> int:
    """Return the ``stacklevel`` of the first caller outside this module (a wrapper may wrap a wrapper).

    So that a warning names the user's line also where :func:`renamed` and :func:`folded` decorate
    one function together.
    """
    frame, level = sys._getframe(1), 1
    while frame is not None and frame.f_globals.get("__name__") == __name__:
        frame, level = frame.f_back, level + 1
    return level


def renamed(**spellings: str) -> Callable:
    """Decorate a function so that each old keyword (``counter="counter_body"``) works, with a warning."""

    def decorate(function: Callable) -> Callable:
        @functools.wraps(function)
        def wrapper(*args, **kwargs):
            for old, new in spellings.items():
                if old in kwargs:
                    if new in kwargs:
                        raise TypeError(f"{function.__name__}() got both {old!r} and its new name {new!r}")
                    warnings.warn(
                        f"{function.__name__}({old}=...) is now spelled {new}=...; the old spelling goes "
                        "in the next release.",
                        DeprecationWarning,
                        stacklevel=_outside(),
                    )
                    kwargs[new] = kwargs.pop(old)
            return function(*args, **kwargs)

        return wrapper

    return decorate


def folded(target: str, names: tuple[str, ...], fold: Callable[..., Any]) -> Callable:
    """Decorate a function whose keywords ``names`` became one option object, the keyword ``target``.

    A call with any of the old keywords warns and gets ``target=fold(old_target, **old_keywords)``
    (``old_target`` is what the call gave for ``target``, or None).
    """

    def decorate(function: Callable) -> Callable:
        @functools.wraps(function)
        def wrapper(*args, **kwargs):
            old = {name: kwargs.pop(name) for name in names if name in kwargs}
            if old:
                warnings.warn(
                    f"{function.__name__}({', '.join(f'{n}=...' for n in old)}) is now given as "
                    f"{target}=...; the old spelling goes in the next release.",
                    DeprecationWarning,
                    stacklevel=_outside(),
                )
                kwargs[target] = fold(kwargs.get(target), **old)
            return function(*args, **kwargs)

        return wrapper

    return decorate
