"""The type stubs of the lazily loaded packages name exactly their public names, from the right homes.

The packages built with :func:`roughcontact._lazy.lazy_names` load their names on first use, which
type checkers and IDEs cannot follow; ``__init__.pyi`` beside each says statically what ``__all__``
says.
"""

import ast
import importlib
from pathlib import Path

import pytest

SOURCE = Path(__file__).resolve().parents[2] / "src" / "roughcontact"


def _stub_names(path: Path) -> dict[str, tuple[str, str]]:
    """Name -> (module relative to the package, name there) of every ``from X import a as a``."""
    names = {}
    for node in ast.parse(path.read_text()).body:
        if isinstance(node, ast.ImportFrom):
            for alias in node.names:
                assert alias.asname == alias.name, f"{path.name}: re-export {alias.name} as itself"
                names[alias.name] = ("." * node.level + (node.module or ""), alias.name)
    return names


@pytest.mark.parametrize(
    "package", ["roughcontact", "roughcontact.contact", "roughcontact.plotting", "roughcontact.topography"]
)
def test_the_stub_names_every_public_name_and_its_home(package):
    module = importlib.import_module(package)
    stub = SOURCE.joinpath(*package.split(".")[1:], "__init__.pyi")
    names = _stub_names(stub)
    assert sorted(names) == sorted(module.__all__)
    for name, (home, original) in names.items():
        target = importlib.import_module(home, package) if home.strip(".") else module
        assert getattr(module, name) is getattr(target, original), name
