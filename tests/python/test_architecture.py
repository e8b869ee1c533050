"""The package layout of kegel (docs/architecture.md): one package per role, in layers.

The import graph is built from the source tree with :mod:`ast` (every import: module level,
function level and ``TYPE_CHECKING`` blocks), for the import package ``kegel`` as the wheel maps
it (pyproject.toml ``[tool.scikit-build.wheel.packages]``: ``kegel/`` plus the top-level folders
``correlations/``, ``coupling/`` and ``cfd_cases/``). Checked:

- every kegel module an import names exists (a relative import that moved with its file, or an
  old path such as ``kegel.scene`` inside the package, fails here with file and line);
- every package has a layer (a new module goes into a package: docs/architecture.md says which);
- no import runs from a lower layer to a higher one;
- the graph of packages has no cycle (packages of one layer may import each other one way).

No kegel import is executed: the test reads files only.
"""

from __future__ import annotations

import ast
import tomllib
from collections import defaultdict
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

#: The layers, lowest first: a package may import its own layer (without a cycle) and the layers
#: below it, never one above. docs/architecture.md draws the same table.
LAYERS: list[tuple[str, tuple[str, ...]]] = [
    ("base", ("kegel._core", "kegel._compat", "kegel.base")),
    ("model", ("kegel.model",)),
    ("physics", ("kegel.physics", "kegel.correlations", "kegel.coupling")),
    ("solutions", ("kegel.solutions",)),
    ("outputs", ("kegel.outputs",)),
    ("runner", ("kegel.runner", "kegel.cfd_cases")),
    ("interface", ("kegel.api", "kegel.cli")),
    ("front", ("kegel",)),
]
LAYER_OF: dict[str, int] = {pkg: i for i, (_, pkgs) in enumerate(LAYERS) for pkg in pkgs}


def source_dirs() -> dict[str, Path]:
    """Import name -> folder, as the wheel maps them (pyproject.toml)."""
    with open(ROOT / "pyproject.toml", "rb") as fh:
        packages = tomllib.load(fh)["tool"]["scikit-build"]["wheel"]["packages"]
    return {name.replace("/", "."): ROOT / folder for name, folder in packages.items()}


def modules() -> dict[str, tuple[Path, bool]]:
    """Every module of the import package: name -> (file, is a package ``__init__``)."""
    out: dict[str, tuple[Path, bool]] = {}
    for base, folder in source_dirs().items():
        for f in sorted(folder.rglob("*.py")):
            if "__pycache__" in f.parts:
                continue
            parts = list(f.relative_to(folder).with_suffix("").parts)
            is_pkg = parts[-1] == "__init__"
            if is_pkg:
                parts = parts[:-1]
            out[".".join([base, *parts])] = (f, is_pkg)
    if (ROOT / "kegel" / "_core").is_dir():  # the compiled extension (stubs in the tree)
        out["kegel._core"] = (ROOT / "kegel" / "_core" / "__init__.pyi", False)
    return out


def imports(mods: dict[str, tuple[Path, bool]]) -> list[tuple[str, str, str]]:
    """Every kegel import: (importing module, imported module, "file:line")."""
    edges = []
    for name, (path, is_pkg) in mods.items():
        if name == "kegel._core":
            continue
        package = name if is_pkg else name.rpartition(".")[0]
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), str(path))):
            where = f"{path.relative_to(ROOT)}:{getattr(node, 'lineno', 0)}"
            if isinstance(node, ast.Import):
                edges += [(name, a.name, where) for a in node.names if a.name.split(".")[0] == "kegel"]
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    up = package.split(".")[: len(package.split(".")) - node.level + 1]
                    target = ".".join(up + ([node.module] if node.module else []))
                else:
                    target = node.module or ""
                if target.split(".")[0] != "kegel":
                    continue
                for a in node.names:  # `from pkg import module` imports the module
                    sub = f"{target}.{a.name}"
                    edges.append((name, sub if sub in mods else target, where))
    return edges


