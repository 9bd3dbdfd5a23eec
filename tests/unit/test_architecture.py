"""The shape of src/roughcontact: imports flow one way, no cycles, no private names across modules.

Read from the source with ``ast`` (every import, also those inside functions), so the rules hold for
the imports that run late too. See docs/architecture.md for the layers.
"""

import ast
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2] / "src"
PACKAGE = "roughcontact"

LAYERS = (
    {"errors", "units", "checks", "results", "display_html", "materials", "_json", "_files", "_deprecation",
     "_text_table", "_backend", "_device", "_gpu", "_fftw_wisdom", "_cache", "_lazy", "_version", "progress",
     "spread", "references", "origin", "messages", "cases"},
    {"topography", "elasticity", "analytic"},
    {"contact", "asperity", "experiment", "theory"},
    {"winkler_lj", "friction"},
    {"papers", "models", "plotting"},
    {"study"},
    {"cli", "__main__", ""},
)  # fmt: skip
"""Top-level modules and subpackages, from the bottom up: a module imports only its own layer or below."""


def modules_of(source: Path, top: str) -> dict[str, tuple[Path, bool]]:
    """Dotted name -> (file, is a package) of every module of the package ``top`` under ``source``."""
    found = {}
    for path in sorted((source / top).rglob("*.py")):
        parts = list(path.relative_to(source).with_suffix("").parts)
        package = parts[-1] == "__init__"
        found[".".join(parts[:-1] if package else parts)] = (path, package)
    return found


def imports_of(modules: dict[str, tuple[Path, bool]], top: str):
    """(importer, imported module, imported name, name is a module, line) for every import of ``top``."""
    for name, (path, package) in modules.items():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom):
                if node.level:
                    base = name.split(".") if package else name.split(".")[:-1]
                    base = base[: len(base) - node.level + 1]
                    target = ".".join(base + ([node.module] if node.module else []))
                else:
                    target = node.module or ""
                if target.split(".")[0] != top:
                    continue
                for alias in node.names:
                    submodule = f"{target}.{alias.name}"
                    if submodule in modules:
                        yield name, submodule, alias.name, True, node.lineno
                    else:
                        yield name, target, alias.name, False, node.lineno
            elif isinstance(node, ast.Import):
                for alias in node.names:
                    if alias.name.split(".")[0] == top:
                        yield name, alias.name, alias.name, True, node.lineno
            elif target := _imported_by_string(node, name, package):  # import_module("...") by a literal
                if target.split(".")[0] == top:
                    yield name, target, target.rsplit(".", 1)[-1], True, node.lineno


def _imported_by_string(node: ast.AST, name: str, package: bool) -> str | None:
    """The module an ``import_module("literal")`` call imports (relative to its package), else None.

    An import written as a string runs as much up or down the floors as one written as a
    statement; f-strings and names (a registry's lookups) are not literals and are left out.
    """
    if not (
        isinstance(node, ast.Call)
        and getattr(node.func, "id", getattr(node.func, "attr", None)) == "import_module"
        and node.args
        and isinstance(node.args[0], ast.Constant)
        and isinstance(node.args[0].value, str)
    ):
        return None
    text = node.args[0].value
    if not text.startswith("."):
        return text
    level = len(text) - len(text.lstrip("."))
    base = name.split(".") if package else name.split(".")[:-1]
    base = base[: len(base) - level + 1]
    return ".".join(base + ([text.lstrip(".")] if text.lstrip(".") else []))


def private_imports(imports) -> list[str]:
    """The imports of a private name (not a private module) from another module."""
    return [
        f"{importer} imports {name} from {module} (line {line})"
        for importer, module, name, is_module, line in imports
        if name.startswith("_") and not is_module and name != "__version__"
    ]


def cycles_of(imports, modules) -> list[list[str]]:
    """The import cycles (strongly connected components of more than one module)."""
    graph: dict[str, set[str]] = {}
    for importer, module, *_ in imports:
        if module in modules and module != importer:
            graph.setdefault(importer, set()).add(module)
    order, low, stack, on_stack, cycles = {}, {}, [], set(), []

    def visit(node: str) -> None:  # Tarjan's strongly connected components
        order[node] = low[node] = len(order)
        stack.append(node)
        on_stack.add(node)
        for nxt in graph.get(node, ()):
            if nxt not in order:
                visit(nxt)
                low[node] = min(low[node], low[nxt])
            elif nxt in on_stack:
                low[node] = min(low[node], order[nxt])
        if low[node] == order[node]:
            component = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                component.append(member)
                if member == node:
                    break
            if len(component) > 1:
                cycles.append(sorted(component))

    for module in modules:
        if module not in order:
            visit(module)
    return cycles


