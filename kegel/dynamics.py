"""Dynamic multibody simulation of a tapered roller bearing (C++ core, ``kegel._core.dynamics``).

Every roller and the cage are 6-DOF rigid bodies; the inner ring turns at a prescribed speed
profile and is free in translation under its loads (or held); the outer ring is fixed and its
reaction torque is the friction torque a test rig measures. CVODE (BDF, Newton, dense direct
solver with a coloured finite-difference Jacobian) integrates the equations of motion; the
initial state is the quasi-static solution. See ``mbs_core/include/kegel/core/dynamics.hpp`` for
the equations and the contact models.

:func:`dynamic_model` builds the model of a bearing; :func:`simulate` runs it along a speed
profile and returns a :class:`DynamicResult` (time series, steady-state averages with their
spread, power balance); :func:`write_result` writes it (JSON, CSV, VTK series, plots) atomically.
"""

from __future__ import annotations

import json
import math
import os
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Sequence

import numpy as np

from . import _core
from .data import BearingData, MaterialData
from .errors import KegelInputError
from .geometry import BearingGeometry
from .quasi_static import bearing_friction, bearing_model

D = _core.dynamics

__all__ = [
    "DAMPING_TIME_S",
    "DynamicResult",
    "SimulationDiverged",
    "cage_mass_properties",
    "dynamic_model",
    "simulate",
]

#: Stiffness-proportional contact damping, d = tau * k (Eq. 2's d_max from the contact stiffness
#: at delta_max). Rolling bearings damp with d = (0.25 ... 2.5) 1e-5 s x their stiffness
#: (E. Kraemer, Dynamics of Rotors and Foundations, Springer 1993, Sec. on rolling bearings; the
#: rule quoted for rotor dynamics); kegel takes the lower end (the least damping, so the
#: damping does not hide dynamics). Listed with verify = true in kegel/data/friction.
DAMPING_TIME_S = 2.5e-6

# Cage geometry: the pressed-steel window cage of kegel.cfd_cases.geometry (its mid-surface
# CAGE_OFFSET_RATIO * D_w outside the roller axes, thickness CAGE_THICKNESS_RATIO * D_w, side
# rings CAGE_OVERHANG_RATIO * L beyond the roller ends); the window edges touch the roller on
# the shell's inner face.
from .cfd_cases.geometry import CAGE_OFFSET_RATIO, CAGE_OVERHANG_RATIO, CAGE_THICKNESS_RATIO  # noqa: E402

#: Inner-ring mass when the scene gives none: the ring itself plus nothing of the shaft [kg];
#: computed from the ring's section in :func:`ring_mass_kg`.


class SimulationDiverged(RuntimeError):
    """CVODE could not continue; the message carries its reason and the state that shows why."""


def cage_mass_properties(g: BearingGeometry, density_kg_m3: float) -> tuple[float, float, float, float]:
    """Mass, axial and transverse inertia and window-edge height of the pressed-steel cage.

    A conical shell parallel to the roller axes at ``CAGE_OFFSET_RATIO * D_w`` outside them,
    thickness ``CAGE_THICKNESS_RATIO * D_w``, from ``CAGE_OVERHANG_RATIO * L`` before the rollers'
    small ends to as far beyond their large ends, minus Z windows (each the roller's chord at the
    shell times the roller length). Returns (mass_kg, I_axial_kgm2, I_transverse_kgm2,
    edge_height_m) with the transverse inertia about the cage centre on the axis.
    """
    Dw, L, Z = g.roller_mean_diameter_m, g.roller_length_m, g.roller_count
    t = CAGE_THICKNESS_RATIO * Dw
    off = CAGE_OFFSET_RATIO * Dw
    beta = g.roller_axis_angle_rad
    rp = 0.5 * g.cage_pitch_diameter_m
    # shell section: s along the roller axis from the roller middle, radius r(s)
    s = np.linspace(-(0.5 + CAGE_OVERHANG_RATIO) * L, (0.5 + CAGE_OVERHANG_RATIO) * L, 401)
    r = rp + s * math.sin(beta) + off * math.cos(beta)
    z = s * math.cos(beta) - off * math.sin(beta)
    ds = s[1] - s[0]
    dA = 2 * math.pi * r * ds                       # shell area per length
    edge_h = off - 0.5 * t                          # inner face of the shell above the roller axis
    chord = 2.0 * math.sqrt(max((0.5 * Dw) ** 2 - edge_h ** 2, 0.0))
    window = np.where(np.abs(s) <= 0.5 * L, Z * chord * ds, 0.0)
    dm = density_kg_m3 * t * np.maximum(dA - window, 0.0)
    mass = float(dm.sum())
    I_ax = float((dm * r ** 2).sum())
    zc = float((dm * z).sum() / mass)
    I_tr = float((dm * (0.5 * r ** 2 + (z - zc) ** 2)).sum())
    return mass, I_ax, I_tr, edge_h


