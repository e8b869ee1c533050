"""Internal geometry of a tapered roller bearing, derived in one place from its data file.

Derivation
==========
Frame ``B`` (bearing): ``x`` along the bearing axis, ``r`` radial, both in the axial plane that
contains a roller axis. ``x = 0`` is the cup (outer ring) back face, at the small end of the
rollers; ``x = T`` is the cone (inner ring) back face, behind the large rib. Points are written
``p_B = (x, r)``.

1. Cup angle (ISO 281): ``e = 1.5 tan(alpha_o)``, so ``alpha_o = atan(e / 1.5)``. This is the
   half-angle of the outer raceway cone, i.e. the contact angle.
2. Roller: a truncated cone of mean diameter ``D_w`` (at mid-length), length ``L`` along its
   axis and half-angle ``gamma``. Its axis makes ``beta = alpha_o - gamma`` with the bearing
   axis and passes through the roller mid-point ``M`` on the pitch circle, ``r_M = d_m / 2``.
   The inner raceway cone has half-angle ``alpha_i = beta - gamma``.
3. Apex condition (true rolling): the roller cone's apex lies on the bearing axis, where the
   raceway cones also meet. Along the roller axis, the apex is ``s_m = r_M / sin(beta)`` from
   ``M``; the roller cone's apex is ``(D_w / 2) / tan(gamma)`` from ``M``. Equal distances give

       tan(gamma) = (D_w / d_m) sin(alpha_o - gamma),

   solved for ``gamma`` by bracketed root finding (the left side rises and the right side falls
   with ``gamma`` on ``(0, alpha_o / 2)``, so the root is unique).
   The outer contact line through ``M + (D_w/2) n`` (``n`` the unit normal of the roller axis
   pointing outward) then has slope ``tan(beta + gamma)`` and passes through the same apex, and
   so does the inner one with ``tan(beta - gamma)``; :func:`apex_residual` checks this from the
   derived points alone.
4. Raceway diameters at the roller mid-length: ``d_o = d_m + D_w cos(beta)``,
   ``d_i = d_m - D_w cos(beta)``; at the ends of the contact lines from the end points of the
   roller generators ``M + xi a +/- r(xi) n`` with ``r(xi) = D_w/2 + xi tan(gamma)``.
5. Axial position (assumption, see the data file): the outer contact line is centred on the cup
   width ``C``; the tests check that the large end and the rib then lie inside the cone width.
6. Roller large end: a sphere of radius ``R_e = k_R S_L`` centred on the roller axis, with
   ``S_L`` the apex distance of the large-end crown and ``k_R`` the assumed ratio (0.90).
7. Rib contact: at the assumed height ``h_c = k_h r_L`` above the inner raceway (``r_L`` the
   large-end radius), i.e. at distance ``h = r_L - h_c`` from the roller axis on the inner side.
   The rib face (a cone about the bearing axis) is tangent to the end sphere there, so its
   generator is perpendicular to the sphere radius: it is inclined by ``asin(h / R_e)`` to the
   plane normal to the roller axis.
8. Cage: pocket centres on the pitch circle (ratio 1.0 assumed); pocket clearances as fractions
   of ``D_w`` (assumed, see the data file).
9. Roller mass and inertia: the truncated cone of steel, integrated exactly (the profile drop,
   edge radii and the spherical end are neglected: they change the mass by well under 1 %).
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, fields

import numpy as np
from numpy.polynomial import Polynomial
from scipy.optimize import brentq

from .data import BearingData, MaterialData
from ..base.errors import KegelInputError

__all__ = [
    "BearingGeometry",
    "derive_geometry",
    "apex_residual",
    "envelope_violations",
    "roller_half_angle_rad",
    "centrifugal_axial_load_N",
]


#: The pressed-steel window cage (assumed shape; the bearing tables give none), shared by the
#: dynamic model (mass, inertia, window edges: kegel.dynamics) and the CFD geometry
#: (kegel.cfd_cases.geometry): a conical shell parallel to the roller axes, its mid-surface
#: CAGE_OFFSET_RATIO * D_w outside them (toward the cup, as in pressed-steel TRB cages), thickness
#: CAGE_THICKNESS_RATIO * D_w, side rings CAGE_OVERHANG_RATIO * L beyond the roller ends.
CAGE_OFFSET_RATIO = 0.25
CAGE_THICKNESS_RATIO = 0.08
CAGE_OVERHANG_RATIO = 0.12

@dataclass(frozen=True)
class BearingGeometry:
    """Derived internal geometry of a tapered roller bearing (SI units, frame ``B``).

    Points are ``(x, r)`` pairs in the axial plane of a roller (see the module docstring).
    """

    designation: str
    # Boundary and published dimensions
    bore_diameter_m: float
    outer_diameter_m: float
    total_width_m: float
    cone_width_m: float
    cup_width_m: float
    pitch_diameter_m: float
    roller_count: int
    roller_mean_diameter_m: float
    roller_length_m: float
    roller_effective_length_m: float
    # Angles
    cup_angle_rad: float
    cone_angle_rad: float
    roller_half_angle_rad: float
    roller_axis_angle_rad: float
    # Positions along the axis
    apex_x_m: float
    roller_mid_x_m: float
    roller_apex_distance_m: float
    # Roller
    roller_small_end_diameter_m: float
    roller_large_end_diameter_m: float
    roller_end_radius_m: float
    roller_mass_kg: float
    roller_inertia_axial_kgm2: float
    roller_inertia_transverse_kgm2: float
    roller_com_offset_m: float
    # Raceways (diameters at the roller mid-length and at the ends of the contact lines)
    outer_raceway_diameter_mid_m: float
    inner_raceway_diameter_mid_m: float
    outer_raceway_small_end_m: tuple[float, float]
    outer_raceway_large_end_m: tuple[float, float]
    inner_raceway_small_end_m: tuple[float, float]
    inner_raceway_large_end_m: tuple[float, float]
    # Rib
    rib_contact_point_m: tuple[float, float]
    rib_contact_height_m: float
    rib_height_m: float
    rib_face_angle_to_roller_end_plane_rad: float
    rib_face_angle_to_radial_plane_rad: float
    rib_top_point_m: tuple[float, float]
    # Roller corners (large end, small end; outer and inner side)
    roller_corners_m: tuple[tuple[float, float], ...]
    # Cage
    cage_pitch_diameter_m: float
    cage_pocket_clearance_circumferential_m: float
    cage_pocket_clearance_axial_m: float
    # Provenance
    mean_diameter_catalogue_m: float

    def as_dict(self) -> dict[str, object]:
        """All fields as plain Python values (for JSON)."""
        return asdict(self)

    def roller_axis_unit(self) -> np.ndarray:
        """Unit vector of the roller axis in frame B, from the small to the large end."""
        return np.array([math.cos(self.roller_axis_angle_rad), math.sin(self.roller_axis_angle_rad)])

    @property
    def pure_rolling_cage_ratio(self) -> float:
        """Cage over inner-ring speed of apex-matched pure rolling with the outer ring fixed,
        ``d_i / (2 d_m)`` (``d_i`` the inner raceway's diameter at the roller mid-length)."""
        return self.inner_raceway_diameter_mid_m / (2.0 * self.pitch_diameter_m)

    def roller_mid_point(self) -> np.ndarray:
        """Roller mid-point M in frame B."""
        return np.array([self.roller_mid_x_m, 0.5 * self.pitch_diameter_m])


def roller_half_angle_rad(cup_angle_rad: float, diameter_ratio: float) -> float:
    """Solve the apex condition ``tan(g) = k sin(alpha_o - g)`` for the roller half-angle ``g``.

    Parameters
    ----------
    cup_angle_rad
        Outer raceway half-angle ``alpha_o`` (0 < alpha_o < pi/2).
    diameter_ratio
        ``k = D_w / d_m`` (0 < k < 1).
    """
    if not 0.0 < cup_angle_rad < 0.5 * math.pi:
        raise ValueError(f"cup_angle_rad = {cup_angle_rad}: expected a value in (0, pi/2)")
    if not 0.0 < diameter_ratio < 1.0:
        raise ValueError(f"diameter_ratio = {diameter_ratio}: expected a value in (0, 1)")

    def f(g: float) -> float:
        return math.tan(g) - diameter_ratio * math.sin(cup_angle_rad - g)

    return brentq(f, 0.0, 0.5 * cup_angle_rad, xtol=1e-16, rtol=4 * np.finfo(float).eps, maxiter=200)


def _roller_mass_properties(
    r_mid: float, tan_g: float, length: float, density: float
) -> tuple[float, float, float, float]:
    """Mass, axial inertia, transverse inertia about the centre of mass, CoM offset from M.

    Exact integrals of the truncated cone r(xi) = r_mid + xi tan(g), xi in [-L/2, L/2].
    """
    r = Polynomial([r_mid, tan_g])
    xi = Polynomial([0.0, 1.0])
    lo, hi = -0.5 * length, 0.5 * length

    def integral(p: Polynomial) -> float:
        q = p.integ()
        return float(q(hi) - q(lo))

    mass = density * math.pi * integral(r**2)
    com = density * math.pi * integral(xi * r**2) / mass
    i_axial = 0.5 * density * math.pi * integral(r**4)
    i_trans_m = density * math.pi * integral(r**4 / 4.0 + xi**2 * r**2)
    i_trans = i_trans_m - mass * com**2
    return mass, i_axial, i_trans, com


def derive_geometry(bearing: BearingData, material: MaterialData, *, check_envelope: bool = True) -> BearingGeometry:
    """Derive the internal geometry of a tapered roller bearing (see the module docstring).

    Parameters
    ----------
    bearing
        Published and catalogue data (:func:`kegel.data.load_bearing`).
    material
        Roller material, for the roller mass and inertia.
    check_envelope
        Check the result against the bearing's boundary dimensions (:func:`envelope_violations`:
        rollers inside the rings' width and diameters, raceways and rib inside their rings,
        rollers not overlapping on the pitch circle). ``False`` only to list the violations, as
        ``kegel bearing`` does.

    Raises
    ------
    KegelInputError
        With ``check_envelope``, a geometry that leaves the envelope: the message names the
        bearing's data file and every violated condition.
    """
    g = _derive_geometry(bearing, material)
    if check_envelope:
        problems = envelope_violations(g)
        if problems:
            raise KegelInputError(bearing.source_file, "(geometry)", bearing.designation,
                                  "bearing data whose derived geometry fits its boundary dimensions; it does not: "
                                  + "; ".join(problems))
    return g


def _derive_geometry(bearing: BearingData, material: MaterialData) -> BearingGeometry:
    d_m = bearing.pitch_diameter_m
    D_w = bearing.roller_mean_diameter_m
    L = bearing.roller_length_m

    alpha_o = math.atan(bearing.calculation_factor_e / 1.5)  # 1.
    gamma = roller_half_angle_rad(alpha_o, D_w / d_m)  # 3.
    beta = alpha_o - gamma  # 2.
    alpha_i = beta - gamma
    tan_g = math.tan(gamma)

    a = np.array([math.cos(beta), math.sin(beta)])  # roller axis, small -> large end
    n = np.array([-math.sin(beta), math.cos(beta)])  # outward normal of the roller axis

    def radius(xi: float) -> float:
        return 0.5 * D_w + xi * tan_g

    # 5. axial position: outer contact line centred on the cup width
    x_contact_mid_rel = -0.5 * D_w * math.sin(beta)  # x of the outer contact mid-point minus x_M
    x_M = 0.5 * bearing.cup_width_m - x_contact_mid_rel
    M = np.array([x_M, 0.5 * d_m])
    s_m = M[1] / math.sin(beta)  # apex distance of M along the roller axis
    apex_x = x_M - s_m * math.cos(beta)

    def outer_point(xi: float) -> np.ndarray:
        return M + xi * a + radius(xi) * n

    def inner_point(xi: float) -> np.ndarray:
        return M + xi * a - radius(xi) * n

    half = 0.5 * L
    r_L = radius(half)
    r_S = radius(-half)

    # 6. large-end sphere
    S_L = s_m + half
    R_e = bearing.assumed_roller_end_radius_ratio * S_L
    centre = M + (half - R_e) * a

    # 7. rib contact
    h_c = bearing.assumed_rib_contact_height_ratio * r_L
    h = r_L - h_c
    if h >= R_e:
        raise ValueError("rib contact height leaves the roller end sphere")
    P_rib = centre + math.sqrt(R_e**2 - h**2) * a - h * n
    normal_rib = (P_rib - centre) / R_e  # from the roller into the rib
    rib_angle_end_plane = math.asin(h / R_e)
    rib_angle_radial = math.atan2(normal_rib[1], normal_rib[0])
    rib_height = bearing.assumed_rib_height_over_contact_height * h_c
    inner_large = inner_point(half)
    rib_top = inner_large + rib_height * n  # along the end face, from the raceway towards the axis

    mass, i_ax, i_tr, com = _roller_mass_properties(0.5 * D_w, tan_g, L, material.density_kg_m3)

    def tup(v: np.ndarray) -> tuple[float, float]:
        return (float(v[0]), float(v[1]))

    return BearingGeometry(
        designation=bearing.designation,
        bore_diameter_m=bearing.bore_diameter_m,
        outer_diameter_m=bearing.outer_diameter_m,
        total_width_m=bearing.total_width_m,
        cone_width_m=bearing.cone_width_m,
        cup_width_m=bearing.cup_width_m,
        pitch_diameter_m=d_m,
        roller_count=bearing.roller_count,
        roller_mean_diameter_m=D_w,
        roller_length_m=L,
        roller_effective_length_m=L - 2.0 * bearing.edge_radius_m,
        cup_angle_rad=alpha_o,
        cone_angle_rad=alpha_i,
        roller_half_angle_rad=gamma,
        roller_axis_angle_rad=beta,
        apex_x_m=apex_x,
        roller_mid_x_m=x_M,
        roller_apex_distance_m=s_m,
        roller_small_end_diameter_m=2.0 * r_S,
        roller_large_end_diameter_m=2.0 * r_L,
        roller_end_radius_m=R_e,
        roller_mass_kg=mass,
        roller_inertia_axial_kgm2=i_ax,
        roller_inertia_transverse_kgm2=i_tr,
        roller_com_offset_m=com,
        outer_raceway_diameter_mid_m=d_m + D_w * math.cos(beta),
        inner_raceway_diameter_mid_m=d_m - D_w * math.cos(beta),
        outer_raceway_small_end_m=tup(outer_point(-half)),
        outer_raceway_large_end_m=tup(outer_point(half)),
        inner_raceway_small_end_m=tup(inner_point(-half)),
        inner_raceway_large_end_m=tup(inner_large),
        rib_contact_point_m=tup(P_rib),
        rib_contact_height_m=h_c,
        rib_height_m=rib_height,
        rib_face_angle_to_roller_end_plane_rad=rib_angle_end_plane,
        rib_face_angle_to_radial_plane_rad=rib_angle_radial,
        rib_top_point_m=tup(rib_top),
        roller_corners_m=(
            tup(outer_point(half)),
            tup(inner_large),
            tup(outer_point(-half)),
            tup(inner_point(-half)),
        ),
        cage_pitch_diameter_m=bearing.assumed_cage_pitch_ratio * d_m,
        cage_pocket_clearance_circumferential_m=bearing.assumed_cage_pocket_clearance_circumferential_ratio
        * D_w,
        cage_pocket_clearance_axial_m=bearing.assumed_cage_pocket_clearance_axial_ratio * D_w,
        mean_diameter_catalogue_m=0.5 * (bearing.bore_diameter_m + bearing.outer_diameter_m),
    )


def _axis_intercept(point: tuple[float, float], angle_rad: float) -> float:
    """x where the line through ``point`` with slope angle ``angle_rad`` meets r = 0."""
    return point[0] - point[1] / math.tan(angle_rad)


def apex_residual(g: BearingGeometry) -> float:
    """Largest distance between the axis intercepts of the outer raceway, the inner raceway and
    the roller axis, relative to the roller's apex distance.

    Computed from the derived points and angles alone, independently of the derivation.
    """
    xs = [
        _axis_intercept(g.outer_raceway_large_end_m, g.cup_angle_rad),
        _axis_intercept(g.outer_raceway_small_end_m, g.cup_angle_rad),
        _axis_intercept(g.inner_raceway_large_end_m, g.cone_angle_rad),
        _axis_intercept(g.inner_raceway_small_end_m, g.cone_angle_rad),
        _axis_intercept((g.roller_mid_x_m, 0.5 * g.pitch_diameter_m), g.roller_axis_angle_rad),
    ]
    return (max(xs) - min(xs)) / g.roller_apex_distance_m


def envelope_violations(g: BearingGeometry) -> list[str]:
    """Check the derived geometry against the catalogue boundary dimensions.

    Returns
    -------
    list of str
        One sentence per violated condition; empty when the geometry fits.
    """
    out: list[str] = []
    r_bore, r_out = 0.5 * g.bore_diameter_m, 0.5 * g.outer_diameter_m
    T, B, C = g.total_width_m, g.cone_width_m, g.cup_width_m
    for i, (x, r) in enumerate(g.roller_corners_m):
        if not 0.0 < x < T:
            out.append(f"roller corner {i} at x = {x * 1e3:.3f} mm lies outside the width [0, T]")
        if not r_bore < r < r_out:
            out.append(f"roller corner {i} at r = {r * 1e3:.3f} mm lies outside (d/2, D/2)")
    for name in ("outer_raceway_small_end_m", "outer_raceway_large_end_m"):
        x, r = getattr(g, name)
        if not 0.0 <= x <= C:
            out.append(f"{name} at x = {x * 1e3:.3f} mm lies outside the cup width [0, C]")
        if not r < r_out:
            out.append(f"{name} at r = {r * 1e3:.3f} mm lies outside the outer diameter")
    for name in ("inner_raceway_small_end_m", "inner_raceway_large_end_m", "rib_contact_point_m"):
        x, r = getattr(g, name)
        if not T - B <= x <= T:
            out.append(f"{name} at x = {x * 1e3:.3f} mm lies outside the cone width [T-B, T]")
        if not r > r_bore:
            out.append(f"{name} at r = {r * 1e3:.3f} mm lies inside the bore")
    x_top, r_top = g.rib_top_point_m
    if not x_top <= T:
        out.append(f"rib top at x = {x_top * 1e3:.3f} mm lies behind the cone back face")
    # the rib must stay clear of the cup raceway cone at the same x
    r_cup_at_rib = (x_top - g.apex_x_m) * math.tan(g.cup_angle_rad)
    if not r_top < r_cup_at_rib:
        out.append("rib top reaches the cup raceway cone")
    # rollers must not overlap on the pitch circle (large end is the widest)
    spacing = g.pitch_diameter_m * math.sin(math.pi / g.roller_count)
    if not spacing > g.roller_mean_diameter_m + g.cage_pocket_clearance_circumferential_m:
        out.append("rollers (with pocket clearance) overlap on the pitch circle")
    return out


def geometry_table(g: BearingGeometry) -> list[tuple[str, float, str]]:
    """Rows (name, value, unit) of the derived geometry, in the units engineers read."""
    deg = math.degrees
    mm = 1e3
    rows: list[tuple[str, float, str]] = [
        ("bore diameter d", g.bore_diameter_m * mm, "mm"),
        ("outer diameter D", g.outer_diameter_m * mm, "mm"),
        ("total width T", g.total_width_m * mm, "mm"),
        ("cone width B", g.cone_width_m * mm, "mm"),
        ("cup width C", g.cup_width_m * mm, "mm"),
        ("pitch diameter d_m", g.pitch_diameter_m * mm, "mm"),
        ("roller count Z", g.roller_count, "-"),
        ("roller mean diameter D_w", g.roller_mean_diameter_m * mm, "mm"),
        ("roller small-end diameter", g.roller_small_end_diameter_m * mm, "mm"),
        ("roller large-end diameter", g.roller_large_end_diameter_m * mm, "mm"),
        ("roller length L", g.roller_length_m * mm, "mm"),
        ("roller effective length L - 2 r_e", g.roller_effective_length_m * mm, "mm"),
        ("cup angle alpha_o (contact angle)", deg(g.cup_angle_rad), "deg"),
        ("cone angle alpha_i", deg(g.cone_angle_rad), "deg"),
        ("roller half-angle gamma", deg(g.roller_half_angle_rad), "deg"),
        ("roller axis angle beta", deg(g.roller_axis_angle_rad), "deg"),
        ("apex distance of roller mid-point", g.roller_apex_distance_m * mm, "mm"),
        ("outer raceway diameter at roller mid", g.outer_raceway_diameter_mid_m * mm, "mm"),
        ("inner raceway diameter at roller mid", g.inner_raceway_diameter_mid_m * mm, "mm"),
        ("outer raceway diameter small/large end", 2 * g.outer_raceway_small_end_m[1] * mm, "mm"),
        ("", 2 * g.outer_raceway_large_end_m[1] * mm, "mm"),
        ("inner raceway diameter small/large end", 2 * g.inner_raceway_small_end_m[1] * mm, "mm"),
        ("", 2 * g.inner_raceway_large_end_m[1] * mm, "mm"),
        ("roller large-end sphere radius", g.roller_end_radius_m * mm, "mm"),
        ("rib contact height above raceway", g.rib_contact_height_m * mm, "mm"),
        ("rib height", g.rib_height_m * mm, "mm"),
        ("rib face angle to roller end plane", deg(g.rib_face_angle_to_roller_end_plane_rad), "deg"),
        ("rib face normal angle to bearing axis", deg(g.rib_face_angle_to_radial_plane_rad), "deg"),
        ("cage pitch diameter", g.cage_pitch_diameter_m * mm, "mm"),
        ("cage pocket clearance, circumferential", g.cage_pocket_clearance_circumferential_m * mm, "mm"),
        ("cage pocket clearance, axial", g.cage_pocket_clearance_axial_m * mm, "mm"),
        ("roller mass", g.roller_mass_kg * 1e3, "g"),
        ("roller inertia, axial", g.roller_inertia_axial_kgm2 * 1e9, "g mm^2"),
        ("roller inertia, transverse (CoM)", g.roller_inertia_transverse_kgm2 * 1e9, "g mm^2"),
        ("apex residual (relative)", apex_residual(g), "-"),
    ]
    return rows


def field_names() -> list[str]:
    """Names of the :class:`BearingGeometry` fields (the JSON keys of ``kegel bearing``)."""
    return [f.name for f in fields(BearingGeometry)]


def centrifugal_axial_load_N(g: BearingGeometry, speed_rad_s: float) -> float:
    """The axial load the rollers' centrifugal force alone puts on the cup of a single TRB,
    ``Z m r_M w_c^2 tan(alpha_o)`` [N], the cage at its pure-rolling speed
    (:attr:`BearingGeometry.pure_rolling_cage_ratio` of the inner ring's ``speed_rad_s``), the
    roller's mass at the pitch radius ``r_M``.

    Each roller's cup contact carries at least its centrifugal force radially, so at least that
    force times tan(alpha_o) axially, and the cup's axial reaction is the axial load. A
    force-controlled axial load at or below it leaves no quasi-static state with the rollers
    seated on the cone (kegel's load distribution fails from about 0.96 of it).
    """
    w_c = abs(float(speed_rad_s)) * g.pure_rolling_cage_ratio
    return g.roller_count * g.roller_mass_kg * 0.5 * g.pitch_diameter_m * w_c ** 2 * math.tan(g.cup_angle_rad)
