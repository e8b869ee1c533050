"""Analytic loss terms of the thin films the CFD mesh cannot resolve (issue 29, item 1).

The CFD geometry (:mod:`kegel.cfd_cases.geometry`) keeps the real rollers but opens the roller
end / rib film and the cage pockets to the clearance ``c = clearance_ratio * D_w`` (0.8 mm on the
32208). The real films there are much thinner, and their viscous loss is missing from the CFD.
This module adds it back as separate terms, each the loss of the real film **minus** the loss a
film of the CFD's gap would have over the same wall area (Couette estimate), so that
``CFD + thin films`` counts every part of the oil once:

(a) ``rib``: the roller's large end (a sphere of radius ``R_e``) against the inner ring's rib
    face (a cone about the bearing axis, tangent to the end sphere at the rib contact point). The
    gap ``h(xi, eta) = h_film + g(xi, eta)`` is the rigid gap ``g`` of the sphere and the cone
    (exact ray intersections along the rib normal, zero at the contact point) plus the central
    film thickness ``h_film`` of the rib contact, on the overlap of the spherical cap (radius
    ``D_L/2 - r_edge``) and the rib face (up to its top). The Hertz ellipse of the rib contact is
    left out: the contact model (MBS, ``evaluate_cell``: Bair-Winer shear of the EHL film over the
    Hertz area) owns it. The CFD's film there is the flat roller end against its rib face set
    back by ``c`` (the same ray construction).
(b) ``pocket_sides``: the roller's lateral surface against its cage pocket, a concentric annulus
    of the real radial pocket clearance per side, ``cage_pocket_clearance_circumferential_m / 2``
    (the data's clearance is the total over both sides; the CFD's
    pocket is the roller cone grown by ``c``), over the pocket wall: the part of the pocket cone
    that lies inside the cage shell (:data:`kegel.geometry.CAGE_OFFSET_RATIO`, ...).
(c) ``pocket_ends``: the roller's end faces against the pocket's end walls (the cage side rings),
    at the real axial pocket clearance per end, ``cage_pocket_clearance_axial_m / 2`` (the CFD's: ``c``), over
    the part of each end disc that faces the cage shell.

Not counted: the small rib (an assumption of the CFD geometry with no real clearance in the
bearing data), the roller's edge radius next to the rib (the gap opens from about 10 um to
0.7 mm over 0.7 mm: under 3 % of (a)), the eccentricity of a roller in its pocket (it raises (b)
as ``1 / sqrt(1 - e^2)`` for a full annulus, Petroff/Sommerfeld), and the pressure-driven part of
the rib film's dissipation: it is bounded (:func:`rib_film_loss`, ``pressure_flow_bound_W``) and
reported, not added; the Reynolds check (:func:`rib_film_reynolds`) puts it at 5 % of the Couette
part for the flooded 32208 at 2000 rpm, 50 degC, 1 kN, where the rigid isoviscous film carries
the rib load at 2.77 um against the contact model's 2.60 um.

Physics and sources
-------------------
Thin film between two surfaces in relative tangential motion ``u`` (Newtonian, isoviscous,
inertia-free): the velocity profile is the Couette profile plus the Poiseuille profile of the
pressure gradient, and the dissipation per unit area is

    q = eta |u|^2 / h + h^3 |grad p|^2 / (12 eta)

(the cross term integrates to zero across the film). Hamrock, Schmid and Jacobson,
*Fundamentals of Fluid Film Lubrication*, 2nd ed., Dekker 2004, Ch. 7 (velocity profile of the
Reynolds equation's derivation) and Ch. 8 (Petroff's equation: the concentric journal bearing's
torque ``2 pi eta omega R^3 l / c``). The concentric annulus is evaluated exactly (not in the
thin-gap limit): inner cylinder ``R1`` turning at ``omega``, outer ``R2`` at rest, the wall shear
stress on the inner cylinder is ``tau = 2 eta omega R2^2 / (R2^2 - R1^2)`` (the torque per unit
length ``4 pi eta omega R1^2 R2^2 / (R2^2 - R1^2)``: Landau and Lifshitz, *Fluid Mechanics*,
2nd ed., Sec. 18, flow between rotating cylinders), which tends to Petroff's ``eta omega R1 / c``
as ``c / R1 -> 0``.

The rib film's central thickness is the contact model's (seed paper, Wingertszahn et al. 2023,
Eq. 31-35: Hamrock-Dowson's elliptic central film thickness with the Zhu-Cheng thermal factor,
Eq. 11-14), evaluated as ``mbs_core`` ``evaluate_cell`` does: entrainment and sliding velocities
in the cage frame (where the contact stands still), the Hertz ellipse of the rib load. At light
load the rib contact is nearly rigid (Hertz approach 0.3 um at 17 N) and the film is
hydrodynamic (several um): the roller end / rib pair is highly conformal in the circumferential
direction (relative radius 1.25 m for the 32208, against 0.139 m along the rib generator).

Pressure flow (rib): for a steady film ``div(h^3 grad p / (12 eta)) = div(h u_m)`` (``u_m`` the
mean surface velocity); multiplying by ``p`` and integrating with ``p = 0`` on the edge of the
film (and in a cavitated zone) gives the pressure part of the dissipation exactly as
``-int p div(h u_m) dA``, and with ``p >= 0`` and ``int p dA = Q_rib`` it is at most
``Q_rib max |div(h u_m)|`` over the film. That bound is reported with the Couette term.

Units: SI throughout; names carry units.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = [
    "REFERENCE_AXIAL_LOAD_N",
    "couette_power_W",
    "annulus_couette_shear_stress_Pa",
    "annulus_couette_power_W",
    "film_dissipation_W",
    "rib_film_gap_m",
    "rib_film_loss",
    "rib_film_reynolds",
    "pocket_film_loss",
    "thin_film_losses",
    "RibFilmGrid",
]

#: The axial load the rib film's thickness is evaluated at when none is given: the seed paper's
#: flooded 32208 case (Wingertszahn et al. 2023, Section 4: 1 kN). The CFD points carry no load;
#: the rib film's loss depends on it only through the film thickness (Hamrock-Dowson, W^-0.067)
#: and the Hertz ellipse left to the contact model: 0.1 kN or 10 kN change it by a few per cent.
REFERENCE_AXIAL_LOAD_N = 1000.0

#: Accepted ranges (inclusive) of the inputs, for the range checks.
VISCOSITY_RANGE_PAS = (1e-5, 10.0)
GAP_RANGE_M = (1e-9, 0.1)
GRID_CELLS_RANGE = (20, 4000)


def _check(name: str, value: Any, lo: float, hi: float, what: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise ValueError(f"{name} = {value!r}: expected {what} in [{lo:g}, {hi:g}]")
    v = float(value)
    if not (math.isfinite(v) and lo <= v <= hi):
        raise ValueError(f"{name} = {value!r}: expected {what} in [{lo:g}, {hi:g}]")
    return v


def _check_array(name: str, a: np.ndarray, lo: float, hi: float, what: str) -> None:
    if not np.all(np.isfinite(a)) or (a.size and (float(a.min()) < lo or float(a.max()) > hi)):
        bad = a[~np.isfinite(a) | (a < lo) | (a > hi)].ravel()[:1]
        raise ValueError(f"{name}: {bad[0] if bad.size else a!r} out of range; expected {what} in [{lo:g}, {hi:g}]")


def couette_power_W(viscosity_Pas: float, sliding_speed_m_s: float, gap_m: float, area_m2: float) -> float:
    """Viscous power of a plane Couette film: ``eta u^2 A / h``.

    Parameters
    ----------
    viscosity_Pas
        Dynamic viscosity of the oil.
    sliding_speed_m_s
        Relative tangential speed of the two walls.
    gap_m
        Film thickness (the walls parallel).
    area_m2
        Wetted area.

    Returns
    -------
    float
        Dissipated power [W] (Hamrock, Schmid and Jacobson 2004, Ch. 7: Couette part of the film's
        dissipation).
    """
    eta = _check("viscosity_Pas", viscosity_Pas, *VISCOSITY_RANGE_PAS, "a dynamic viscosity in Pa s")
    u = _check("sliding_speed_m_s", sliding_speed_m_s, -1e3, 1e3, "a speed in m/s")
    h = _check("gap_m", gap_m, *GAP_RANGE_M, "a film thickness in m")
    A = _check("area_m2", area_m2, 0.0, 1.0, "an area in m^2")
    return eta * u * u * A / h


def annulus_couette_shear_stress_Pa(viscosity_Pas: float, omega_rad_s: float, inner_radius_m: float,
                                    gap_m: float) -> float:
    """Wall shear stress on the turning inner cylinder of a concentric annulus (outer at rest).

    ``tau = 2 eta omega R2^2 / (R2^2 - R1^2)``, ``R2 = R1 + gap``: the exact circular Couette
    flow (Landau and Lifshitz, Fluid Mechanics, Sec. 18: torque per unit length
    ``4 pi eta omega R1^2 R2^2 / (R2^2 - R1^2)``); Petroff's ``eta omega R1 / gap`` in the
    thin-gap limit (Hamrock, Schmid and Jacobson 2004, Ch. 8). Returns the magnitude [Pa].
    """
    eta = _check("viscosity_Pas", viscosity_Pas, *VISCOSITY_RANGE_PAS, "a dynamic viscosity in Pa s")
    w = _check("omega_rad_s", omega_rad_s, -1e5, 1e5, "an angular speed in rad/s")
    R1 = _check("inner_radius_m", inner_radius_m, 1e-6, 10.0, "a radius in m")
    c = _check("gap_m", gap_m, *GAP_RANGE_M, "a radial clearance in m")
    R2 = R1 + c
    return 2.0 * eta * abs(w) * R2 * R2 / ((R2 - R1) * (R2 + R1))


def annulus_couette_power_W(viscosity_Pas: float, omega_rad_s: float, inner_radius_m: float, gap_m: float,
                            inner_area_m2: float) -> float:
    """Power of the circular Couette flow over ``inner_area_m2`` of the inner cylinder:
    ``tau omega R1 A1`` (see :func:`annulus_couette_shear_stress_Pa`)."""
    tau = annulus_couette_shear_stress_Pa(viscosity_Pas, omega_rad_s, inner_radius_m, gap_m)
    A = _check("inner_area_m2", inner_area_m2, 0.0, 1.0, "an area in m^2")
    return tau * abs(omega_rad_s) * inner_radius_m * A


def film_dissipation_W(viscosity_Pas: float, sliding_speed_sq_m2_s2: np.ndarray, gap_m: np.ndarray,
                       cell_area_m2: float, mask: np.ndarray | None = None) -> float:
    """Couette dissipation ``sum eta |u|^2 / h dA`` of a film on a grid of equal cells.

    Parameters
    ----------
    viscosity_Pas
        Dynamic viscosity.
    sliding_speed_sq_m2_s2
        ``|u|^2`` of the relative tangential velocity in each cell.
    gap_m
        Film thickness in each cell (same shape).
    cell_area_m2
        Area of one cell.
    mask
        Cells that belong to the film (default: all).
    """
    eta = _check("viscosity_Pas", viscosity_Pas, *VISCOSITY_RANGE_PAS, "a dynamic viscosity in Pa s")
    dA = _check("cell_area_m2", cell_area_m2, 0.0, 1.0, "a cell area in m^2")
    u2 = np.asarray(sliding_speed_sq_m2_s2, float)
    h = np.asarray(gap_m, float)
    if u2.shape != h.shape:
        raise ValueError(f"sliding_speed_sq_m2_s2 {u2.shape} and gap_m {h.shape}: expected the same shape")
    m = np.ones(h.shape, bool) if mask is None else np.asarray(mask, bool)
    if m.shape != h.shape:
        raise ValueError(f"mask {m.shape}: expected the shape of gap_m {h.shape}")
    if not m.any():
        return 0.0
    _check_array("gap_m", h[m], *GAP_RANGE_M, "film thicknesses in m")
    _check_array("sliding_speed_sq_m2_s2", u2[m], 0.0, 1e6, "squared speeds in m^2/s^2")
    return float(eta * np.sum(u2[m] / h[m]) * dA)


# ---------------------------------------------------------------------------------------------
# geometry: frame (x, y, w) = (bearing axis, radial in the roller's axial plane, circumferential),
# right-handed; a point's axial position is x, its radius hypot(y, w). Roller 0 in the plane w = 0.
# ---------------------------------------------------------------------------------------------

def _to3(p2) -> np.ndarray:
    return np.array([float(p2[0]), float(p2[1]), 0.0])


def _xr(p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return p[..., 0], np.hypot(p[..., 1], p[..., 2])


def _ray_to_revolved_line(q: np.ndarray, d: np.ndarray, p0: np.ndarray, nu: np.ndarray) -> np.ndarray:
    """Parameter ``s`` where the rays ``q + s d`` (q: (..., 3), d: (3,)) meet the surface of
    revolution (about x) of the line through ``p0`` ((x, r)) with unit normal ``nu`` ((x, r));
    Newton on the signed distance in the (x, r) plane, from s = 0 (the rays start near it)."""
    s = np.zeros(q.shape[:-1])
    for _ in range(30):
        p = q + s[..., None] * d
        x, r = _xr(p)
        f = (x - p0[0]) * nu[0] + (r - p0[1]) * nu[1]
        dr = (p[..., 1] * d[1] + p[..., 2] * d[2]) / np.maximum(r, 1e-300)
        df = d[0] * nu[0] + dr * nu[1]
        step = f / df
        s = s - step
        if float(np.max(np.abs(step))) < 1e-15:
            break
    return s


@dataclass(frozen=True)
class RibFilmGrid:
    """The roller end / rib film on a grid in the rib's tangent plane at the contact point.

    ``xi`` along the rib generator (toward the rib top), ``eta`` circumferential; arrays of shape
    (n, n). ``gap_rigid_m`` is the real rigid gap (sphere to cone, 0 at the contact point),
    ``gap_cfd_m`` the CFD's (flat end to the rib set back by ``c``); ``on_film`` the cells on the
    end cap and the rib face; ``in_hertz`` the cells in the rib contact's Hertz ellipse.
    """

    xi_m: np.ndarray
    eta_m: np.ndarray
    cell_area_m2: float
    points_m: np.ndarray          # (n, n, 3) the points on the rib face
    normal: np.ndarray            # (3,) unit normal, rib -> roller
    gap_rigid_m: np.ndarray
    gap_cfd_m: np.ndarray
    on_film: np.ndarray
    in_hertz: np.ndarray


def rib_film_gap_m(g, clearance_m: float, *, cells: int = 200, hertz_semi_axes_m: tuple[float, float] = (0.0, 0.0),
                   edge_radius_m: float = 0.0) -> RibFilmGrid:
    """The real and the CFD's roller end / rib gaps of bearing ``g`` on a grid (see
    :class:`RibFilmGrid`).

    Parameters
    ----------
    g
        :class:`kegel.geometry.BearingGeometry`.
    clearance_m
        The CFD's roller end / rib clearance ``c``.
    cells
        Grid cells per side; the grid spans the roller end cap.
    hertz_semi_axes_m
        Semi-axes (along the generator, circumferential) of the rib contact's Hertz ellipse,
        centred on the contact point; its cells are marked ``in_hertz``.
    edge_radius_m
        The roller's edge radius: the spherical cap ends at ``D_L / 2 - edge_radius_m``.

    Notes
    -----
    Real geometry (:mod:`kegel.geometry`, steps 6-7): the end sphere (centre ``M + (L/2 - R_e) a``)
    touches the rib cone at the rib contact point, whose generator is normal to the sphere radius
    there. Along the rib normal from each grid point: the rib cone is met by Newton iteration, the
    sphere by the nearer root of a quadratic. In the axial plane (``eta = 0``) the generator is
    the tangent of the sphere's great circle, so there the gap is ``R_e - sqrt(R_e^2 - xi^2)``
    exactly (the tests check this). CFD geometry (:func:`kegel.cfd_cases.geometry.cfd_geometry`):
    the flat end (the plane through ``M + (L/2) a`` normal to ``a``) and the rib face through
    the roller's inner large-end corner set back by ``c`` along ``a``, parallel to the end face in
    the axial plane, revolved about the bearing axis.
    """
    c = _check("clearance_m", clearance_m, *GAP_RANGE_M, "a clearance in m")
    n_cells = int(_check("cells", cells, *GRID_CELLS_RANGE, "a number of grid cells"))
    a2 = np.asarray(g.roller_axis_unit(), float)
    n2 = np.array([-a2[1], a2[0]])
    M2 = np.asarray(g.roller_mid_point(), float)
    L, R_e = g.roller_length_m, g.roller_end_radius_m
    r_L = 0.5 * g.roller_large_end_diameter_m
    cap = r_L - _check("edge_radius_m", edge_radius_m, 0.0, r_L, "an edge radius in m")
    centre2 = M2 + (0.5 * L - R_e) * a2
    P2 = np.asarray(g.rib_contact_point_m, float)
    nu2 = (P2 - centre2) / R_e                     # roller -> rib, (x, r)
    t2 = np.array([-nu2[1], nu2[0]])               # along the generator
    if t2 @ n2 < 0.0:                              # toward the rib top (toward the roller axis)
        t2 = -t2
    normal = -_to3(nu2)                            # rib -> roller
    t1 = _to3(t2)
    tw = np.array([0.0, 0.0, 1.0])
    P = _to3(P2)
    # grid centred on the projection of the end-face centre, spanning the cap
    end_c = _to3(M2 + 0.5 * L * a2)
    xi0 = float((end_c - P) @ t1)
    half = 1.05 * cap
    edges = np.linspace(-half, half, n_cells + 1)
    mid = 0.5 * (edges[:-1] + edges[1:])
    XI, ETA = np.meshgrid(xi0 + mid, mid, indexing="ij")
    q = P + XI[..., None] * t1 + ETA[..., None] * tw
    # real rib cone: the generator through P tangent to the sphere (normal nu2)
    s_rib = _ray_to_revolved_line(q, normal, P2, nu2)
    C3 = _to3(centre2)
    w = q - C3
    b = w @ normal
    disc = b * b - np.einsum("...i,...i", w, w) + R_e * R_e
    s_sph = -b - np.sqrt(np.maximum(disc, 0.0))    # the sphere's near side (toward the rib)
    x_sph = q + s_sph[..., None] * normal
    a3 = _to3(a2)
    rel = x_sph - C3
    off_axis = np.linalg.norm(rel - (rel @ a3)[..., None] * a3, axis=-1)
    x_rib = q + s_rib[..., None] * normal
    _, r_rib = _xr(x_rib)
    on_film = (disc >= 0.0) & (off_axis <= cap) & (r_rib <= g.rib_top_point_m[1]) & ((rel @ a3) > 0.0)
    gap = s_sph - s_rib
    # CFD: flat end plane and the rib face line through the corner set back by c along a
    corner2 = np.asarray(g.inner_raceway_large_end_m, float) + c * a2
    s_rib_cfd = _ray_to_revolved_line(q, normal, corner2, a2)
    s_plane = ((end_c - q) @ a3) / float(normal @ a3)
    gap_cfd = s_plane - s_rib_cfd
    ax, bx = hertz_semi_axes_m
    in_hertz = np.zeros(XI.shape, bool)
    if ax > 0.0 and bx > 0.0:
        in_hertz = (XI / ax) ** 2 + (ETA / bx) ** 2 <= 1.0
    dA = float((edges[1] - edges[0]) ** 2)
    return RibFilmGrid(xi_m=XI, eta_m=ETA, cell_area_m2=dA, points_m=0.5 * (x_sph + x_rib), normal=normal,
                       gap_rigid_m=np.where(on_film, gap, np.inf), gap_cfd_m=gap_cfd, on_film=on_film,
                       in_hertz=in_hertz)


def _kinematics(g, inner_speed_rad_s: float) -> dict[str, float]:
    from .run import kinematics

    return kinematics(g, inner_speed_rad_s)


def _surface_velocities(g, kin: dict[str, float], p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Velocities in the cage frame of the roller surface (its spin about its axis through M)
    and of the inner ring (about the bearing axis) at points ``p`` (..., 3)."""
    a3 = _to3(g.roller_axis_unit())
    M3 = _to3(g.roller_mid_point())
    ex = np.array([1.0, 0.0, 0.0])
    u_roller = kin["roller_spin_rad_s"] * np.cross(a3, p - M3)
    u_ring = (kin["inner_ring_rad_s"] - kin["cage_rad_s"]) * np.cross(ex, p)
    return u_roller, u_ring


