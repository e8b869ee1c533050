"""Bearing CFD runs: prepare a case from the templates, mesh, run on N cores, follow, post-process.

Modelling choices (and what they cost):

- Frame: frozen rotor in the cage frame (MRF over the whole oil space at the cage speed). The
  rollers and the cage stand still in that frame, so the geometry does not move and the run is
  cheap and conserves the liquid volume (moving meshes with cyclicAMI lost about 2 % of it on
  this OpenFOAM, see ../shared/notes). The cost: the rollers' positions relative to gravity (the
  sump) are frozen, so the periodic passage of rollers through the oil bath is replaced by one
  frozen arrangement (roller 0 at the bottom); torque fluctuations at the roller-pass frequency
  are lost, and the mean can carry a bias of the order of the difference between arrangements
  (half a roller pitch apart). ``frame = "moving_mesh"`` is the check: the whole mesh turns with
  the cage as a solid body (no interface to interpolate across, so the oil is kept), gravity
  fixed (benchmarks/cfd_oil_bath_moving_mesh.py).
- Walls carry their absolute velocities: rings and cage turn about z, each roller's orbit plus
  spin is one rotation (see 0/U in the templates); speeds from kegel's pure-rolling kinematics
  (:func:`kegel.tribology.cage_speed_rad_s`).
- Laminar flow (gap Reynolds numbers of a few hundred at the design points).
- Line contacts are opened to a gap (kegel.cfd_cases.geometry).

Flooded: steady single-phase ``simpleFoam``. Oil bath: transient ``interFoam`` (oil/air, gravity
``-y``), run until the loss torque is statistically steady (:mod:`kegel.cfd_cases.steady`).

Oil-bath time step: the Courant number is limited to ``max_courant`` (default 5) in the
oil-filled gaps and ``max_interface_courant`` (default 1) at the free surface, with the momentum
predictor (PIMPLE, one outer corrector, semi-implicit MULES). The former limits (0.5 / 0.5, no
momentum predictor) needed 5-10 us steps. ``benchmarks/cfd_oil_bath_courant.py`` measures what the
larger step costs on the steepest part of the start-up (tiny, 32208, 2000 rpm: 5 / 1 within
1.5 % of 0.5 / 0.5 at 2.8 times its speed, 10 / 3 within 3.1 % at 8.4 times). The spin-up of the
oil and its transport around the housing take tenths of a second of simulated time (0.2 s for
the 32208 at 2000 rpm), so a fine mesh is best started from a coarse run of the same point
(``initial_from``: the fields are mapped volume-conservatively; ``kegel cfd run --start-on tiny``
runs both in one call: 49 min on 2 cores for the small 32208 point at Courant 10 / 3).
"""

from __future__ import annotations

import json
import math
import shutil
import sys
import time
from collections.abc import Callable
from dataclasses import MISSING, asdict, dataclass, field, fields
from pathlib import Path
from typing import Any, TextIO

import numpy as np

from .foam import (FoamError, LogState, controldict_value, cut_write, read_boundary_geometry, read_field,
                   run_solver, run_utility, set_aside_cut_writes, set_controldict_value, time_dirs,
                   write_field_values)
from .forces import ForceSeries, read_forces
from .geometry import (CELLS_ACROSS_GAP, CELLS_ACROSS_GAP_RANGE, CLEARANCE_RATIO, GAP_RATIO, MESH_LEVELS, RATIO_RANGES,
                       CfdGeometry, build_mesh,
                       cfd_geometry, roller_name)
from .mesh import MeshQuality, check_mesh, gmsh_to_foam
from .steady import SteadyTest, drift_of_means, first_steady_time, steady_drift, window_means
from .template import render_case

__all__ = ["CfdPoint", "CfdResult", "prepare_case", "run_case", "roller_wall_rotation", "kinematics",
           "loss_torque_series", "replay_oil_bath_steady_test", "wall_torque_series", "angular_momentum_balance"]

#: the oil's initial velocity, a rigid rotation at this fraction of the cage's speed (absolute
#: frame). The oil bath starts from (nearly) rest: its start-up is part of the transient the
#: steady test waits out. A flooded (steady) run starts with the oil turning with the cage, its
#: nearest rigid-body guess (the roller row's oil moves with the cage; the side chambers' core
#: turns between housing and shaft, about the cage's speed): from (nearly) rest the side
#: chambers spin up over thousands of SIMPLE iterations. The two starts end in two different
#: steady states on the default sector (every torque constant to 4 digits): loss 82.82 mN m
#: from the cage's rotation (steady test passed at iteration 940), 83.77 from rest (2120); the
#: resting walls' and the cage's torques differ by 7-22 %. Neither is shown to be the physical one
#: (benchmarks/cfd_flooded_convergence.py, docs/cfd.md)
INITIAL_ROTATION_FRACTION = 0.01
FLOODED_INITIAL_ROTATION_FRACTION = 1.0
FRAMES = ("cage", "absolute", "moving_mesh")
AIR_DENSITY_KG_M3 = 1.2          # at 20-50 degC, 1 bar
AIR_KINEMATIC_VISCOSITY_M2_S = 1.6e-5
#: the walls (besides the rollers) whose torques about the bearing axis close the angular-momentum
#: balance
BALANCE_WALLS = ("inner_ring", "shaft", "outer_ring", "housing", "cage")
OIL_AIR_SURFACE_TENSION_N_M = 0.03  # mineral oil against air, typical 0.03 N/m (e.g. Totten, Handbook of Lubrication)


@dataclass(frozen=True)
class CfdPoint:
    """One CFD operating point (SI units).

    ``oil_level_m`` is the oil surface above the lowest point of the bearing's outer diameter
    (horizontal shaft), ``None`` for a fully flooded bearing.
    """

    bearing: str
    speed_rad_s: float
    temperature_K: float
    oil_level_m: float | None
    mesh: str = "tiny"
    n_procs: int = 2
    lubricant: str = "FVA3"
    material: str = "bearing_steel"
    housing_clearance_m: float | None = None
    # Frame of the steady (frozen-rotor) solution: "cage" - MRF over the whole oil space at the
    # cage speed, so rollers and cage stand still in the frame (the default); "absolute" - no
    # MRF, the same frozen geometry in the inertial frame with the walls' absolute velocities (a
    # modelling-choice check: the two frozen-rotor readings bracket the effect of the frame);
    # "moving_mesh" - oil bath only: no frozen rotor, the whole mesh turns with the cage (a solid
    # body; rings, shaft and housing are surfaces of revolution, so nothing else needs to move)
    # while gravity stays put, so the rollers pass through the sump as they do in the bearing (the
    # check of the frozen rotor; see _write_wall_velocities)
    frame: str = "cage"
    # False: the same bearing without its cage (a modelling-choice check: how much of the loss the
    # cage's presence makes; the cage's torque is then zero and the rollers keep their orbit)
    cage: bool = True
    end_time_s: float | None = None        # oil bath: simulated time limit (default: 20 shaft revolutions)
    max_iterations: int = 2000            # flooded: SIMPLE iteration limit
    # Relative tolerance of the steady test (see _SteadyMonitor); 0 never stops on it (the run
    # goes to end_time_s / max_iterations), e.g. for a reference run.
    steady_tolerance: float = 0.02
    max_wall_time_s: float | None = None   # stop (and write) when the run takes longer than this
    max_courant: float = 5.0               # oil bath: time step limit (Courant number, oil-filled gaps)
    max_interface_courant: float = 1.0     # oil bath: time step limit at the free surface
    initial_from: str | None = None        # a run of this point (another mesh) to start from
    # Oil bath: forces are sampled every this many time steps. Each of the 22 ``forces`` objects
    # evaluates the viscous stress over the whole mesh; sampling every step cost about 1 s of a
    # 2.5 s step on the small mesh. Steps are tens of microseconds, so the histories keep their shape.
    force_sample_steps: int = 5
    # The bearing's data file when it was given as a file (``kegel cfd run --bearing FILE``);
    # None: the shipped data of the designation ``bearing``
    bearing_file: str | None = None
    # Contact gap g / D_w: the raceways are set back by g from the real rollers (the contact
    # model owns the film below g; see kegel.cfd_cases.geometry and benchmarks/cfd_gap_study.py)
    gap_ratio: float = GAP_RATIO
    # Roller end / rib and pocket clearance c / D_w (at least the real pocket clearance per side)
    clearance_ratio: float = CLEARANCE_RATIO
    # Cells across the narrowest point of each raceway contact gap (None: the level's wall size)
    cells_across_gap: int | None = CELLS_ACROSS_GAP
    # Flooded only: one roller pitch with periodic sides (the flow repeats in the cage frame)
    sector: bool = False

    @property
    def flooded(self) -> bool:
        return self.oil_level_m is None

    def validate(self) -> None:
        if not isinstance(self.cage, bool):
            raise ValueError(f"cage = {self.cage!r}: expected true or false")
        if not isinstance(self.sector, bool):
            raise ValueError(f"sector = {self.sector!r}: expected true or false")
        if self.sector and not self.flooded:
            raise ValueError("sector = true: only for a flooded bearing (an oil bath's free surface and gravity "
                             "do not repeat from pocket to pocket)")
        if self.sector and self.frame != "cage":
            raise ValueError("sector = true: only in the cage frame (frame = 'cage'), where the flow repeats")
        for name, (lo, hi) in RATIO_RANGES.items():
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not (math.isfinite(v) and lo <= v <= hi):
                raise ValueError(f"{name} = {v!r}: expected a fraction of the roller diameter in [{lo}, {hi}]")
        c_lo, c_hi = CELLS_ACROSS_GAP_RANGE
        if self.cells_across_gap is not None and (isinstance(self.cells_across_gap, bool)
                                                  or not isinstance(self.cells_across_gap, int)
                                                  or not c_lo <= self.cells_across_gap <= c_hi):
            raise ValueError(f"cells_across_gap = {self.cells_across_gap!r}: expected a whole number from {c_lo} to {c_hi}")
        if self.frame not in FRAMES:
            raise ValueError(f"frame = {self.frame!r}: expected one of {', '.join(FRAMES)}")
        if self.frame == "moving_mesh" and self.flooded:
            raise ValueError("frame = 'moving_mesh': only for an oil bath (a flooded bearing's flow is steady in "
                             "the cage frame, where the frozen rotor is exact)")
        if self.housing_clearance_m is not None and not (math.isfinite(self.housing_clearance_m)
                                                         and self.housing_clearance_m > 0.0):
            raise ValueError(f"housing_clearance_m = {self.housing_clearance_m}: expected a positive distance")
        if self.mesh not in MESH_LEVELS:
            raise ValueError(f"mesh = {self.mesh!r}: expected one of {', '.join(MESH_LEVELS)}")
        if self.n_procs < 1:
            raise ValueError(f"n_procs = {self.n_procs}: expected at least 1")
        if self.speed_rad_s == 0.0:
            raise ValueError("speed = 0: expected a turning shaft")
        if not (isinstance(self.force_sample_steps, int) and self.force_sample_steps >= 1):
            raise ValueError(f"force_sample_steps = {self.force_sample_steps!r}: expected a whole number of at least 1")
        if not (math.isfinite(self.steady_tolerance) and 0.0 <= self.steady_tolerance < 1.0):
            raise ValueError(f"steady_tolerance = {self.steady_tolerance}: expected a fraction in [0, 1) "
                             "(0: no steady stop)")
        for name in ("max_courant", "max_interface_courant"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0.0):
                raise ValueError(f"{name} = {value}: expected a positive Courant number")


