"""Quasi-static load distribution of a tapered roller bearing (C++ core, ``kegel._core.quasi_static``).

:func:`load_distribution` builds the bearing model from the derived geometry and solves the
inner ring's equilibrium under axial load, radial load and tilt moment: ring displacement, each
roller's outer, inner and rib loads. Frame: z along the bearing axis towards the rollers' large
ends, x along the radial load (the load zone is centred at azimuth 0); see
``mbs_core/include/kegel/core/quasi_static.hpp``.

Kinematics with slip and the friction torque build on this (issue "Quasi-static bearing
solution", next steps).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import _core
from ..model.data import BearingData, MaterialData
from ..base.errors import KegelInputError, KegelSolverError
from ..model.geometry import BearingGeometry
from ..physics.tribology import cage_speed_rad_s as pure_rolling_cage_speed

Q = _core.quasi_static

__all__ = ["BearingFrictionResult", "LoadDistribution", "GATE_TOLERANCES", "ROLLING_SPIN_SHARE", "MAX_SLICES", "bearing_friction", "bearing_model",
           "load_distribution", "plausibility_failures", "ring_lubricant_states"]


from ..model.options import MAX_SLICES  # noqa: E402  (the scene's limit too: kegel.model.options)


def bearing_model(g: BearingGeometry, bearing: BearingData, material: MaterialData, *, slices: int = 30,
                  method: str = "alternative_slicing") -> "Q.BearingModel":
    """The C++ bearing model of a bearing's derived geometry."""
    if method not in ("alternative_slicing", "independent"):
        raise KegelInputError("<argument>", "method", method, "'alternative_slicing' or 'independent'")
    if not (isinstance(slices, int) and 2 <= slices <= MAX_SLICES):
        raise KegelInputError("<argument>", "slices", slices, f"an integer in [2, {MAX_SLICES}]")
    v = Q.BearingModelValues()
    v.roller_count = g.roller_count
    v.pitch_radius_m = 0.5 * g.pitch_diameter_m
    v.roller_mid_z_m = g.roller_mid_x_m
    v.roller_axis_angle_rad = g.roller_axis_angle_rad
    v.apex_z_m = g.apex_x_m
    v.cup_angle_rad = g.cup_angle_rad
    v.cone_angle_rad = g.cone_angle_rad
    v.roller_mean_radius_m = 0.5 * g.roller_mean_diameter_m
    v.roller_half_angle_rad = g.roller_half_angle_rad
    v.roller_length_m = g.roller_length_m
    v.roller_mass_kg = g.roller_mass_kg
    v.cage_pocket_clearance_m = g.cage_pocket_clearance_circumferential_m
    v.E_reduced_Pa = _core.reduced_modulus_Pa(material.core, material.core)
    phi = g.rib_face_angle_to_radial_plane_rad
    x_p, r_p = g.rib_contact_point_m
    v.rib_half_angle_rad = 0.5 * math.pi + phi
    v.rib_apex_z_m = x_p + r_p * math.tan(phi)
    v.rib_outer_radius_m = g.rib_top_point_m[1]
    v.end_sphere_radius_m = g.roller_end_radius_m
    v.end_cap_radius_m = 0.5 * g.roller_large_end_diameter_m - bearing.edge_radius_m
    v.end_sphere_offset_m = 0.5 * g.roller_length_m - g.roller_end_radius_m
    v.slices = slices
    v.method = (_core.contact.SliceMethod.alternative_slicing if method == "alternative_slicing"
                else _core.contact.SliceMethod.independent)
    v.set_profile(bearing.roller_mean_diameter_m, bearing.roller_length_m, bearing.profile_a_p, bearing.profile_c_p_m,
                  bearing.profile_d_p_m, bearing.profile_k_p_m, bearing.edge_radius_m)
    return Q.BearingModel(v)