def ring_mass_kg(g: BearingGeometry, bearing: BearingData, density_kg_m3: float) -> float:
    """Mass of the inner ring (cone): the ring between the bore and the raceway's mean diameter
    over the cone width B."""
    d_in = bearing.bore_diameter_m
    d_out = g.inner_raceway_diameter_mid_m
    B = bearing.cone_width_m
    return density_kg_m3 * math.pi / 4 * (d_out ** 2 - d_in ** 2) * B


def dynamic_model(g: BearingGeometry, bearing: BearingData, material: MaterialData, lubricant, friction, *,
                  temperature_K: float, slices: int = 20, method: str = "independent", cage: bool = True,
                  cage_points: int = 4, damping_time_s: float = DAMPING_TIME_S, ring_mass: float | None = None,
                  gravity_m_s2: Sequence[float] = (0.0, 0.0, 0.0)) -> tuple["D.DynamicModel", Any]:
    """The C++ dynamic model and its quasi-static bearing model (for the initial state)."""
    qs_model = bearing_model(g, bearing, material, slices=slices, method=method)
    T = _core.tribology
    E = _core.reduced_modulus_Pa(material.core, material.core)
    race = T.SurfacePair(bearing.sigma_raceway_m, bearing.zhou_hoeprich_raceway_B, bearing.zhou_hoeprich_raceway_C, E)
    rib = T.SurfacePair(bearing.sigma_rib_m, bearing.zhou_hoeprich_rib_B, bearing.zhou_hoeprich_rib_C, E)
    state = T.make_contact_lubricant_state(lubricant.core, temperature_K)
    v = D.DynamicValues()
    v.roller_mass_kg = g.roller_mass_kg
    v.roller_inertia_axial_kgm2 = g.roller_inertia_axial_kgm2
    v.roller_inertia_transverse_kgm2 = g.roller_inertia_transverse_kgm2
    v.roller_com_offset_m = g.roller_com_offset_m
    mc, Ia, It, edge = cage_mass_properties(g, material.density_kg_m3)
    v.cage_mass_kg, v.cage_inertia_axial_kgm2, v.cage_inertia_transverse_kgm2 = mc, Ia, It
    v.cage_edge_height_m = edge
    v.cage_pitch_radius_m = 0.5 * g.cage_pitch_diameter_m
    v.cage_pocket_clearance_m = g.cage_pocket_clearance_circumferential_m
    v.cage_pocket_axial_clearance_m = g.cage_pocket_clearance_axial_m
    v.ring_mass_kg = ring_mass if ring_mass is not None else ring_mass_kg(g, bearing, material.density_kg_m3)
    v.damping_time_s = damping_time_s
    v.gravity_m_s2 = np.asarray(gravity_m_s2, dtype=float)
    v.cage_points = cage_points
    v.cage = cage
    model = D.DynamicModel(qs_model, v, friction.core(lubricant), race, rib, state)
    return model, qs_model


@dataclass
class DynamicResult:
    """Time series and steady-state figures of a dynamic run (SI units).

    ``series`` maps a name to an array over ``time_s``; per-roller quantities are arrays of shape
    (time, Z). ``steady`` holds the means and standard deviations over the averaging window
    (the last ``average_fraction`` of the run).
    """

    time_s: np.ndarray
    series: dict[str, np.ndarray]
    steady: dict[str, float]
    stats: dict[str, Any]
    states: np.ndarray           # the state vectors at the output times (for VTK, restarts)
    quadratures: np.ndarray      # time integrals of QUADRATURES at the output times
    runtime_s: float
    finished: bool = True
    message: str = ""

    @property
    def revolutions(self) -> float:
        """Shaft revolutions simulated."""
        w = self.series["inner_speed_rad_s"]
        return float(np.trapezoid(np.abs(w), self.time_s) / (2 * math.pi)) if len(w) > 1 else 0.0