def kinematics(g, omega_i: float) -> dict[str, float]:
    """Cage speed and roller spin (relative to the cage, about the roller axis small -> large end)
    of apex-matched pure rolling with the outer ring fixed."""
    from kegel.physics.tribology import cage_speed_rad_s

    omega_c = cage_speed_rad_s(g, omega_i)
    omega_s = -(omega_i - omega_c) * g.inner_raceway_diameter_mid_m / g.roller_mean_diameter_m
    return {"inner_ring_rad_s": omega_i, "cage_rad_s": omega_c, "roller_spin_rad_s": omega_s}


def roller_wall_rotation(cg: CfdGeometry, k: int, omega_c: float, omega_s: float) -> dict[str, Any]:
    """Roller k's absolute wall motion as one rotation: ``omega`` about ``axis`` through ``origin``.

    The motion is ``v(r) = omega_c e_z x r + omega_s a x (r - c)``. With ``w = omega_c e_z +
    omega_s a`` and ``b = omega_s a x c`` (perpendicular to ``w`` because ``a``, ``e_z`` and
    ``c`` lie in one axial plane), ``v = w x (r - o)`` with ``o = (b x w) / |w|^2``.
    """
    c, a = cg.roller_centre_and_axis(k)
    w = omega_c * np.array([0.0, 0.0, 1.0]) + omega_s * a
    b = omega_s * np.cross(a, c)
    o = np.cross(b, w) / float(np.dot(w, w))
    mag = float(np.linalg.norm(w))
    return {"name": roller_name(k), "origin": o, "axis": w / mag, "omega": mag, "centre": c,
            "roller_axis": a}


def _bodies(cg: CfdGeometry, cage: bool = True) -> list[dict[str, Any]]:
    bodies = [{"name": n, "patches": [n], "origin": np.zeros(3)}
              for n in ("inner_ring", "outer_ring", "cage", "shaft", "housing") if cage or n != "cage"]
    for k in cg.modelled_rollers:
        c, _ = cg.roller_centre_and_axis(k)
        bodies.append({"name": roller_name(k), "patches": [roller_name(k)], "origin": c})
    return bodies


def point_bearing(point: CfdPoint):
    """The point's bearing data: its data file when it was given one, else the shipped data of
    its designation."""
    from kegel.model.data import load_bearing

    return load_bearing(point.bearing_file or point.bearing)


def _load(point: CfdPoint):
    from kegel.model.data import load_lubricant, load_material
    from kegel.model.geometry import derive_geometry
    from kegel.model.lubricant import lubricant_state

    bearing = point_bearing(point)
    g = derive_geometry(bearing, load_material(point.material))
    lub = lubricant_state(load_lubricant(point.lubricant), point.temperature_K)
    return bearing, g, lub


def oil_bath_write_interval_s(speed_rad_s: float, end_time_s: float) -> float:
    """Oil bath: fields are written every shaft revolution (or at the end of a shorter run),
    whatever the end time. The solver lands its time steps on the write times, so an interval
    that followed the end time (it was end / 20) made a run to 0.9 s another realisation of the
    flow than one to 0.6 s, from the first step on."""
    return min(2 * math.pi / abs(speed_rad_s), end_time_s)


#: Settings that may change when a run is resumed (they do not change the case itself).
RESUMABLE_SETTINGS = ("max_wall_time_s", "max_iterations", "end_time_s", "steady_tolerance")


#: Oil bath: the steady test's window, in cage revolutions (see _SteadyMonitor). The oil is
#: carried around the housing at about the cage speed; in the 32208 start-up (tiny, 2000 rpm) the
#: loss torque levels off after 3 shaft revolutions and rises again over the next 3 as the oil
#: spreads through the bearing, so windows of a shaft revolution or less stop too early.
STEADY_WINDOW_CAGE_REVOLUTIONS = 0.5


def steady_window_s(cage_rad_s: float) -> float:
    """The window of the oil bath's steady test (simulated seconds) at the cage speed ``cage_rad_s``."""
    return STEADY_WINDOW_CAGE_REVOLUTIONS * 2 * math.pi / abs(cage_rad_s)


#: Oil bath: the steady test applies only after this many cage revolutions from rest (counting
#: the run a case was started from, ``initial_from``). The 32208 start-up (tiny, 2000 rpm) has
#: false plateaus. With the old shrunk rollers the loss fell to 17.6 mN m at 1.1-1.6 cage
#: revolutions, held for 3 windows and rose by 30 % as the oil spread through the bearing (a run at
#: Courant 5 / 1 stopped on it at 0.128 s); three revolutions were then enough. With the real
#: rollers the loss holds at 27.2-27.9 mN m from 2.0 to 3.5 cage revolutions and rises by 14 %
#: up to 5 revolutions (run to 10.5 revolutions, benchmarks/cfd_oil_bath_stop_rule.py): the rule
#: from 3 revolutions stopped there at 0.215 s, 11.8 % below the mean of the last three
#: revolutions. From 5 revolutions it stops within 1 % of that mean. Taken from that one run;
#: benchmarks/results/cfd_oil_bath_stop_rule.json has the variants, docs/cfd.md "Oil bath: how
#: steady" the checks at other points.
STEADY_MIN_CAGE_REVOLUTIONS_FROM_REST = 5.0


#: Oil bath: the steady test must pass at every check point over this many windows before the
#: run stops (see kegel.cfd_cases.steady.SteadyTest); 0 stops on the first pass. Half a window
#: keeps a run from stopping on a turn of the loss's slow swing (period about 1.4 cage
#: revolutions): with the real rollers it stopped at 0.378 s, +0.2 % from the long-time mean,
#: at 1.65 times the wall time of the old rule.
STEADY_HOLD_WINDOWS = 0.5


def steady_min_time_s(cage_rad_s: float) -> float:
    """Simulated time from rest before the oil bath's steady test applies (see above)."""
    return STEADY_MIN_CAGE_REVOLUTIONS_FROM_REST * 2 * math.pi / abs(cage_rad_s)


def replay_oil_bath_steady_test(t: np.ndarray, loss: np.ndarray, cage_rad_s: float, *,
                                window_cage_revolutions: float | None = None, tol: float | None = None,
                                hold_windows: float | None = None,
                                min_cage_revolutions: float | None = None) -> tuple[float, float] | None:
    """Where the oil bath's steady test would stop a recorded run (``t`` from rest, ``loss`` the
    loss torque at the shaft), at the runner's check points (every window /
    ``_SteadyMonitor.CHECK_PER_WINDOW``), and the loss it would report there (the mean over the
    last window); None if it never passes. Each setting defaults to the runner's rule
    (:data:`STEADY_WINDOW_CAGE_REVOLUTIONS`, ``CfdPoint.steady_tolerance``,
    :data:`STEADY_HOLD_WINDOWS`, :data:`STEADY_MIN_CAGE_REVOLUTIONS_FROM_REST`)."""
    rev = 2 * math.pi / abs(cage_rad_s)
    w = (STEADY_WINDOW_CAGE_REVOLUTIONS if window_cage_revolutions is None else window_cage_revolutions) * rev
    tol = CfdPoint.steady_tolerance if tol is None else tol
    hold = STEADY_HOLD_WINDOWS if hold_windows is None else hold_windows
    min_revs = STEADY_MIN_CAGE_REVOLUTIONS_FROM_REST if min_cage_revolutions is None else min_cage_revolutions
    step = w / _SteadyMonitor.CHECK_PER_WINDOW
    ts = first_steady_time(t, loss, w, tol, min_time=min_revs * rev, hold=hold * w,
                           check_times=step * np.arange(1, math.floor(t[-1] / step) + 1))
    if ts is None:
        return None
    k = t <= ts
    return ts, float(window_means(t[k], loss[k], w, 1)[0])


def _differing_settings(stored: dict[str, Any], point: CfdPoint, ignore: tuple[str, ...],
                        rel_tol: float = 0.0) -> list[str]:
    """The settings in which a point stored in a kegel-case.json differs from ``point``, apart
    from ``ignore``. Settings added to :class:`CfdPoint` since the case was made count with their
    defaults; floats agree within ``rel_tol`` (0: exactly)."""
    defaults = {f.name: f.default for f in fields(CfdPoint) if f.default is not MISSING}
    old, new = {**defaults, **stored}, _point_json(point)

    def same(a: Any, b: Any) -> bool:
        if isinstance(a, float) and isinstance(b, float):
            return math.isclose(a, b, rel_tol=rel_tol)
        return a == b

    return sorted(k for k in set(old) | set(new) if k not in ignore and not same(old.get(k), new.get(k)))


