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
     "spread", "references", "origin"},
    {"topography", "elasticity", "analytic"},
    {"contact", "asperity", "experiment"},
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