MODULES = modules_of(SOURCE, PACKAGE)
IMPORTS = list(imports_of(MODULES, PACKAGE))


def _layer(module: str) -> int:
    top = module.split(".")[1] if "." in module else ""
    for number, layer in enumerate(LAYERS):
        if top in layer:
            return number
    raise AssertionError(f"{module}: its top-level name {top!r} is in no layer of this test; add it")


def test_no_private_name_is_imported_from_another_module():
    private = private_imports(IMPORTS)
    assert not private, "make them public in one module or keep them in one:\n" + "\n".join(private)


def test_imports_flow_down_the_layers():
    upward = [
        f"{importer} (layer {_layer(importer)}) imports {module} (layer {_layer(module)}), line {line}"
        for importer, module, _, _, line in IMPORTS
        if module in MODULES and _layer(module) > _layer(importer)
    ]
    assert not upward, "\n".join(upward)


def test_no_import_cycle():
    cycles = cycles_of(IMPORTS, MODULES)
    assert not cycles, f"import cycles: {cycles}"


def _package(module: str) -> str:
    """The top-level subpackage (or module) of a module: ``contact`` for roughcontact.contact.normal."""
    return module.split(".")[1] if "." in module else ""


def test_no_cycle_between_packages():
    """No two subpackages import each other, directly or round a loop (within a layer too)."""
    between = [(_package(a), _package(b), "", False, 0) for a, b, *_ in IMPORTS if b in MODULES]
    packages = {_package(m): (None, False) for m in MODULES}
    edges = [(a, b, *rest) for a, b, *rest in between if a != b]
    cycles = cycles_of(edges, packages)
    assert not cycles, f"subpackages that import each other: {cycles}"


def test_the_rules_see_a_private_import_and_a_cycle(tmp_path):
    """The checks themselves, on a made-up package with one private import and one cycle (also lazy)."""
    package = tmp_path / "fake"
    (package / "sub").mkdir(parents=True)
    (package / "__init__.py").write_text("")
    (package / "sub" / "__init__.py").write_text("")
    (package / "sub" / "_engine.py").write_text("def _helper():\n    pass\n")
    (package / "a.py").write_text("from .sub import _engine\nfrom .sub._engine import _helper\n")
    (package / "b.py").write_text("def late():\n    from . import c\n")
    (package / "c.py").write_text("from .b import late\n")
    modules = modules_of(tmp_path, "fake")
    imports = list(imports_of(modules, "fake"))
    assert private_imports(imports) == ["fake.a imports _helper from fake.sub._engine (line 2)"]
    assert cycles_of(imports, modules) == [["fake.b", "fake.c"]]


def catch_alls(source: Path, top: str) -> list[str]:
    """Public functions and methods with a ``**`` parameter, as ``module:line name(**kwargs)``.

    Public: in a module whose name has no leading underscore (``_deprecation`` holds the wrappers
    that forward by design), a function or method whose name has none (``__init__`` and
    ``__call__`` count), defined at module level or in a public class; functions defined inside
    functions (a decorator's wrapper) are not part of the interface.
    """
    found = []
    for name, (path, _) in modules_of(source, top).items():
        if any(part.startswith("_") and part != "__init__" for part in name.split(".")):
            continue
        tree = ast.parse(path.read_text())
        scopes = [(node, "") for node in tree.body]
        scopes += [
            (child, f"{node.name}.")
            for node in tree.body
            if isinstance(node, ast.ClassDef) and not node.name.startswith("_")
            for child in node.body
        ]
        for node, owner in scopes:
            if not isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef) or node.args.kwarg is None:
                continue
            if node.name.startswith("_") and node.name not in ("__init__", "__call__"):
                continue
            found.append(f"{name}:{node.lineno} {owner}{node.name}(**{node.args.kwarg.arg})")
    return found


def test_no_public_function_takes_a_catch_all():
    """Every public function names its parameters: no ``**options`` the reader and IDEs cannot see."""
    assert catch_alls(SOURCE, PACKAGE) == []


def test_the_catch_all_rule_sees_one(tmp_path):
    package = tmp_path / "fake"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "_private.py").write_text("def forward(**kwargs):\n    pass\n")
    (package / "api.py").write_text(
        "def solve(x, **options):\n    def wrapper(**kw):\n        pass\n\n"
        "class Model:\n    def run(self, **options):\n        pass\n\n"
        "    def _inner(self, **options):\n        pass\n"
    )
    assert catch_alls(tmp_path, "fake") == ["fake.api:1 solve(**options)", "fake.api:6 Model.run(**options)"]