@dataclass(frozen=True)
class LoadDistribution:
    """Result of :func:`load_distribution` (SI units; azimuths in rad from the radial load)."""

    ring_displacement_m: np.ndarray   # dx, dy, dz of the inner ring
    ring_tilt_rad: np.ndarray         # rx, ry
    reaction_moment_Nm: np.ndarray    # moment of the rollers on the ring about x, y (imposed tilt)
    axial_force_N: float              # axial force carried by the rollers
    azimuth_rad: np.ndarray
    outer_N: np.ndarray
    inner_N: np.ndarray
    rib_N: np.ndarray
    residual: float                   # ring equilibrium residual / load scale
    roller_residual_max: float
    iterations: int
    runtime_s: float
    #: loaded length of each roller's line contacts [m], one row per roller, columns (inner,
    #: outer): the widths of the slices that carry load (the rest of the line is unloaded)
    loaded_length_m: np.ndarray | None = None

    @property
    def loaded(self) -> np.ndarray:
        """Rollers carrying load at the inner raceway."""
        return self.inner_N > 1e-6 * max(self.inner_N.max(), 1e-300)


def _loads(axial_N: float | None, axial_offset_m: float | None, radial_N: float, tilt_moment_Nm: float,
           misalignment_rad: float) -> "Q.BearingLoads":
    loads = Q.BearingLoads()
    if axial_offset_m is not None:
        loads.axial_offset_controlled = True
        loads.axial_offset_m = axial_offset_m
    else:
        loads.axial_N = axial_N
    loads.radial_N = radial_N
    loads.tilt_moment_Nm = tilt_moment_Nm
    loads.misalignment_y_rad = misalignment_rad
    return loads


def load_distribution(g: BearingGeometry, bearing: BearingData, material: MaterialData, *,
                      axial_N: float | None = None, axial_offset_m: float | None = None, radial_N: float = 0.0, tilt_moment_Nm: float = 0.0, misalignment_rad: float = 0.0,
                      tilt_free: bool = False, cage_speed_rad_s: float = 0.0,
                      slices: int = 30, method: str = "alternative_slicing",
                      model: "Q.BearingModel | None" = None, data: "Q.BearingData | None" = None) -> LoadDistribution:
    """Solve the quasi-static load distribution (see the module docstring).

    The inner ring's tilt is imposed (``misalignment_rad`` about the axis normal to the radial
    load; the moment is then an output) unless ``tilt_free``, when ``tilt_moment_Nm`` is
    imposed instead. The axial load is force-controlled (``axial_N``) or displacement-controlled
    (``axial_offset_m``: the inner ring pushed towards the apex by this much; the axial force is
    then an output). ``model`` and ``data`` may be passed in to reuse them (``data`` then
    warm-starts the solution, e.g. along a sweep).

    Raises
    ------
    KegelInputError
        Neither or both of ``axial_N`` and ``axial_offset_m``, or a force-controlled axial load
        too small for the radial load: a single tapered roller bearing needs
        Fa / Fr > tan(alpha_o), the ratio of one roller carrying everything.
    """
    if (axial_N is None) == (axial_offset_m is None):
        raise KegelInputError("<argument>", "axial_N", axial_N, "exactly one of axial_N and axial_offset_m")
    if axial_N is not None and radial_N > 0 and axial_N / radial_N <= math.tan(g.cup_angle_rad):
        raise KegelInputError(
            "<argument>", "axial_N", axial_N,
            f"Fa / Fr > tan(alpha_o) = {math.tan(g.cup_angle_rad):.3f} for a single tapered roller bearing "
            f"(here {axial_N / radial_N:.3f}: the inner ring would lift off); use a displacement-controlled "
            f"axial offset for such load cases")
    from ..model.scene import check_operating_point  # the scenes' ranges of the loads (C0r included)

    check_operating_point(bearing, g, axial_N=axial_N, axial_offset_m=axial_offset_m, radial_N=radial_N,
                          tilt_moment_Nm=tilt_moment_Nm if tilt_free else 0.0, misalignment_rad=misalignment_rad)
    t0 = time.perf_counter()
    model = model or bearing_model(g, bearing, material, slices=slices, method=method)
    data = data or Q.BearingData(model)
    loads = _loads(axial_N, axial_offset_m, radial_N, tilt_moment_Nm, misalignment_rad)
    loads.tilt_free = tilt_free
    loads.cage_speed_rad_s = cage_speed_rad_s
    try:
        status = Q.solve_load_distribution(model, data, loads)
    except ValueError as exc:
        raise KegelInputError("<argument>", "loads", (axial_N, axial_offset_m, radial_N), str(exc)) from None
    if status != 0:
        raise KegelSolverError(
            f"load distribution did not converge (Fa = {axial_N} N, axial offset = {axial_offset_m} m, Fr = "
            f"{radial_N} N, tilt moment = {tilt_moment_Nm} N m, misalignment = {misalignment_rad} rad): ring "
            f"residual {data.residual:.3e} of the load after {data.iterations} iterations")
    ring = np.asarray(data.ring)
    rollers = data.rollers
    Z = len(rollers)
    return LoadDistribution(
        ring_displacement_m=ring[:3].copy(),
        ring_tilt_rad=ring[3:].copy(),
        reaction_moment_Nm=np.asarray(data.reaction_moment_Nm).copy(),
        axial_force_N=data.axial_force_N,
        azimuth_rad=2 * np.pi * np.arange(Z) / Z,
        outer_N=np.array([r.outer_N for r in rollers]),
        inner_N=np.array([r.inner_N for r in rollers]),
        rib_N=np.array([r.rib_N for r in rollers]),
        residual=data.residual,
        roller_residual_max=max(r.residual for r in rollers),
        iterations=data.iterations,
        runtime_s=time.perf_counter() - t0,
        loaded_length_m=np.asarray(Q.loaded_lengths_m(model, data)),
    )


