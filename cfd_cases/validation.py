"""Validation cases run through the same pipeline as the bearing (gmsh -> gmshToFoam -> solver ->
forces): laminar Taylor-Couette torque against the analytic solution.

Couette flow between an inner cylinder of radius R1 turning at omega and a resting outer cylinder
of radius R2 (laminar, below the Taylor instability) has the azimuthal velocity
``u(r) = A r + B / r`` with ``A = -omega R1^2 / (R2^2 - R1^2)``, ``B = omega R1^2 R2^2 /
(R2^2 - R1^2)``; the shear stress on the inner cylinder gives the torque on it

    M_z = -4 pi mu omega R1^2 R2^2 / (R2^2 - R1^2) * h

for a height h (Landau & Lifshitz, Fluid Mechanics, section 18; any fluid-mechanics text).
"""

from __future__ import annotations

import math
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from .foam import run_solver
from .forces import read_forces
from .mesh import check_mesh, gmsh_to_foam, write_msh22
from .template import render_case

__all__ = ["CouetteResult", "couette_torque_analytic", "taylor_couette"]


def couette_torque_analytic(r_inner_m: float, r_outer_m: float, omega_rad_s: float,
                            dynamic_viscosity_pa_s: float, height_m: float) -> float:
    """Torque about the axis exerted by the fluid on the turning inner cylinder (N m)."""
    r1, r2 = r_inner_m, r_outer_m
    return -4.0 * math.pi * dynamic_viscosity_pa_s * omega_rad_s * r1**2 * r2**2 / (r2**2 - r1**2) * height_m


@dataclass(frozen=True)
class CouetteResult:
    """Torque on the inner cylinder: simulated and analytic, and the run's figures."""

    torque_simulated_Nm: float
    torque_analytic_Nm: float
    relative_error: float
    cells: int
    reynolds: float
    iterations: int
    wall_time_s: float


def _annulus_mesh(msh: Path, r1: float, r2: float, height: float, n_radial: int, n_theta: int) -> None:
    """Structured annulus (four quarter rings), extruded by one cell layer: hexahedra."""
    import gmsh

    gmsh.initialize(interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("couette")
        geo = gmsh.model.geo
        c = geo.addPoint(0, 0, 0)
        p_in = [geo.addPoint(r1 * math.cos(a), r1 * math.sin(a), 0) for a in (0, math.pi / 2, math.pi, 1.5 * math.pi)]
        p_out = [geo.addPoint(r2 * math.cos(a), r2 * math.sin(a), 0) for a in (0, math.pi / 2, math.pi, 1.5 * math.pi)]
        arc_in = [geo.addCircleArc(p_in[i], c, p_in[(i + 1) % 4]) for i in range(4)]
        arc_out = [geo.addCircleArc(p_out[i], c, p_out[(i + 1) % 4]) for i in range(4)]
        rad = [geo.addLine(p_in[i], p_out[i]) for i in range(4)]
        surfs = []
        for i in range(4):
            loop = geo.addCurveLoop([rad[i], arc_out[i], -rad[(i + 1) % 4], -arc_in[i]])
            surfs.append(geo.addPlaneSurface([loop]))
        for a in arc_in + arc_out:
            geo.mesh.setTransfiniteCurve(a, n_theta // 4 + 1)
        for r in rad:
            geo.mesh.setTransfiniteCurve(r, n_radial + 1)
        for s in surfs:
            geo.mesh.setTransfiniteSurface(s)
            geo.mesh.setRecombine(2, s)
        out = geo.extrude([(2, s) for s in surfs], 0, 0, height, numElements=[1], recombine=True)
        geo.synchronize()
        # extrude returns, per surface: top, volume, then the four lateral surfaces in loop order
        tops, vols, inner, outer = [], [], [], []
        for k in range(4):
            block = out[6 * k: 6 * k + 6]
            tops.append(block[0][1])
            vols.append(block[1][1])
            outer.append(block[3][1])
            inner.append(block[5][1])
        gmsh.model.addPhysicalGroup(2, inner, name="inner")
        gmsh.model.addPhysicalGroup(2, outer, name="outer")
        gmsh.model.addPhysicalGroup(2, surfs + tops, name="frontAndBack")
        gmsh.model.addPhysicalGroup(3, vols, name="fluid")
        gmsh.model.mesh.generate(3)
        write_msh22(msh)
    finally:
        gmsh.finalize()


def taylor_couette(
    *,
    r_inner_m: float = 0.020,
    r_outer_m: float = 0.025,
    height_m: float = 0.002,
    omega_rad_s: float = 10.0,
    kinematic_viscosity_m2_s: float = 1e-4,
    density_kg_m3: float = 870.0,
    n_radial: int = 16,
    n_theta: int = 160,
    n_iterations: int = 2000,
    work_dir: str | Path | None = None,
) -> CouetteResult:
    """Run the laminar Taylor-Couette case and compare the torque with the analytic value.

    The defaults are an oil (nu 1e-4 m2/s) in a 5 mm gap at Re = omega R1 (R2 - R1) / nu = 10,
    far below the Taylor instability (Re_c ~ 100 for this radius ratio).
    """
    base = Path(work_dir) if work_dir is not None else Path(tempfile.mkdtemp(prefix="kegel-couette-"))
    case = render_case("taylor_couette", base / "taylor_couette", {
        "n_iterations": n_iterations, "density_kg_m3": density_kg_m3,
        "kinematic_viscosity_m2_s": kinematic_viscosity_m2_s, "omega_rad_s": omega_rad_s,
    }, overwrite=True)
    msh = case / "annulus.msh"
    _annulus_mesh(msh, r_inner_m, r_outer_m, height_m, n_radial, n_theta)
    gmsh_to_foam(case, msh, {"inner": "wall", "outer": "wall", "frontAndBack": "empty"})
    quality = check_mesh(case)
    t0 = time.monotonic()
    summary = run_solver(case, "simpleFoam")
    wall = time.monotonic() - t0
    forces = read_forces(case, "forces")
    m_z = float(forces.moment_total[-1, 2])
    ref = couette_torque_analytic(r_inner_m, r_outer_m, omega_rad_s,
                                  kinematic_viscosity_m2_s * density_kg_m3, height_m)
    return CouetteResult(
        torque_simulated_Nm=m_z, torque_analytic_Nm=ref, relative_error=(m_z - ref) / abs(ref),
        cells=quality.cells, reynolds=omega_rad_s * r_inner_m * (r_outer_m - r_inner_m) / kinematic_viscosity_m2_s,
        iterations=summary.state.steps, wall_time_s=wall,
    )