def _tangential(u: np.ndarray, normal: np.ndarray) -> np.ndarray:
    return u - (u @ normal)[..., None] * normal


def rib_film_loss(g, bearing, lubricant: str, temperature_K: float, inner_speed_rad_s: float, clearance_m: float, *,
                  rib_load_N: float | None = None, cells: int = 200, material: str = "bearing_steel",
                  film_thickness_m: float | None = None) -> dict[str, Any]:
    """Loss of the roller end / rib films of all rollers that the CFD misses (term (a)).

    ``sum over the film, outside the Hertz ellipse, of eta |u|^2 (1/h - 1/h_cfd) dA``, times Z,
    with ``h = h_film + g_rigid`` (see the module docstring).

    Parameters
    ----------
    g, bearing
        :class:`kegel.geometry.BearingGeometry` and its :class:`kegel.data.BearingData`.
    lubricant, temperature_K
        Lubricant name and the oil temperature.
    inner_speed_rad_s
        Inner ring speed (outer ring fixed; cage and roller spin from pure rolling).
    clearance_m
        The CFD's roller end / rib clearance ``c``.
    rib_load_N
        The rib load of one roller; default: :func:`kegel.tribology.axial_roller_loads` at
        :data:`REFERENCE_AXIAL_LOAD_N`.
    cells
        Grid cells per side.
    material
        The rings' and rollers' material (reduced modulus of the Hertz ellipse and film formula).
    film_thickness_m
        The central film thickness at the rib contact; default: the contact model's (Hamrock-Dowson
        with the Zhu-Cheng factor, as ``evaluate_cell``). Given: for a sensitivity study.

    Returns
    -------
    dict
        ``loss_W`` (the term), ``real_film_W`` and ``cfd_film_W`` (its two parts, all rollers),
        ``loss_torque_Nm`` (``loss_W`` over the shaft speed), ``pressure_flow_bound_W`` (all rollers),
        ``film_thickness_m`` (central, at the contact), ``gap_range_m`` (min, max of the real film
        over the counted area), ``area_m2`` (counted, one roller), ``sliding_speed_m_s`` and
        ``entrainment_speed_m_s`` at the contact point, ``rib_load_N``, ``hertz_semi_axes_m``.
    """
    from kegel import _core
    from kegel.model.data import load_lubricant, load_material
    from kegel.model.lubricant import lubricant_state
    from kegel.physics.tribology import axial_roller_loads

    w_i = _check("inner_speed_rad_s", inner_speed_rad_s, 1e-3, 1e4, "a shaft speed in rad/s")
    T = _check("temperature_K", temperature_K, 200.0, 500.0, "a temperature in K")
    Q = (axial_roller_loads(g, REFERENCE_AXIAL_LOAD_N)["rib_N"] if rib_load_N is None
         else _check("rib_load_N", rib_load_N, 1e-3, 1e6, "a rib load in N"))
    lub = load_lubricant(lubricant)
    state = lubricant_state(lub, T)
    cls = _core.tribology.make_contact_lubricant_state(lub.core, T)
    mat = load_material(material)
    E = _core.reduced_modulus_Pa(mat.core, mat.core)
    from kegel.physics.contact import RibContact

    rc = RibContact(g, bearing, mat)
    hz = _core.contact.hertz_point_contact_load(rc.Rx_m, rc.Ry_m, E, Q)
    x_minor = rc.Rx_m <= rc.Ry_m
    semi = (hz["semi_minor_m"], hz["semi_major_m"]) if x_minor else (hz["semi_major_m"], hz["semi_minor_m"])
    grid = rib_film_gap_m(g, clearance_m, cells=cells, hertz_semi_axes_m=semi, edge_radius_m=bearing.edge_radius_m)
    kin = _kinematics(g, w_i)
    u_r, u_i = _surface_velocities(g, kin, grid.points_m)
    u_r, u_i = _tangential(u_r, grid.normal), _tangential(u_i, grid.normal)
    slide = u_r - u_i
    # film thickness at the contact point (as mbs_core evaluate_cell: cage-frame velocities)
    P = _to3(g.rib_contact_point_m)
    ur0, ui0 = (_tangential(v, grid.normal) for v in _surface_velocities(g, kin, P))
    u_av = 0.5 * float(np.linalg.norm(ur0 + ui0))
    u_s = float(np.linalg.norm(ur0 - ui0))
    h_iso = _core.tribology.elliptic_film_thickness_m(cls.eta0_Pas, u_av, rc.Rx_m, rc.Ry_m, Q, cls.alpha_p_1_Pa, E)
    p_mean = Q / (math.pi * hz["semi_major_m"] * hz["semi_minor_m"])
    phi = _core.tribology.zhu_cheng_factor(p_mean, E, u_s, 2.0 * u_av, cls.deta_dtheta_Pas_K, u_av,
                                           state.thermal_conductivity_W_mK)
    h_film = phi * h_iso if film_thickness_m is None else _check("film_thickness_m", film_thickness_m, *GAP_RANGE_M,
                                                                   "a film thickness in m")
    eta = state.dynamic_viscosity_Pas
    h = h_film + grid.gap_rigid_m
    mask = grid.on_film & ~grid.in_hertz
    u2 = np.einsum("...i,...i", slide, slide)
    real = film_dissipation_W(eta, u2, np.where(mask, h, 1.0), grid.cell_area_m2, mask)
    cfd = film_dissipation_W(eta, u2, np.where(mask, grid.gap_cfd_m, 1.0), grid.cell_area_m2, mask)
    Z = g.roller_count
    # pressure flow: at most Q max|div(h u_m)| (module docstring); u_m the mean surface velocity
    um = 0.5 * (u_r + u_i)
    dxi, deta = float(grid.xi_m[1, 0] - grid.xi_m[0, 0]), float(grid.eta_m[0, 1] - grid.eta_m[0, 0])
    # tangent-plane components: xi along the generator, eta circumferential
    gen = grid.points_m[1, 0] - grid.points_m[0, 0]
    gen = gen - (gen @ grid.normal) * grid.normal
    gen /= np.linalg.norm(gen)
    circ = np.cross(grid.normal, gen)
    hx = np.where(grid.on_film, h, np.nan)   # the pressure acts over the whole film, Hertz zone included
    fx, fe = hx * (um @ gen), hx * (um @ circ)
    div = np.gradient(fx, dxi, axis=0) + np.gradient(fe, deta, axis=1)
    div_max = float(np.nanmax(np.abs(div))) if np.isfinite(div).any() else 0.0
    hm = h[mask]
    return {
        "loss_W": Z * (real - cfd), "real_film_W": Z * real, "cfd_film_W": Z * cfd,
        "loss_torque_Nm": Z * (real - cfd) / w_i,
        "pressure_flow_bound_W": Z * Q * div_max,
        "film_thickness_m": h_film, "film_thickness_isothermal_m": h_iso, "thermal_factor": phi,
        "gap_range_m": [float(hm.min()), float(hm.max())] if hm.size else [0.0, 0.0],
        "area_m2": float(mask.sum()) * grid.cell_area_m2,
        "sliding_speed_m_s": u_s, "entrainment_speed_m_s": u_av,
        "rib_load_N": Q, "hertz_semi_axes_m": [float(semi[0]), float(semi[1])],
        "viscosity_Pas": eta,
    }