def _point_json(point: CfdPoint) -> dict[str, Any]:
    d = asdict(point)
    d["speed_rpm"] = point.speed_rad_s * 30.0 / math.pi
    d["temperature_degC"] = point.temperature_K - 273.15
    return d


def prepare_case(point: CfdPoint, case_dir: str | Path, *, log: Callable[[str], None] = print) -> Path:
    """Create (or reuse, for a resumed run) the case folder of ``point``: templates, mesh,
    initial oil distribution, decomposition.

    A case that already holds ``kegel-case.json`` for the same point is reused as it is (the
    solver then starts from its latest time); for another point it is an error.
    """
    point.validate()
    case_dir = Path(case_dir)
    meta_path = case_dir / "kegel-case.json"
    if meta_path.is_file():
        meta = json.loads(meta_path.read_text())
        # the start (initial_from) only matters when the case is made: a resumed case goes on from its own
        differ = _differing_settings(meta.get("point", {}), point, RESUMABLE_SETTINGS + ("initial_from",))
        if differ:
            raise FoamError(f"{case_dir} holds a case of another point ({meta_path}: differs in "
                            f"{', '.join(differ)}); choose another folder")
        log(f"cfd: resuming the case in {case_dir} from its latest time")
        set_aside_cut_writes(case_dir, log=log)  # a write cut by a kill: go on from the one before
        end = point.max_iterations if point.flooded else point.end_time_s
        if end is not None:
            set_controldict_value(case_dir, "endTime", f"{end:.10g}")
        set_controldict_value(case_dir, "stopAt", "endTime")
        meta["point"] = {**_point_json(point), "initial_from": meta.get("point", {}).get("initial_from")}
        meta_path.write_text(json.dumps(meta, indent=2))
        return case_dir
    bearing, g, lub = _load(point)
    cg = cfd_geometry(g, housing_clearance_m=point.housing_clearance_m, gap_ratio=point.gap_ratio,
                      clearance_ratio=point.clearance_ratio, sector=point.sector)
    kin = kinematics(g, point.speed_rad_s)
    rollers = [roller_wall_rotation(cg, k, kin["cage_rad_s"], kin["roller_spin_rad_s"])
               for k in cg.modelled_rollers]
    patch_names = ["inner_ring", "shaft", "outer_ring", "housing", *(["cage"] if point.cage else []),
                   *[r["name"] for r in rollers]]
    # pressure reference: in the side chamber at the top (air in an oil bath); in a sector, in
    # the side chamber on roller 0's azimuth
    r_mid = 0.5 * (cg.shaft_radius_m + cg.housing_radius_m)
    phi_ref = cg.roller_azimuth_rad(0) if cg.sector else 0.5 * math.pi
    p_ref = np.array([r_mid * math.cos(phi_ref), r_mid * math.sin(phi_ref), 0.5 * cg.z_min_m])
    omega_i = point.speed_rad_s
    mesh_motion = kin["cage_rad_s"] if point.frame == "moving_mesh" else None
    if point.flooded:
        template = "bearing_flooded"
        params = {"n_iterations": point.max_iterations, "write_interval": min(100, point.max_iterations)}
    else:
        template = "bearing_oil_bath"
        rev = 2 * math.pi / abs(omega_i)
        end = point.end_time_s if point.end_time_s is not None else 20 * rev
        y_level = -cg.housing_radius_m + point.oil_level_m
        params = {"end_time": end, "write_interval_s": oil_bath_write_interval_s(omega_i, end), "y_level": y_level,
                  "air_density_kg_m3": AIR_DENSITY_KG_M3, "air_nu_m2_s": AIR_KINEMATIC_VISCOSITY_M2_S,
                  "sigma_N_m": OIL_AIR_SURFACE_TENSION_N_M,
                  "box_min": (-1.0, -1.0, -1.0), "box_max": (1.0, y_level, 1.0),
                  "first_delta_t": min(1e-5, rev / 2000),
                  "max_co": point.max_courant, "max_alpha_co": point.max_interface_courant,
                  "force_sample_steps": point.force_sample_steps}
    params.update({
        "patch_names": patch_names, "rollers": rollers, "bodies": _bodies(cg, point.cage),
        "inner_omega_rad_s": omega_i, "cage_omega_rad_s": kin["cage_rad_s"],
        "density_kg_m3": lub.density_kg_m3, "kinematic_viscosity_m2_s": lub.kinematic_viscosity_m2_s,
        "p_ref_point": p_ref, "n_procs": point.n_procs,
        "periodic_patches": ["periodic_lo", "periodic_hi"] if cg.sector else [],
        "mrf_active": "yes" if point.frame == "cage" else "no",
        "mesh_motion_rad_s": mesh_motion,
    })
    tmp = case_dir.with_name(case_dir.name + ".preparing")
    render_case(template, tmp, params, overwrite=True)
    t0 = time.monotonic()
    log(f"cfd: meshing {bearing.designation} at level '{point.mesh}' (gmsh)"
        + ("" if point.cage else ", without the cage"))
    types = build_mesh(cg, point.mesh, tmp / "bearing.msh", cage=point.cage,
                       cells_across_gap=point.cells_across_gap)
    gmsh_to_foam(tmp, tmp / "bearing.msh", types)
    (tmp / "bearing.msh").unlink()
    quality = check_mesh(tmp)
    mesh_s = time.monotonic() - t0
    start = FLOODED_INITIAL_ROTATION_FRACTION if point.flooded else INITIAL_ROTATION_FRACTION
    _write_wall_velocities(tmp, kin, rollers, 0.0 if point.frame == "absolute" else kin["cage_rad_s"],
                           cage=point.cage, initial_rotation_fraction=start, moving_mesh=point.frame == "moving_mesh")
    log(f"cfd: mesh {quality.cells} cells, non-orthogonality {quality.max_non_orthogonality_deg:.1f} deg, "
        f"skewness {quality.max_skewness:.2f} (checkMesh OK, {mesh_s:.1f} s)")
    initial = None
    if not point.flooded:
        run_utility(tmp, "setFields")
    if point.initial_from is not None:
        initial = _map_initial_state(tmp, point, log)
    if point.n_procs > 1:
        run_utility(tmp, "decomposePar", "-force")
    meta = {"point": _point_json(point), "template": template, "kinematics": kin, "initial_state": initial,
            # frame = moving_mesh: the mesh turns about z at this speed (rad/s); None: a static mesh
            "mesh_motion_rad_s": mesh_motion,
            # the start rotation's share of the cage speed (None: the fields were mapped, initial_state)
            "initial_oil_rotation_of_cage": start if initial is None else None,
            "mesh": asdict(quality), "mesh_time_s": mesh_s,
            "lubricant": lub.as_dict(),
            "geometry": {"gap_m": cg.gap_m, "clearance_m": cg.clearance_m,
                         "housing_clearance_m": cg.housing_clearance_m,
                         "z_min_m": cg.z_min_m, "z_max_m": cg.z_max_m,
                         "roller_surface": "real (nominal diameter and length); raceways set back by the gap",
                         "sector": cg.sector, "copies": cg.copies, "roller_count": cg.roller_count},
            "rollers": [{"name": r["name"], "centre_m": r["centre"].tolist(), "axis": r["roller_axis"].tolist(),
                         "wall_rotation_origin_m": r["origin"].tolist(), "wall_rotation_axis": r["axis"].tolist(),
                         "wall_rotation_rad_s": r["omega"]} for r in rollers]}
    (tmp / "kegel-case.json").write_text(json.dumps(meta, indent=2))
    if case_dir.exists():
        shutil.rmtree(case_dir)
    tmp.rename(case_dir)
    return case_dir


#: Point settings that may differ between a run and the run it starts from: the mesh (its level
#: and the cells across each contact gap; the geometry stays the same) and how the run is made.
_MAPPABLE_SETTINGS = ("mesh", "cells_across_gap", "n_procs", "max_courant", "max_interface_courant",
                      "initial_from", "force_sample_steps")


def _mapped_fields(flooded: bool) -> tuple[str, ...]:
    """The fields a start from another run maps: the flooded (single-phase, simpleFoam) case's
    velocity and pressure, the oil bath's velocity, oil fraction and pressure."""
    return ("U", "p") if flooded else ("U", "alpha.oil", "p_rgh")


def time_from_rest_at_start_s(meta: dict[str, Any]) -> float:
    """Simulated time from rest at the start of a case (the time of the state it was mapped
    from, plus that run's own start, and so on; 0 for a run from rest)."""
    init = meta.get("initial_state") or {}
    return float(init.get("time_from_rest_s", init.get("source_time_s", 0.0)))


def mapping_source_time(src: Path, fields: tuple[str, ...] = ("U", "alpha.oil")) -> tuple[str, str]:
    """The time folder of case ``src`` that a run started from it maps, and why that one: the
    last regular write before its steady stop (``restart_state_time_s`` in its results, see
    :func:`_restart_state`), else its latest reconstructed time with all of ``fields`` (an oil
    bath: U and alpha.oil; a flooded case: U and p, its time being the iteration). A time that
    lacks one of ``fields`` or holds a file cut short (a solver or reconstructPar killed while
    writing, see :func:`~kegel.cfd_cases.foam.cut_write`) is passed over."""
    later = [d for d in time_dirs(src) if float(d.name) > 0]
    unusable = {d.name: reason for d in later if (reason := cut_write(d, fields)) is not None}
    times = [d for d in later if d.name not in unusable]
    if not times:
        raise FoamError(f"initial_from = {src}: no whole reconstructed time with {' and '.join(fields)} after 0 "
                        "(run it first; kegel cfd run reconstructs its last time)")
    source_time, why = times[-1].name, "its latest time"
    cut_later = [reason for d in later if d.name in unusable and float(d.name) > float(source_time)
                 and "cut short" in (reason := unusable[d.name])]
    if cut_later:
        why = f"its latest whole time: {cut_later[-1]}"
    done = src / "results.json"
    restart = json.loads(done.read_text()).get("restart_state_time_s") if done.is_file() else None
    if restart is not None:  # a steady run: the write before its stop point (see _restart_state)
        if isinstance(restart, bool) or not isinstance(restart, (int, float)) or not math.isfinite(restart):
            raise FoamError(f"{done}: restart_state_time_s = {restart!r}; expected a finite time in seconds "
                            "(the results of kegel cfd run)")
        found = last_write_at_or_before(times, restart)
        if found is not None and float(found.name) >= restart * (1 - 1e-9):
            source_time, why = found.name, "its last regular write before the steady stop"
        else:
            why = f"its latest time: the write before its steady stop (t = {restart:g} s) is gone"
    return source_time, why


