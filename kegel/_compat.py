"""The module paths of kegel before the packages per role (``kegel.scene``, ``kegel.run``, ...).

Scripts, notebooks and the documentation name modules as ``kegel.scene`` or ``kegel.run``; since
the relayout (docs/architecture.md) they live in ``kegel.model.scene``, ``kegel.runner.run`` and
so on. :data:`MOVED` maps each old path to the new one and :func:`install` puts a finder first on
``sys.meta_path`` that answers an old path with the very module object of the new one (not a copy
and not a re-export), so ``from kegel.scene import load_scene``, ``import kegel.run`` and
``monkeypatch.setattr("kegel.run._friction", ...)`` keep working and patch the module the code
uses. Code inside kegel imports the new paths (tests/python/test_architecture.py checks it).
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import sys
from types import ModuleType

__all__ = ["MOVED", "install"]

#: Old module path -> new module path.
MOVED: dict[str, str] = {
    "kegel.errors": "kegel.base.errors",
    "kegel.units": "kegel.base.units",
    "kegel._toml": "kegel.base._toml",
    "kegel.io": "kegel.base.io",
    "kegel.limits": "kegel.base.limits",
    "kegel.data": "kegel.model.data",
    "kegel.estimate": "kegel.model.estimate",
    "kegel.geometry": "kegel.model.geometry",
    "kegel.lubricant": "kegel.model.lubricant",
    "kegel.scene": "kegel.model.scene",
    "kegel.scene_model": "kegel.model.scene_model",
    "kegel.inventory": "kegel.model.inventory",
    "kegel.tribology": "kegel.physics.tribology",
    "kegel.contact": "kegel.physics.contact",
    "kegel.supply": "kegel.coupling.supply",
    "kegel.quasi_static": "kegel.solutions.quasi_static",
    "kegel.dynamics": "kegel.solutions.dynamics",
    "kegel.steady": "kegel.solutions.steady",
    "kegel.plots": "kegel.outputs.plots",
    "kegel.study": "kegel.outputs.study",
    "kegel.point_warnings": "kegel.outputs.point_warnings",
    "kegel.run": "kegel.runner.run",
    "kegel.parallel": "kegel.runner.parallel",
    "kegel.uncertainty": "kegel.runner.uncertainty",
    "kegel.validation": "kegel.runner.validation",
}


class _AliasLoader(importlib.abc.Loader):
    """Loads an old path as the module already imported (or importable) under its new path."""

    def __init__(self, target: str) -> None:
        self.target = target
        self._spec: importlib.machinery.ModuleSpec | None = None

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> ModuleType:
        module = importlib.import_module(self.target)
        self._spec = module.__spec__  # importlib sets __spec__ to the alias's spec: put it back below
        return module

    def exec_module(self, module: ModuleType) -> None:
        """Nothing to run (the target module ran on its own import); restore its ``__spec__``."""
        module.__spec__ = self._spec


class _AliasFinder(importlib.abc.MetaPathFinder):
    """Finds the old module paths of :data:`MOVED` (and nothing else)."""

    def find_spec(self, fullname: str, path=None, target=None):  # noqa: ANN001 - importlib's signature
        new = MOVED.get(fullname)
        if new is None:
            return None
        return importlib.machinery.ModuleSpec(fullname, _AliasLoader(new))


def install() -> None:
    """Put the finder of the old module paths first on ``sys.meta_path`` (once).

    First, because ``kegel/data/`` (the shipped data files) would otherwise be found as a
    namespace package for ``kegel.data``.
    """
    if not any(isinstance(f, _AliasFinder) for f in sys.meta_path):
        sys.meta_path.insert(0, _AliasFinder())