@dataclass(frozen=True)
class BearingFrictionResult:
    """Friction of the whole bearing at one operating point (SI units).

    ``power_W[contact][mechanism]`` explains the torque: contacts ``outer_raceway``,
    ``inner_raceway``, ``rib``; mechanisms ``ehl_sliding``, ``solid_sliding``, ``ehl_rolling``,
    ``solid_rolling``, ``hysteresis``. The torque share of a mechanism is its power divided by the
    inner-ring speed.
    """

    drive_torque_Nm: float
    outer_ring_torque_Nm: float
    power_input_W: float
    power_dissipated_W: float
    cage_speed_rad_s: float
    cage_speed_pure_rolling_rad_s: float
    roller_spin_rad_s: np.ndarray
    roller_spin_pure_rolling_rad_s: np.ndarray
    power_W: dict
    cage_power_W: float
    Lambda_min: dict
    phi_max: dict
    converged: bool
    runtime_s: float
    cage_model: str = "pocket"
    #: share of the pocket solution in the result: 0 free rollers, 1 pocket model, in between
    #: ``cage_model = "mixed"`` (rollers touching their pocket walls over part of a revolution)
    pocket_fraction: float = 1.0
    roller_orbit_rad_s: np.ndarray | None = None
    roller_drift_m: float = 0.0
    locked_rollers: int = 0
    #: why the point failed its plausibility gates (None when it passed them); see
    #: :func:`plausibility_failures`
    failure: str | None = None
    #: how it was solved: "warm" (from the previous point's state), "cold" (fresh state, after
    #: a warm solution failed its gates, or when no state was passed in)
    start: str = "cold"
    #: rib cell model: the rollers whose Hertz ellipse at the rib is cut by the edge of the
    #: roller end's cap or of the rib (edge loading; their pressure field is solved, not Hertz's)
    rib_edge_rollers: int = 0

    @property
    def cage_slip(self) -> float:
        """1 - cage speed / pure-rolling cage speed (> 0: the cage lags)."""
        return 1.0 - self.cage_speed_rad_s / self.cage_speed_pure_rolling_rad_s

    @property
    def power_balance_error(self) -> float:
        """Dissipated over input power minus 1."""
        return self.power_dissipated_W / self.power_input_W - 1.0

    def torque_by_contact_Nm(self, inner_speed_rad_s: float) -> dict[str, float]:
        """Share of the friction torque of each contact (its power / inner-ring speed); ``cage``:
        the cage pockets."""
        out = {k: sum(v.values()) / inner_speed_rad_s for k, v in self.power_W.items()}
        out["cage"] = self.cage_power_W / inner_speed_rad_s
        return out

    def torque_by_mechanism_Nm(self, inner_speed_rad_s: float) -> dict[str, float]:
        """Share of the friction torque of each mechanism, summed over the contacts."""
        out: dict[str, float] = {}
        for row in self.power_W.values():
            for k, v in row.items():
                out[k] = out.get(k, 0.0) + v / inner_speed_rad_s
        out["solid_sliding"] += self.cage_power_W / inner_speed_rad_s  # Coulomb friction in the pockets
        return out


