"""gmsh geometry and mesh of a tapered roller bearing's oil space, from kegel's bearing data.

One source of truth: every dimension comes from :func:`kegel.geometry.derive_geometry` of the
bearing's data file; the CFD-only choices below are named, with their reasons.

Frames and units: SI; OpenFOAM's ``z`` is the bearing axis with ``z = 0`` at the cup back face
and ``z = T`` at the cone back face (kegel.geometry's ``x``); ``y`` points up (gravity ``-y``).

Solids (cut out of the fluid):

- cup (outer ring): revolved section between its raceway cone and the housing bore ``D/2``,
  over ``0 <= z <= C``, the raceway **set back by the contact gap g** along its normal;
- cone (inner ring): revolved section with the raceway (set back by ``g``), the large rib (face
  through the rib contact point, set back by the clearance ``c``; top at kegel.geometry's rib top
  point) and a small rib (height ``SMALL_RIB_RATIO`` of the small-end roller radius, its face
  parallel to the roller's small end and ``c`` from it: an assumption, the paper gives no small
  rib), bore ``d/2`` on the shaft;
- rollers: the **real** truncated cones on their axes (nominal diameter and length), so their
  surfaces move as the real ones. A CFD mesh cannot resolve the line contacts (zero film
  thickness at this scale): the contact model owns the film below ``g`` (its rolling force is cut
  off where the film reaches ``g``, ``model.contact_film_limit``), the CFD everything beyond, so
  the rings are set back by ``g = gap_ratio * D_w``. The gap study
  (``benchmarks/cfd_gap_study.py``) varies ``g``; the mesh puts ``CELLS_ACROSS_GAP`` cells
  across its narrowest point. The flat large end replaces the spherical one (R_e = 139 mm for the
  32208: 0.1 um of crown over the end face). The roller end / rib film (tens of micrometres)
  and the real pocket clearance (0.01 D_w per side, half the data's total) are opened to the clearance ``c = clearance_ratio *
  D_w`` (0.08 D_w by default; at least the real pocket clearance);
- cage: a pressed-steel window cage as a conical shell parallel to the roller axes, its
  mid-surface ``CAGE_OFFSET_RATIO * D_w`` outside the roller axes (toward the cup, as in
  pressed-steel TRB cages), thickness ``CAGE_THICKNESS_RATIO * D_w``, extending
  ``CAGE_OVERHANG_RATIO * L`` beyond the roller ends (the side rings); pockets are the roller
  cones grown by ``c``, so every roller is ``c`` from its pocket walls;
- housing: a closed cylinder of the housing bore ``D/2`` from ``z = -s`` to ``T + s`` (side walls
  at ``s`` = ``housing_clearance_m``, default ``HOUSING_CLEARANCE_RATIO * T``), shaft ``d/2``
  through it.

Patches: ``inner_ring`` (cone surfaces), ``shaft``, ``outer_ring`` (cup), ``housing``, ``cage``,
``roller_00`` ... ``roller_NN`` (roller k at azimuth ``2 pi k / Z``, roller 0 at the bottom,
``-y``, where an oil bath wets it first).

Sector (``sector=True``, flooded only): one roller pitch centred on roller 0, its sides
``periodic_lo`` / ``periodic_hi`` a rotational ``cyclicAMI`` pair. In the cage frame the flooded
flow repeats from pocket to pocket (no gravity in a single-phase flooded case), so the sector
gives the whole bearing's flow at 1/Z of the cells; the torques are scaled by Z.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from kegel.model.geometry import CAGE_OFFSET_RATIO, CAGE_OVERHANG_RATIO, CAGE_THICKNESS_RATIO, BearingGeometry

from .mesh import restore_sigpipe, write_msh22

__all__ = ["MESH_LEVELS", "CfdGeometry", "cfd_geometry", "build_mesh", "roller_name"]

GAP_RATIO = 0.08
CLEARANCE_RATIO = 0.08
#: Cells across the narrowest point of each raceway contact gap (the mesh size there is the local
#: gap over this number, growing with the gap away from the contact line); None: the mesh level's
#: wall size only (a whole-bearing mesh with 3 cells across costs about 17 x 80 k cells at tiny).
CELLS_ACROSS_GAP: int | None = None
#: Accepted ranges (inclusive) of the gap and clearance ratios (fractions of D_w) and of the cells
#: across a gap; one table for the geometry, CfdPoint and the command line.
RATIO_RANGES = {"gap_ratio": (1e-4, 0.2), "clearance_ratio": (1e-3, 0.2)}
CELLS_ACROSS_GAP_RANGE = (1, 20)
SMALL_RIB_RATIO = 0.35
HOUSING_CLEARANCE_RATIO = 0.25

#: Mesh levels: cell size far from walls and at the walls of the narrow gaps, as fractions of D_w.
MESH_LEVELS = {
    "tiny": {"size_max": 0.45, "size_gap": 0.16},
    "small": {"size_max": 0.30, "size_gap": 0.09},
    "fine": {"size_max": 0.18, "size_gap": 0.05},
}


def roller_name(k: int) -> str:
    """Patch name of roller ``k``."""
    return f"roller_{k:02d}"


@dataclass(frozen=True)
class CfdGeometry:
    """The CFD geometry's dimensions (SI), all derived from a :class:`BearingGeometry`."""

    bearing: BearingGeometry
    gap_m: float
    housing_clearance_m: float
    z_min_m: float
    z_max_m: float
    shaft_radius_m: float
    housing_radius_m: float
    cup_section: tuple[tuple[float, float], ...]   # (z, r) polygon
    cone_section: tuple[tuple[float, float], ...]  # (z, r) polygon
    cage_section: tuple[tuple[float, float], ...]  # (z, r) polygon of the shell (before pockets)
    roller_small_end_m: tuple[float, float]         # (z, r) of the shrunk roller's small-end centre
    roller_axis: tuple[float, float]                # (z, r) unit vector
    roller_length_m: float                          # shrunk
    roller_radii_m: tuple[float, float]             # shrunk small-end and large-end radii
    pocket_small_end_m: tuple[float, float]
    pocket_length_m: float
    pocket_radii_m: tuple[float, float]
    clearance_m: float = 0.0                       # roller end / rib and cage pocket clearance
    sector: bool = False                           # one roller pitch around roller 0, periodic sides
    inner_raceway_line_m: tuple[tuple[float, float], tuple[float, float]] = ((0.0, 0.0), (1.0, 0.0))
    outer_raceway_line_m: tuple[tuple[float, float], tuple[float, float]] = ((0.0, 0.0), (1.0, 0.0))

    @property
    def roller_count(self) -> int:
        return self.bearing.roller_count

    @property
    def modelled_rollers(self) -> list[int]:
        """The rollers in the model: all, or roller 0 alone in a sector."""
        return [0] if self.sector else list(range(self.roller_count))

    @property
    def sector_angles_rad(self) -> tuple[float, float]:
        """The azimuths of a sector's periodic sides (roller 0's pitch, centred on it)."""
        phi0, half = self.roller_azimuth_rad(0), math.pi / self.roller_count
        return phi0 - half, phi0 + half

    @property
    def copies(self) -> int:
        """How many times the modelled oil space repeats round the bearing (Z for a sector)."""
        return self.roller_count if self.sector else 1

    def roller_azimuth_rad(self, k: int) -> float:
        """Azimuth of roller k, measured from +x toward +y; roller 0 at the bottom (-y)."""
        return -0.5 * math.pi + 2.0 * math.pi * k / self.roller_count

    def roller_centre_and_axis(self, k: int) -> tuple[np.ndarray, np.ndarray]:
        """Roller k's mid-point and unit axis (small to large end) in the global frame."""
        phi = self.roller_azimuth_rad(k)
        er = np.array([math.cos(phi), math.sin(phi), 0.0])
        ez = np.array([0.0, 0.0, 1.0])
        zr = np.array(self.roller_small_end_m) + 0.5 * self.roller_length_m * np.array(self.roller_axis)
        centre = zr[0] * ez + zr[1] * er
        axis = self.roller_axis[0] * ez + self.roller_axis[1] * er
        return centre, axis


