"""Packages whose public names load on first use (PEP 562), so that importing a package stays cheap.

``roughcontact``, ``roughcontact.contact``, ``roughcontact.plotting`` and ``roughcontact.topography``
name their public objects in ``__all__`` but import the modules that define them only when a name
is first asked for: ``import roughcontact.topography.io`` then costs that module's imports, not the
whole package's (SciPy's signal processing, the generators), and the normal solver does not import
the adhesive, tangential and plastic ones. Each such package has an ``__init__.pyi`` stub
saying the same statically, for type checkers and IDEs (``tests/unit/test_type_stubs.py``).
"""

from __future__ import annotations

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
        ``roughcontact.topography``) is that submodule.

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
        value = getattr(home, name) if hasattr(home, name) else import_module(f"{home.__name__}.{name}")
        namespace[name] = value
        return value

    def __dir__() -> list[str]:
        return sorted(set(namespace) | set(homes))

    return __getattr__, __dir__