def _reynolds_pressure_Pa(h: np.ndarray, um_x: np.ndarray, um_y: np.ndarray, film: np.ndarray, dx: float, dy: float,
                          viscosity_Pas: float, max_sets: int = 50) -> np.ndarray:
    """Pressure of the steady, rigid, isoviscous Reynolds equation
    ``div(h^3 grad p / (12 eta)) = div(h u_m)`` on the cells ``film`` (p = 0 elsewhere), with
    cavitation by active sets: cells with negative pressure are set to 0 and dropped until none
    is left (the Reynolds / Swift-Stieber condition p = 0, dp/dn = 0 at the film's rupture, to the
    grid's resolution). Five-point conservative differences, face values as cell means; p = 0 on
    the faces of the film's edge."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.linalg import spsolve

    nx, ny = h.shape
    k = h**3 / (12.0 * viscosity_Pas)
    fx, fy = h * um_x, h * um_y
    active = film.copy()
    p = np.zeros_like(h)
    for _ in range(max_sets):
        idx = -np.ones(h.shape, int)
        cells = np.argwhere(active)
        idx[active] = np.arange(len(cells))
        rows, cols, vals = [], [], []
        rhs = np.zeros(len(cells))
        for di, dj, d, f in ((1, 0, dx, fx), (-1, 0, dx, fx), (0, 1, dy, fy), (0, -1, dy, fy)):
            i2, j2 = cells[:, 0] + di, cells[:, 1] + dj
            inside = (i2 >= 0) & (i2 < nx) & (j2 >= 0) & (j2 < ny)
            i2c, j2c = np.clip(i2, 0, nx - 1), np.clip(j2, 0, ny - 1)
            on = inside & film[i2c, j2c]
            kf = np.where(on, 0.5 * (k[cells[:, 0], cells[:, 1]] + k[i2c, j2c]), k[cells[:, 0], cells[:, 1]])
            ff = np.where(on, 0.5 * (f[cells[:, 0], cells[:, 1]] + f[i2c, j2c]), f[cells[:, 0], cells[:, 1]])
            # p = 0 on the face to a cell off the film: half a cell away
            a = np.where(on, kf / (d * d), 2.0 * kf / (d * d))
            n = np.arange(len(cells))
            rows += [n]
            cols += [n]
            vals += [-a]
            nb = on & active[i2c, j2c]
            rows += [n[nb]]
            cols += [idx[i2c[nb], j2c[nb]]]
            vals += [a[nb]]
            # flux out through this face: sign + for the +1 neighbours
            rhs += (1.0 if (di + dj) > 0 else -1.0) * ff / d
        A = coo_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                       shape=(len(cells), len(cells))).tocsr()
        sol = spsolve(A, rhs)
        p = np.zeros_like(h)
        p[active] = sol
        negative = active & (p < 0.0)
        if not negative.any():
            return np.maximum(p, 0.0)
        active &= ~negative
    return np.maximum(p, 0.0)


def rib_film_reynolds(g, bearing, lubricant: str, temperature_K: float, inner_speed_rad_s: float, *,
                      rib_load_N: float | None = None, cells: int = 120) -> dict[str, Any]:
    """A check of the rib film's thickness and of its pressure-flow dissipation: the rigid,
    isoviscous Reynolds film of the real roller end / rib gap (no Hertz zone), with the central
    film thickness that makes its hydrodynamic pressure carry the rib load.

    At light load the rib pair is nearly rigid (17 N at 1 kN axial on the 32208: Hertz approach
    0.3 um) and its pressure (tens of MPa) raises the viscosity by ``exp(alpha p)``, which this
    isoviscous check leaves out, so it gives a lower bound of the film that carries the load.

    Returns
    -------
    dict
        ``film_thickness_m`` (the minimum gap that carries ``rib_load_N``), ``couette_W`` and
        ``pressure_flow_W`` (dissipation of the whole film of one roller, Hertz zone included),
        ``rib_load_N``, ``max_pressure_Pa``.
    """
    from scipy.optimize import brentq

    from kegel.model.lubricant import lubricant_state
    from kegel.physics.tribology import axial_roller_loads

    w_i = _check("inner_speed_rad_s", inner_speed_rad_s, 1e-3, 1e4, "a shaft speed in rad/s")
    Q = (axial_roller_loads(g, REFERENCE_AXIAL_LOAD_N)["rib_N"] if rib_load_N is None
         else _check("rib_load_N", rib_load_N, 1e-3, 1e6, "a rib load in N"))
    eta = lubricant_state(lubricant, temperature_K).dynamic_viscosity_Pas
    grid = rib_film_gap_m(g, 1e-3, cells=cells, edge_radius_m=bearing.edge_radius_m)
    kin = _kinematics(g, w_i)
    u_r, u_i = (_tangential(v, grid.normal) for v in _surface_velocities(g, kin, grid.points_m))
    gen = grid.points_m[1, 0] - grid.points_m[0, 0]
    gen = gen - (gen @ grid.normal) * grid.normal
    gen /= np.linalg.norm(gen)
    circ = np.cross(grid.normal, gen)
    um = 0.5 * (u_r + u_i)
    slide = u_r - u_i
    dx, dy = float(grid.xi_m[1, 0] - grid.xi_m[0, 0]), float(grid.eta_m[0, 1] - grid.eta_m[0, 0])
    film = grid.on_film
    dA = grid.cell_area_m2

    def solve(h0: float) -> tuple[np.ndarray, np.ndarray]:
        h = np.where(film, h0 + grid.gap_rigid_m, 1.0)
        return h, _reynolds_pressure_Pa(h, um @ gen, um @ circ, film, dx, dy, eta)

    def excess(log_h0: float) -> float:
        _, p = solve(math.exp(log_h0))
        return math.log(max(float(p.sum()) * dA, 1e-300) / Q)

    log_h = brentq(excess, math.log(1e-8), math.log(1e-4), xtol=1e-3)
    h, p = solve(math.exp(log_h))
    gx = np.gradient(np.where(film, p, 0.0), dx, axis=0)
    gy = np.gradient(np.where(film, p, 0.0), dy, axis=1)
    couette = float(np.sum(np.where(film, eta * np.einsum("...i,...i", slide, slide) / h, 0.0)) * dA)
    poiseuille = float(np.sum(np.where(film, h**3 * (gx * gx + gy * gy) / (12.0 * eta), 0.0)) * dA)
    return {"film_thickness_m": math.exp(log_h), "couette_W": couette, "pressure_flow_W": poiseuille,
            "rib_load_N": Q, "max_pressure_Pa": float(p.max())}


def _inside_shell(g, p: np.ndarray) -> np.ndarray:
    """Whether points ``p`` (..., 3) lie inside the cage shell (its (x, r) section)."""
    from kegel.model.geometry import CAGE_OFFSET_RATIO, CAGE_OVERHANG_RATIO, CAGE_THICKNESS_RATIO

    a2 = np.asarray(g.roller_axis_unit(), float)
    n2 = np.array([-a2[1], a2[0]])
    Dw, L = g.roller_mean_diameter_m, g.roller_length_m
    small = np.asarray(g.roller_mid_point(), float) - 0.5 * L * a2
    x, r = _xr(p)
    rel_x, rel_r = x - small[0], r - small[1]
    along = rel_x * a2[0] + rel_r * a2[1]
    off = rel_x * n2[0] + rel_r * n2[1]
    mid, t = CAGE_OFFSET_RATIO * Dw, 0.5 * CAGE_THICKNESS_RATIO * Dw
    return ((off >= mid - t) & (off <= mid + t) & (along >= -CAGE_OVERHANG_RATIO * L)
            & (along <= (1 + CAGE_OVERHANG_RATIO) * L))


def _pocket_side_power_W(g, eta: float, omega_s: float, gap_m: float, n_axial: int, n_theta: int) -> tuple[float, float]:
    """Circular Couette power of one roller's lateral surface against its pocket walls at radial
    clearance ``gap_m`` (the pocket cone: the roller cone grown by it), and the wall's inner area."""
    a2 = np.asarray(g.roller_axis_unit(), float)
    n2 = np.array([-a2[1], a2[0]])
    M2 = np.asarray(g.roller_mid_point(), float)
    L = g.roller_length_m
    tan_g = math.tan(g.roller_half_angle_rad)
    ds = L / n_axial
    s = -0.5 * L + (np.arange(n_axial) + 0.5) * ds
    dth = 2.0 * math.pi / n_theta
    th = (np.arange(n_theta) + 0.5) * dth
    S, TH = np.meshgrid(s, th, indexing="ij")
    R1 = 0.5 * g.roller_mean_diameter_m + S * tan_g
    rho = R1 + gap_m
    base = M2[None, None, :] + S[..., None] * a2
    p = np.zeros(S.shape + (3,))
    p[..., 0] = base[..., 0] + rho * np.cos(TH) * n2[0]
    p[..., 1] = base[..., 1] + rho * np.cos(TH) * n2[1]
    p[..., 2] = rho * np.sin(TH)
    wall = _inside_shell(g, p)
    R1w = R1[wall]
    R2w = R1w + gap_m
    tau = 2.0 * eta * abs(omega_s) * R2w * R2w / ((R2w - R1w) * (R2w + R1w))
    dA1 = R1w * dth * ds / math.cos(g.roller_half_angle_rad)
    return float(np.sum(tau * abs(omega_s) * R1w * dA1)), float(np.sum(dA1))