def _map_initial_state(case: Path, point: CfdPoint, log: Callable[[str], None]) -> dict[str, Any]:
    """Start a case from the state of a run of the same point on another mesh (another level,
    or other cells across the contact gaps): its latest time, or, when it stopped on a steady
    torque, its last regular write before the stop point (``restart_state_time_s`` in its
    results; the same on every machine, see :func:`_restart_state`).

    A flooded case maps the velocity and pressure: a fine mesh of the 0.02 D_w gap (4.6 M cells,
    about 22-25 s an iteration on 2 cores alone) then starts from the coarser run's flow instead of a rigid
    rotation and has only its gaps' refinement to settle. Its steady test still waits out its
    own first iterations (``_SteadyMonitor.FLOODED_MIN_ITERATIONS``).

    In an oil bath the spin-up of the oil and its transport around the housing take a few
    tenths of a second of simulated time; on a coarse mesh that costs a fraction of the fine
    mesh's time. The fields are mapped with ``mapFieldsPar -mapMethod cellVolumeWeight``
    (conservative where the meshes overlap: an oil bath's oil volume changes by the difference
    of the two discretised domains, recorded here); the case keeps its own boundary conditions
    (exact wall velocities).
    """
    src = Path(point.initial_from)
    meta_path = src / "kegel-case.json"
    if not meta_path.is_file():
        raise FoamError(f"initial_from = {src}: not a kegel CFD case (no kegel-case.json)")
    src_meta = json.loads(meta_path.read_text())
    src_point = src_meta.get("point", {})
    # floats within 1e-9: the same temperature given in degC or K
    differ = _differing_settings(src_point, point, RESUMABLE_SETTINGS + _MAPPABLE_SETTINGS, rel_tol=1e-9)
    if src_point.get("frame") == "moving_mesh":
        raise FoamError(f"initial_from = {src}: a moving-mesh run; its mesh has turned since t = 0, so its state "
                        "does not fit a new case (start from a frozen-rotor run of the point, frame = 'cage')")
    if differ == ["frame"] and point.frame == "moving_mesh" and src_point.get("frame", "cage") == "cage":
        differ = []  # the frozen rotor stands where the moving mesh starts: release it
    if differ:
        raise FoamError(f"initial_from = {src}: a run of another point (differs in {', '.join(differ)}); "
                        "expected the same bearing, speed, temperature, oil level and lubricant")
    fields = _mapped_fields(point.flooded)
    source_time, why = mapping_source_time(src, fields[:2])
    originals = {f: (case / "0" / f).read_text() for f in fields}
    oil_before = None
    if not point.flooded:  # the oil volume before and after (a flooded case is all oil)
        run_utility(case, "postProcess", "-func", "writeCellVolumes", "-time", "0", log_name="writeCellVolumes")
        volume = read_field(case / "0" / "V")
        (case / "0" / "V").unlink()
        oil_before = float(read_field(case / "0" / "alpha.oil") @ volume)
    at = f"iteration {source_time}" if point.flooded else f"t = {source_time} s"
    log(f"cfd: mapping the state at {at} ({why}) of {src} onto this mesh (mapFieldsPar)")
    run_utility(case, "mapFieldsPar", str(src.resolve()), "-consistent", "-sourceTime", source_time,
                "-mapMethod", "cellVolumeWeight")
    mapped = {f: read_field(case / "0" / f) for f in fields}
    for f in fields:  # the mapped boundary values are the coarse mesh's: keep this case's own
        (case / "0" / f).write_text(originals[f])
        write_field_values(case / "0" / f, mapped[f])
    for extra in ("p", "phi"):
        if extra not in fields:
            (case / "0" / extra).unlink(missing_ok=True)
    out = {"case": str(src.resolve()), "source_time_s": float(source_time), "source_state": why,
           "source_mesh": src_point.get("mesh"), "source_cells_across_gap": src_point.get("cells_across_gap")}
    if point.flooded:  # its time is the SIMPLE iteration
        out["iterations_before"] = float(source_time) + float((src_meta.get("initial_state") or {}).get(
            "iterations_before", 0.0))
    else:
        out["time_from_rest_s"] = float(source_time) + time_from_rest_at_start_s(src_meta)
    if oil_before is not None:
        oil_after = float(mapped["alpha.oil"] @ volume)
        change = oil_after / oil_before - 1.0
        log(f"cfd: oil volume after mapping {oil_after:.6g} m3, {100 * change:+.3f} % against the level's")
        out.update(oil_volume_m3=oil_after, oil_volume_of_the_level_m3=oil_before, oil_volume_change=change)
    return out


def _write_wall_velocities(case: Path, kin: dict[str, float], rollers: list[dict[str, Any]],
                           frame_rad_s: float, *, cage: bool = True,
                           initial_rotation_fraction: float = INITIAL_ROTATION_FRACTION,
                           moving_mesh: bool = False) -> None:
    """Wall velocities of every patch at its face centres (see 0/U) for the MRF frame turning
    at ``frame_rad_s`` (0: no MRF), and the initial oil velocity, a rigid rotation at
    ``initial_rotation_fraction`` of the cage's speed; keeps the cell centres for the oil
    pictures.

    ``moving_mesh``: the mesh turns with the cage at ``frame_rad_s`` (a solid body), so a
    velocity per face written once would go stale; each wall's velocity is instead an
    expression of the face's current centre and time (``exprFixedValue``, evaluated every step):
    ``U = W + P_t(V - W)`` with ``W = omega_c e_z x r`` the mesh's own velocity there and ``V`` the
    true wall velocity (a roller's orbit plus its spin about its axis, which has turned with the
    mesh by ``omega_c t``). The wall flux relative to the moving faces is then zero, as in the
    frozen rotor."""
    run_utility(case, "postProcess", "-func", "writeCellCentres", "-time", "0", log_name="writeCellCentres")
    cells = read_field(case / "0" / "C")
    for f in ("C", "Cx", "Cy", "Cz"):
        (case / "0" / f).unlink(missing_ok=True)
    np.save(case / "cell_centres.npy", cells)
    faces = {k: v for k, v in read_boundary_geometry(case).items() if not k.startswith("periodic")}
    ez = np.array([0.0, 0.0, 1.0])
    omega_c, omega_i = kin["cage_rad_s"], kin["inner_ring_rad_s"]
    motions: dict[str, tuple[np.ndarray, np.ndarray]] = {
        "inner_ring": (omega_i * ez, np.zeros(3)), "shaft": (omega_i * ez, np.zeros(3)),
        "outer_ring": (np.zeros(3), np.zeros(3)), "housing": (np.zeros(3), np.zeros(3)),
        "cage": (omega_c * ez, np.zeros(3)),
    }
    if not cage:
        del motions["cage"]
    for r in rollers:
        motions[r["name"]] = (r["omega"] * r["axis"], r["origin"])
    folder = case / "0" / "wallVelocity"
    folder.mkdir(exist_ok=True)
    missing = set(motions) ^ set(faces)
    if missing:
        raise FoamError(f"{case}: patches {sorted(missing)} have no wall motion or are not in the mesh")
    if moving_mesh:
        for name, (w, o) in motions.items():
            (folder / name).write_text(_moving_wall_expression(name, w, o, frame_rad_s,
                                                               kin["roller_spin_rad_s"], rollers))
        write_field_values(case / "0" / "U", initial_rotation_fraction * omega_c * np.cross(ez, cells))
        return
    for name, (w, o) in motions.items():
        cf, sf = faces[name]
        frame = frame_rad_s * np.cross(ez, cf)
        rel = np.cross(w, cf - o) - frame
        n = sf / np.linalg.norm(sf, axis=1)[:, None]
        u = frame + rel - n * np.einsum("ij,ij->i", rel, n)[:, None]
        rows = "\n".join(f"({x:.12g} {y:.12g} {z:.12g})" for x, y, z in u)
        (folder / name).write_text(f"type fixedValue;\nvalue nonuniform List<vector> {len(u)}\n(\n{rows}\n);\n")
    # Initial oil velocity: a fraction of the cage's rigid rotation, never exactly rest. The wall
    # fluxes balance only to round-off, and v1912's CorrectPhi/adjustPhi judges that imbalance
    # relative to the internal flux, which is zero for oil at rest (fatal error).
    if not 0.0 < initial_rotation_fraction <= 2.0:
        raise ValueError(f"initial_rotation_fraction = {initial_rotation_fraction}: expected a fraction of the "
                         "cage's speed in (0, 2]")
    write_field_values(case / "0" / "U", initial_rotation_fraction * omega_c * np.cross(ez, cells))


