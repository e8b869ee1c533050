"""OpenFOAM cases of the bearing: solvers, case templates, gmsh geometry, runner, post-processing.

Mapped into the import package as ``kegel.cfd_cases``.
"""

from .checks import RotationCheck, rotation_check
from .foam import (
    FoamDivergenceError,
    FoamInterrupted,
    FoamError,
    FoamRunError,
    FoamSetupError,
    run_solver,
    run_utility,
    solver_executable,
)
from .template import render_case

__all__ = [
    "FoamDivergenceError",
    "FoamInterrupted",
    "FoamError",
    "FoamRunError",
    "FoamSetupError",
    "RotationCheck",
    "render_case",
    "rotation_check",
    "run_solver",
    "run_utility",
    "solver_executable",
]