def _pocket_end_power_W(g, eta: float, omega_s: float, gap_m: float, n_r: int, n_theta: int) -> tuple[float, float]:
    """Couette power of one roller's two end faces (spinning discs) against the pocket's end walls
    at axial clearance ``gap_m``, over the part of each disc that faces the cage shell."""
    a2 = np.asarray(g.roller_axis_unit(), float)
    n2 = np.array([-a2[1], a2[0]])
    M2 = np.asarray(g.roller_mid_point(), float)
    L = g.roller_length_m
    total_W, total_A = 0.0, 0.0
    for sign, radius in ((-1.0, 0.5 * g.roller_small_end_diameter_m), (1.0, 0.5 * g.roller_large_end_diameter_m)):
        dr = radius / n_r
        rr = (np.arange(n_r) + 0.5) * dr
        dth = 2.0 * math.pi / n_theta
        th = (np.arange(n_theta) + 0.5) * dth
        RR, TH = np.meshgrid(rr, th, indexing="ij")
        centre = M2 + sign * (0.5 * L + gap_m) * a2      # on the pocket's end wall
        p = np.zeros(RR.shape + (3,))
        p[..., 0] = centre[0] + RR * np.cos(TH) * n2[0]
        p[..., 1] = centre[1] + RR * np.cos(TH) * n2[1]
        p[..., 2] = RR * np.sin(TH)
        wall = _inside_shell(g, p)
        dA = RR[wall] * dr * dth
        total_W += float(np.sum(eta * (omega_s * RR[wall]) ** 2 / gap_m * dA))
        total_A += float(np.sum(dA))
    return total_W, total_A