_SCALARS = ("inner_speed_rad_s", "cage_speed_rad_s", "drive_torque_Nm", "outer_ring_torque_Nm", "damping_power_W",
            "cage_power_W", "external_power_W", "power_input_W", "kinetic_energy_J", "max_penetration_m",
            "contact_work_W")
_ROLLER = ("roller_outer_N", "roller_inner_N", "roller_rib_N", "roller_cage_N", "roller_spin_rad_s",
           "roller_sliding_outer_m_s", "roller_sliding_inner_m_s", "roller_skew_rad", "roller_tilt_rad")
CONTACTS = ("outer_raceway", "inner_raceway", "rib")
MECHANISMS = ("ehl_sliding", "solid_sliding", "ehl_rolling", "solid_rolling", "hysteresis")


def _record(rows: dict[str, list], out: dict) -> None:
    for k in _SCALARS:
        rows.setdefault(k, []).append(out[k])
    for k in _ROLLER:
        rows.setdefault(k, []).append(list(out[k]))
    for c in CONTACTS:
        rows.setdefault(f"torque_{c}_Nm", []).append(out["torque_by_contact_Nm"][c])
        for mch in MECHANISMS:
            rows.setdefault(f"power_{c}_{mch}_W", []).append(out["power_W"][c][mch])
    rows.setdefault("ring_force_N", []).append(list(out["ring_force_N"]))


QUADRATURES = (["outer_ring_torque_Nm", "drive_torque_Nm", "power_input_W"]
               + [f"power_{c}_{m}_W" for c in CONTACTS for m in MECHANISMS]
               + ["damping_power_W", "cage_power_W", "external_power_W", "cage_speed_rad_s"]
               + [f"torque_{c}_Nm" for c in CONTACTS] + ["contact_work_W"])


def _interval_means(t: np.ndarray, Q: np.ndarray) -> dict[str, np.ndarray]:
    """Mean of each quadrature over each output interval (exact means of the solution; the value
    at t[i] is the mean over (t[i-1], t[i]], the first repeats the second)."""
    dt = np.diff(t)
    m = np.diff(Q, axis=0) / dt[:, None]
    m = np.vstack([m[:1], m])
    return {f"mean_{k}": m[:, i] for i, k in enumerate(QUADRATURES)}


def _steady(t: np.ndarray, series: dict[str, np.ndarray], Q: np.ndarray, fraction: float) -> dict[str, float]:
    """Means over the last ``fraction`` of the run (from the quadratures: exact time means),
    spreads of the interval means there, and the power balance."""
    i0 = int(np.searchsorted(t, t[0] + (1.0 - fraction) * (t[-1] - t[0])))
    i0 = min(i0, len(t) - 2)
    span = t[-1] - t[i0]
    out: dict[str, float] = {"window_start_s": float(t[i0]), "window_end_s": float(t[-1])}
    for i, k in enumerate(QUADRATURES):
        out[k] = float((Q[-1, i] - Q[i0, i]) / span)
        x = series[f"mean_{k}"][i0 + 1:]
        out[k.rsplit("_", 1)[0] + "_std"] = float(np.std(x)) if len(x) else 0.0
    out["inner_speed_rad_s"] = float(np.trapezoid(series["inner_speed_rad_s"][i0:], t[i0:]) / span)
    out["power_contacts_W"] = sum(out[f"power_{c}_{m}_W"] for c in CONTACTS for m in MECHANISMS)
    E = series["kinetic_energy_J"]
    dE = float(E[-1] - E[i0]) / span
    out["kinetic_energy_rate_W"] = dE
    out["power_dissipated_W"] = (out["power_contacts_W"] + out["cage_power_W"] + out["damping_power_W"]
                                 + out["external_power_W"])
    P_in = out["power_input_W"]
    out["power_balance_error"] = (P_in - out["power_dissipated_W"] - dE) / P_in if P_in else float("nan")
    return out


class _Progress:
    def __init__(self, t0: float, t1: float, enabled: bool) -> None:
        self.t0, self.t1, self.enabled, self.w0, self.last = t0, t1, enabled, time.perf_counter(), 0.0

    def update(self, t: float, h: float, steps: int) -> None:
        if not self.enabled:
            return
        now = time.perf_counter()
        if now - self.last < 1.0:
            return
        self.last = now
        el = now - self.w0
        frac = (t - self.t0) / (self.t1 - self.t0)
        eta = el / frac * (1 - frac) if frac > 0 else float("nan")
        sys.stderr.write(f"\rt = {t * 1e3:8.3f} ms of {self.t1 * 1e3:.1f} ms, step {h * 1e6:7.2f} us, "
                         f"{steps} steps, {el:6.1f} s, ETA {eta:6.1f} s ")
        sys.stderr.flush()

    def close(self) -> None:
        if self.enabled and self.last:
            sys.stderr.write("\n")


