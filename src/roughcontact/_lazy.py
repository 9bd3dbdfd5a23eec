"""Packages whose public names load on first use (PEP 562), listed once: in the package's type stub.

``roughcontact``, ``roughcontact.contact``, ``roughcontact.plotting`` and ``roughcontact.topography``
name their public objects but import the modules that define them only when a name is first asked
for: ``import roughcontact.topography.io`` then costs that module's imports, not the whole
package's (SciPy's signal processing, the generators), and the normal solver does not import the
adhesive, tangential and plastic ones.

The names are written once, in the ``__init__.pyi`` stub beside the package's ``__init__.py``, as
re-exports (``from .io import read_topography as read_topography``), which type checkers and IDEs
read. The package reads the same file when it is imported (:func:`attach_stub`, the idea of
scientific-python's ``lazy_loader.attach_stub``): each import says a name's home, and the names
are the package's ``__all__``. A new public name is one line of the stub, nothing else.
"""

from __future__ import annotations

import ast
import os
import sys
import types
from collections.abc import Callable, Mapping
from importlib import import_module
from importlib.util import find_spec


class _Package(types.ModuleType):
    """A lazy package: a public name keeps its object when the submodule of the same name is imported.

    Importing ``roughcontact.contact.load_unload`` makes the import system bind the submodule to
    the package's attribute ``load_unload``, where the public name is the function of that
    module. An eager ``from .load_unload import load_unload`` rebinds the function after the
    import; this does the same whenever the submodule is imported.
    """

    def __setattr__(self, name: str, value) -> None:
        if (
            isinstance(value, types.ModuleType)
            and value.__name__ == f"{self.__name__}.{name}"
            and name in self._lazy_homes
            and hasattr(value, name)
        ):
            value = getattr(value, name)
        super().__setattr__(name, value)


def lazy_names(package: str, homes: Mapping[str, str]) -> tuple[Callable, Callable]:
    """Return a package's ``__getattr__`` and ``__dir__`` that load ``homes``' names on first use.

    Parameters
    ----------
    package : str
        The package's ``__name__`` (it must be importing: called from its ``__init__``).
    homes : mapping
        Public name -> the module that defines it, absolute or relative to ``package``
        (``".io"``). A name that is a submodule of its home (``generate`` of
        ``roughcontact.topography``, or of the package itself, home ``"."``) is that submodule.

    Returns
    -------
    __getattr__, __dir__
        To be bound to those names in the package; a loaded name is kept in the package's
        namespace, so ``__getattr__`` runs once per name. A submodule is an attribute as well,
        imported on first use (``rc.topography.level``), as after ``import roughcontact.topography``.
    """
    module = sys.modules[package]
    module.__class__ = _Package
    namespace = vars(module)
    namespace["_lazy_homes"] = homes

    def __getattr__(name: str):
        if name not in homes:
            if not name.startswith("_") and find_spec(f"{package}.{name}") is not None:
                return import_module(f"{package}.{name}")  # a subpackage or module: rc.topography
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        home = import_module(homes[name], package)
        if home is module or not hasattr(home, name):
            value = import_module(f"{home.__name__}.{name}")
        else:
            value = getattr(home, name)
        namespace[name] = value
        return value

    def __dir__() -> list[str]:
        return sorted(set(namespace) | set(homes))

    return __getattr__, __dir__


def stub_homes(stub: str, name: str = "__init__.pyi") -> dict[str, str]:
    """Return public name -> its home module of every re-export in a type stub's text, in order.

    Parameters
    ----------
    stub : str
        The stub's text: top-level ``from .module import name as name`` statements (a module
        relative to the package, or absolute; several names and parentheses allowed), a
        docstring, and a declaration ``__all__: list[str]``.
    name : str
        The stub's file name, for the error messages.

    Returns
    -------
    dict
        Name -> module as written (``".io"``, ``".."``-relative or absolute); ``"."`` for a
        submodule of the package (``from . import generate as generate``).

    Raises
    ------
    ValueError
        On an import that is not a re-export under the same name (``import x``, ``from .x import
        a``, ``from .x import a as b``, ``*``), which a type checker would not count as a public
        name of the package, and on a name re-exported twice.
    """
    homes: dict[str, str] = {}
    for node in ast.parse(stub, filename=name).body:
        if isinstance(node, ast.Import):
            raise ValueError(f"{name}, line {node.lineno}: write 'from MODULE import NAME as NAME'")
        if not isinstance(node, ast.ImportFrom):
            continue
        module = "." * node.level + (node.module or "")
        for alias in node.names:
            if alias.asname != alias.name:
                raise ValueError(
                    f"{name}, line {node.lineno}: {alias.name!r} must be re-exported as itself "
                    f"('from {module} import {alias.name} as {alias.name}')"
                )
            if alias.name in homes:
                raise ValueError(f"{name}, line {node.lineno}: {alias.name!r} is re-exported twice")
            homes[alias.name] = module
    return homes


def attach_stub(package: str) -> tuple[Callable, Callable, list[str]]:
    """Make ``package`` load the public names its ``__init__.pyi`` stub re-exports, on first use.

    Use as the last line of the package's ``__init__.py``::

        __getattr__, __dir__, __all__ = attach_stub(__name__)

    Parameters
    ----------
    package : str
        The package's ``__name__`` (it must be importing: called from its ``__init__``).

    Returns
    -------
    __getattr__, __dir__, __all__
        The first two as :func:`lazy_names` returns them for the stub's names
        (:func:`stub_homes`), then the names, sorted: the package's ``__all__``.

    Raises
    ------
    FileNotFoundError
        Without a stub beside the package's ``__init__.py`` (the wheel ships them,
        ``pyproject.toml``'s package data).
    """
    stub = os.path.join(os.path.dirname(sys.modules[package].__file__), "__init__.pyi")
    with open(stub, encoding="utf-8") as file:
        homes = stub_homes(file.read(), f"{package.replace('.', '/')}/__init__.pyi")
    return (*lazy_names(package, homes), sorted(homes))