def _line_r(p: tuple[float, float], q: tuple[float, float], x: float) -> float:
    return p[1] + (q[1] - p[1]) * (x - p[0]) / (q[0] - p[0])


def _unit(v) -> np.ndarray:
    v = np.asarray(v, dtype=float)
    return v / float(np.linalg.norm(v))


def _intersect(p, u, q, v) -> np.ndarray:
    """Intersection of the lines p + s u and q + t v in the (z, r) plane."""
    A = np.column_stack([u, -np.asarray(v)])
    s, _ = np.linalg.solve(A, np.asarray(q, float) - np.asarray(p, float))
    return np.asarray(p, float) + s * np.asarray(u)


def cfd_geometry(g: BearingGeometry, *, housing_clearance_m: float | None = None,
                 gap_ratio: float = GAP_RATIO, clearance_ratio: float = CLEARANCE_RATIO,
                 sector: bool = False) -> CfdGeometry:
    """Dimensions of the CFD model of bearing ``g`` (see the module docstring).

    Parameters
    ----------
    gap_ratio
        Contact gap ``g / D_w``: each raceway is set back by ``g`` along its normal, so that the
        real roller stands ``g`` off it along the contact line (the contact model owns the film
        below ``g``).
    clearance_ratio
        Roller-end / rib and cage-pocket clearance ``c / D_w`` per side (the real pocket
        clearance ``cage_pocket_clearance_*`` is the total over both sides; the CFD opens both
        to ``c`` where ``c`` is larger than half of it).
    sector
        One roller pitch (``2 pi / Z``) around roller 0 with periodic sides, for a flow that is
        periodic in the cage frame (flooded, no gravity).
    """
    T, C = g.total_width_m, g.cup_width_m
    B = g.cone_width_m
    Dw, L = g.roller_mean_diameter_m, g.roller_length_m
    s = HOUSING_CLEARANCE_RATIO * T if housing_clearance_m is None else housing_clearance_m
    if s <= 0:
        raise ValueError(f"housing_clearance_m = {s}: expected a positive distance")
    for name, value in (("gap_ratio", gap_ratio), ("clearance_ratio", clearance_ratio)):
        lo, hi = RATIO_RANGES[name]
        if not (isinstance(value, (int, float)) and math.isfinite(value) and lo <= value <= hi):
            raise ValueError(f"{name} = {value!r}: expected a fraction of the roller diameter in [{lo}, {hi}]")
    gap = gap_ratio * Dw
    # the bearing data's pocket clearance is the total over both sides of the roller: half per side
    clear = max(clearance_ratio * Dw, 0.5 * g.cage_pocket_clearance_circumferential_m)
    R_h, r_s = 0.5 * g.outer_diameter_m, 0.5 * g.bore_diameter_m
    # cup: the raceway cone set back by the gap (outward), extended over the cup width
    o_se, o_le = np.array(g.outer_raceway_small_end_m), np.array(g.outer_raceway_large_end_m)
    u_o = _unit(o_le - o_se)
    n_o = np.array([-u_o[1], u_o[0]])          # outward (away from the rollers)
    o_se, o_le = o_se + gap * n_o, o_le + gap * n_o
    cup = ((0.0, _line_r(o_se, o_le, 0.0)), (0.0, R_h), (C, R_h), (C, _line_r(o_se, o_le, C)))
    # cone: bore, back face, large rib, raceway, small rib, front face; the raceway set back by the
    # gap (toward the axis), the rib face by the clearance (away from the roller end)
    i_se, i_le = np.array(g.inner_raceway_small_end_m), np.array(g.inner_raceway_large_end_m)
    u_i = _unit(i_le - i_se)
    n_i = np.array([-u_i[1], u_i[0]])          # toward the rollers
    rib_top = np.array(g.rib_top_point_m)
    v_rib = _unit(rib_top - i_le)               # up the rib face
    n_rib = np.array([v_rib[1], -v_rib[0]])     # into the rib (away from the roller end)
    race_p = i_se - gap * n_i
    rib_p = i_le + clear * n_rib
    corner = _intersect(race_p, u_i, rib_p, v_rib)
    rib_top_set = rib_top + clear * n_rib
    z0 = T - B
    a = np.array(g.roller_axis_unit())
    M = np.array(g.roller_mid_point())
    up_end = np.array([-a[1], a[0]])            # along the roller end faces, away from the axis
    r_small_end = 0.5 * g.roller_small_end_diameter_m
    # small rib: face parallel to the roller's small end, the clearance before it
    small_foot = _intersect(race_p, u_i, M - (0.5 * L + clear) * a, up_end)
    small_top = small_foot + SMALL_RIB_RATIO * r_small_end * up_end
    if small_top[0] <= z0:
        raise ValueError(f"the small rib ({small_top[0]:.4g} m) reaches past the cone's front face ({z0:.4g} m): "
                         "reduce clearance_ratio")
    cone = ((z0, r_s), (T, r_s), (T, float(rib_top_set[1])), tuple(rib_top_set), tuple(corner),
            tuple(small_foot), tuple(small_top), (z0, float(small_top[1])))
    # rollers: the real truncated cones on their axes through M
    tan_g = math.tan(g.roller_half_angle_rad)
    r1 = r_small_end
    small = M - 0.5 * L * a
    radius_at = lambda xi: r1 + xi * tan_g  # noqa: E731 - radius at distance xi from the small end
    # cage shell: offset outward (normal n to the axis, pointing away from the bearing axis)
    n = np.array([-a[1], a[0]])
    mid = CAGE_OFFSET_RATIO * Dw
    t = 0.5 * CAGE_THICKNESS_RATIO * Dw
    e0, e1 = -CAGE_OVERHANG_RATIO * L, (1 + CAGE_OVERHANG_RATIO) * L
    cage = tuple(tuple(float(c) for c in small + xi * a + off * n)
                 for xi, off in ((e0, mid - t), (e1, mid - t), (e1, mid + t), (e0, mid + t)))
    pocket_small = small - clear * a
    cg = CfdGeometry(
        bearing=g, gap_m=gap, housing_clearance_m=s, z_min_m=-s, z_max_m=T + s,
        shaft_radius_m=r_s, housing_radius_m=R_h,
        cup_section=tuple(tuple(float(c) for c in p) for p in cup),
        cone_section=tuple(tuple(float(c) for c in p) for p in cone),
        cage_section=cage,
        roller_small_end_m=(float(small[0]), float(small[1])),
        roller_axis=(float(a[0]), float(a[1])), roller_length_m=L,
        roller_radii_m=(r1, radius_at(L)),
        pocket_small_end_m=(float(pocket_small[0]), float(pocket_small[1])), pocket_length_m=L + 2 * clear,
        pocket_radii_m=(radius_at(-clear) + clear, radius_at(L + clear) + clear),
        clearance_m=clear, sector=bool(sector),
        inner_raceway_line_m=(tuple(float(c) for c in race_p), tuple(float(c) for c in race_p + u_i)),
        outer_raceway_line_m=(tuple(float(c) for c in o_se), tuple(float(c) for c in o_le)),
    )
    _check(cg)
    return cg


