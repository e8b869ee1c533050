"""gmsh geometry and mesh of a tapered roller bearing's oil space, from kegel's bearing data.

One source of truth: every dimension comes from :func:`kegel.geometry.derive_geometry` of the
bearing's data file; the CFD-only choices below are named, with their reasons.

Frames and units: SI; OpenFOAM's ``z`` is the bearing axis with ``z = 0`` at the cup back face
and ``z = T`` at the cone back face (kegel.geometry's ``x``); ``y`` points up (gravity ``-y``).

Solids (cut out of the fluid):

- cup (outer ring): revolved section between its raceway cone and the housing bore ``D/2``,
  over ``0 <= z <= C``;
- cone (inner ring): revolved section with the raceway, the large rib (face through the rib
  contact point, top at kegel.geometry's rib top point) and a small rib (height
  ``SMALL_RIB_RATIO`` of the small-end roller radius, an assumption: the paper gives no small
  rib), bore ``d/2`` on the shaft;
- rollers: truncated cones on their axes, **shrunk by the gap g** on the radius and shortened by
  ``g`` at each end. A CFD mesh cannot resolve the line contacts (zero film thickness at this
  scale); the gap ``g = GAP_RATIO * D_w`` (0.08 D_w, 0.8 mm for the 32208) holds one to two
  tetrahedra at the ``small`` level and about one at ``tiny``. The flat large end replaces the spherical one (R_e = 139 mm
  for the 32208: 0.1 um of crown over the end face);
- cage: a pressed-steel window cage as a conical shell parallel to the roller axes, its
  mid-surface ``CAGE_OFFSET_RATIO * D_w`` outside the roller axes (toward the cup, as in
  pressed-steel TRB cages), thickness ``CAGE_THICKNESS_RATIO * D_w``, extending
  ``CAGE_OVERHANG_RATIO * L`` beyond the roller ends (the side rings); pockets are the
  unshrunk roller cones, so every roller is ``g`` from its pocket walls;
- housing: a closed cylinder of the housing bore ``D/2`` from ``z = -s`` to ``T + s`` (side walls
  at ``s`` = ``housing_clearance_m``, default ``HOUSING_CLEARANCE_RATIO * T``), shaft ``d/2``
  through it.

Patches: ``inner_ring`` (cone surfaces), ``shaft``, ``outer_ring`` (cup), ``housing``, ``cage``,
``roller_00`` ... ``roller_NN`` (roller k at azimuth ``2 pi k / Z``, roller 0 at the bottom,
``-y``, where an oil bath wets it first).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from kegel.geometry import CAGE_OFFSET_RATIO, CAGE_OVERHANG_RATIO, CAGE_THICKNESS_RATIO, BearingGeometry

from .mesh import write_msh22

__all__ = ["MESH_LEVELS", "CfdGeometry", "cfd_geometry", "build_mesh", "roller_name"]

GAP_RATIO = 0.08
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

    @property
    def roller_count(self) -> int:
        return self.bearing.roller_count

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


def cfd_geometry(g: BearingGeometry, *, housing_clearance_m: float | None = None) -> CfdGeometry:
    """Dimensions of the CFD model of bearing ``g`` (see the module docstring)."""
    T, C = g.total_width_m, g.cup_width_m
    B = g.cone_width_m
    Dw, L = g.roller_mean_diameter_m, g.roller_length_m
    s = HOUSING_CLEARANCE_RATIO * T if housing_clearance_m is None else housing_clearance_m
    if s <= 0:
        raise ValueError(f"housing_clearance_m = {s}: expected a positive distance")
    gap = GAP_RATIO * Dw
    R_h, r_s = 0.5 * g.outer_diameter_m, 0.5 * g.bore_diameter_m
    # cup: the raceway cone extended over the cup width
    o_se, o_le = g.outer_raceway_small_end_m, g.outer_raceway_large_end_m
    cup = ((0.0, _line_r(o_se, o_le, 0.0)), (0.0, R_h), (C, R_h), (C, _line_r(o_se, o_le, C)))
    # cone: bore, back face, large rib, raceway, small rib, front face
    i_se, i_le = g.inner_raceway_small_end_m, g.inner_raceway_large_end_m
    rib_top = g.rib_top_point_m
    z0 = T - B
    r_small_end = 0.5 * g.roller_small_end_diameter_m
    small_rib_r = i_se[1] + SMALL_RIB_RATIO * r_small_end
    small_rib_z = max(z0, i_se[0] - gap - 0.15 * r_small_end)
    cone = ((z0, r_s), (T, r_s), (T, rib_top[1]), rib_top, i_le, i_se,
            (small_rib_z + 0.15 * r_small_end, small_rib_r), (z0, small_rib_r))
    # rollers: axis through M, shrunk
    a = g.roller_axis_unit()
    M = g.roller_mid_point()
    tan_g = math.tan(g.roller_half_angle_rad)
    r1 = 0.5 * g.roller_small_end_diameter_m
    small = M - 0.5 * L * a
    roller_small = small + gap * a
    roller_len = L - 2.0 * gap
    radius_at = lambda xi: r1 + xi * tan_g  # noqa: E731 - radius at distance xi from the small end
    roller_radii = (radius_at(gap) - gap, radius_at(L - gap) - gap)
    # cage shell: offset outward (normal n to the axis, pointing away from the bearing axis)
    n = np.array([-a[1], a[0]])
    mid = CAGE_OFFSET_RATIO * Dw
    t = 0.5 * CAGE_THICKNESS_RATIO * Dw
    e0, e1 = -CAGE_OVERHANG_RATIO * L, (1 + CAGE_OVERHANG_RATIO) * L
    cage = tuple(tuple(float(c) for c in small + xi * a + off * n)
                 for xi, off in ((e0, mid - t), (e1, mid - t), (e1, mid + t), (e0, mid + t)))
    cg = CfdGeometry(
        bearing=g, gap_m=gap, housing_clearance_m=s, z_min_m=-s, z_max_m=T + s,
        shaft_radius_m=r_s, housing_radius_m=R_h,
        cup_section=cup, cone_section=tuple(tuple(float(c) for c in p) for p in cone),
        cage_section=cage,
        roller_small_end_m=(float(roller_small[0]), float(roller_small[1])),
        roller_axis=(float(a[0]), float(a[1])), roller_length_m=roller_len,
        roller_radii_m=roller_radii,
        pocket_small_end_m=(float(small[0]), float(small[1])), pocket_length_m=L,
        pocket_radii_m=(r1, radius_at(L)),
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
                if _inside(sec, z, r) or _dist_section(sec, z, r) < 0.5 * cg.gap_m:
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


def build_mesh(cg: CfdGeometry, level: str, msh_path: str | Path, *, threads: int = 1,
               cage: bool = True) -> dict[str, str]:
    """Build the fluid volume, mesh it with tetrahedra at ``level`` and write ASCII msh 2.2.

    ``cage=False`` leaves the cage out (a modelling-choice check): its space is oil.

    One thread by default: with two, gmsh's mesh of the same geometry differs from run to run
    (tiny: 71 338 and 71 292 cells for the 32208 in two runs, and a different msh file each
    time), and so do the torques (-1.3 % between those two tiny oil-bath runs); with one thread
    the file repeats byte for byte, at 13 s instead of 11.5 s for tiny.

    Returns
    -------
    dict
        Patch name -> OpenFOAM patch type, for :func:`kegel.cfd_cases.mesh.gmsh_to_foam`.
    """
    import gmsh

    with_cage = cage
    if level not in MESH_LEVELS:
        raise ValueError(f"mesh level {level!r}: expected one of {', '.join(MESH_LEVELS)}")
    Dw = cg.bearing.roller_mean_diameter_m
    size_max = MESH_LEVELS[level]["size_max"] * Dw
    size_gap = MESH_LEVELS[level]["size_gap"] * Dw
    gmsh.initialize(interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setNumber("General.NumThreads", threads)
        gmsh.model.add("bearing")
        occ = gmsh.model.occ
        housing = occ.addCylinder(0, 0, cg.z_min_m, 0, 0, cg.z_max_m - cg.z_min_m, cg.housing_radius_m)
        shaft = occ.addCylinder(0, 0, cg.z_min_m - 1e-3, 0, 0, cg.z_max_m - cg.z_min_m + 2e-3, cg.shaft_radius_m)
        cup = _revolve_section(occ, cg.cup_section)
        cone = _revolve_section(occ, cg.cone_section)
        Z = cg.roller_count
        cage: list = []
        if with_cage:
            shell = _revolve_section(occ, cg.cage_section)
            pockets = [_cone_along(occ, cg, k, cg.pocket_small_end_m, cg.pocket_length_m, cg.pocket_radii_m)
                       for k in range(Z)]
            cage, _ = occ.cut([(3, shell)], [(3, p) for p in pockets])
        rollers = [_cone_along(occ, cg, k, cg.roller_small_end_m, cg.roller_length_m, cg.roller_radii_m)
                   for k in range(Z)]
        tools = [(3, shaft), (3, cup), (3, cone), *cage, *[(3, r) for r in rollers]]
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
        # size: fine at the rollers, cage and raceways (the narrow gaps), coarse elsewhere
        near = [t for name, tags in patches.items() if name not in ("housing",) for t in tags]
        f_dist = gmsh.model.mesh.field.add("Distance")
        gmsh.model.mesh.field.setNumbers(f_dist, "SurfacesList", near)
        gmsh.model.mesh.field.setNumber(f_dist, "Sampling", 20)
        f_th = gmsh.model.mesh.field.add("Threshold")
        gmsh.model.mesh.field.setNumber(f_th, "InField", f_dist)
        gmsh.model.mesh.field.setNumber(f_th, "SizeMin", size_gap)
        gmsh.model.mesh.field.setNumber(f_th, "SizeMax", size_max)
        gmsh.model.mesh.field.setNumber(f_th, "DistMin", cg.gap_m)
        gmsh.model.mesh.field.setNumber(f_th, "DistMax", cg.gap_m + 3 * size_max)
        gmsh.model.mesh.field.setAsBackgroundMesh(f_th)
        gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 12)
        gmsh.option.setNumber("Mesh.MeshSizeMax", size_max)
        gmsh.option.setNumber("Mesh.MeshSizeMin", 0.5 * size_gap)
        gmsh.option.setNumber("Mesh.Algorithm", 1)  # MeshAdapt: no sliver triangles on the trimmed cage faces
        gmsh.option.setNumber("Mesh.Algorithm3D", 1)  # Delaunay: fewer slivers than HXT here
        gmsh.option.setNumber("Mesh.OptimizeThreshold", 0.45)
        gmsh.option.setNumber("Mesh.Optimize", 1)
        gmsh.option.setNumber("Mesh.OptimizeNetgen", 1)
        gmsh.model.mesh.generate(3)
        write_msh22(msh_path)
    finally:
        gmsh.finalize()
    types = {name: "wall" for name in patches}
    return types


def _classify_surfaces(cg: CfdGeometry, surfaces: list[int], *, with_cage: bool = True) -> dict[str, list[int]]:
    """Name each boundary surface of the oil space by the solid it belongs to.

    A point on the surface (its parametric centre) is tested against each solid's analytic
    shape; the nearest solid wins.
    """
    import gmsh

    g = cg.bearing
    out: dict[str, list[int]] = {}
    for s in surfaces:
        p = _point_on_face(s)
        z, r = p[2], math.hypot(p[0], p[1])
        d = {
            "shaft": abs(r - cg.shaft_radius_m),
            "housing": min(abs(r - cg.housing_radius_m), abs(z - cg.z_min_m), abs(z - cg.z_max_m)),
            "outer_ring": _dist_section(cg.cup_section, z, r),
            "inner_ring": _dist_section(cg.cone_section, z, r),
            "cage": min(_dist_section(cg.cage_section, z, r),
                        min(_dist_cone(cg, k, p, cg.pocket_small_end_m, cg.pocket_length_m, cg.pocket_radii_m)
                            for k in range(g.roller_count))) if with_cage else math.inf,
        }
        for k in range(g.roller_count):
            d[roller_name(k)] = _dist_cone(cg, k, p, cg.roller_small_end_m, cg.roller_length_m, cg.roller_radii_m)
        name = min(d, key=d.get)
        if d[name] > 0.05 * cg.gap_m:
            raise RuntimeError(f"surface {s} at (z={z:.5g}, r={r:.5g}) belongs to no solid (nearest {name}, {d[name]:.3g} m)")
        out.setdefault(name, []).append(s)
    return out


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