def _moving_wall_expression(name: str, w: np.ndarray, o: np.ndarray, omega_mesh: float, omega_spin: float,
                            rollers: list[dict[str, Any]]) -> str:
    """The ``exprFixedValue`` entry of wall ``name`` on a mesh turning at ``omega_mesh`` about z
    (see :func:`_write_wall_velocities`). A roller's true velocity is its orbit (the mesh's) plus
    its spin ``omega_spin a_k x (r - c_k)`` with its axis and centre turned with the mesh; the
    spin is evaluated at the face's position at t = 0 (``r0``, the mesh turned back) and turned
    forward. The rings, shaft and housing turn (or rest) about z: ``V = w x r``."""
    def num(x: float) -> str:
        return repr(float(x))

    def vec(v: np.ndarray) -> str:
        return f"vector({num(v[0])}, {num(v[1])}, {num(v[2])})"

    lines = [f"W = {vec([0.0, 0.0, omega_mesh])} ^ pos()", "n = face()/area()"]
    roller = next((r for r in rollers if r["name"] == name), None)
    if roller is None:
        if abs(float(np.linalg.norm(o))) > 0.0 or abs(w[0]) > 0.0 or abs(w[1]) > 0.0:
            raise ValueError(f"wall {name}: a moving mesh takes only walls turning about z or rollers")
        lines.append(f"V = {vec(w)} ^ pos()")
    else:
        c0, a0 = np.asarray(roller["centre"], float), np.asarray(roller["roller_axis"], float)
        lines += [f"th = {num(omega_mesh)}*time()", "ct = cos(th)", "st = sin(th)",
                  "r0 = vector(ct*pos().x() + st*pos().y(), -st*pos().x() + ct*pos().y(), pos().z())",
                  f"s0 = {vec(omega_spin * a0)} ^ (r0 - {vec(c0)})",
                  "V = W + vector(ct*s0.x() - st*s0.y(), st*s0.x() + ct*s0.y(), s0.z())"]
    body = " ".join(f'"{line}"' for line in lines)
    return (f"type exprFixedValue;\nvalue uniform (0 0 0);\nvariables ( {body} );\n"
            'valueExpr "W + (V - W) - n*((V - W) & n)";\n')


@dataclass
class CfdResult:
    """What :func:`run_case` measured (SI)."""

    case: Path
    point: dict[str, Any]
    torques_Nm: dict[str, dict[str, float]]
    rollers: list[dict[str, Any]]
    cage: dict[str, Any]
    power_loss_W: float
    loss_torque_at_shaft_Nm: float
    window_s: tuple[float, float]
    steady: bool
    liquid_volume: dict[str, list[float]] = field(default_factory=dict)
    runtime_s: float = 0.0
    cells: int = 0
    stopped_by: str = ""
    simulated_time: float = 0.0


class _Progress:
    """One status line about every ``every_s`` seconds: time, step, dt, Courant, residuals, ETA.

    The ETA is to the end time (``end``, simulated seconds or iterations, named in the line); a
    steady torque usually stops the run sooner, at a point no one can foresee."""

    def __init__(self, every_s: float = 5.0, stream: "TextIO | None" = None, end: str = "", monitor: "_SteadyMonitor | None" = None):
        self.every_s = every_s
        self.stream = stream if stream is not None else sys.stderr  # at call time: a redirect counts
        self.last = 0.0
        self.end = end
        self.monitor = monitor  # its steady test's state is what tells when the run ends

    def __call__(self, st: LogState, eta: float) -> None:
        now = time.monotonic()
        if now - self.last < self.every_s:
            return
        self.last = now
        res = " ".join(f"{k} {v:.1e}" for k, v in list(st.residuals.items())[:4])
        eta_txt = "?" if not math.isfinite(eta) else f"{eta / 60:.1f} min"
        if math.isfinite(st.delta_t):
            head = f"t = {st.time:.6g} s  step {st.steps}  dt {st.delta_t:.2e}  Co {st.courant_max:.2f}"
        else:
            head = f"iteration {st.time:.0f}"
        to = f" to {self.end}" if self.end else ""
        status = self.monitor.status if self.monitor is not None and self.monitor.tol > 0.0 else ""
        if status:
            # a steady torque ends the run, usually long before the end time: say how far the
            # steady test is, and give the end time's ETA as the latest end
            print(f"cfd: {head}  {res}  {status}; at the latest{to}, ETA {eta_txt}", file=self.stream, flush=True)
        else:
            print(f"cfd: {head}  {res}  ETA{to} {eta_txt}", file=self.stream, flush=True)


class _SteadyMonitor:
    """Stops a run when the torques are (statistically) steady.

    Flooded (steady solver), from iteration :attr:`FLOODED_MIN_ITERATIONS` on: the loss torque
    at the shaft passes the three-window test below with windows of
    :attr:`FLOODED_WINDOW_ITERATIONS` iterations, and each wall's torque about the axis (inner
    ring, shaft, outer ring, housing, cage, the rollers' moments) changes and is still to change
    by at most the tolerance times the inner ring's. Every wall, the resting ones too: the
    housing's torque is the side chambers' spin-up, the slowest part of a flooded run (from oil
    at rest it still moved by 5 % of the drive per window at iteration 1000 on the 6-cell
    sectors, and the wall torques' balance with it; benchmarks/cfd_flooded_convergence.py).
    The balance itself is reported, not tested: at a converged state what is left is the
    scheme's (-0.5 % and -3.5 % on the default sector's two steady states, one per start, see
    :data:`FLOODED_INITIAL_ROTATION_FRACTION`). Window means, not the spread within a window: SIMPLE on the sector can carry an
    iteration-to-iteration oscillation of the outer ring's torque (about ±5 % of it) that
    averages out. The test must hold over :attr:`FLOODED_HOLD_ITERATIONS`. Oil bath (transient):
    the loss torque at the shaft (every body, :func:`loss_torque_series`) over three windows of
    ``window_s``; steady when the change still to come, extrapolated from them
    (:func:`~kegel.cfd_cases.steady.steady_drift`), and the last window-to-window change are both
    within the tolerance, and not before ``min_time_s`` (the run's own simulated time; see
    :data:`STEADY_MIN_CAGE_REVOLUTIONS_FROM_REST`). The result is then the mean over the last window.

    The force files are read every few seconds of wall time, but the test is applied at fixed
    points of the run (every :attr:`CHECK_ITERATIONS` iterations, every ``window_s /``
    :attr:`CHECK_PER_WINDOW` of simulated time) to the series up to that point, each point once
    (:class:`~kegel.cfd_cases.steady.SteadyTest`). The averaging window and what a run reports
    therefore do not depend on how fast the machine is or what else runs on it; the solver itself
    stops at the next read after the passing point, a few milliseconds later, so a finer run
    started from this one maps the regular write before the passing point instead of the last
    state (:func:`_restart_state`).
    """

    BODIES = BALANCE_WALLS
    CHECK_ITERATIONS = 10
    CHECK_PER_WINDOW = 20

    def __init__(self, case: Path, flooded: bool, window_s: float, tol: float, meta: dict | None = None,
                 min_time_s: float = 0.0, hold_s: float = 0.0):
        self.case, self.flooded, self.window_s, self.tol, self.meta = case, flooded, window_s, tol, meta
        self.min_time_s = min_time_s  # oil bath: no steady verdict before this (own simulated time)
        self.last_check = 0.0
        self.every_s = 3.0 if flooded else 15.0  # the oil bath reads every body's forces
        self.step = float(self.CHECK_ITERATIONS) if flooded else window_s / self.CHECK_PER_WINDOW
        self.checked_until = -math.inf  # the test has been applied at the check points up to here
        self.test = SteadyTest(window_s, tol, hold=hold_s)  # check points start at min_time_s
        self.window: tuple[float, float] | None = None
        self.flooded_since: float | None = None  # flooded: first check point of the current passes
        #: the steady test's state in words, for the progress line
        self.status = (f"steady test from iteration {self.FLOODED_MIN_ITERATIONS:.0f}" if flooded else
                       f"steady test from t = {min_time_s:.3g} s (own time)")

    def _check_points(self, t_end: float, t_min: float) -> np.ndarray:
        """The check points in (checked_until, t_end] from t_min on (multiples of the step)."""
        lo = max(self.checked_until, t_min - 1e-12 * abs(t_min))
        k0 = math.floor(lo / self.step) + 1
        k1 = math.floor(t_end / self.step * (1 + 1e-12))
        self.checked_until = max(self.checked_until, t_end)
        return self.step * np.arange(k0, k1 + 1, dtype=float) if k1 >= k0 else np.empty(0)

    def __call__(self, st: LogState) -> bool:
        now = time.monotonic()
        if self.tol <= 0.0 or now - self.last_check < self.every_s:  # tol 0: run to the end
            return False
        self.last_check = now
        try:
            if self.flooded:
                return self._flooded()
            t, loss = loss_torque_series(self.case, self.meta)
        except FoamError:
            return False
        if len(t) == 0:
            return False
        ts = self.test.update(t, loss, self._check_points(float(t[-1]), self.min_time_s))
        if ts is None:
            drift = steady_drift(t, loss, self.window_s)
            if drift is not None and t[-1] >= self.min_time_s:
                scale = max(abs(drift.estimate), 1e-300)
                d2 = abs(drift.means[2] - drift.means[1])
                worst = max(abs(drift.remaining), d2) / (self.tol * scale)
                self.status = (f"loss {1e3 * drift.estimate:.3g} mN m, change {worst:.1f} x the steady limit"
                               if math.isfinite(worst) else f"loss {1e3 * drift.means[2]:.3g} mN m, still drifting")
            return False
        self.window = (ts - self.window_s, ts)
        return True

    def _flooded(self) -> bool:
        t, loss = loss_torque_series(self.case, self.meta)
        if len(t) == 0:
            return False
        forces = {b: _forces(self.case, b) for b in self.BODIES}
        series = {b: (f.time, f.moment_total[:, 2]) for b, f in forces.items()}
        series["rollers about the axis"] = (t, self._rollers_about_axis(t))
        w = self.FLOODED_WINDOW_ITERATIONS
        for n in self._check_points(float(t[-1]), self.FLOODED_MIN_ITERATIONS):
            k = int(np.searchsorted(t, n, side="right"))
            ml = window_means(t[:k], loss[:k], w, 3)
            if ml is None:
                continue
            d = drift_of_means(ml, (0.0, 0.0), self.FLOODED_BODY_RESOLUTION * self.tol * abs(float(ml[2])))
            lo = int(np.searchsorted(t, t[k - 1] - w, side="right"))
            drive = abs(float(forces["inner_ring"].moment_total[lo:k, 2].mean()))
            # each body's torque about the axis (the split, and the rollers' orbit drag the
            # coupling uses): its change within tol of the drive torque
            worst_body = 0.0
            for tb, yb in series.values():
                mb = window_means(tb[:k], yb[:k], w, 3)
                if mb is None:
                    worst_body = math.inf
                    continue
                # a creep slower than FLOODED_BODY_RESOLUTION tolerances per window counts as
                # scatter (a cage torque creeping by 0.2 % of the drive over 400 iterations
                # would otherwise hold the run for ever)
                db = drift_of_means(mb, (0.0, 0.0), self.FLOODED_BODY_RESOLUTION * self.tol * drive)
                change = max(abs(db.remaining), abs(db.means[2] - db.means[1]))
                worst_body = max(worst_body, change / max(self.tol * drive, 1e-300))
            d2 = abs(d.means[2] - d.means[1])
            worst_loss = max(abs(d.remaining), d2) / max(self.tol * abs(d.estimate), 1e-300)
            imbalance = self._imbalance(lo, k)
            # the last window's mean (the extrapolated estimate swings wildly when the means turn)
            # the whole bearing's loss (a sector's times its copies), as results.json reports it
            copies = ((self.meta or {}).get("geometry") or {}).get("copies", 1)
            self.status = (f"loss {1e3 * copies * float(ml[2]):.3g} mN m, change {max(worst_loss, worst_body):.1f} x the "
                           f"steady limit, balance " + ("?" if imbalance is None else f"{100 * imbalance:+.1f} %"))
            if not (worst_loss <= 1.0 and worst_body <= 1.0):
                self.flooded_since = None
                continue
            self.flooded_since = n if self.flooded_since is None else self.flooded_since
            if n - self.flooded_since >= self.FLOODED_HOLD_ITERATIONS:
                self.window = (float(t[k - 1] - w), float(t[k - 1]))
                return True
        return False

    #: flooded: the window of the steady test in iterations (three of them: steady_drift), and no
    #: verdict before this many iterations
    FLOODED_WINDOW_ITERATIONS = 100.0
    FLOODED_MIN_ITERATIONS = 300.0
    #: flooded: the test must pass at every check point over this many iterations (one window:
    #: the rollers' and the outer ring's torques pause and drift again; replayed on the stored
    #: histories, 300 would stop the whole bearing's tiny case only at its 600-iteration limit)
    FLOODED_HOLD_ITERATIONS = 100.0
    #: flooded: a loss (body) torque whose window means move one way by less than this many
    #: tolerances times the loss (drive) torque per window scatters, it does not drift
    FLOODED_BODY_RESOLUTION = 0.1

    def _rollers_about_axis(self, t: np.ndarray) -> np.ndarray:
        """The rollers' orbit moments at times ``t`` (:func:`rollers_about_axis`). Flat ring and
        cage torques alone passed the g = 0.02 D_w gap-study case at iteration 264 while the oil
        between the rollers was still spinning up (the wall torques' balance moving from -23 %
        towards -7 %): the rollers' share must hold too."""
        return rollers_about_axis(self.case, self.meta or {}, t)

    def _imbalance(self, lo: int, hi: int) -> float | None:
        """The angular-momentum balance over the samples ``lo:hi`` of the force files: (mean sum of
        every wall's torque about the bearing axis, rollers' orbit moments included) / |mean drive
        torque| (inner ring and shaft); None when a force file is missing or too short. The
        sector's periodic sides carry no net angular momentum, so its ratio is the bearing's."""
        try:
            bodies = [_forces(self.case, b) for b in BALANCE_WALLS]
            rollers = [(_forces(self.case, r["name"]), np.array(r["centre_m"]))
                       for r in (self.meta or {}).get("rollers", [])]
        except (FoamError, OSError):
            return None
        if not rollers or any(len(f.time) < hi for f in bodies) or any(len(f.time) < hi for f, _ in rollers):
            return None
        t = {b: {"total": float(f.moment_total[lo:hi, 2].mean())} for b, f in zip(BALANCE_WALLS, bodies)}
        orbit = 0.0
        for f, c in rollers:
            F, M = f.force_total[lo:hi].mean(axis=0), f.moment_total[lo:hi].mean(axis=0)
            orbit += float(np.cross(c, F)[2] + M[2])
        t["rollers_about_bearing_axis"] = {"total": orbit}
        # no gravity: the flooded monitor's cases have none (results.json's balance has the same formula)
        return angular_momentum_balance(t)["relative_to_drive_torque"]


