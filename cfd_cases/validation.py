"""Validation cases run through the same pipeline as the bearing (gmsh -> gmshToFoam -> solver ->
forces): laminar Taylor-Couette torque against the analytic solution, and the free surface and
volume of oil in a turning tank (VOF) against the paraboloid.

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

import numpy as np

from .foam import run_solver
from .forces import read_forces
from .mesh import check_mesh, gmsh_to_foam, write_msh22
from .template import render_case, render_file

__all__ = ["CouetteResult", "couette_torque_analytic", "taylor_couette", "RotatingTankResult",
           "rotating_tank_surface", "rotating_tank"]


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


@dataclass(frozen=True)
class RotatingTankResult:
    """Free surface of oil in a turning tank: simulated against the paraboloid, and volume.

    Attributes
    ----------
    radius_m, height_sim_m, height_analytic_m
        Radial bins and the oil column height in each (simulated and analytic).
    max_height_error_m
        Largest |simulated - analytic| over the bins.
    cell_height_m
        Height of one cell layer (the resolution of the surface).
    volume_change
        Relative change of the oil volume from start to end.
    """

    radius_m: list[float]
    height_sim_m: list[float]
    height_analytic_m: list[float]
    max_height_error_m: float
    cell_height_m: float
    volume_change: float
    cells: int
    wall_time_s: float


def rotating_tank_surface(r: np.ndarray, radius_m: float, fill_height_m: float, omega_rad_s: float,
                          g_m_s2: float = 9.81) -> np.ndarray:
    """Height of the free surface of a liquid in solid-body rotation in a closed cylinder, at
    rest height ``fill_height_m``: ``h(r) = h0 + omega^2 (r^2 - R^2/2) / (2 g)`` (the paraboloid
    of equal volume; valid while it touches neither bottom nor lid)."""
    return fill_height_m + omega_rad_s**2 * (np.asarray(r) ** 2 - 0.5 * radius_m**2) / (2.0 * g_m_s2)


def _tank_mesh(msh: Path, radius: float, height: float, n_radial: int, n_layers: int) -> None:
    import gmsh

    gmsh.initialize(interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("tank")
        occ = gmsh.model.occ
        disk = occ.addDisk(0, 0, 0, radius, radius)
        occ.synchronize()
        gmsh.option.setNumber("Mesh.MeshSizeMax", radius / n_radial)
        gmsh.option.setNumber("Mesh.MeshSizeMin", 0.7 * radius / n_radial)
        gmsh.model.mesh.setRecombine(2, disk)
        gmsh.option.setNumber("Mesh.Algorithm", 8)  # frontal-Delaunay for quads
        out = occ.extrude([(2, disk)], 0, 0, height, numElements=[n_layers], recombine=True)
        occ.synchronize()
        top = out[0][1]
        vol = out[1][1]
        side = [t for d, t in out[2:] if d == 2]
        gmsh.model.addPhysicalGroup(2, [disk, top, *side], name="walls")
        gmsh.model.addPhysicalGroup(3, [vol], name="tank")
        gmsh.model.mesh.generate(3)
        write_msh22(msh)
    finally:
        gmsh.finalize()


def rotating_tank(
    *,
    radius_m: float = 0.05,
    height_m: float = 0.08,
    fill_height_m: float = 0.04,
    omega_rad_s: float = 12.0,
    oil_nu_m2_s: float = 5e-3,
    oil_density_kg_m3: float = 870.0,
    n_radial: int = 14,
    n_layers: int = 40,
    end_time_s: float = 1.5,
    n_procs: int = 2,
    max_courant: float | None = None,
    max_interface_courant: float | None = None,
    work_dir: str | Path | None = None,
) -> RotatingTankResult:
    """Oil in a closed tank turning at ``omega`` about the vertical axis (rotating walls,
    absolute frame), starting in solid-body rotation with a flat surface. After the surface
    settles it must be the paraboloid of :func:`rotating_tank_surface`, and the oil volume
    must be unchanged. The viscous oil (nu 5e-3 m2/s) damps the sloshing within the run.

    The solver settings are the bearing oil bath's (its ``fvSolution`` template and, unless
    given, its Courant limits from :class:`~kegel.cfd_cases.run.CfdPoint`), so this checks them."""
    from .foam import read_field, run_utility, time_dirs, write_field_values
    from .run import CfdPoint

    base = Path(work_dir) if work_dir is not None else Path(tempfile.mkdtemp(prefix="kegel-tank-"))
    params = {
        "end_time": end_time_s, "fill_height_m": fill_height_m, "omega_rad_s": omega_rad_s,
        "oil_nu_m2_s": oil_nu_m2_s, "oil_density_kg_m3": oil_density_kg_m3,
        "p_ref_point": (0.0, 0.0, 0.97 * height_m),
        "max_co": CfdPoint.max_courant if max_courant is None else max_courant,
        "max_alpha_co": CfdPoint.max_interface_courant if max_interface_courant is None else max_interface_courant,
    }
    case = render_case("rotating_tank", base / "rotating_tank", params, overwrite=True)
    render_file("bearing_oil_bath/system/fvSolution.template", case / "system" / "fvSolution", params)
    _tank_mesh(case / "tank.msh", radius_m, height_m, n_radial, n_layers)
    gmsh_to_foam(case, case / "tank.msh", {"walls": "wall"})
    quality = check_mesh(case)
    run_utility(case, "setFields")
    run_utility(case, "postProcess", "-func", "writeCellCentres", "-time", "0", log_name="writeCellCentres")
    run_utility(case, "postProcess", "-func", "writeCellVolumes", "-time", "0", log_name="writeCellVolumes")
    c = read_field(case / "0" / "C")
    vol = read_field(case / "0" / "V")
    for f in ("C", "Cx", "Cy", "Cz", "V"):
        (case / "0" / f).unlink(missing_ok=True)
    write_field_values(case / "0" / "U", omega_rad_s * np.cross(np.array([0.0, 0.0, 1.0]), c))
    if n_procs > 1:
        (case / "system" / "decomposeParDict").write_text(
            "FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
            f"numberOfSubdomains {n_procs};\nmethod hierarchical;\ncoeffs {{ n ({n_procs} 1 1); order xyz; }}\n")
        run_utility(case, "decomposePar", "-force")
    t0 = time.monotonic()
    run_solver(case, "interFoam", n_procs=n_procs, end_time=end_time_s)
    wall = time.monotonic() - t0
    if n_procs > 1:
        run_utility(case, "reconstructPar", "-latestTime")
    last = time_dirs(case)[-1]
    alpha = read_field(last / "alpha.oil")
    # column height per radial bin: oil volume in the annulus / annulus area
    r = np.hypot(c[:, 0], c[:, 1])
    edges = np.linspace(0.0, radius_m, 8)
    centres, h_sim = [], []
    for lo, hi in zip(edges[:-1], edges[1:]):
        sel = (r >= lo) & (r < hi)
        area = float(vol[sel].sum()) / height_m
        h_sim.append(float((alpha[sel] * vol[sel]).sum()) / area)
        centres.append(float(np.sqrt(0.5 * (lo**2 + hi**2))))  # area-weighted bin radius
    # the analytic height averaged over each annulus: h is linear in r^2, so the mean over the
    # annulus equals h at the area-weighted radius used above
    h_ref = rotating_tank_surface(np.array(centres), radius_m, fill_height_m, omega_rad_s)
    v0 = float((np.clip(read_field(case / "0" / "alpha.oil"), 0, 1) * vol).sum())
    v1 = float((alpha * vol).sum())
    return RotatingTankResult(
        radius_m=centres, height_sim_m=h_sim, height_analytic_m=h_ref.tolist(),
        max_height_error_m=float(np.max(np.abs(np.array(h_sim) - h_ref))),
        cell_height_m=height_m / n_layers, volume_change=(v1 - v0) / v0, cells=quality.cells, wall_time_s=wall,
    )