def pocket_film_loss(g, viscosity_Pas: float, inner_speed_rad_s: float, clearance_m: float, *,
                     n_axial: int = 200, n_theta: int = 2000) -> dict[str, Any]:
    """Loss of the roller / cage pocket films of all rollers that the CFD misses (terms (b), (c)).

    Each roller spins (relative to the cage, where the pocket stands still) at the pure-rolling
    spin; its lateral surface and its end faces shear the oil against the pocket walls. The term
    is the loss at the real pocket clearances per side (half the data's totals: radial
    ``cage_pocket_clearance_circumferential_m / 2``, axial ``cage_pocket_clearance_axial_m / 2``;
    the roller centred in its pocket) minus that at the CFD's clearance ``c`` over the CFD's
    walls (sides: exact circular Couette flow, :func:`annulus_couette_shear_stress_Pa`; ends:
    plane Couette flow of a spinning disc, ``eta (omega r)^2 / h``). A real clearance at or above
    ``clearance_m`` counts nothing (the CFD then has the real pocket). The pocket walls are taken
    conformal to the roller, as in the CFD geometry (the roller cone grown by the clearance); a
    flat-walled pocket would have a wider film where the cage sheet meets the roller.

    Returns
    -------
    dict
        ``sides`` and ``ends``, each with ``loss_W``, ``real_film_W``, ``cfd_film_W`` (all rollers)
        and ``wall_area_m2`` (one roller, real); ``loss_W`` and ``loss_torque_Nm`` of both.
    """
    eta = _check("viscosity_Pas", viscosity_Pas, *VISCOSITY_RANGE_PAS, "a dynamic viscosity in Pa s")
    w_i = _check("inner_speed_rad_s", inner_speed_rad_s, 1e-3, 1e4, "a shaft speed in rad/s")
    c = _check("clearance_m", clearance_m, *GAP_RANGE_M, "a clearance in m")
    for name, n in (("n_axial", n_axial), ("n_theta", n_theta)):
        _check(name, n, *GRID_CELLS_RANGE, "a number of grid cells")
    omega_s = _kinematics(g, w_i)["roller_spin_rad_s"]
    Z = g.roller_count
    out: dict[str, Any] = {}
    # the data's pocket clearances are totals over both sides (kegel/data/bearings/32216.toml,
    # [assumed]; mbs_core dynamics.cpp: pocket wall at r + clearance / 2): half of each per side
    for part, real_gap, fn, n1 in (("sides", 0.5 * g.cage_pocket_clearance_circumferential_m, _pocket_side_power_W, n_axial),
                                   ("ends", 0.5 * g.cage_pocket_clearance_axial_m, _pocket_end_power_W, n_axial)):
        if real_gap >= c:
            out[part] = {"loss_W": 0.0, "real_film_W": 0.0, "cfd_film_W": 0.0, "wall_area_m2": 0.0,
                         "real_clearance_m": real_gap}
            continue
        real, area = fn(g, eta, omega_s, real_gap, n1, n_theta)
        cfd, _ = fn(g, eta, omega_s, c, n1, n_theta)
        out[part] = {"loss_W": Z * (real - cfd), "real_film_W": Z * real, "cfd_film_W": Z * cfd,
                     "wall_area_m2": area, "real_clearance_m": real_gap}
    out["loss_W"] = out["sides"]["loss_W"] + out["ends"]["loss_W"]
    out["loss_torque_Nm"] = out["loss_W"] / w_i
    return out