def _check(cg: CfdGeometry) -> None:
    """The cage must not touch the rings or leave the housing (its section, sampled along its
    edges, stays at least half a gap away from the ring sections)."""
    z_cage = [p[0] for p in cg.cage_section]
    if min(z_cage) <= cg.z_min_m or max(z_cage) >= cg.z_max_m:
        raise ValueError("cage side rings reach the housing walls: increase housing_clearance_m")
    pts = list(cg.cage_section)
    for i in range(len(pts)):
        a, b = np.array(pts[i]), np.array(pts[(i + 1) % len(pts)])
        for t in np.linspace(0.0, 1.0, 21):
            z, r = a + t * (b - a)
            for name, sec in (("cup", cg.cup_section), ("cone", cg.cone_section)):
                if _inside(sec, z, r) or _dist_section(sec, z, r) < 0.5 * min(cg.gap_m, cg.clearance_m):
                    raise ValueError(f"cage section point (z={z:.4g} m, r={r:.4g} m) touches the {name}")


def _inside(section, z: float, r: float) -> bool:
    """Point-in-polygon test (ray casting) in the (z, r) plane."""
    inside = False
    pts = list(section)
    for i in range(len(pts)):
        (z1, r1), (z2, r2) = pts[i], pts[(i + 1) % len(pts)]
        if (r1 > r) != (r2 > r) and z < z1 + (r - r1) * (z2 - z1) / (r2 - r1):
            inside = not inside
    return inside