def _case_meta(case: Path) -> dict[str, Any]:
    """The case's kegel-case.json ({} without one)."""
    meta = case / "kegel-case.json"
    return json.loads(meta.read_text()) if meta.is_file() else {}


def mesh_rotation_rad_s(meta: dict[str, Any]) -> float:
    """The speed (rad/s) at which the case's mesh turns about z (``frame = "moving_mesh"``: the
    cage's); 0 for a static mesh. At time t the mesh has turned by this times t."""
    return float(meta.get("mesh_motion_rad_s") or 0.0)


def _to_initial_position(f: ForceSeries, omega: float, centre: np.ndarray) -> ForceSeries:
    """A body that turns with the mesh at ``omega`` about z: its forces and its moments about its
    own (turning) centre, expressed where the body stood at t = 0. The forces function object
    takes moments about the fixed point ``centre`` (the body's centre at t = 0); about the
    turned centre ``c(t)`` the moment is ``M - (c(t) - centre) x F``."""
    th = omega * f.time
    cos, sin = np.cos(th), np.sin(th)
    shift = np.column_stack([cos * centre[0] - sin * centre[1], sin * centre[0] + cos * centre[1],
                             np.full_like(th, centre[2])]) - centre

    def back(v: np.ndarray) -> np.ndarray:
        return np.column_stack([cos * v[:, 0] + sin * v[:, 1], -sin * v[:, 0] + cos * v[:, 1], v[:, 2]])

    def moment(m: np.ndarray, force: np.ndarray) -> np.ndarray:
        return back(m - np.cross(shift, force))

    return ForceSeries(f.time, back(f.force_total), back(f.force_pressure), back(f.force_viscous),
                       moment(f.moment_total, f.force_total), moment(f.moment_pressure, f.force_pressure),
                       moment(f.moment_viscous, f.force_viscous))


def _forces(case: Path, name: str) -> ForceSeries:
    """The force history of body ``name``; the cage of a case built without it (its
    kegel-case.json says so, not a missing force file: a caged case without its cage forces is
    an error, never a zero) has none: zero forces at the inner ring's times. On a moving mesh
    the cage's and the rollers' forces are taken back to where each stood at t = 0 (see
    :func:`_to_initial_position`), so that every reading of a frozen rotor applies."""
    name = name.removeprefix("forces_")
    meta = _case_meta(case)
    if name == "cage" and meta.get("point", {}).get("cage", True) is False:
        ref = read_forces(case, "forces_inner_ring")
        z = np.zeros_like(ref.force_total)
        return ForceSeries(ref.time, z, z, z, z, z, z)
    f = read_forces(case, f"forces_{name}")
    omega = mesh_rotation_rad_s(meta)
    if omega != 0.0:
        centres = {r["name"]: np.array(r["centre_m"], dtype=float) for r in meta.get("rollers", [])}
        if name == "cage" or name in centres:
            f = _to_initial_position(f, omega, centres.get(name, np.zeros(3)))
    return f


def _turning_walls(kin: dict[str, float]) -> dict[str, float]:
    """The walls that turn about the bearing axis, and their speeds (rad/s)."""
    return {"inner_ring": kin["inner_ring_rad_s"], "shaft": kin["inner_ring_rad_s"], "cage": kin["cage_rad_s"]}


def _roller_motion(roller: dict[str, Any], kin: dict[str, float]) -> tuple[np.ndarray, np.ndarray]:
    """A roller's centre velocity (its orbit) and absolute angular velocity (orbit plus spin)."""
    ez = np.array([0.0, 0.0, 1.0])
    c, a = np.array(roller["centre_m"]), np.array(roller["axis"])
    return kin["cage_rad_s"] * np.cross(ez, c), kin["cage_rad_s"] * ez + kin["roller_spin_rad_s"] * a


def rollers_about_axis(case: Path, meta: dict, t: np.ndarray) -> np.ndarray:
    """The rollers' moments about the bearing axis (their orbit drag), summed over the rollers
    of the case (a sector's: times its copies for the bearing), at times ``t``."""
    out = np.zeros_like(t, dtype=float)
    for r in meta.get("rollers", []):
        f = _forces(case, r["name"])
        mz = np.cross(np.array(r["centre_m"]), f.force_total)[:, 2] + f.moment_total[:, 2]
        out += np.interp(t, f.time, mz)
    return out


def wall_torque_series(case: Path, meta: dict) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    """Every wall's torque about the bearing axis from the oil over time (N m, at the inner
    ring's sample times): the rings, shaft, housing and cage, and the rollers' orbit moments
    summed (``rollers_about_bearing_axis``). In a steady state their sum is the moment of the
    fluid's weight (zero without gravity); see :func:`angular_momentum_balance`."""
    t = read_forces(case, "forces_inner_ring").time
    out = {}
    for name in BALANCE_WALLS:
        f = _forces(case, name)
        out[name] = np.interp(t, f.time, f.moment_total[:, 2])
    out["rollers_about_bearing_axis"] = rollers_about_axis(case, meta, t)
    return t, out