def bearing_friction(g: BearingGeometry, bearing: BearingData, material: MaterialData, lubricant, friction,
                     *, temperature_K: float, inner_speed_rad_s: float, axial_N: float | None = None,
                     axial_offset_m: float | None = None, radial_N: float = 0.0, misalignment_rad: float = 0.0,
                     tilt_moment_Nm: float = 0.0,
                     slices: int = 30, method: str = "alternative_slicing", rib_cells: int = 0,
                     cage: bool | str = True, rib_pressure: str = "hertz",
                     model: "Q.BearingModel | None" = None, data: "Q.BearingData | None" = None,
                     inner_ring_temperature_K: float | None = None, outer_ring_temperature_K: float | None = None
                     ) -> tuple[LoadDistribution, BearingFrictionResult]:
    """Load distribution and friction of the whole bearing at one operating point.

    Parameters
    ----------
    lubricant, friction
        :class:`kegel.LubricantData` and :class:`kegel.FrictionData`.
    temperature_K, inner_speed_rad_s
        Oil temperature and inner-ring speed (outer ring fixed).
    inner_ring_temperature_K, outer_ring_temperature_K
        Contact temperature per ring (issue 27, item 6): the inner ring's raceway and rib contacts
        are evaluated with the lubricant's state at ``inner_ring_temperature_K`` (viscosity,
        pressure-viscosity coefficient, thermal conductivity, Eq. 7-8 and 15 of the seed paper),
        the outer raceway's at ``outer_ring_temperature_K``. ``None`` (default): the oil
        temperature, bit-identical to one state for all contacts.
    rib_cells
        0: the rib as one closed-form elliptic contact; n > 0: its pressure field by the cell
        model (n x n) with every cell's friction at its own sliding velocity.
    rib_pressure
        The cell model's pressure field (``kegel._core.quasi_static.RibPressure``): ``"hertz"``
        (default) - Hertz's elliptic pressure sampled on the cells wherever the contact ellipse
        lies wholly on the roller end's cap and the rib face (the gap is then the surfaces'
        quadratic, Hertz's own problem), the elastic half-space solve (FFT + conjugate
        gradients) for a roller whose ellipse an edge cuts (counted in ``rib_edge_rollers``);
        ``"solved"`` - the half-space solve for every roller.
    cage
        How the cage enters (``kegel._core.quasi_static.CageModel``): ``"free_rollers"`` - every
        loaded roller orbits at the speed at which its contacts have no circumferential
        resultant, the cage at the rollers' time-mean orbital speed, no pocket forces;
        ``"pocket"`` - every roller orbits with the cage and its pocket takes its circumferential
        load, with Coulomb friction (Eq. 37); ``False`` / ``"off"`` - rollers at the cage speed,
        no pocket forces; ``"walls"`` - the free rollers in pockets of the bearing's
        circumferential clearance: a roller runs free while its walk through its pocket (its
        orbit against the cage's, accumulated round the revolution) stays inside the clearance,
        and a wall holds it at the cage's speed, its spin braked by the wall's friction (Eq. 37),
        for the share of each azimuth step it spends there; rollers without an orbit of their
        own sit at a wall throughout; the cage turns where the walls' moments cancel.
        ``True`` (default): ``"walls"``, reported as ``"free_rollers"`` when no roller meets a
        wall, ``"pocket"`` when every loaded one is held throughout, else ``"mixed"`` with
        ``pocket_fraction``, the rollers' share of time at a wall (continuous from the free
        rollers to the pocket model as the clearance shrinks); a walls solution that fails the
        gates falls back to ``"pocket"``. The dynamic simulation supports
        the free rollers under the seed paper's combined loads (they move +-6 um in +-170 um
        pockets); the pocket model there gave a 15 % higher torque.
    tilt_moment_Nm
        A tilt moment on the inner ring (about the axis normal to the radial load): the ring
        tilts freely under it (``tilt_free`` of :func:`load_distribution`); 0 holds the ring's
        tilt at ``misalignment_rad``. Not both.
    Other parameters as in :func:`load_distribution`; the centrifugal force uses the
    pure-rolling cage speed.

    Every solution passes the plausibility gates of :func:`plausibility_failures` (power balance,
    drive against outer-ring torque, sign, ring equilibrium) before it is called converged. A
    warm-started solution (``data`` passed in) that fails them is solved again from a fresh state;
    one that still fails is returned with ``converged = False`` and the residuals in ``failure``.

    Raises
    ------
    KegelInputError
        A value outside the scenes' ranges (:func:`kegel.scene.check_operating_point`: the
        lubricant's temperature range, the speed limit n d_m, the loads, C0r, the misalignment,
        the tilt moment), naming the argument.
    """
    if tilt_moment_Nm != 0.0 and misalignment_rad != 0.0:
        raise KegelInputError("<argument>", "tilt_moment_Nm", tilt_moment_Nm,
                              "either a tilt moment (the ring tilts freely) or a misalignment (its tilt imposed), not both")
    # the ranges of a scene's operating point (temperature of the lubricant data, speed limit
    # n d_m, loads, C0r): a public function that takes SI floats checks what a scene checks
    from ..model.scene import check_operating_point

    check_operating_point(bearing, g, lubricant=lubricant, temperature_K=temperature_K,
                          speed_rad_s=inner_speed_rad_s, axial_N=axial_N, axial_offset_m=axial_offset_m,
                          radial_N=radial_N, tilt_moment_Nm=tilt_moment_Nm, misalignment_rad=misalignment_rad,
                          names={"speed": "inner_speed_rad_s"})
    if axial_N is not None:  # a force-controlled load must hold the rollers on the cone at speed
        from ..model.scene import centrifugal_seating_error

        expected = centrifugal_seating_error(g, float(axial_N), inner_speed_rad_s)
        if expected is not None:
            raise KegelInputError("<argument>", "axial_N", axial_N, expected)
    ring_states = ring_lubricant_states(lubricant, temperature_K, inner_ring_temperature_K, outer_ring_temperature_K)
    model = model or bearing_model(g, bearing, material, slices=slices, method=method)
    warm = data is not None
    data = data or Q.BearingData(model)
    cage0 = pure_rolling_cage_speed(g, inner_speed_rad_s)

    def distribute(data) -> LoadDistribution:
        return load_distribution(g, bearing, material, axial_N=axial_N, axial_offset_m=axial_offset_m,
                                 radial_N=radial_N, misalignment_rad=misalignment_rad, cage_speed_rad_s=cage0,
                                 tilt_moment_Nm=tilt_moment_Nm, tilt_free=tilt_moment_Nm != 0.0,
                                 model=model, data=data)

    t0 = time.perf_counter()
    T = _core.tribology
    E = _core.reduced_modulus_Pa(material.core, material.core)
    race = T.SurfacePair(bearing.sigma_raceway_m, bearing.zhou_hoeprich_raceway_B, bearing.zhou_hoeprich_raceway_C, E)
    rib = T.SurfacePair(bearing.sigma_rib_m, bearing.zhou_hoeprich_rib_B, bearing.zhou_hoeprich_rib_C, E)
    loads = _loads(axial_N, axial_offset_m, radial_N, tilt_moment_Nm, misalignment_rad)
    loads.tilt_free = tilt_moment_Nm != 0.0
    state = T.make_contact_lubricant_state(lubricant.core, temperature_K)
    modes = {True: "walls", False: "off", "off": "off", "pocket": "pocket", "free_rollers": "free_rollers",
             "walls": "walls"}
    if not (isinstance(cage, (bool, str)) and cage in modes):
        raise KegelInputError("<argument>", "cage", cage, "True, False, 'off', 'pocket', 'free_rollers' or 'walls'")
    mode = modes[cage]
    if rib_pressure not in ("hertz", "solved"):
        raise KegelInputError("<argument>", "rib_pressure", rib_pressure, "'hertz' or 'solved'")
    pressure = getattr(Q.RibPressure, rib_pressure)

    def evaluate(mode: str, data) -> dict:
        return Q.evaluate_bearing_friction(model, data, loads, inner_speed_rad_s, state, friction.core(lubricant),
                                           race, rib, rib_cells, getattr(Q.CageModel, mode),
                                           outer_lubricant_state=ring_states[1], inner_lubricant_state=ring_states[0],
                                           rib_pressure=pressure)

    def solve(data, start: str) -> tuple[str, dict]:
        f = evaluate(mode, data)
        if mode != "walls":
            return mode, f
        # The rollers in their pockets: free where their walk through the pocket stays inside
        # the clearance, held at a wall for the share of the revolution where it does not
        # (CageModel.walls): "free_rollers" when no roller meets a wall, "pocket" when every
        # loaded one is held throughout, else "mixed" with that share.
        share = f["pocket_fraction"]
        if plausibility_failures(f, inner_speed_rad_s, 0.0) and start == "cold":
            # no balanced solution with the walls even from a fresh state: the pockets carry
            # every roller (a warm start's failure is returned as it is, so that the point is
            # solved again cold: a warm start must never choose the model)
            return "pocket", evaluate("pocket", data)
        return ("free_rollers" if share == 0.0 else "pocket" if share == 1.0 else "mixed"), f

    # A warm start must never decide the answer: a warm solution whose load distribution fails
    # or whose result misses a gate is solved again from a fresh state (once).
    for start in ("warm", "cold") if warm else ("cold",):
        if start == "cold" and warm:
            data = Q.BearingData(model)
        try:
            dist = distribute(data)
        except KegelSolverError:
            if start == "cold":
                raise
            continue
        used, f = solve(data, start)
        problems = plausibility_failures(f, inner_speed_rad_s, dist.residual, dist.roller_residual_max)
        if not problems:
            break
    if f["power_input_W"] == 0.0:
        # nothing to balance: the contact forces of a vanishing load underflow, and a record
        # without power would carry no figure worth keeping (a force-controlled load that small
        # is refused before, below the rollers' centrifugal share; an axial offset is not)
        raise KegelSolverError(
            f"no power enters the bearing (drive torque {f['drive_torque_Nm']:.6g} N m at {inner_speed_rad_s:.6g} "
            f"rad/s; Fa = {axial_N} N, axial offset = {axial_offset_m} m, Fr = {radial_N} N): the load is too small "
            "for the contact models to resolve a contact force")
    res = BearingFrictionResult(
        drive_torque_Nm=f["drive_torque_Nm"],
        outer_ring_torque_Nm=f["outer_ring_torque_Nm"],
        power_input_W=f["power_input_W"],
        power_dissipated_W=f["power_dissipated_W"],
        cage_speed_rad_s=f["cage_speed_rad_s"],
        cage_speed_pure_rolling_rad_s=f["cage_speed_pure_rolling_rad_s"],
        roller_spin_rad_s=np.asarray(f["roller_spin_rad_s"]),
        roller_spin_pure_rolling_rad_s=np.asarray(f["roller_spin_pure_rolling_rad_s"]),
        power_W={k: dict(v) for k, v in f["power_W"].items()},
        cage_power_W=f["cage_power_W"],
        Lambda_min=dict(f["Lambda_min"]),
        phi_max=dict(f["phi_max"]),
        converged=not problems,
        runtime_s=time.perf_counter() - t0,  # load distribution(s) and friction
        cage_model=used,
        pocket_fraction=f["pocket_fraction"],
        roller_orbit_rad_s=np.asarray(f["roller_orbit_rad_s"]),
        roller_drift_m=f["roller_drift_m"],
        locked_rollers=f["locked_rollers"],
        failure="; ".join(problems) if problems else None,
        start=start,
        rib_edge_rollers=f["rib_edge_rollers"],
    )
    return dist, res