def _revolve_section(occ, section) -> int:
    pts = [occ.addPoint(r, 0.0, z) for z, r in section]
    lines = [occ.addLine(pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts))]
    surf = occ.addPlaneSurface([occ.addCurveLoop(lines)])
    out = occ.revolve([(2, surf)], 0, 0, 0, 0, 0, 1, 2 * math.pi)
    return next(tag for dim, tag in out if dim == 3)


def _cone_along(occ, cg: CfdGeometry, k: int, small_end, length, radii) -> int:
    """Truncated cone of roller k, built along +z and turned into place so that the seam of its
    lateral surface faces the inner ring: a seam crossing the cage's pocket edge leaves
    sliver cells there."""
    from scipy.spatial.transform import Rotation

    phi = cg.roller_azimuth_rad(k)
    er = np.array([math.cos(phi), math.sin(phi), 0.0])
    ez = np.array([0.0, 0.0, 1.0])
    a = cg.roller_axis[0] * ez + cg.roller_axis[1] * er
    n_in = -(cg.roller_axis[0] * er - cg.roller_axis[1] * ez)   # normal toward the inner ring
    frame = np.column_stack([n_in, np.cross(a, n_in), a])        # local x (seam), y, z (axis)
    p = small_end[0] * ez + small_end[1] * er
    tag = occ.addCone(0.0, 0.0, 0.0, 0.0, 0.0, length, radii[0], radii[1])
    rotvec = Rotation.from_matrix(frame).as_rotvec()
    angle = float(np.linalg.norm(rotvec))
    if angle > 1e-12:
        occ.rotate([(3, tag)], 0.0, 0.0, 0.0, *(rotvec / angle), angle)
    occ.translate([(3, tag)], *p)
    return tag