def oil_bath_film_factors(g, bearing, *, oil_level_m: float, inner_speed_rad_s: float,
                          kinematic_viscosity_m2_s: float) -> dict[str, Any]:
    """The supply factors of the thin films in an oil bath: the share of the full (flooded) film
    loss each film keeps, by the model the raceway contacts use (:mod:`kegel.coupling.supply`).

    A film is full over the share ``x`` of its orbit under the oil surface
    (:func:`kegel.coupling.supply.immersed_fraction` at its radius: the rib film at the rib
    contact point, the pocket films at the pitch radius) and filled to SKF's kinematic
    replenishment factor ``phi_rs`` above it (``K_rs`` of the low-level oil bath): ``f = x + (1 -
    x) phi_rs``. The viscous loss of a Couette film scales with its wetted area, so each film's
    loss is ``f`` times its flooded value. An assumption carried over from the raceway contacts,
    not a film model of its own: the rib and the pocket faces pass through the bath every
    revolution and carry its oil round, so ``f`` is near 1 at moderate speed (0.96 for the 32208
    at 2000 rpm, 50 degC, oil to the shaft centre).

    Returns
    -------
    dict
        ``rib`` and ``pockets`` (the factors), ``immersed_rib``, ``immersed_pockets``, ``phi_rs``,
        ``K_rs`` and ``model``.
    """
    from kegel.coupling.supply import K_RS, immersed_fraction, skf_replenishment_factor

    D = bearing.outer_diameter_m
    phi = skf_replenishment_factor(K_rs=K_RS["oil_bath"], kinematic_viscosity_m2_s=kinematic_viscosity_m2_s,
                                   speed_rpm=abs(inner_speed_rad_s) * 30.0 / math.pi, bore_m=bearing.bore_diameter_m,
                                   outer_diameter_m=D)
    x_rib = immersed_fraction(oil_level_m, D, g.rib_contact_point_m[1])
    x_pocket = immersed_fraction(oil_level_m, D, 0.5 * g.pitch_diameter_m)
    return {"rib": x_rib + (1.0 - x_rib) * phi, "pockets": x_pocket + (1.0 - x_pocket) * phi,
            "immersed_rib": x_rib, "immersed_pockets": x_pocket, "phi_rs": phi, "K_rs": K_RS["oil_bath"],
            "model": "full film under the oil surface, SKF's kinematic replenishment factor above it "
                     "(the raceway contacts' supply model, kegel.coupling.supply)"}


