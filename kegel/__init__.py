"""kegel: power losses of tapered roller bearings.

Contact friction from a multibody model (C++ core ``kegel._core``), hydraulic drag and churning
losses from correlations (``kegel.correlations``) and OpenFOAM CFD (``kegel.cfd_cases``), coupled
in ``kegel.coupling``.

The package is laid out by role, in layers that import only downwards (docs/architecture.md):
``kegel.base`` < ``kegel.model`` < ``kegel.physics`` / ``kegel.correlations`` / ``kegel.coupling``
< ``kegel.solutions`` < ``kegel.outputs`` < ``kegel.runner`` / ``kegel.cfd_cases`` < ``kegel.api`` /
``kegel.cli``. This front module re-exports the public objects; the module paths of before the
relayout (``kegel.scene``, ``kegel.run``, ...) still import (:mod:`kegel._compat`).
"""

from __future__ import annotations

import importlib as _importlib
from typing import Any as _Any

from . import _compat

_compat.install()

from . import _core  # noqa: E402
from .base.version import __version__  # noqa: E402
from .base.errors import KegelInputError, KegelSolverError  # noqa: E402
from .base.units import parse_quantity  # noqa: E402
from .model.data import (  # noqa: E402
    BearingData,
    LubricantData,
    MaterialData,
    available_bearings,
    available_lubricants,
    available_materials,
    load_bearing,
    load_lubricant,
    load_material,
)
from .model.geometry import BearingGeometry, apex_residual, derive_geometry, envelope_violations  # noqa: E402
from .model.lubricant import LubricantState, lubricant_state  # noqa: E402
from .model.scene import OperatingPoint, Scene, load_scene  # noqa: E402
from .physics import contact  # noqa: E402
from .physics.tribology import ContactFriction, FrictionData, evaluate_raceway_contact, load_friction  # noqa: E402
from .solutions.dynamics import DynamicResult, SimulationDiverged, simulate  # noqa: E402
from .runner import run  # noqa: E402  (the module kegel.run: kegel.runner.run)
from .runner.run import run_scene  # noqa: E402
from .api import Bearing, FrictionResult  # noqa: E402


def __getattr__(name: str) -> _Any:
    """``kegel.io``, ``kegel.scene``, ...: the modules of before the relayout, as attributes."""
    if "kegel." + name in _compat.MOVED:
        return _importlib.import_module("kegel." + name)
    raise AttributeError(f"module 'kegel' has no attribute {name!r}")


__all__ = [
    "__version__",
    "contact",
    "Bearing",
    "BearingData",
    "BearingGeometry",
    "ContactFriction",
    "DynamicResult",
    "FrictionData",
    "FrictionResult",
    "KegelInputError",
    "KegelSolverError",
    "LubricantData",
    "LubricantState",
    "MaterialData",
    "OperatingPoint",
    "Scene",
    "SimulationDiverged",
    "apex_residual",
    "available_bearings",
    "available_lubricants",
    "available_materials",
    "derive_geometry",
    "envelope_violations",
    "evaluate_raceway_contact",
    "load_bearing",
    "load_friction",
    "load_lubricant",
    "load_material",
    "load_scene",
    "lubricant_state",
    "parse_quantity",
    "run",
    "run_scene",
    "simulate",
]
