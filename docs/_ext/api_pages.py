"""Sphinx extension: write the API reference's pages, one per documented package and module.

Each page shows the package's docstring and an ``autosummary`` table of its public names (its
``__all__``; for a module without one, the functions and classes it defines); ``autosummary``
then writes a page per name. An object reachable under several names (``solve_normal`` is in
``roughcontact`` and ``roughcontact.contact``) gets one page, under the first package of
:data:`DOCUMENTED` that names it; the other packages link to it. The pages are written into
``docs/api/`` at every build (the folder is not kept in git).
"""

from __future__ import annotations

import importlib
import inspect
import sys
from pathlib import Path

DOCUMENTED = (
    "roughcontact.topography",
    "roughcontact.topography.io",
    "roughcontact.topography.generate",
    "roughcontact.topography.process",
    "roughcontact.topography.statistics",
    "roughcontact.topography.native",
    "roughcontact.topography.file_cache",
    "roughcontact.topography.plausible",
    "roughcontact.materials",
    "roughcontact.units",
    "roughcontact.errors",
    "roughcontact.results",
    "roughcontact.spread",
    "roughcontact.references",
    "roughcontact.elasticity",
    "roughcontact.contact",
    "roughcontact.contact.trust",
    "roughcontact.analytic",
    "roughcontact.asperity",
    "roughcontact.theory",
    "roughcontact.winkler_lj",
    "roughcontact.experiment",
    "roughcontact.experiment.friction_loop",
    "roughcontact.experiment.nanoindentation",
    "roughcontact.papers.paper000",
    "roughcontact.papers.paper001",
    "roughcontact.papers.paper002",
    "roughcontact.plotting",
    "roughcontact.plotting.topography",
    "roughcontact.plotting.contact",
    "roughcontact.plotting.adhesion",
    "roughcontact.plotting.friction",
    "roughcontact.plotting.presliding",
    "roughcontact.plotting.asperity",
    "roughcontact.plotting.indentation",
    "roughcontact.study",
    "roughcontact",
)
"""The packages and modules with a reference page, in the order that decides a name's home page."""


def public_names(module) -> list[str]:
    """Return a module's public names: its ``__all__``, else the functions and classes it defines."""
    names = getattr(module, "__all__", None)
    if names is None:
        names = [
            name
            for name, value in vars(module).items()
            if not name.startswith("_")
            and (inspect.isfunction(value) or inspect.isclass(value))
            and value.__module__ == module.__name__
        ]
    return sorted(names, key=str.lower)


def homes() -> dict[str, dict[str, str]]:
    """Return, per documented package, its names -> the package whose page documents each.

    A name that is a documented module (``generate`` of ``roughcontact``, the module
    ``roughcontact.topography.generate``) is documented by that module's own page, under the name
    that imports it, not as ``roughcontact.generate``, which ``import`` does not find.
    """
    placed: dict[int, str] = {}
    result: dict[str, dict[str, str]] = {}
    for package in DOCUMENTED:
        module = importlib.import_module(package)
        result[package] = {}
        for name in public_names(module):
            value = getattr(module, name)
            if inspect.ismodule(value) and value.__name__ in DOCUMENTED:
                result[package][name] = value.__name__
                continue
            result[package][name] = placed.setdefault((name, id(value)), package)
    return result


def canonical_names() -> dict[int, str]:
    """Return id(object) -> the dotted name of its reference page, for every documented object."""
    names = {}
    for package, placed in homes().items():
        module = importlib.import_module(package)
        names.setdefault(id(module), package)
        for name, home in placed.items():
            if home == package:
                names.setdefault(id(getattr(module, name)), f"{package}.{name}")
    return names


_NONE = object()


def _attribute(value, names: list[str]):
    """Return ``value``'s attribute path ``names`` (a class for a field it declares); _NONE if none."""
    for attribute in names:
        if hasattr(value, attribute):
            value = getattr(value, attribute)
        elif inspect.isclass(value) and any(
            attribute in getattr(c, "__annotations__", {}) for c in value.__mro__
        ):
            return value  # a declared field: documented on its class's page
        else:
            return _NONE
    return value


