"""One list of public names: each lazy package's ``__init__.pyi`` stub, which the package reads.

``roughcontact._lazy.attach_stub`` reads the stub beside a package's ``__init__.py`` when the
package is imported: each ``from .module import name as name`` says a public name and its home,
and the names are the package's ``__all__``. Type checkers and IDEs read the same file. Here: every
name of every stub imports, from the home its stub gives it; ``__all__`` and ``dir()`` hold the
stub's names; the reader refuses what a type checker would not count as a re-export; and the
wheel ships the stubs.
"""

import ast
import importlib
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from roughcontact._lazy import stub_homes

ROOT = Path(__file__).resolve().parents[2]
SOURCE = ROOT / "src" / "roughcontact"


def _lazy_packages() -> list[str]:
    """The packages whose ``__init__.py`` calls ``attach_stub`` (read from the source)."""
    found = []
    for init in sorted(SOURCE.rglob("__init__.py")):
        calls = [
            node
            for node in ast.walk(ast.parse(init.read_text(encoding="utf-8")))
            if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "attach_stub"
        ]
        if calls:
            found.append(".".join(init.parent.relative_to(SOURCE.parent).parts))
    return found


PACKAGES = _lazy_packages()


def test_the_lazy_packages_are_found():
    assert {
        "roughcontact",
        "roughcontact.contact",
        "roughcontact.plotting",
        "roughcontact.topography",
    } <= set(PACKAGES)


@pytest.mark.parametrize("package", PACKAGES)
def test_every_name_of_the_stub_imports_from_its_home(package):
    module = importlib.import_module(package)
    stub = SOURCE.joinpath(*package.split(".")[1:], "__init__.pyi")
    homes = stub_homes(stub.read_text(encoding="utf-8"))
    assert homes, f"{stub} names nothing"
    for name, home in homes.items():
        target = importlib.import_module(home, package)
        expected = (
            getattr(target, name) if target is not module else importlib.import_module(f"{package}.{name}")
        )
        assert getattr(module, name) is expected, name


@pytest.mark.parametrize("package", PACKAGES)
def test_all_and_dir_hold_the_names_of_the_stub(package):
    module = importlib.import_module(package)
    stub = SOURCE.joinpath(*package.split(".")[1:], "__init__.pyi")
    names = sorted(stub_homes(stub.read_text(encoding="utf-8")))
    assert module.__all__ == names
    assert set(names) <= set(dir(module))
    assert not any(hasattr(module, f) for f in ("_HOMES",)), "a second list of names beside the stub"


def test_a_name_loads_on_first_use_and_an_unknown_one_is_refused():
    script = (
        "import sys, roughcontact.topography as t\n"
        "before = 'roughcontact.topography.statistics' in sys.modules\n"
        "t.summary\n"
        "print(before, 'roughcontact.topography.statistics' in sys.modules)\n"
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    assert done.stdout.split() == ["False", "True"]
    with pytest.raises(AttributeError, match="no attribute 'no_such_name'"):
        _ = importlib.import_module("roughcontact.contact").no_such_name


def test_the_reader_takes_re_exports_in_every_form():
    stub = (
        '"""A stub."""\n\n'
        "from . import generate as generate\n"
        "from .io import (\n    read as read,\n)\n"
        "from .io import write as write, list_channels as list_channels\n"
        "from ..errors import InputError as InputError\n"
        "from roughcontact.units import quantity as quantity\n\n"
        "__all__: list[str]\n"
    )
    assert stub_homes(stub) == {
        "generate": ".",
        "read": ".io",
        "write": ".io",
        "list_channels": ".io",
        "InputError": "..errors",
        "quantity": "roughcontact.units",
    }


@pytest.mark.parametrize(
    ("line", "problem"),
    [
        ("from .io import read\n", "re-exported as itself"),
        ("from .io import read as load\n", "re-exported as itself"),
        ("from .io import *\n", "re-exported as itself"),
        ("import numpy\n", "from MODULE import NAME as NAME"),
        ("from .io import read as read\nfrom .native import read as read\n", "re-exported twice"),
    ],
)
def test_the_reader_refuses_what_a_type_checker_would_not_export(line, problem):
    with pytest.raises(ValueError, match=problem):
        stub_homes(line, "fake/__init__.pyi")


def test_a_package_loads_the_names_of_its_own_stub(tmp_path, monkeypatch):
    package = tmp_path / "fakepkg"
    package.mkdir()
    (package / "__init__.py").write_text(
        "from roughcontact._lazy import attach_stub\n\n"
        "__getattr__, __dir__, __all__ = attach_stub(__name__)\n"
    )
    (package / "__init__.pyi").write_text(
        "from . import tools as tools\n"
        "from .shapes import Square as Square\n"
        "from .shapes import area as area\n"
    )
    (package / "shapes.py").write_text("class Square:\n    pass\n\ndef area(side):\n    return side * side\n")
    (package / "tools.py").write_text("VALUE = 1\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    fake = importlib.import_module("fakepkg")
    try:
        assert fake.__all__ == ["Square", "area", "tools"]
        assert "fakepkg.shapes" not in sys.modules
        assert fake.area(3) == 9 and fake.tools.VALUE == 1
        assert {"Square", "area", "tools"} <= set(dir(fake))
    finally:
        for name in [n for n in sys.modules if n.split(".")[0] == "fakepkg"]:
            del sys.modules[name]


def test_a_package_without_its_stub_says_so(tmp_path, monkeypatch):
    package = tmp_path / "nostub"
    package.mkdir()
    (package / "__init__.py").write_text(
        "from roughcontact._lazy import attach_stub\n\nattach_stub(__name__)\n"
    )
    monkeypatch.syspath_prepend(str(tmp_path))
    with pytest.raises(FileNotFoundError, match="__init__.pyi"):
        importlib.import_module("nostub")
    sys.modules.pop("nostub", None)


def test_the_wheel_ships_every_stub():
    """Each ``.pyi`` file matches a package-data pattern of pyproject.toml (the lazy packages read it)."""
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    shipped = {
        path
        for pattern in config["tool"]["setuptools"]["package-data"]["roughcontact"]
        for path in SOURCE.glob(pattern)
    }
    assert set(SOURCE.rglob("*.pyi")) <= shipped