def loss_torque_series(case: Path, meta: dict) -> tuple[np.ndarray, np.ndarray]:
    """The hydraulic loss torque at the shaft over time: the power the moving walls (rings,
    shaft, cage, and each roller's orbit and spin) put into the oil, divided by the shaft
    speed. It is linear in the forces, so its mean over a window is the loss of the mean forces."""
    kin = meta["kinematics"]
    t = read_forces(case, "forces_inner_ring").time
    power = np.zeros_like(t)
    for name, w in _turning_walls(kin).items():
        f = _forces(case, name)
        power -= w * np.interp(t, f.time, f.moment_total[:, 2])
    for r in meta["rollers"]:
        f = _forces(case, r["name"])
        v_c, w_abs = _roller_motion(r, kin)
        power -= np.interp(t, f.time, f.force_total @ v_c + f.moment_total @ w_abs)
    return t, power / abs(kin["inner_ring_rad_s"])


def run_case(point: CfdPoint, case_dir: str | Path, *, log: Callable[[str], None] = print,
             progress: bool = True) -> CfdResult:
    """Prepare (or resume) and run the case of ``point``; write ``results.json`` into it."""
    from kegel.base.io import atomic_write_json, provenance

    case = prepare_case(point, case_dir, log=log)
    meta = json.loads((case / "kegel-case.json").read_text())
    kin = meta["kinematics"]
    solver = "simpleFoam" if point.flooded else "interFoam"
    window = steady_window_s(kin["cage_rad_s"])
    min_time = max(0.0, steady_min_time_s(kin["cage_rad_s"]) - time_from_rest_at_start_s(meta))
    monitor = _SteadyMonitor(case, point.flooded, window, point.steady_tolerance, meta, min_time_s=min_time,
                             hold_s=STEADY_HOLD_WINDOWS * window)
    end = float(controldict_value(case, "endTime"))
    log(f"cfd: running {solver} on {point.n_procs} core(s) in {case}")
    t0 = time.monotonic()
    budget_hit = {"hit": False}

    def stop_when(st: LogState) -> bool:
        if monitor(st):
            return True
        if point.max_wall_time_s is not None and time.monotonic() - t0 > point.max_wall_time_s:
            budget_hit["hit"] = True
            log(f"cfd: wall-time budget of {point.max_wall_time_s:.0f} s reached at t = {st.time:g}; stopping")
            return True
        return False

    summary = run_solver(case, solver, n_procs=point.n_procs, end_time=end,
                         progress=_Progress(end=f"iteration {end:.0f}" if point.flooded else f"t = {end:g} s",
                                            monitor=monitor, every_s=5.0 if sys.stderr.isatty() else 30.0)
                         if progress else None, stop_when=stop_when,
                         max_courant=max(25.0, 5.0 * point.max_courant) if not point.flooded else 1e30)
    runtime = time.monotonic() - t0
    if point.n_procs > 1 and time_dirs(case / "processor0"):
        run_utility(case, "reconstructPar", "-latestTime")
    restart = None
    if monitor.window is not None:  # a steady stop: the state a finer run maps (flooded: an iteration)
        restart = _restart_state(case, point.n_procs, monitor.window[1])
    result = _postprocess(case, point, meta, monitor.window, window)
    result.stopped_by = ("steady torque" if monitor.window is not None else
                         "wall-time budget" if budget_hit["hit"] else "end time / iteration limit")
    # a resumed run that had nothing left to do logs no time step: the case's latest time counts
    written = time_dirs(case)
    result.simulated_time = max(float(summary.state.time), float(written[-1].name) if written else 0.0)
    result.runtime_s = runtime + meta.get("runtime_before_s", 0.0)
    meta["runtime_before_s"] = result.runtime_s
    (case / "kegel-case.json").write_text(json.dumps(meta, indent=2))
    fidelity = {"mesh": point.mesh, "cells": result.cells, "solver": solver, "n_procs": point.n_procs,
                "steady_tolerance": point.steady_tolerance}
    if not point.flooded:
        fidelity.update(max_courant=point.max_courant, max_interface_courant=point.max_interface_courant,
                        initial_state=meta.get("initial_state"))
    elif meta.get("initial_state") is not None:
        fidelity["initial_state"] = meta["initial_state"]
    out = {"provenance": provenance(), "fidelity": fidelity,
           "point": result.point, "kinematics": kin, "runtime_s": result.runtime_s,
           "torques_Nm": result.torques_Nm, "power_loss_W": result.power_loss_W,
           "loss_torque_at_shaft_Nm": result.loss_torque_at_shaft_Nm,
           # the films thinner than the CFD's clearance, as analytic terms (thin_films); the CFD's
           # own numbers above are unchanged
           **thin_film_fields(result.loss_torque_at_shaft_Nm, thin_film_json(point, meta)),
           "averaging_window": list(result.window_s), "steady": result.steady,
           "stopped_by": result.stopped_by,
           **({} if restart is None else {"restart_state_time_s": restart}),
           "simulated_time_s" if not point.flooded else "iterations": result.simulated_time,
           "rollers": result.rollers, "cage": result.cage, "liquid_volume": result.liquid_volume,
           "angular_momentum_balance": angular_momentum_balance(result.torques_Nm, None if point.flooded else
                                                fluid_gravity_torque(case, meta, result.window_s, point.n_procs)),
           **({} if point.flooded else {"loss_torque_drift": _drift_json(
               case, meta, window, until=monitor.window[1] if monitor.window is not None else None)}),
           "mesh_quality": meta["mesh"], "sign_convention": "moments about +z (bearing axis) acting "
           "on the body from the oil; power_loss_W = -(sum over moving bodies of F.v + M.omega)"}
    atomic_write_json(case / "results.json", out)
    return result


def refresh_thin_films(case_dir: str | Path) -> dict[str, Any]:
    """Evaluate the thin-film terms of a finished case again (after a change of the thin-film
    model) and rewrite its ``results.json``; the CFD's own figures are left as they are.

    Raises
    ------
    FoamError
        ``case_dir`` holds no finished ``kegel cfd run`` case (``kegel-case.json`` and
        ``results.json``).
    """
    from kegel.base.io import atomic_write_json

    case = Path(case_dir)
    meta_path, res_path = case / "kegel-case.json", case / "results.json"
    if not (meta_path.is_file() and res_path.is_file()):
        raise FoamError(f"{case}: expected a finished kegel cfd case (kegel-case.json and results.json)")
    meta = json.loads(meta_path.read_text())
    data = json.loads(res_path.read_text())
    names = {f.name for f in fields(CfdPoint)}
    raw = {k: v for k, v in meta.get("point", {}).items() if k in names}
    point = CfdPoint(**{k: tuple(v) if isinstance(v, list) else v for k, v in raw.items()})
    data.update(thin_film_fields(data["loss_torque_at_shaft_Nm"], thin_film_json(point, meta)))
    atomic_write_json(res_path, data)
    return data


def thin_film_fields(cfd_loss_Nm: float, thin: dict[str, Any]) -> dict[str, Any]:
    """The thin-film keys of ``results.json`` for a CFD loss and its :func:`thin_film_json`."""
    return {"thin_film_loss_Nm": thin["loss_torque_Nm"], "thin_films": thin,
            "loss_torque_at_shaft_with_thin_films_Nm": cfd_loss_Nm + thin["loss_torque_Nm"]}


def thin_film_json(point: CfdPoint, meta: dict[str, Any]) -> dict[str, Any]:
    """The analytic terms of the films thinner than the CFD's clearance ``c`` (roller end / rib,
    cage pockets; :func:`kegel.cfd_cases.thin_films.thin_film_losses`) for ``results.json``. An
    oil bath's terms are the full films' times each film's supply factor
    (:func:`kegel.cfd_cases.thin_films.oil_bath_film_factors`, written as ``supply``)."""
    from .thin_films import thin_film_losses

    bearing, g, _ = _load(point)
    c = meta.get("geometry", {}).get("clearance_m")
    if c is None:
        c = cfd_geometry(g, housing_clearance_m=point.housing_clearance_m, gap_ratio=point.gap_ratio,
                         clearance_ratio=point.clearance_ratio).clearance_m
    return thin_film_losses(g, bearing, lubricant=point.lubricant, temperature_K=point.temperature_K,
                            inner_speed_rad_s=abs(point.speed_rad_s), clearance_m=float(c), material=point.material,
                            oil_level_m=None if point.flooded else point.oil_level_m)


def last_write_at_or_before(times: list[Path], t_s: float) -> Path | None:
    """The latest of the time folders ``times`` (in time order) at or before ``t_s`` (to the
    written precision), or ``None``."""
    best = None
    for d in times:
        if float(d.name) <= t_s * (1 + 1e-9):
            best = d
    return best


def _restart_state(case: Path, n_procs: int, stop_s: float) -> float | None:
    """The state a run started from this one maps (``--start-on``, ``initial_from``): the last
    regular write (every shaft revolution) at or before the end of the averaging window.

    The solver stops at the next read of the force files after the passing check point, which
    depends on the machine's speed and load; the regular write before that point does not (the
    trajectories of two runs of a case are identical), so neither does the start of a finer run.
    Reconstructed here when the run was parallel. ``None`` when there is no such write yet."""
    src = case / "processor0" if n_procs > 1 and (case / "processor0").is_dir() else case
    found = last_write_at_or_before([d for d in time_dirs(src) if (d / "U").is_file()], stop_s)
    if found is None:
        return None
    if src != case and not (case / found.name / "U").is_file():
        run_utility(case, "reconstructPar", "-time", found.name, log_name="reconstructPar.restart")
    return float(found.name)