def ring_lubricant_states(lubricant, temperature_K: float, inner_ring_temperature_K: float | None,
                          outer_ring_temperature_K: float | None, *, source: str = "<argument>",
                          names: tuple[str, str] = ("inner_ring_temperature_K", "outer_ring_temperature_K")
                          ) -> tuple[Any, Any]:
    """The contact lubricant states of the inner ring's contacts (raceway and rib) and of the
    outer ring's raceway (``kegel._core.tribology.ContactLubricantState``), each at its ring's
    temperature; ``None`` for a ring without its own temperature (the contacts then take the
    oil's state at ``temperature_K``, passed separately).

    Raises
    ------
    KegelInputError
        A ring temperature that is not a finite number in kegel's temperature range or outside
        the domain of the lubricant's formulas, naming ``names`` (inner, outer).
    """
    from ..model.lubricant import lubricant_state
    from ..model.scene import operating_range_error

    out = []
    for value, name in zip((inner_ring_temperature_K, outer_ring_temperature_K), names):
        if value is None:
            out.append(None)
            continue
        if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
            raise KegelInputError(source, name, value, "a temperature in K (a number) or None (the oil temperature)")
        v = float(value)
        expected = operating_range_error("temperature", v, None)  # the range needs no bearing
        if expected is not None:
            raise KegelInputError(source, name, value, expected)
        lubricant_state(lubricant, v, source=source, key=name)  # the oil's formulas hold there
        out.append(_core.tribology.make_contact_lubricant_state(lubricant.core, v))
    return out[0], out[1]