def _revolve_wedge(occ, section, phi0: float, angle: float) -> int:
    """The section revolved from azimuth ``phi0`` through ``angle`` about z."""
    pts = [occ.addPoint(r, 0.0, z) for z, r in section]
    lines = [occ.addLine(pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts))]
    surf = occ.addPlaneSurface([occ.addCurveLoop(lines)])
    out = occ.revolve([(2, surf)], 0, 0, 0, 0, 0, 1, angle)
    tag = next(t for d, t in out if d == 3)
    occ.rotate([(3, tag)], 0, 0, 0, 0, 0, 1, phi0)
    return tag


def _gap_size_expression(cg: CfdGeometry, k: int, line, cells: int) -> str:
    """gmsh MathEval expression of the mesh size in raceway contact gap of roller ``k``: the sum
    of the distances to the roller's cone and to the raceway cone (the local gap where the
    point lies between them) over ``cells``; large away from the gap."""
    phi = cg.roller_azimuth_rad(k)
    c, s_ = math.cos(phi), math.sin(phi)
    (bz, br) = cg.roller_small_end_m
    az, ar = cg.roller_axis
    bx, by = br * c, br * s_
    ax, ay = ar * c, ar * s_
    r1, r2 = cg.roller_radii_m
    tan_g = (r2 - r1) / cg.roller_length_m
    cos_g = 1.0 / math.sqrt(1.0 + tan_g * tan_g)
    f = lambda v: f"{v:.12g}"  # noqa: E731
    sx = f"((x-({f(bx)}))*({f(ax)})+(y-({f(by)}))*({f(ay)})+(z-({f(bz)}))*({f(az)}))"
    q2 = f"((x-({f(bx)}))^2+(y-({f(by)}))^2+(z-({f(bz)}))^2-{sx}^2)"
    d_roller = f"abs(sqrt(abs({q2}))-({f(r1)}+{sx}*{f(tan_g)}))*{f(cos_g)}"
    (pz, pr), (qz, qr) = line
    k_ = (qr - pr) / (qz - pz)
    d_race = f"abs(sqrt(x^2+y^2)-({f(pr)}+(z-({f(pz)}))*({f(k_)})))*{f(1.0 / math.sqrt(1.0 + k_ * k_))}"
    return f"({d_roller}+{d_race})/{cells}"