def package_of(module: str) -> str:
    """``kegel.model.scene`` -> ``kegel.model``; ``kegel.api`` -> ``kegel.api``; ``kegel`` -> ``kegel``."""
    parts = module.split(".")
    return ".".join(parts[:2])


def back_up_imports(edges, layer_of) -> list[str]:
    """Imports from a lower layer to a higher one."""
    bad = []
    for src, dst, where in edges:
        a, b = layer_of.get(package_of(src)), layer_of.get(package_of(dst))
        if a is not None and b is not None and b > a:
            bad.append(f"{where}: {src} (layer {LAYERS[a][0] if a < len(LAYERS) else a}) imports {dst} "
                       f"(layer {LAYERS[b][0] if b < len(LAYERS) else b})")
    return bad


def package_cycles(edges) -> list[list[str]]:
    """The strongly connected components of more than one package (Tarjan)."""
    graph: dict[str, set[str]] = defaultdict(set)
    for src, dst, _ in edges:
        a, b = package_of(src), package_of(dst)
        if a != b:
            graph[a].add(b)
            graph.setdefault(b, set())
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    out: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


@pytest.fixture(scope="module")
def graph():
    mods = modules()
    return mods, imports(mods)


def test_every_imported_kegel_module_exists(graph):
    mods, edges = graph
    missing = sorted({f"{where}: imports {dst}" for _, dst, where in edges if dst not in mods})
    assert not missing, ("imports of kegel modules that do not exist (a relative import that moved with its "
                         "file, or a path of before the relayout: kegel._compat.MOVED has the new one):\n"
                         + "\n".join(missing))


def test_every_package_has_a_layer(graph):
    mods, _ = graph
    unplaced = sorted({package_of(m) for m in mods} - set(LAYER_OF))
    assert not unplaced, (f"packages or top-level modules without a layer: {unplaced}; put the module into "
                          "the package of its role (docs/architecture.md) or add the package to LAYERS")


def test_no_import_runs_back_up_the_layers(graph):
    _, edges = graph
    bad = back_up_imports(edges, LAYER_OF)
    assert not bad, "imports from a lower layer to a higher one:\n" + "\n".join(bad)


def test_the_package_graph_has_no_cycle(graph):
    _, edges = graph
    assert package_cycles(edges) == []


def test_the_layers_cover_the_documented_packages():
    """docs/architecture.md names every package of LAYERS (the document and the test agree)."""
    text = (ROOT / "docs" / "architecture.md").read_text(encoding="utf-8")
    for _, pkgs in LAYERS:
        for pkg in pkgs:
            assert f"`{pkg}`" in text, f"docs/architecture.md does not name {pkg}"


def test_the_checks_catch_a_cycle_and_a_back_up_import():
    """The checker itself: a made-up graph with a cycle and an upward import is caught."""
    layer_of = {"kegel.model": 1, "kegel.physics": 2, "kegel.runner": 5}
    edges = [("kegel.model.scene", "kegel.physics.tribology", "scene.py:1"),
             ("kegel.physics.tribology", "kegel.model.scene", "tribology.py:2"),
             ("kegel.runner.run", "kegel.model.scene", "run.py:3")]
    assert package_cycles(edges) == [["kegel.model", "kegel.physics"]]
    bad = back_up_imports(edges, layer_of)
    assert len(bad) == 1 and bad[0].startswith("scene.py:1: kegel.model.scene (layer model)")


def test_old_module_paths_still_import():
    """The paths of before the relayout answer with the very module (so monkeypatching works)."""
    import importlib

    import kegel
    from kegel._compat import MOVED

    for old, new in MOVED.items():
        assert importlib.import_module(old) is importlib.import_module(new), old
    assert kegel.run is importlib.import_module("kegel.runner.run")
    assert importlib.import_module("kegel.scene").__spec__.name == "kegel.model.scene"