#: Tolerances of the plausibility gates every quasi-static point must pass to be called converged.
GATE_TOLERANCES = {
    "power_balance": 1e-3,     # |dissipated / input power - 1|
    "torque_balance": 1e-3,    # |drive - outer-ring torque| / |drive torque| (the cage carries no net moment)
    "load_residual": 1e-6,     # ring equilibrium residual / load scale
    "roller_residual": 1e-6,   # largest roller equilibrium residual / load scale
    "contact_power": 1e-9,     # most negative power of one mechanism in one contact / input power
}


#: A roller spinning at less than this share of its pure-rolling spin does not roll (it stalls or
#: turns backwards); named in the negative-dissipation gate's message.
ROLLING_SPIN_SHARE = 0.5


def _spin_diagnosis(f: dict) -> str:
    """Why a light point's rolling moments drive, when its rollers do not roll: "" otherwise.

    The rolling resistance acts as a shift of the normal force towards the inlet, set by the sign
    of the entrainment speed u_m, and does the work M (u1/R1 + u2/R2). A roller that spins
    backwards (or stalls) leaves u_m small and of either sign while the pair's relative rolling
    rate is large: the shift then delivers power and holds the roller in that state. Measured on
    the 32216 (FVA 3, 50 degC): at 10 rpm / 30 N the rollers spin at -0.52 of their pure-rolling
    spin, at 100 rpm / 30 N at -0.76, at 100 rpm / 300 N at +0.001 with the cage at the inner
    ring's speed. Turning the shift against the relative rolling rate instead removed the negative
    power but left no equilibrium (power balance off by 2-23 %): at such loads the quasi-static
    model found no rolling solution.
    """
    spin, pure = f.get("roller_spin_rad_s"), f.get("roller_spin_pure_rolling_rad_s")
    if spin is None or pure is None or len(spin) == 0 or len(spin) != len(pure):
        return ""
    ratios = [s / p for s, p in zip(spin, pure) if p != 0.0 and math.isfinite(s / p)]
    if not ratios or min(ratios) >= ROLLING_SPIN_SHARE:
        return ""
    lo, hi = min(ratios), max(ratios)
    share = f"{lo:.3g}" if f"{lo:.3g}" == f"{hi:.3g}" else f"{lo:.3g} to {hi:.3g}"
    what = "spinning backwards" if lo < 0.0 else "nearly stalled"
    return (f"; the rollers do not roll: their spin is {share} of its pure-rolling value ({what}), the load "
            "too light to make them roll at this speed; the quasi-static model (rollers in steady rolling) "
            "found no rolling solution")


