"""The package layout of kegel (docs/architecture.md): one package per role, in layers.

The import graph is built from the source tree with :mod:`ast` (every import: module level,
function level and ``TYPE_CHECKING`` blocks), for the import package ``kegel`` as the wheel maps
it (pyproject.toml ``[tool.scikit-build.wheel.packages]``: ``kegel/`` plus the top-level folders
``correlations/``, ``coupling/`` and ``cfd_cases/``). Checked:

- every kegel module an import names exists (a relative import that moved with its file fails
  here with file and line), and package code names the new paths, not the old ones such as
  ``kegel.scene`` (``python tests/python/test_architecture.py --fix`` rewrites both);
- every package has a layer (a new module goes into a package: docs/architecture.md says which);
- no import runs from a lower layer to a higher one;
- the graph of packages has no cycle (packages of one layer may import each other one way).

No kegel import is executed (but in the test of the old paths): the test reads files only.
"""

from __future__ import annotations

import ast
import re
import sys
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


def moved() -> dict[str, str]:
    """``kegel._compat.MOVED`` (old module path -> new), read from the file, not imported."""
    tree = ast.parse((ROOT / "kegel" / "_compat.py").read_text(encoding="utf-8"))
    for node in tree.body:
        if isinstance(node, ast.AnnAssign) and getattr(node.target, "id", "") == "MOVED":
            return ast.literal_eval(node.value)
    raise AssertionError("kegel/_compat.py has no MOVED")


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


def back_up_imports(edges, layer_of, old: dict[str, str] | None = None) -> list[str]:
    """Imports from a lower layer to a higher one (an old module path counts as its new one)."""
    bad = []
    for src, dst, where in edges:
        dst = (old or {}).get(dst, dst)
        a, b = layer_of.get(package_of(src)), layer_of.get(package_of(dst))
        if a is not None and b is not None and b > a:
            bad.append(f"{where}: {src} (layer {LAYERS[a][0] if a < len(LAYERS) else a}) imports {dst} "
                       f"(layer {LAYERS[b][0] if b < len(LAYERS) else b})")
    return bad


def package_cycles(edges, old: dict[str, str] | None = None) -> list[list[str]]:
    """The strongly connected components of more than one package (Tarjan)."""
    graph: dict[str, set[str]] = defaultdict(set)
    for src, dst, _ in edges:
        a, b = package_of(src), package_of((old or {}).get(dst, dst))
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
    old = moved()
    missing = sorted({f"{where}: imports {dst}" for _, dst, where in edges if dst not in mods and dst not in old})
    assert not missing, ("imports of kegel modules that do not exist (a relative import that moved with its "
                         "file? `python tests/python/test_architecture.py --fix` rewrites it):\n" + "\n".join(missing))


def test_package_code_uses_the_new_module_paths(graph):
    """kegel._compat keeps the old paths (``kegel.scene``) for users; the package names the new ones."""
    _, edges = graph
    old = moved()
    used = sorted({f"{where}: {dst} (now {old[dst]})" for _, dst, where in edges if dst in old})
    assert not used, ("module paths of before the relayout inside the package "
                      "(`python tests/python/test_architecture.py --fix` rewrites them):\n" + "\n".join(used))


def test_every_package_has_a_layer(graph):
    mods, _ = graph
    unplaced = sorted({package_of(m) for m in mods} - set(LAYER_OF))
    assert not unplaced, (f"packages or top-level modules without a layer: {unplaced}; put the module into "
                          "the package of its role (docs/architecture.md) or add the package to LAYERS")


def test_no_import_runs_back_up_the_layers(graph):
    _, edges = graph
    bad = back_up_imports(edges, LAYER_OF, moved())
    assert not bad, "imports from a lower layer to a higher one:\n" + "\n".join(bad)


def test_the_package_graph_has_no_cycle(graph):
    _, edges = graph
    assert package_cycles(edges, moved()) == []


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


def fix(write: bool = True) -> list[str]:
    """Rewrite the ``from X import`` of package code that names an old module path
    (``kegel.scene``, ``..scene``) or a relative path that moved with its file (``.limits`` in
    ``kegel/physics/``, meant as ``kegel.limits``) to the new path; returns what it changed and
    what it left (``import kegel.x`` and ``from kegel import x``: by hand)."""
    mods, old = modules(), moved()
    by_file: dict[Path, list[tuple[int, int, str]]] = defaultdict(list)
    report = []
    for name, (path, is_pkg) in mods.items():
        if name == "kegel._core":
            continue
        package = name if is_pkg else name.rpartition(".")[0]
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), str(path))):
            if not isinstance(node, (ast.Import, ast.ImportFrom)):
                continue
            where = f"{path.relative_to(ROOT)}:{node.lineno}"
            if isinstance(node, ast.Import):
                report += [f"{where}: import {a.name}: by hand (now {old[a.name]})" for a in node.names if a.name in old]
                continue
            if node.level:
                up = package.split(".")[: len(package.split(".")) - node.level + 1]
                target = ".".join(up + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if target.split(".")[0] != "kegel" or target in mods:
                if any(f"{target}.{a.name}" in old for a in node.names):
                    report.append(f"{where}: from {target} import ...: by hand (a moved module imported by name)")
                continue
            new = old.get(target) or old.get("kegel." + target.rpartition(".")[2])
            if new is None or new not in mods:
                report.append(f"{where}: {target}: no new path known")
                continue
            if node.level:
                p, t = package.split("."), new.split(".")
                n = 0
                while n < min(len(p), len(t)) and p[n] == t[n]:
                    n += 1
                spec = "." * (len(p) - n + 1) + ".".join(t[n:])
            else:
                spec = new
            by_file[path].append((node.lineno, node.col_offset, spec))
            report.append(f"{where}: {target} -> {spec}")
    if write:
        for path, edits in by_file.items():
            lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
            for lineno, col, spec in edits:
                line = lines[lineno - 1]
                m = re.compile(r"from\s+(\.+[\w.]*|[\w.]+)\s+import").match(line, col)
                lines[lineno - 1] = line[:m.start(1)] + spec + line[m.end(1):]
            path.write_text("".join(lines), encoding="utf-8")
    return report


if __name__ == "__main__":  # python tests/python/test_architecture.py --fix  (or --dry-run)
    if sys.argv[1:] not in (["--fix"], ["--dry-run"]):
        sys.exit("usage: python tests/python/test_architecture.py --fix | --dry-run")
    print("\n".join(fix(write=sys.argv[1] == "--fix")) or "nothing to fix")
