"""Solver checks: a case rotated by an angle must give the rotated answer of the unrotated case.

Physics does not depend on the orientation of the mesh. A solver that is compiled correctly
therefore gives, on a mesh rotated by R (with gravity and wall velocities rotated too), the
velocity field R U of the unrotated run, cell by cell, to round-off. Debian's OpenFOAM v1912
solvers, compiled by GCC 12 with tree vectorisation, fail this for interFoam (the flux-to-velocity
reconstruction is miscompiled); :func:`rotation_check` is the guard used by the tests and by
``kegel cfd check-solvers``.
"""

from __future__ import annotations

import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .foam import FoamDivergenceError, read_field, rotation_matrix, run_solver, run_utility, time_dirs
from .template import render_case

__all__ = ["RotationCheck", "rotation_check", "ROTATION_CHECK_CASES"]

#: Which check case exercises each solver.
ROTATION_CHECK_CASES = {"interFoam": "check_dambreak", "pimpleFoam": "check_cavity",
                        "simpleFoam": "check_cavity"}


@dataclass
class RotationCheck:
    """Result of :func:`rotation_check`.

    Attributes
    ----------
    solver, stock, angle_deg, n_steps
        What was checked.
    velocity_error
        max over cells of |U_rotated - R U_reference| / max |U_reference|.
    scalar_error
        max |alpha_rotated - alpha_reference| (VOF) or NaN.
    diverged
        The rotated run diverged (the error is then infinite).
    message
        The divergence message, if any.
    """

    solver: str
    stock: bool
    angle_deg: float
    n_steps: int
    velocity_error: float
    scalar_error: float
    diverged: bool
    message: str = ""

    def passed(self, tol: float = 1e-6) -> bool:
        """True when the rotated run reproduces the reference within ``tol``."""
        return (not self.diverged and self.velocity_error <= tol
                and not (self.scalar_error > tol))


def _params(solver: str, rot: np.ndarray, n_steps: int) -> dict:
    if solver == "interFoam":
        dt = 1e-3
        return {"n_cells": 40, "delta_t": dt, "end_time": dt * n_steps, "n_steps": n_steps,
                "gravity": rot @ np.array([0.0, -9.81, 0.0])}
    steady = solver == "simpleFoam"
    dt = 1.0 if steady else 5e-3
    return {"n_cells": 20, "delta_t": dt, "end_time": dt * n_steps, "n_steps": n_steps,
            "solver": solver, "steady": steady,
            "lid_velocity": rot @ np.array([1.0, 0.0, 0.0])}


def rotation_check(
    solver: str,
    *,
    stock: bool = False,
    angle_deg: float = 30.0,
    n_steps: int = 40,
    work_dir: str | Path | None = None,
) -> RotationCheck:
    """Run a check case unrotated and rotated about z by ``angle_deg`` and compare.

    Parameters
    ----------
    solver
        ``interFoam`` (dam break), ``pimpleFoam`` or ``simpleFoam`` (lid-driven cavity).
    stock
        Check Debian's binary instead of kegel's rebuild.
    angle_deg, n_steps
        Rotation about the z axis and number of time steps (fixed step size).
    work_dir
        Where to put the two cases (a temporary folder by default, removed afterwards).
    """
    template = ROTATION_CHECK_CASES[solver]
    rot = rotation_matrix((0, 0, 1), angle_deg)
    own_tmp = work_dir is None
    base = Path(tempfile.mkdtemp(prefix="kegel-rotcheck-")) if own_tmp else Path(work_dir)
    try:
        fields = {}
        message = ""
        for label, r in (("reference", np.eye(3)), ("rotated", rot)):
            case = render_case(template, base / f"{solver}-{label}", _params(solver, r, n_steps),
                               overwrite=True)
            run_utility(case, "blockMesh")
            if solver == "interFoam":
                run_utility(case, "setFields")
            if label == "rotated":
                run_utility(case, "transformPoints", "-rotate-angle", f"((0 0 1) {angle_deg:.17g})")
            try:
                run_solver(case, solver, stock=stock, max_courant=1e3)
            except FoamDivergenceError as exc:
                message = str(exc)
                return RotationCheck(solver, stock, angle_deg, n_steps, float("inf"),
                                     float("inf"), True, message)
            last = time_dirs(case)[-1]
            u = read_field(last / "U")
            alpha = read_field(last / "alpha.water") if solver == "interFoam" else None
            fields[label] = (u, alpha)
        u_ref, a_ref = fields["reference"]
        u_rot, a_rot = fields["rotated"]
        scale = float(np.max(np.linalg.norm(u_ref, axis=1)))
        vel_err = float(np.max(np.linalg.norm(u_rot - u_ref @ rot.T, axis=1)) / scale)
        sc_err = float(np.max(np.abs(a_rot - a_ref))) if a_ref is not None else float("nan")
        if not (np.isfinite(vel_err)):
            vel_err = float("inf")
        return RotationCheck(solver, stock, angle_deg, n_steps, vel_err, sc_err, False, message)
    finally:
        if own_tmp:
            import shutil

            shutil.rmtree(base, ignore_errors=True)