def simulate(g: BearingGeometry, bearing: BearingData, material: MaterialData, lubricant, friction, *,
             temperature_K: float, speed_profile: Sequence[tuple[float, float]], duration_s: float,
             axial_N: float | None = None, axial_offset_m: float | None = None, radial_N: float = 0.0,
             misalignment_rad: float = 0.0, slices: int = 20, method: str = "independent", cage: bool = True,
             output_interval_s: float = 1e-4, average_fraction: float = 0.5, rtol: float = 1e-7,
             atol_velocity_m_s: float = 1e-8,
             damping_time_s: float = DAMPING_TIME_S, elements: Sequence[Any] = (), progress: bool = False,
             checkpoint: str | Path | None = None, checkpoint_interval_s: float = 5e-3,
             initial_speed_rad_s: float | None = None, coloured_jacobian: bool = True,
             raise_on_failure: bool = True) -> DynamicResult:
    """Run the dynamic simulation along a speed profile.

    Parameters
    ----------
    speed_profile
        (time_s, inner-ring speed in rad/s) points; linear in between, constant after the last.
    duration_s
        Simulated time.
    axial_N, axial_offset_m
        Force-controlled axial load (the ring is free axially) or a held axial offset towards the
        apex (the ring is held axially at the quasi-static position for that offset).
    output_interval_s
        Spacing of the recorded outputs.
    average_fraction
        The last part of the run that the steady-state averages cover.
    elements
        Force elements (``kegel._core.dynamics.DragElement``, ``PythonForceElement``) acting on the
        rollers and the cage: the hydraulic forces of the coupling layer.
    checkpoint
        A file (.npz) the state is written to every ``checkpoint_interval_s`` (atomically); when it
        exists at the start, the run resumes from it.
    initial_speed_rad_s
        Speed of the quasi-static initial state (default: the profile's speed at t = 0; with 0 the
        bodies start at rest).
    """
    if (axial_N is None) == (axial_offset_m is None):
        raise KegelInputError("<argument>", "axial_N", axial_N, "exactly one of axial_N and axial_offset_m")
    if not duration_s > 0:
        raise KegelInputError("<argument>", "duration_s", duration_s, "a time > 0")
    if not (0 < output_interval_s <= duration_s):
        raise KegelInputError("<argument>", "output_interval_s", output_interval_s, f"in (0, {duration_s}]")
    prof = np.asarray(speed_profile, dtype=float)
    if prof.ndim != 2 or prof.shape[1] != 2 or not np.all(np.diff(prof[:, 0]) > 0) or not np.isfinite(prof).all():
        raise KegelInputError("<argument>", "speed_profile", speed_profile,
                              "(time_s, speed_rad_s) pairs with increasing times")
    w_start = float(np.interp(0.0, prof[:, 0], prof[:, 1])) if initial_speed_rad_s is None else initial_speed_rad_s
    wall0 = time.perf_counter()
    model, qs_model = dynamic_model(g, bearing, material, lubricant, friction, temperature_K=temperature_K,
                                    slices=slices, method=method, cage=cage, damping_time_s=damping_time_s)
    # initial state from the quasi-static solution at the start speed
    qs_data = _core.quasi_static.BearingData(qs_model)
    if abs(w_start) > 0:
        _, fr = bearing_friction(g, bearing, material, lubricant, friction, temperature_K=temperature_K,
                                 inner_speed_rad_s=w_start, axial_N=axial_N, axial_offset_m=axial_offset_m,
                                 radial_N=radial_N, misalignment_rad=misalignment_rad, model=qs_model, data=qs_data,
                                 cage=cage)
        wc, spins = fr.cage_speed_rad_s, list(fr.roller_spin_rad_s)
    else:
        from .quasi_static import load_distribution
        load_distribution(g, bearing, material, axial_N=axial_N, axial_offset_m=axial_offset_m, radial_N=radial_N,
                          misalignment_rad=misalignment_rad, model=qs_model, data=qs_data)
        wc, spins = 0.0, [0.0] * g.roller_count
    y0 = np.asarray(D.initial_state(model, qs_data, wc, spins))
    drive = D.RingDrive()
    drive.time_s = list(prof[:, 0])
    drive.speed_rad_s = list(prof[:, 1])
    if axial_N is not None:
        drive.axial_N = axial_N
    else:
        drive.free_z = False
    drive.radial_N = radial_N
    drive.misalignment_y_rad = misalignment_rad
    st = D.IntegratorSettings()
    st.rtol = rtol
    st.atol_velocity_m_s = atol_velocity_m_s
    st.atol_rate_rad_s = atol_velocity_m_s / g.roller_mean_diameter_m * 2.0
    st.atol_position_m = 1e-3 * atol_velocity_m_s / max(abs(w_start), 1.0) + 1e-12
    st.coloured_jacobian = coloured_jacobian
    t_start = 0.0
    rows: dict[str, list] = {}
    times: list[float] = []
    states: list[np.ndarray] = []
    quads: list[np.ndarray] = []
    ck = Path(checkpoint) if checkpoint is not None else None
    if ck is not None and ck.exists():
        saved = np.load(ck, allow_pickle=False)
        if saved["y"].shape != y0.shape:
            raise KegelInputError(str(ck), "y", saved["y"].shape, f"a state of size {y0.size} (another model)")
        t_start, y0 = float(saved["t"]), saved["y"]
        times = list(saved["times"])
        states = list(saved["states"])
        quads = list(saved["quads"])
        rows = json.loads(str(saved["rows"]))
    sim = D.DynamicSimulation(model, drive, st, t_start, list(y0))
    if quads:
        sim.set_quadrature_offset(list(quads[-1]))
    for e in elements:
        sim.add_element(e)
    n_out = int(round(duration_s / output_interval_s))
    grid = np.linspace(0.0, duration_s, n_out + 1)
    grid = grid[grid > t_start + 1e-15] if times else grid
    prog = _Progress(t_start, duration_s, progress)
    finished, message, last_ck = True, "", t_start
    for tk in grid:
        if tk > sim.time_s:
            flag = sim.advance(float(tk))
            if flag != 0:
                finished, message = False, sim.message
                break
        out = sim.outputs()
        times.append(float(sim.time_s))
        states.append(np.asarray(sim.state))
        quads.append(np.asarray(sim.quadratures))
        _record(rows, out)
        prog.update(sim.time_s, sim.last_step_s, sim.steps)
        if ck is not None and sim.time_s - last_ck >= checkpoint_interval_s - 1e-15:
            _save_checkpoint(ck, sim.time_s, np.asarray(sim.state), times, states, quads, rows)
            last_ck = sim.time_s
    prog.close()
    t = np.asarray(times)
    series = {k: np.asarray(v, dtype=float) for k, v in rows.items()}
    Q = np.asarray(quads)
    if len(t) > 1:
        series.update(_interval_means(t, Q))
    stats = {"steps": sim.steps, "rhs_evaluations": sim.rhs_evaluations,
             "jacobian_evaluations": sim.jacobian_evaluations, "state_size": model.state_size,
             "slices": slices, "method": method, "cage": cage, "rtol": rtol}
    steady = _steady(t, series, Q, average_fraction) if len(t) > 1 else {}
    res = DynamicResult(time_s=t, series=series, steady=steady, stats=stats, states=np.asarray(states), quadratures=Q,
                        runtime_s=time.perf_counter() - wall0, finished=finished, message=message)
    if not finished and raise_on_failure:
        raise SimulationDiverged(_divergence_report(res, message))
    return res


def _save_checkpoint(path: Path, t: float, y: np.ndarray, times: list, states: list, quads: list,
                     rows: dict) -> None:
    tmp = path.with_name(path.name + ".tmp.npz")
    np.savez(tmp, t=t, y=y, times=np.asarray(times), states=np.asarray(states), quads=np.asarray(quads),
             rows=json.dumps(rows))
    os.replace(tmp, path)


def _divergence_report(res: DynamicResult, message: str) -> str:
    lines = [message or "the integration stopped"]
    if len(res.time_s):
        s = res.series
        lines.append(f"last good output at t = {res.time_s[-1] * 1e3:.4f} ms: inner speed "
                     f"{s['inner_speed_rad_s'][-1]:.2f} rad/s, cage {s['cage_speed_rad_s'][-1]:.2f} rad/s, "
                     f"largest interference {s['max_penetration_m'][-1] * 1e6:.3f} um, kinetic energy "
                     f"{s['kinetic_energy_J'][-1]:.4g} J")
    return "; ".join(lines)
