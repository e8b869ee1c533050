"""kegel: power losses of tapered roller bearings.

Contact friction from a multibody model (C++ core ``kegel._core``), hydraulic drag and churning
losses from correlations (``kegel.correlations``) and OpenFOAM CFD (``kegel.cfd_cases``), coupled
in ``kegel.coupling``.
"""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version as _pkg_version

from . import _core
from . import contact
from .dynamics import DynamicResult, SimulationDiverged, simulate
from .data import (
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
from .errors import KegelInputError, KegelSolverError
from .geometry import BearingGeometry, apex_residual, derive_geometry, envelope_violations
from .lubricant import LubricantState, lubricant_state
from .scene import OperatingPoint, Scene, load_scene
from .tribology import ContactFriction, FrictionData, evaluate_raceway_contact, load_friction
from .units import parse_quantity
from . import run  # the module kegel.run (imported after the modules it uses)
from .run import run_scene
from .api import Bearing, FrictionResult

try:
    __version__ = _pkg_version("kegel")
except PackageNotFoundError:  # pragma: no cover - running from a source tree without install
    __version__ = _core.core_version()

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