def raceway_gap_m(cg: CfdGeometry, k: int, line, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The local gap of roller ``k``'s raceway wedge at ``points`` (shape (n, 3), OpenFOAM frame):
    the sum of the distances to the roller's cone and to the raceway cone ``line`` (exact for the
    two cones where the point lies between them; what :func:`_gap_size_expression` sizes the mesh
    by), and the coordinate along the roller's axis from its small end (in [0, length] beside the
    roller). g along the contact line."""
    phi = cg.roller_azimuth_rad(k)
    c, s_ = math.cos(phi), math.sin(phi)
    (bz, br), (az, ar) = cg.roller_small_end_m, cg.roller_axis
    r1, r2 = cg.roller_radii_m
    tan_g = (r2 - r1) / cg.roller_length_m
    x, y, z = points[:, 0], points[:, 1], points[:, 2]
    sx = (x - br * c) * ar * c + (y - br * s_) * ar * s_ + (z - bz) * az
    q2 = (x - br * c) ** 2 + (y - br * s_) ** 2 + (z - bz) ** 2 - sx ** 2
    d_roller = np.abs(np.sqrt(np.abs(q2)) - (r1 + sx * tan_g)) / math.sqrt(1.0 + tan_g * tan_g)
    (pz, pr), (qz, qr) = line
    k_ = (qr - pr) / (qz - pz)
    d_race = np.abs(np.hypot(x, y) - (pr + (z - pz) * k_)) / math.sqrt(1.0 + k_ * k_)
    return d_roller + d_race, sx


def build_mesh(cg: CfdGeometry, level: str, msh_path: str | Path, *, threads: int = 1,
               cage: bool = True, cells_across_gap: int | None = CELLS_ACROSS_GAP) -> dict[str, Any]:
    """Build the fluid volume, mesh it with tetrahedra at ``level`` and write ASCII msh 2.2.

    ``cage=False`` leaves the cage out (a modelling-choice check): its space is oil.

    Mesh size: the level's ``size_max`` away from the walls and ``size_gap`` within the
    clearance of every wall but the housing (as before); in each raceway contact gap the local
    gap over ``cells_across_gap`` (the sum of the distances to the roller and to the raceway,
    exact for the two cones), so that the narrowest point of the gap holds that many cells and
    the size grows with the wedge (``None``: no such refinement).

    One thread by default: with two, gmsh's mesh of the same geometry differs from run to run
    (tiny: 71 338 and 71 292 cells for the 32208 in two runs, and a different msh file each
    time), and so do the torques (-1.3 % between those two tiny oil-bath runs); with one thread
    the file repeats byte for byte, at 13 s instead of 11.5 s for tiny.

    Returns
    -------
    dict
        Patch name -> OpenFOAM patch type (a word, or a dict of the patch's entries for the
        periodic sides of a sector), for :func:`kegel.cfd_cases.mesh.gmsh_to_foam`.
    """
    import gmsh

    with_cage = cage
    if level not in MESH_LEVELS:
        raise ValueError(f"mesh level {level!r}: expected one of {', '.join(MESH_LEVELS)}")
    lo, hi = CELLS_ACROSS_GAP_RANGE
    if cells_across_gap is not None and not (isinstance(cells_across_gap, int) and lo <= cells_across_gap <= hi):
        raise ValueError(f"cells_across_gap = {cells_across_gap!r}: expected a whole number from {lo} to {hi}")
    Dw = cg.bearing.roller_mean_diameter_m
    size_max = MESH_LEVELS[level]["size_max"] * Dw
    size_gap = MESH_LEVELS[level]["size_gap"] * Dw
    gmsh.initialize(interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setNumber("General.NumThreads", threads)
        gmsh.model.add("bearing")
        occ = gmsh.model.occ
        if cg.sector:
            lo, hi = cg.sector_angles_rad
            housing = _revolve_wedge(occ, ((cg.z_min_m, cg.shaft_radius_m), (cg.z_min_m, cg.housing_radius_m),
                                           (cg.z_max_m, cg.housing_radius_m), (cg.z_max_m, cg.shaft_radius_m)),
                                     lo, hi - lo)
            shaft = None
        else:
            housing = occ.addCylinder(0, 0, cg.z_min_m, 0, 0, cg.z_max_m - cg.z_min_m, cg.housing_radius_m)
            shaft = occ.addCylinder(0, 0, cg.z_min_m - 1e-3, 0, 0, cg.z_max_m - cg.z_min_m + 2e-3, cg.shaft_radius_m)
        cup = _revolve_section(occ, cg.cup_section)
        cone = _revolve_section(occ, cg.cone_section)
        ks = cg.modelled_rollers
        cage: list = []
        if with_cage:
            shell = _revolve_section(occ, cg.cage_section)
            pockets = [_cone_along(occ, cg, k, cg.pocket_small_end_m, cg.pocket_length_m, cg.pocket_radii_m)
                       for k in range(cg.roller_count)]
            cage, _ = occ.cut([(3, shell)], [(3, p) for p in pockets])
        rollers = [_cone_along(occ, cg, k, cg.roller_small_end_m, cg.roller_length_m, cg.roller_radii_m)
                   for k in ks]
        tools = [*([(3, shaft)] if shaft is not None else []), (3, cup), (3, cone), *cage, *[(3, r) for r in rollers]]
        fluid, _ = occ.cut([(3, housing)], tools)
        occ.synchronize()
        if len(fluid) != 1:
            raise RuntimeError(f"the oil space should be one volume, got {len(fluid)}")
        vol = fluid[0][1]
        patches = _classify_surfaces(cg, [s for d, s in gmsh.model.getBoundary(fluid, oriented=False)],
                                     with_cage=with_cage)
        for name, tags in patches.items():
            gmsh.model.addPhysicalGroup(2, tags, name=name)
        gmsh.model.addPhysicalGroup(3, [vol], name="oil")
        # size: fine at the rollers, cage and rings (the clearances), coarse elsewhere
        fields = gmsh.model.mesh.field
        near = [t for name, tags in patches.items() if name not in ("housing",) and not name.startswith("periodic")
                for t in tags]
        f_dist = fields.add("Distance")
        fields.setNumbers(f_dist, "SurfacesList", near)
        fields.setNumber(f_dist, "Sampling", 20)
        f_th = fields.add("Threshold")
        fields.setNumber(f_th, "InField", f_dist)
        fields.setNumber(f_th, "SizeMin", size_gap)
        fields.setNumber(f_th, "SizeMax", size_max)
        fields.setNumber(f_th, "DistMin", cg.clearance_m)
        fields.setNumber(f_th, "DistMax", cg.clearance_m + 3 * size_max)
        # and in each raceway contact gap: the local gap over cells_across_gap
        gap_fields = []
        for k in ks if cells_across_gap is not None else []:
            for line in (cg.inner_raceway_line_m, cg.outer_raceway_line_m):
                f = fields.add("MathEval")
                fields.setString(f, "F", _gap_size_expression(cg, k, line, cells_across_gap))
                gap_fields.append(f)
        f_min = fields.add("Min")
        fields.setNumbers(f_min, "FieldsList", [f_th, *gap_fields])
        fields.setAsBackgroundMesh(f_min)
        size_min = 0.5 * size_gap if cells_across_gap is None else min(0.5 * size_gap, cg.gap_m / cells_across_gap)
        gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 12)
        gmsh.option.setNumber("Mesh.MeshSizeMax", size_max)
        gmsh.option.setNumber("Mesh.MeshSizeMin", size_min)
        gmsh.option.setNumber("Mesh.Algorithm", 1)  # MeshAdapt: no sliver triangles on the trimmed cage faces
        gmsh.option.setNumber("Mesh.Algorithm3D", 1)  # Delaunay: fewer slivers than HXT here
        gmsh.option.setNumber("Mesh.OptimizeThreshold", 0.6)  # 0.45 left 75.7 deg of non-orthogonality (32208, tiny)
        gmsh.option.setNumber("Mesh.Optimize", 1)
        gmsh.option.setNumber("Mesh.OptimizeNetgen", 1)
        gmsh.model.mesh.generate(3)
        write_msh22(msh_path)
    finally:
        gmsh.finalize()
        restore_sigpipe()
    types: dict[str, Any] = {name: "wall" for name in patches if not name.startswith("periodic")}
    if cg.sector:
        for name, other in (("periodic_lo", "periodic_hi"), ("periodic_hi", "periodic_lo")):
            types[name] = {"type": "cyclicAMI", "neighbourPatch": other, "transform": "rotational",
                           "rotationAxis": "(0 0 1)", "rotationCentre": "(0 0 0)", "matchTolerance": "0.0001"}
    return types


def _classify_surfaces(cg: CfdGeometry, surfaces: list[int], *, with_cage: bool = True) -> dict[str, list[int]]:
    """Name each boundary surface of the oil space by the solid it belongs to.

    A point on the surface (its parametric centre) is tested against each solid's analytic
    shape; the nearest solid wins.
    """
    import gmsh

    g = cg.bearing
    out: dict[str, list[int]] = {}
    tol = 0.05 * min(cg.gap_m, cg.clearance_m)
    for s in surfaces:
        p = _point_on_face(s)
        z, r = p[2], math.hypot(p[0], p[1])
        if cg.sector:
            lo, hi = cg.sector_angles_rad
            d_lo = abs(-math.sin(lo) * p[0] + math.cos(lo) * p[1])
            d_hi = abs(-math.sin(hi) * p[0] + math.cos(hi) * p[1])
            if min(d_lo, d_hi) < 1e-9 * g.outer_diameter_m and _on_plane(s, lo if d_lo < d_hi else hi):
                out.setdefault("periodic_lo" if d_lo < d_hi else "periodic_hi", []).append(s)
                continue
        d = {
            "shaft": abs(r - cg.shaft_radius_m),
            "housing": min(abs(r - cg.housing_radius_m), abs(z - cg.z_min_m), abs(z - cg.z_max_m)),
            "outer_ring": _dist_section(cg.cup_section, z, r),
            "inner_ring": _dist_section(cg.cone_section, z, r),
            "cage": min(_dist_section(cg.cage_section, z, r),
                        min(_dist_cone(cg, k, p, cg.pocket_small_end_m, cg.pocket_length_m, cg.pocket_radii_m)
                            for k in range(g.roller_count))) if with_cage else math.inf,
        }
        for k in cg.modelled_rollers:
            d[roller_name(k)] = _dist_cone(cg, k, p, cg.roller_small_end_m, cg.roller_length_m, cg.roller_radii_m)
        name = min(d, key=d.get)
        if d[name] > tol:
            raise RuntimeError(f"surface {s} at (z={z:.5g}, r={r:.5g}) belongs to no solid (nearest {name}, {d[name]:.3g} m)")
        out.setdefault(name, []).append(s)
    return out


def _on_plane(s: int, phi: float) -> bool:
    """Whether face ``s`` is a plane face lying in the axial plane at azimuth ``phi`` (a sector's
    periodic side, not a wall that crosses the plane): its normal is the plane's."""
    import gmsh

    if "Plane" not in gmsh.model.getType(2, s):
        return False
    lo, hi = gmsh.model.getParametrizationBounds(2, s)
    nx, ny, nz = gmsh.model.getNormal(s, [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])])
    return abs(abs(-math.sin(phi) * nx + math.cos(phi) * ny) - 1.0) < 1e-6