def angular_momentum_balance(t: dict[str, dict[str, float]], gravity: dict[str, Any] | None = None) -> dict[str, Any]:
    """The angular-momentum balance about the bearing axis. In a steady state the oil's angular
    momentum is constant, so the torques the walls take from the oil sum to the moment of the
    fluid's weight (zero without gravity, flooded; in an oil bath the flow holds the oil up on one
    side: 32208, 500 rpm, tiny mesh, its centre of mass 5-6 mm off the axis, +2 mN m, as large as
    the drive torque). ``relative_to_drive_torque`` is (sum of wall torques - weight's moment) /
    |drive torque|."""
    total = sum(t[k]["total"] for k in (*BALANCE_WALLS, "rollers_about_bearing_axis"))
    drive = abs(t["inner_ring"]["total"] + t["shaft"]["total"])
    weight = 0.0 if gravity is None else gravity["torque_Nm"]
    out: dict[str, Any] = {"sum_of_wall_torques_Nm": total}
    if gravity is not None:
        out["weight_moment_on_fluid_Nm"] = weight
        out["weight_moment_states_s"] = gravity["states_s"]
    # None (never NaN: results.json is strict JSON) where the balance cannot be evaluated
    if weight is None:
        out["relative_to_drive_torque"] = None
        out["not_evaluated"] = "no oil distribution written yet (the run is shorter than a shaft revolution)"
    elif not drive:
        out["relative_to_drive_torque"] = None
        out["not_evaluated"] = "no drive torque"
    else:
        out["relative_to_drive_torque"] = (total - weight) / drive
    return out


def fluid_gravity_torque(case: Path, meta: dict[str, Any], window: tuple[float, float], n_procs: int) -> dict[str, Any]:
    """The moment of the fluid's weight about the bearing axis (oil and air, SI), the mean over
    the written states in the averaging ``window`` (fields are written every shaft revolution;
    with none inside it, the last one before its end, else the first after it).

    Returns ``{"torque_Nm": ..., "states_s": [...]}``; ``torque_Nm`` is None when no state is
    written (the balance then says so instead of passing)."""
    src = case / "processor0" if n_procs > 1 and (case / "processor0").is_dir() else case
    written = [d for d in time_dirs(src) if float(d.name) > 0.0 and (d / "alpha.oil").is_file()]
    inside = [d for d in written if window[0] <= float(d.name) <= window[1] * (1 + 1e-9)]
    if not inside:
        # none inside: the last one before its end, else the first after it (a run shorter than a
        # shaft revolution writes its state only at its end, a few force samples after the window)
        last = last_write_at_or_before(written, window[1])
        after = [d for d in written if float(d.name) > window[1]]
        inside = [last] if last is not None else after[:1]
    if not inside:
        return {"torque_Nm": None, "states_s": []}
    volumes = case / "cell_volumes.npy"
    if not volumes.is_file():
        run_utility(case, "postProcess", "-func", "writeCellVolumes", "-time", "0", log_name="writeCellVolumes")
        np.save(volumes, read_field(case / "0" / "V"))
        (case / "0" / "V").unlink(missing_ok=True)
    V = np.load(volumes)
    C = np.load(case / "cell_centres.npy")
    g_text = (case / "constant" / "g").read_text()
    g = np.array(g_text[g_text.index("(", g_text.index("value")) + 1:g_text.index(")", g_text.index("value"))].split(),
                 dtype=float)
    rho_oil = float(meta["lubricant"]["density_kg_m3"])
    torques = []
    for d in inside:
        if not (case / d.name / "alpha.oil").is_file():
            run_utility(case, "reconstructPar", "-time", d.name, log_name="reconstructPar.weight")
        alpha = np.clip(read_field(case / d.name / "alpha.oil"), 0.0, 1.0)
        m = (alpha * rho_oil + (1.0 - alpha) * AIR_DENSITY_KG_M3) * V
        c = C @ _rotation_z(mesh_rotation_rad_s(meta) * float(d.name)).T  # a moving mesh has turned
        torques.append(float(np.sum(m * (c[:, 0] * g[1] - c[:, 1] * g[0]))))
    return {"torque_Nm": float(np.mean(torques)), "states_s": [float(d.name) for d in inside]}


def _drift_json(case: Path, meta: dict, window_s: float, until: float | None = None) -> dict[str, Any]:
    """How far the oil bath's loss torque is from its steady value (see kegel.cfd_cases.steady),
    from the series up to ``until`` (the point the steady test passed at; default: the end)."""
    rest = {"window_s": window_s, "time_from_rest_at_start_s": time_from_rest_at_start_s(meta),
            "min_time_from_rest_s": steady_min_time_s(meta["kinematics"]["cage_rad_s"])}
    t, loss = loss_torque_series(case, meta)
    if until is not None:
        rest["until_s"] = until
        keep = t <= until * (1 + 1e-12)
        t, loss = t[keep], loss[keep]
    d = steady_drift(t, loss, window_s)
    if d is None:
        return {**rest, "note": "run shorter than three windows: no estimate"}
    finite = math.isfinite(d.remaining)
    return {**rest, "window_means_Nm": list(d.means),
            "estimated_steady_Nm": d.estimate if finite else None,
            "remaining_change_Nm": d.remaining if finite else None,
            "note": "extrapolated from three window means" if finite else
                    "the drift does not slow down: no estimate of the steady value"}


def _postprocess(case: Path, point: CfdPoint, meta: dict, window, window_s: float) -> CfdResult:
    kin = meta["kinematics"]
    turning = _turning_walls(kin)
    f_ir = read_forces(case, "forces_inner_ring")
    t = f_ir.time
    if window is None:
        # not steady: average over the last 10 % of the iterations (flooded), or over the last
        # window of the steady test when the run lasted three, else over the last 20 % of the time
        if point.flooded:
            span = 0.1 * (t[-1] - t[0])
        else:
            span = window_s if t[-1] - t[0] >= 3 * window_s else 0.2 * (t[-1] - t[0])
        window = (float(max(t[-1] - span, t[0])), float(t[-1]))
        steady = False
    else:
        steady = True

    def mean(series: np.ndarray, times: np.ndarray) -> np.ndarray:
        sel = (times >= window[0]) & (times <= window[1])
        if not sel.any():
            sel = times == times[-1]
        return series[sel].mean(axis=0)

    # a sector holds 1/copies of the oil space: the whole bearing's torques about the axis are
    # copies times the sector's, its resultant forces on the rings and cage vanish by symmetry,
    # and its rollers are the modelled one turned round by the roller pitch
    copies = int(meta.get("geometry", {}).get("copies", 1))
    ez = np.array([0.0, 0.0, 1.0])

    def whole(v: np.ndarray) -> np.ndarray:
        return v if copies == 1 else copies * float(v[2]) * ez

    torques = {}
    power = 0.0
    for name in ("inner_ring", "outer_ring", "cage", "shaft", "housing"):
        f = _forces(case, name)
        mz = {"total": copies * float(mean(f.moment_total[:, 2], f.time)),
              "pressure": copies * float(mean(f.moment_pressure[:, 2], f.time)),
              "viscous": copies * float(mean(f.moment_viscous[:, 2], f.time))}
        torques[name] = mz
        power -= mz["total"] * turning.get(name, 0.0)
    rollers = []
    spin_sum = {"total": 0.0, "pressure": 0.0, "viscous": 0.0}
    for r in meta["rollers"]:
        f = _forces(case, r["name"])
        F0 = mean(f.force_total, f.time)
        M0 = mean(f.moment_total, f.time)
        Mp0, Mv0 = mean(f.moment_pressure, f.time), mean(f.moment_viscous, f.time)
        for j in range(copies):
            rot = _rotation_z(2.0 * math.pi * j / copies)
            F, M = rot @ F0, rot @ M0
            a = rot @ np.array(r["axis"])
            c = rot @ np.array(r["centre_m"])
            name = r["name"] if copies == 1 else roller_name(j)
            v_c, w_abs = _roller_motion({"centre_m": c, "axis": a}, kin)
            p_k = float(F @ v_c + M @ w_abs)
            power -= p_k
            spin = {"total": float(M @ a), "pressure": float((rot @ Mp0) @ a), "viscous": float((rot @ Mv0) @ a)}
            for k in spin_sum:
                spin_sum[k] += spin[k]
            # the orbiting drag of the roller: its force's moment about the bearing axis (plus its own z moment)
            orbit_mz = float(np.cross(c, F)[2] + M[2])
            rollers.append({"name": name, "force_N": F.tolist(), "moment_about_centre_Nm": M.tolist(),
                            "spin_torque_Nm": spin, "moment_about_bearing_axis_Nm": orbit_mz,
                            "power_W": -p_k, **({} if copies == 1 else {"from": r["name"]})})
    torques["rollers_about_bearing_axis"] = {"total": float(sum(r["moment_about_bearing_axis_Nm"] for r in rollers))}
    torques["rollers_spin_sum"] = spin_sum
    f_cage = _forces(case, "cage")
    cage = {"force_N": whole(mean(f_cage.force_total, f_cage.time)).tolist(),
            "moment_Nm": whole(mean(f_cage.moment_total, f_cage.time)).tolist()}
    volume = {}
    vol_file = case / "postProcessing" / "liquidVolume"
    if vol_file.is_dir():
        volume = _read_liquid_volume(vol_file)
    cells = int(meta["mesh"]["cells"])
    return CfdResult(case=case, point=meta["point"], torques_Nm=torques, rollers=rollers, cage=cage,
                     power_loss_W=power, loss_torque_at_shaft_Nm=power / abs(kin["inner_ring_rad_s"]),
                     window_s=window, steady=steady, liquid_volume=volume, cells=cells)


def _rotation_z(angle: float) -> np.ndarray:
    """The rotation matrix about the bearing axis (z) by ``angle``."""
    c, s_ = math.cos(angle), math.sin(angle)
    return np.array([[c, -s_, 0.0], [s_, c, 0.0], [0.0, 0.0, 1.0]])


def _read_liquid_volume(root: Path) -> dict[str, list[float]]:
    times, vols = [], []
    for d in sorted((p for p in root.iterdir() if p.is_dir()), key=lambda p: float(p.name)):
        for f in d.glob("*.dat"):
            for line in f.read_text().splitlines():
                if line.startswith("#") or not line.strip():
                    continue
                parts = line.split()
                times.append(float(parts[0]))
                vols.append(float(parts[1]))
    order = np.argsort(times)
    return {"time_s": [times[i] for i in order], "volume_m3": [vols[i] for i in order]}