def plausibility_failures(f: dict, inner_speed_rad_s: float, load_residual: float,
                          roller_residual: float = 0.0) -> list[str]:
    """The plausibility gates of one quasi-static friction solution; an empty list when it passes.

    A point is converged only when its solvers reported convergence and its result is physical:
    every torque and power finite, the friction torque opposing the rotation (drive torque times
    speed > 0), the drive torque equal to the outer ring's reaction (no unbalanced moment left on
    rollers or cage), the dissipated power equal to the input power (power balance), and the ring
    and every roller in equilibrium (``roller_residual``, the largest of
    :attr:`LoadDistribution.roller_residual_max`: an unloaded roller that stalled on its slide
    along the cup once left the 15 kN point of Table 3 depending on the sweep before it by 5 %);
    tolerances in :data:`GATE_TOLERANCES`. Each message names the residual.
    """
    out = []
    T, T_o = f["drive_torque_Nm"], f["outer_ring_torque_Nm"]
    P_in, P_d = f["power_input_W"], f["power_dissipated_W"]
    if not all(math.isfinite(x) for x in (T, T_o, P_in, P_d, f["cage_speed_rad_s"])):
        return [f"non-finite result (drive torque {T}, outer-ring torque {T_o}, power {P_in} / {P_d} W)"]
    if f["status"] != 0:
        out.append(f"a roller or cage balance did not converge (cage residual {f['cage_residual_Nm']:.3e} N m, "
                   f"{f['locked_rollers']} roller(s) without a free-roller solution)")
    if not T * inner_speed_rad_s > 0:
        out.append(f"friction torque {T:.6g} N m does not oppose the rotation ({inner_speed_rad_s:.6g} rad/s)")
    else:
        tb = abs(T - T_o) / abs(T)
        if tb > GATE_TOLERANCES["torque_balance"]:
            out.append(f"torque balance: drive {T:.6g} N m, outer ring {T_o:.6g} N m (relative difference {tb:.3e}, "
                       f"tolerance {GATE_TOLERANCES['torque_balance']:g})")
        pb = P_d / P_in - 1.0
        if abs(pb) > GATE_TOLERANCES["power_balance"]:
            out.append(f"power balance: dissipated {P_d:.6g} W, input {P_in:.6g} W (error {pb:+.3e}, tolerance "
                       f"{GATE_TOLERANCES['power_balance']:g})")
    # the second law: a friction mechanism dissipates, it never drives (a light load at a low
    # speed once converged with the outer raceway's rolling "resistance" driving a cage at three
    # times its pure-rolling speed: the 32216 at 10 rpm, 30 N, its rollers spinning backwards)
    floor = -GATE_TOLERANCES["contact_power"] * abs(P_in)
    negative = [(c, m, P) for c, mechs in f.get("power_W", {}).items() for m, P in mechs.items() if P < floor]
    if f.get("cage_power_W", 0.0) < floor:
        negative.append(("cage", "pocket", f["cage_power_W"]))
    if negative:
        c, m, P = min(negative, key=lambda x: x[2])
        out.append(f"negative dissipation: {len(negative)} mechanism(s) deliver power, the largest {m} at the {c} "
                   f"({P:.6g} W of {P_in:.6g} W input; a friction mechanism only dissipates)"
                   + _spin_diagnosis(f))
    if not load_residual <= GATE_TOLERANCES["load_residual"]:
        out.append(f"ring equilibrium residual {load_residual:.3e} of the load (tolerance "
                   f"{GATE_TOLERANCES['load_residual']:g})")
    if not roller_residual <= GATE_TOLERANCES["roller_residual"]:
        out.append(f"roller equilibrium residual {roller_residual:.3e} of the load (tolerance "
                   f"{GATE_TOLERANCES['roller_residual']:g})")
    return out