def _point_on_face(s: int) -> np.ndarray:
    """A point on face ``s``: the first parametric grid point inside the trimmed face (the
    parametric centre of an annulus or of a face with pockets cut out lies in a hole)."""
    import gmsh

    lo, hi = gmsh.model.getParametrizationBounds(2, s)
    for n in (2, 5, 11, 23):
        for i in range(1, n):
            for j in range(1, n):
                uv = [lo[0] + (hi[0] - lo[0]) * i / n, lo[1] + (hi[1] - lo[1]) * j / n]
                if gmsh.model.isInside(2, s, uv, parametric=True):
                    return np.array(gmsh.model.getValue(2, s, uv))
    raise RuntimeError(f"no point found on surface {s}")


def _dist_segment(p, a, b) -> float:
    p, a, b = map(np.asarray, (p, a, b))
    ab = b - a
    t = np.clip(np.dot(p - a, ab) / np.dot(ab, ab), 0.0, 1.0)
    return float(np.linalg.norm(p - (a + t * ab)))


def _dist_section(section, z: float, r: float) -> float:
    pts = list(section)
    return min(_dist_segment((z, r), pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts)))


def _dist_cone(cg: CfdGeometry, k: int, p: np.ndarray, small_end, length, radii) -> float:
    phi = cg.roller_azimuth_rad(k)
    er = np.array([math.cos(phi), math.sin(phi), 0.0])
    ez = np.array([0.0, 0.0, 1.0])
    a = cg.roller_axis[0] * ez + cg.roller_axis[1] * er
    base = small_end[0] * ez + small_end[1] * er
    v = p - base
    s = float(np.dot(v, a))
    rho = float(np.linalg.norm(v - s * a))
    sec = ((0.0, 0.0), (0.0, radii[0]), (length, radii[1]), (length, 0.0))
    # the axis segment is not a surface: measure to the three real edges only
    return min(_dist_segment((s, rho), sec[i], sec[i + 1]) for i in range(3))