SIDE_CHANNELS = {
    "matplotlib.use": "switches the caller's plotting backend (a notebook's, an svg caller's)",
    "logging.basicConfig": "configures the caller's logging (only the command line may: cli/__init__.py)",
    "np.seterr": "changes how the caller's NumPy reports floating-point errors",
    "numpy.seterr": "changes how the caller's NumPy reports floating-point errors",
    "rcParams": "changes the caller's matplotlib defaults (use matplotlib.rc_context)",
    "os.environ": "passes state through the process environment instead of an argument",
}
"""Calls and stores that change process-wide state a caller owns, with why each is refused."""

ALLOWED_SIDE_CHANNELS = {
    ("roughcontact.cli", "logging.basicConfig"),  # the command line is the program: it owns the logging
    ("roughcontact._backend", "os.environ"),  # OMP_WAIT_POLICY for pyFFTW's loading only, restored after
}


_ENVIRONMENT_WRITES = (".setdefault", ".update", ".pop", ".clear", ".popitem")


def side_channels(source: Path, top: str) -> list[str]:
    """Every write of process-wide state in the package (see :data:`SIDE_CHANNELS`), not allowed."""
    found = []
    for name, (path, _) in modules_of(source, top).items():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Call):
                called = ast.unparse(node.func)
                if called.startswith("os.environ.") and not called.endswith(_ENVIRONMENT_WRITES):
                    continue  # reading the user's settings is no side channel
            elif isinstance(node, ast.Assign | ast.AugAssign):
                targets = node.targets if isinstance(node, ast.Assign) else [node.target]
                called = next((ast.unparse(t.value) for t in targets if isinstance(t, ast.Subscript)), None)
                called = (
                    called.removesuffix(".rcParams") + ".rcParams"
                    if called and "rcParams" in called
                    else called
                )
            else:
                continue
            for channel in SIDE_CHANNELS:
                if called and (
                    called == channel or called.endswith(f".{channel}") or called.startswith(f"{channel}.")
                ):
                    if (name, channel) not in ALLOWED_SIDE_CHANNELS:
                        found.append(
                            (node.lineno, f"{name}:{node.lineno} {called}: {SIDE_CHANNELS[channel]}")
                        )
    return [line for _, line in sorted(found)]


def test_no_module_changes_process_state_a_caller_owns():
    """No backend switch, logging set-up, NumPy error mode or environment variable as a side channel."""
    assert side_channels(SOURCE, PACKAGE) == []


def test_the_side_channel_rule_sees_them(tmp_path):
    package = tmp_path / "fake"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "figures.py").write_text(
        "import matplotlib\nimport os\n\ndef draw():\n    matplotlib.use('Agg')\n"
        "    os.environ['DEVICE'] = 'gpu'\n    os.environ.setdefault('X', '1')\n"
    )
    found = side_channels(tmp_path, "fake")
    assert [line.split(":")[1].split()[0] for line in found] == ["5", "6", "7"]


def test_a_study_hands_its_device_to_the_solver_as_an_argument(monkeypatch, tmp_path):
    """The study's device reaches solve_normal as ``device=``, not through ROUGHCONTACT_DEVICE."""
    import roughcontact.contact.normal as normal

    solve_normal = normal.solve_normal
    from roughcontact.study.answers import answer
    from roughcontact.study.config import build_study

    seen = []

    def spy(*args, **kwargs):
        seen.append((kwargs.get("device"), dict(__import__("os").environ).get("ROUGHCONTACT_DEVICE")))
        return solve_normal(*args, **kwargs)

    # the package's name first: loaded on first use, it would otherwise load (and keep) the spy
    monkeypatch.setattr("roughcontact.contact.solve_normal", spy)  # the name the study kind imports
    monkeypatch.setattr(normal, "solve_normal", spy)
    document = {
        "study": {"name": "device", "device": "cpu"},
        "topographies": {"s": {"generate": "sphere", "shape": 16, "size": "1 um", "radius": "5 um"}},
        "analysis": [
            {"name": "n", "model": "normal", "topography": "s", "material": "SiO2", "force": "1 uN"}
        ],
    }
    answer(build_study(document, folder=tmp_path, text="", source="device"))
    assert seen == [("cpu", None)]