def thin_film_losses(g, bearing, *, lubricant: str, temperature_K: float, inner_speed_rad_s: float,
                     clearance_m: float, rib_load_N: float | None = None, cells: int = 200,
                     material: str = "bearing_steel", oil_level_m: float | None = None) -> dict[str, Any]:
    """All thin-film terms of a CFD point, as they go into its ``results.json``.

    Parameters
    ----------
    g, bearing
        :class:`kegel.geometry.BearingGeometry` and its :class:`kegel.data.BearingData`.
    lubricant, temperature_K, inner_speed_rad_s
        The CFD point's oil, temperature and shaft speed.
    clearance_m
        The CFD geometry's clearance ``c`` (``CfdGeometry.clearance_m``).
    rib_load_N
        One roller's rib load (default: at :data:`REFERENCE_AXIAL_LOAD_N` axial load).
    cells, material
        See :func:`rib_film_loss`.
    oil_level_m
        ``None``: flooded, every film full. An oil level (above the lowest point of the outer
        diameter): each term times its film's supply factor (:func:`oil_bath_film_factors`,
        written as ``supply``).

    Returns
    -------
    dict
        ``loss_torque_Nm`` (at the shaft, all terms), ``power_loss_W``, ``parts_Nm`` (``rib``,
        ``pocket_sides``, ``pocket_ends``) and the details of each term (``rib``, ``pocket``,
        flooded), ``supply`` for an oil bath.
    """
    from kegel.model.lubricant import lubricant_state

    rib = rib_film_loss(g, bearing, lubricant, temperature_K, inner_speed_rad_s, clearance_m,
                        rib_load_N=rib_load_N, cells=cells, material=material)
    oil = lubricant_state(lubricant, temperature_K)
    pocket = pocket_film_loss(g, oil.dynamic_viscosity_Pas, inner_speed_rad_s, clearance_m)
    w = abs(inner_speed_rad_s)
    supply = None
    f_rib = f_pocket = 1.0
    if oil_level_m is not None:
        supply = oil_bath_film_factors(g, bearing, oil_level_m=oil_level_m, inner_speed_rad_s=inner_speed_rad_s,
                                       kinematic_viscosity_m2_s=oil.kinematic_viscosity_m2_s)
        f_rib, f_pocket = supply["rib"], supply["pockets"]
    parts = {"rib": f_rib * rib["loss_W"] / w, "pocket_sides": f_pocket * pocket["sides"]["loss_W"] / w,
             "pocket_ends": f_pocket * pocket["ends"]["loss_W"] / w}
    total_W = f_rib * rib["loss_W"] + f_pocket * pocket["loss_W"]
    return {"loss_torque_Nm": total_W / w, "power_loss_W": total_W, "parts_Nm": parts, "supply": supply,
            "clearance_m": clearance_m,
            "rib_load_N": rib["rib_load_N"],
            "rib_load_from": "given" if rib_load_N is not None else f"axial load {REFERENCE_AXIAL_LOAD_N:g} N",
            "rib": rib, "pocket": pocket,
            "source": "kegel.cfd_cases.thin_films: real film minus the CFD's film (Couette estimate) over the "
                      "same walls; the rib contact's Hertz ellipse is the contact model's"}