def _imported(target: str, module: str | None, klass: str | None):
    """Return the object a Python cross-reference names, as Python would find it; _NONE if none.

    Tried: the target in the current class and module, then as a dotted name; an attribute a
    class declares (a dataclass field) is its class; a name whose first part is defined in
    exactly one of roughcontact's modules starts there.
    """
    candidates = [target]
    if module:
        candidates = [f"{module}.{klass}.{target}"] * bool(klass) + [f"{module}.{target}", target]
    for dotted in candidates:
        parts = dotted.split(".")
        for cut in range(len(parts), 0, -1):
            try:
                value = importlib.import_module(".".join(parts[:cut]))
            except ImportError:
                continue
            value = _attribute(value, parts[cut:])
            if value is not _NONE:
                return value
            break
    first, *rest = target.split(".")
    found = {
        id(getattr(loaded, first)): getattr(loaded, first)
        for name, loaded in list(sys.modules.items())
        if name.startswith("roughcontact.") and loaded is not None and first in vars(loaded)
    }
    return _attribute(next(iter(found.values())), rest) if len(found) == 1 else _NONE


def resolve(app, env, node, contnode):
    """Resolve a reference to an object by another of its names (Sphinx ``missing-reference``).

    Docstrings name an object where it is defined (``roughcontact.topography.io.read_topography``),
    the site documents it once, under its public name (``roughcontact.topography.read_topography``).
    A reference that imports to a documented object links to its page; one that imports to an
    object outside the public API (a private helper) is shown as code without a link; one that
    does not import is left unresolved, and the build fails on it.
    """
    if node.get("refdomain") != "py":
        return None
    value = _imported(node["reftarget"], node.get("py:module"), node.get("py:class"))
    if value is _NONE:
        return None
    if not hasattr(app.env, "_roughcontact_canonical"):
        app.env._roughcontact_canonical = canonical_names()
    canonical = app.env._roughcontact_canonical.get(id(value))
    if canonical is None:
        return contnode
    domain = env.get_domain("py")
    found = domain.resolve_any_xref(env, node["refdoc"], app.builder, canonical, node, contnode)
    return found[0][1] if found else contnode


def _title(text: str) -> str:
    return f"{text}\n{'=' * len(text)}\n"


def package_page(package: str, names: dict[str, str]) -> str:
    """Return the reST page of one package: its docstring, its own names, links to the others."""
    own = [name for name, home in names.items() if home == package]
    elsewhere = [(name, home) for name, home in names.items() if home != package]
    lines = [
        _title(package),
        f".. automodule:: {package}\n   :no-members:\n",
        f".. currentmodule:: {package}\n",
    ]
    if own:
        lines.append(".. autosummary::\n   :toctree: generated\n   :nosignatures:\n")
        lines += [f"   {name}" for name in own]
        lines.append("")
    if elsewhere:
        lines.append("Also here, documented with the package that holds them:\n")
        lines += [
            f"- :py:mod:`{name} <{home}>` (:doc:`{home}`)"
            if home in DOCUMENTED and home.rsplit(".", 1)[-1] == name
            else f"- :py:obj:`{name} <{home}.{name}>` (:doc:`{home}`)"
            for name, home in elsewhere
        ]
        lines.append("")
    return "\n".join(lines) + "\n"


def write_pages(app, config) -> None:
    """Write ``api/index.rst`` and a page per documented package (Sphinx ``config-inited``)."""
    folder = Path(app.srcdir) / "api"
    folder.mkdir(exist_ok=True)
    placed = homes()
    for package, names in placed.items():
        page = folder / f"{package}.rst"
        text = package_page(package, names)
        if not page.exists() or page.read_text() != text:  # unchanged pages keep their build
            page.write_text(text)
    named = {
        f"{home}.{name}"
        for package, names in placed.items()
        for name, home in names.items()
        if home == package
    }
    for stale in (folder / "generated").glob("*.rst"):  # a name that moved: its old page is in no toctree
        if stale.stem not in named:
            stale.unlink()
    index = [
        _title("API reference"),
        "Every public name, one page each, from the docstrings (numpy style: parameters with their "
        "units, the equation and the paper each function implements). ``import roughcontact as rc`` "
        "offers the common jobs; the packages hold the rest.\n",
        ".. toctree::\n   :maxdepth: 1\n",
        "   roughcontact",
        *[f"   {package}" for package in DOCUMENTED if package != "roughcontact"],
        "",
    ]
    text = "\n".join(index) + "\n"
    if not (folder / "index.rst").exists() or (folder / "index.rst").read_text() != text:
        (folder / "index.rst").write_text(text)


def setup(app):
    """Register the page writer."""
    app.connect("config-inited", write_pages)  # before Sphinx lists the source files
    app.connect("missing-reference", resolve)
    return {"parallel_read_safe": True, "version": "1"}
