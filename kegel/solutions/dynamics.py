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

Steady state is detected, not assumed (:func:`settling`): the drive torque, the outer-ring torque
and the cage speed must have settled, by the drift-and-spread test on window means that the CFD
uses too (:func:`kegel.steady.settled_window`), on windows of a roller pass. The steady
figures are the means over the settled part only; a run whose signals have not settled says so
(``steady["settled"]`` false, with the reason and the remaining drift).
"""

from __future__ import annotations

import json
import math
import os
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from .. import _core
from ..model.data import BearingData, MaterialData
from ..base.errors import KegelInputError
from ..model.geometry import BearingGeometry
from .quasi_static import bearing_friction, bearing_model, load_distribution, ring_lubricant_states
from .steady import SettledWindow, settled_window
from ..physics.tribology import cage_speed_rad_s

D = _core.dynamics

__all__ = [
    "ATOL_VELOCITY_M_S",
    "DAMPING_TIME_S",
    "POWER_BALANCE_TOLERANCE",
    "power_balanced",
    "STEADY_HOLD_PASSES",
    "STEADY_SIGNALS",
    "STEADY_TOLERANCE",
    "STEADY_TREND_PASSES",
    "DynamicResult",
    "SimulationDiverged",
    "cage_mass_properties",
    "plot_result",
    "write_result",
    "write_vtk_series",
    "dynamic_model",
    "settling",
    "simulate",
]

#: The signals that must have settled before a dynamic run's means are its steady answer: the
#: drive torque (what the shaft pays), the outer-ring torque (what a rig measures; it differs from
#: the drive torque by the inertia torques of a speed change) and the cage speed (its free flight
#: in the pocket clearance after a speed change).
STEADY_SIGNALS = ("drive_torque_Nm", "outer_ring_torque_Nm", "cage_speed_rad_s")
#: Relative tolerance of the steady test (:func:`settling`): the remaining change, the last
#: roller pass's change and the trend across the averaging window of every signal within 0.5 %
#: of its level. A numerical setting (what "settled" means), not a physical parameter: it sits
#: below the 2-3 % at which the dynamic and quasi-static solutions are compared.
STEADY_TOLERANCE = 5e-3
#: Windows over which the test must keep passing: the settled part (from the first passing
#: check point's last two windows to the end) is at least 2 + 1 = 3 windows long, and a run
#: that is steady from its start needs 3 + 1 = 4 windows (the first check point is three windows
#: in). With windows of one roller pass (a load that varies around the bearing) that is, for the
#: 32216, 8.8 ms at 4000 rpm, 17.7 ms at 2000 rpm and 71 ms at 500 rpm; with a quarter pass (pure
#: axial load, the signals flat) a quarter of it.
STEADY_HOLD_PASSES = 1.0
#: Roller passes over which a trend of the window means may change a signal by at most the
#: tolerance, whatever the window: a slow ramp is a drift, not a steady state.
STEADY_TREND_PASSES = 4.0

#: Largest |power balance error| of a dynamic answer: (input power - dissipated power - the
#: bodies' kinetic-energy rate) / input power over the averaging window. It is an identity of the
#: equations of motion, so what remains is integration error: 2e-6 to 2.2e-4 on the tests' and
#: the docs' runs (docs/dynamics.md, "Power balance"). Before the rolling powers were counted as the
#: shifted normal force's work, the balance missed by about the cage slip (-0.34 % at 1 kN, -9.9 %
#: skidding, -41 % at 50 N): a gate at this level would have caught it. A point outside it is not
#: an answer (kegel.runner: ``converged`` false, with the figures).
POWER_BALANCE_TOLERANCE = 1e-3


def power_balanced(error: float) -> bool:
    """Whether a relative power-balance error passes the gate (:data:`POWER_BALANCE_TOLERANCE`;
    NaN, from no input power, does not)."""
    return bool(math.isfinite(error) and abs(error) <= POWER_BALANCE_TOLERANCE)

#: Absolute tolerance of the velocities in the integrator's error test (m/s; the angular rates get
#: it over the roller radius, the positions 1e-3 of it per rad/s of the start speed + 1 pm).
#: 1e-7 m/s halves the steps of the 32216 at 2000 rpm, 6 kN against 1e-8 and moves its mean
#: torque by +0.007 % (docs/performance.md, Dynamic simulation: 0.73 against 1.48 s of CPU per
#: revolution, -1.08 % from fine); the settled means then depend on the output interval (where
#: the integrator stops) by about 1e-5, the integration error, not a sampling one.
ATOL_VELOCITY_M_S = 1e-7

#: Stiffness-proportional contact damping time when the friction file gives none: d_max = tau x
#: the contact stiffness at delta_max (Eq. 2). The value and its source (Kraemer) live in
#: kegel/data/friction/steel_mineral_oil.toml, [damping] damping_time_us.
DAMPING_TIME_S = 2.5e-6

# Cage geometry: kegel.geometry's pressed-steel window cage; the window edges touch the roller
# on the shell's inner face.
from ..model.geometry import CAGE_OFFSET_RATIO, CAGE_OVERHANG_RATIO, CAGE_THICKNESS_RATIO  # noqa: E402


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


def ring_mass_properties(g: BearingGeometry, bearing: BearingData, density_kg_m3: float) -> tuple[float, float, float]:
    """Mass, axial and transverse inertia (about its centre) of the inner ring as a hollow
    cylinder between the bore and the raceway's mean diameter over the cone width B."""
    ri, ro = 0.5 * bearing.bore_diameter_m, 0.5 * g.inner_raceway_diameter_mid_m
    B = bearing.cone_width_m
    mass = density_kg_m3 * math.pi * (ro ** 2 - ri ** 2) * B
    return mass, 0.5 * mass * (ri ** 2 + ro ** 2), mass * (3 * (ri ** 2 + ro ** 2) + B ** 2) / 12


def dynamic_model(g: BearingGeometry, bearing: BearingData, material: MaterialData, lubricant, friction, *,
                  temperature_K: float, slices: int = 20, method: str = "independent", cage: bool = True,
                  cage_points: int = 4, damping_time_s: float | None = None, ring_mass: float | None = None,
                  gravity_m_s2: Sequence[float] = (0.0, 0.0, 0.0), inner_ring_temperature_K: float | None = None,
                  outer_ring_temperature_K: float | None = None) -> tuple["D.DynamicModel", Any]:
    """The C++ dynamic model and its quasi-static bearing model (for the initial state).

    ``inner_ring_temperature_K`` / ``outer_ring_temperature_K``: the contact temperature of each
    ring's contacts (the inner ring's raceway and rib, the outer raceway); ``None``: the oil
    temperature (:func:`kegel.quasi_static.ring_lubricant_states`)."""
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
    mr, Iar, Itr = ring_mass_properties(g, bearing, material.density_kg_m3)
    v.ring_mass_kg = ring_mass if ring_mass is not None else mr
    v.ring_inertia_axial_kgm2, v.ring_inertia_transverse_kgm2 = Iar, Itr
    v.damping_time_s = (damping_time_s if damping_time_s is not None
                        else (friction.damping_time_s or DAMPING_TIME_S))
    v.gravity_m_s2 = np.asarray(gravity_m_s2, dtype=float)
    v.cage_points = cage_points
    v.cage = cage
    inner_state, outer_state = ring_lubricant_states(lubricant, temperature_K, inner_ring_temperature_K,
                                                     outer_ring_temperature_K)
    model = D.DynamicModel(qs_model, v, friction.core(lubricant), race, rib, state,
                           outer_lubricant=outer_state, inner_lubricant=inner_state)
    return model, qs_model


@dataclass
class DynamicResult:
    """Time series and steady-state figures of a dynamic run (SI units).

    ``series`` maps a name to an array over ``time_s``; per-roller quantities are arrays of shape
    (time, Z). ``steady`` holds the means and standard deviations over the averaging window
    ``window_start_s``-``window_end_s``: the settled part of the run (:func:`settling`) when
    ``steady["settled"]``, otherwise the last ``average_fraction`` of the run (figures that are
    not a steady answer); ``steady["settling"]`` says why (the test's window, tolerance, the
    remaining drift of every signal), ``steady["drift_relative"]`` is the largest remaining
    drift.
    """

    time_s: np.ndarray
    series: dict[str, np.ndarray]
    steady: dict[str, Any]
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

    def __repr__(self) -> str:
        """One line: simulated time, outputs, steady-state means, whether and where the run settled,
        finished (never the arrays, which ``time_s``, ``series`` and ``states`` hold)."""
        t = np.asarray(self.time_s, dtype=float)
        parts = [f"{(t[-1] - t[0]) * 1e3:.4g} ms simulated" if t.size > 1 else "no time simulated",
                 f"{t.size} outputs"]
        st = self.steady or {}
        if "inner_speed_rad_s" in st:
            parts.append(f"mean speed {st['inner_speed_rad_s'] * 30.0 / math.pi:.4g} rpm")
        if "drive_torque_Nm" in st:
            torque = f"mean drive torque {st['drive_torque_Nm']:.4g} N m"
            if "outer_ring_torque_Nm" in st:
                torque += f" (outer ring {st['outer_ring_torque_Nm']:.4g} N m)"
            parts.append(torque)
        if "settled" in st:
            parts.append(f"settled over {st['window_start_s'] * 1e3:.4g}-{st['window_end_s'] * 1e3:.4g} ms"
                         if st["settled"] else "NOT settled (means over the last part, not a steady answer)")
        if st.get("power_balanced") is False:
            parts.append(f"power balance OFF by {100 * st['power_balance_error']:+.3g} %")
        if self.finished:
            parts.append("finished")
        else:
            msg = " ".join(str(self.message).split())
            parts.append("not finished" + (f": {msg[:120]}{'...' if len(msg) > 120 else ''}" if msg else ""))
        parts.append(f"runtime {self.runtime_s:.3g} s")
        return f"DynamicResult({', '.join(parts)})"


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
    for c in CONTACTS:
        rows.setdefault(f"Lambda_min_{c}", []).append(out["Lambda_min"][c])
        rows.setdefault(f"phi_max_{c}", []).append(out["phi_max"][c])


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


def settling(t: np.ndarray, Q: np.ndarray, g: BearingGeometry, final_speed_rad_s: float, *,
             output_interval_s: float, tol: float = STEADY_TOLERANCE) -> SettledWindow:
    """Where the run's :data:`STEADY_SIGNALS` have settled (:func:`kegel.steady.settled_window`).

    The window of the test is a roller pass at the final speed of the profile, the time
    ``P = 2 pi / (Z w_c)`` between two rollers passing a point of the outer ring (w_c the
    pure-rolling cage speed): the torque of a bearing under radial load or tilt varies with it,
    and a window of one pass averages that out. Under a load the same for every roller (pure
    axial load) the signals do not vary with the pass, and shorter windows judge them in a
    shorter run: the windows P / 4, P / 2 and P are tried in turn, and the first that finds the
    signals settled decides. (A pass's variation fails the shorter windows' spread test, so it
    never passes as steady; a creep fails the trend test, which is judged over
    :data:`STEADY_TREND_PASSES` passes whatever the window.) The test must pass over
    :data:`STEADY_HOLD_PASSES` window, so the settled part is at least three windows long. Windows
    are at least two output intervals; a sixteenth of the run when the profile ends at standstill.
    The torques are judged against the larger of the two torques' levels (the outer-ring torque of
    a light-load point is small beside its drive torque), the cage speed against at least 1 % of
    the ring speed. Without a settled window the result is the one-pass window's, with its reason.

    Parameters
    ----------
    t, Q
        Output times and the quadratures (:data:`QUADRATURES`, time integrals) there.
    final_speed_rad_s
        The inner ring's speed at the end of the profile.
    """
    w_c = abs(cage_speed_rad_s(g, abs(final_speed_rad_s))) if final_speed_rad_s else 0.0
    span = float(t[-1] - t[0]) if len(t) else 0.0
    one_pass = 2 * math.pi / (g.roller_count * w_c) if w_c > 0 else span / 16.0
    integrals = {k: Q[:, QUADRATURES.index(k)] for k in STEADY_SIGNALS}
    result = None
    for fraction in (0.25, 0.5, 1.0):
        window = max(fraction * one_pass, 2.0 * output_interval_s)
        last = {}
        if len(t) > 1:
            lo = max(float(t[0]), float(t[-1]) - window)
            for k, integral in integrals.items():
                last[k] = abs(float(integral[-1] - np.interp(lo, t, integral)) / max(float(t[-1]) - lo, 1e-300))
        torque_floor = max(last.get("drive_torque_Nm", 0.0), last.get("outer_ring_torque_Nm", 0.0), 1e-9)
        floors = {"drive_torque_Nm": torque_floor, "outer_ring_torque_Nm": torque_floor,
                  "cage_speed_rad_s": max(0.01 * abs(final_speed_rad_s), 1e-9)}
        result = settled_window(t, integrals, window, tol, floors=floors, hold=STEADY_HOLD_PASSES * window,
                                trend_span=STEADY_TREND_PASSES * max(one_pass, 2.0 * output_interval_s),
                                time_unit=("ms", 1e3))
        if result.settled:
            break
    return result


def _steady(t: np.ndarray, series: dict[str, np.ndarray], Q: np.ndarray, start_s: float) -> dict[str, Any]:
    """Means over ``start_s``-end (from the quadratures: exact time means; interpolated at a
    start between outputs), spreads of the interval means there, and the power balance."""
    t_end = float(t[-1])
    start_s = min(max(float(start_s), float(t[0])), float(t[-2]))
    span = t_end - start_s
    i0 = int(np.searchsorted(t, start_s, side="right"))  # the first output after the start
    out: dict[str, Any] = {"window_start_s": start_s, "window_end_s": t_end}
    for i, k in enumerate(QUADRATURES):
        out[k] = float((Q[-1, i] - np.interp(start_s, t, Q[:, i])) / span)
        x = series[f"mean_{k}"][i0:]
        out[k.rsplit("_", 1)[0] + "_std"] = float(np.std(x)) if len(x) else 0.0
    w = series["inner_speed_rad_s"]
    out["inner_speed_rad_s"] = float(np.trapezoid(np.concatenate(([np.interp(start_s, t, w)], w[i0:])),
                                                  np.concatenate(([start_s], t[i0:]))) / span)
    out["power_contacts_W"] = sum(out[f"power_{c}_{m}_W"] for c in CONTACTS for m in MECHANISMS)
    E = series["kinetic_energy_J"]
    dE = float(E[-1] - np.interp(start_s, t, E)) / span
    out["kinetic_energy_rate_W"] = dE
    out["power_dissipated_W"] = (out["power_contacts_W"] + out["cage_power_W"] + out["damping_power_W"]
                                 + out["external_power_W"])
    P_in = out["power_input_W"]
    out["power_balance_error"] = (P_in - out["power_dissipated_W"] - dE) / P_in if P_in else float("nan")
    return out


class _Progress:
    """Simulated time, step size and ETA on stderr: a refreshed line on a terminal (every
    second), a new line every 10 s otherwise (logs)."""

    def __init__(self, t0: float, t1: float, enabled: bool) -> None:
        self.t0, self.t1, self.enabled, self.w0, self.last = t0, t1, enabled, time.perf_counter(), 0.0
        self.tty = sys.stderr.isatty()

    def update(self, t: float, h: float, steps: int) -> None:
        if not self.enabled:
            return
        now = time.perf_counter()
        if now - self.last < (1.0 if self.tty else 10.0) or now - self.w0 < (0.0 if self.tty else 10.0):
            return
        self.last = now
        el = now - self.w0
        frac = (t - self.t0) / (self.t1 - self.t0)
        eta = el / frac * (1 - frac) if frac > 0 else float("nan")
        line = (f"t = {t * 1e3:8.3f} ms of {self.t1 * 1e3:.1f} ms, step {h * 1e6:7.2f} us, "
                f"{steps} steps, {el:6.1f} s, ETA {eta:6.1f} s")
        sys.stderr.write(f"\r{line} " if self.tty else f"dynamics: {line}\n")
        sys.stderr.flush()

    def close(self) -> None:
        if self.enabled and self.last and self.tty:
            sys.stderr.write("\n")


def simulate(g: BearingGeometry, bearing: BearingData, material: MaterialData, lubricant, friction, *,
             temperature_K: float, speed_profile: Sequence[tuple[float, float]], duration_s: float,
             axial_N: float | None = None, axial_offset_m: float | None = None, radial_N: float = 0.0,
             misalignment_rad: float = 0.0, slices: int = 20, method: str = "independent", cage: bool = True,
             output_interval_s: float = 1e-4, average_fraction: float = 0.5, rtol: float = 1e-7,
             steady_tolerance: float = STEADY_TOLERANCE,
             atol_velocity_m_s: float = ATOL_VELOCITY_M_S,
             damping_time_s: float | None = None, elements: Sequence[Any] = (), progress: bool = False,
             checkpoint: str | Path | None = None, checkpoint_interval_s: float = 5e-3,
             initial_speed_rad_s: float | None = None, coloured_jacobian: bool = True,
             integrator_options: dict[str, Any] | None = None,
             raise_on_failure: bool = True, hold_axial: bool = False, tilt_free: bool = False,
             tilt_moment_Nm: float = 0.0,
             max_ring_displacement_m: float = 0.5e-3, checkpoint_key: str = "", threads: int = 1,
             load_profile: Sequence[tuple[float, float, float]] = (),
             max_duration_s: float | None = None, inner_ring_temperature_K: float | None = None,
             outer_ring_temperature_K: float | None = None) -> DynamicResult:
    """Run the dynamic simulation along a speed profile.

    Parameters
    ----------
    speed_profile
        (time_s, inner-ring speed in rad/s) points; linear in between, constant after the last.
    duration_s
        Simulated time (at least; see ``max_duration_s``).
    inner_ring_temperature_K, outer_ring_temperature_K
        Contact temperature of the inner ring's contacts (raceway and rib) and of the outer
        raceway's [K]; ``None`` (default): ``temperature_K``. The hydraulic losses keep the oil
        temperature.
    max_duration_s
        Automatic duration: a run whose torques and cage speed have not settled (:func:`settling`)
        by ``duration_s`` goes on, a quarter of ``duration_s`` at a time, until they settle or the
        run reaches this cap (at most the scenes' limit of a dynamic run). ``stats["duration_s"]``
        gives the simulated time, ``stats["extended"]`` whether it went past ``duration_s``. None:
        exactly ``duration_s``.
    axial_N, axial_offset_m
        Force-controlled axial load (the ring is free axially) or a held axial offset towards the
        apex (the ring is held axially at the quasi-static position for that offset).
    output_interval_s
        Spacing of the recorded outputs.
    average_fraction
        The last part of the run that the averages cover when the run has not settled (its
        figures are then not a steady answer: ``steady["settled"]`` is false).
    steady_tolerance
        Relative tolerance of the steady test (:func:`settling`).
    elements
        Force elements (``kegel._core.dynamics.DragElement``, ``PythonForceElement``) acting on the
        rollers and the cage: the hydraulic forces of the coupling layer.
    checkpoint
        A file (.npz) the state is written to every ``checkpoint_interval_s`` (atomically); when it
        exists at the start and was written with the same ``checkpoint_key`` (a fingerprint of the
        inputs), the run resumes from it; a finished run removes it.
    misalignment_rad, tilt_free, tilt_moment_Nm
        The inner ring's tilt about y: held at ``misalignment_rad`` (a shaft held by its other
        bearings), or free from there (``tilt_free``) under ``tilt_moment_Nm``, with the
        gyroscopic moments of the spinning ring.
    hold_axial
        Hold the inner ring axially where the quasi-static solution put it (the partner bearing
        of an adjusted pair): needed when the axial load cannot hold the rollers in the cup, e.g.
        a light load at high speed, where the centrifugal force pushes the rollers out of the cup
        with more than the axial load.
    load_profile
        (time_s, axial_N, radial_N) points of a load history (linear in between, held after the
        last point); the initial state is solved for the loads at t = 0. With ``axial_offset_m``
        (or ``hold_axial``) the axial values are not used.
    threads
        Rollers evaluated in parallel (OpenMP); the results do not depend on it. Python force
        elements run serially.
    max_ring_displacement_m
        The run stops with :class:`SimulationDiverged` when the inner ring moves further: the
        bearing has come apart (far beyond any elastic deflection).
    atol_velocity_m_s
        Absolute tolerance of the velocities (:data:`ATOL_VELOCITY_M_S`); velocities and rates
        have no relative tolerance (a relative one on the orbital speed would not bound the
        sliding speed that sets the friction).
    integrator_options
        Numerical switches of ``kegel._core.dynamics.IntegratorSettings`` by name (for
        benchmarks and checks): ``structured_linear_solver`` (block-arrow LU of the Newton
        matrix, default true; false: SUNDIALS' dense LU), ``quadratures_in_state`` (the torque
        and power integrals as states, default true; false: CVODES' quadratures, one more
        evaluation of the contacts per step), ``jacobian_max_age_steps`` (0: CVODE's 51),
        ``max_step_s``, ``max_steps``. Unknown names are an error.
    initial_speed_rad_s
        Speed of the quasi-static initial state (default: the profile's speed at t = 0; with 0 the
        bodies start at rest).
    """
    # the limits of a dynamic scene (kegel.scene), the same for the Python API
    from ..model.lubricant import lubricant_state
    from ..model.scene import (MAX_DYNAMIC_DURATION_S, MAX_DYNAMIC_OUTPUTS, MIN_OUTPUT_INTERVAL_S, _speed_limit_text,
                               centrifugal_seating_error, max_speed_rpm, static_equivalent_load_N)
    from ..base.units import RPM_TO_RAD_S

    if (axial_N is None) == (axial_offset_m is None):
        raise KegelInputError("<argument>", "axial_N", axial_N, "exactly one of axial_N and axial_offset_m")
    if not 0 < duration_s <= MAX_DYNAMIC_DURATION_S:
        raise KegelInputError("<argument>", "duration_s", duration_s,
                              f"a time > 0 and at most {MAX_DYNAMIC_DURATION_S:g} s (time steps are microseconds)")
    if not (MIN_OUTPUT_INTERVAL_S <= output_interval_s <= duration_s):
        raise KegelInputError("<argument>", "output_interval_s", output_interval_s,
                              f"in [{MIN_OUTPUT_INTERVAL_S:g}, {duration_s:g}] s")
    if max_duration_s is not None and not duration_s <= max_duration_s <= MAX_DYNAMIC_DURATION_S:
        raise KegelInputError("<argument>", "max_duration_s", max_duration_s,
                              f"a time from duration_s = {duration_s:g} s to {MAX_DYNAMIC_DURATION_S:g} s")
    if max(duration_s, max_duration_s or 0.0) / output_interval_s > MAX_DYNAMIC_OUTPUTS:
        raise KegelInputError("<argument>", "output_interval_s", output_interval_s,
                              f"at most {MAX_DYNAMIC_OUTPUTS} outputs (here {duration_s / output_interval_s:.3g})")
    lubricant_state(lubricant, temperature_K, key="temperature_K")
    prof = np.asarray(speed_profile, dtype=float)
    if prof.ndim != 2 or prof.shape[1] != 2 or not np.all(np.diff(prof[:, 0]) > 0) or not np.isfinite(prof).all():
        raise KegelInputError("<argument>", "speed_profile", speed_profile,
                              "(time_s, speed_rad_s) pairs with increasing times")
    if not np.all(np.abs(prof[:, 1]) / RPM_TO_RAD_S <= max_speed_rpm(bearing)):
        raise KegelInputError("<argument>", "speed_profile", speed_profile, f"speeds with {_speed_limit_text(bearing)}")
    for fa, fr in ([(axial_N, radial_N)] if axial_N is not None else []) + [
            (row[1], row[2]) for row in np.asarray(load_profile, dtype=float).reshape(-1, 3)]:
        if math.isfinite(fa) and math.isfinite(fr) and fa > 0 and fr >= 0 \
                and static_equivalent_load_N(g, fa, fr) > bearing.C0r_N:
            raise KegelInputError("<argument>", "axial_N" if not len(load_profile) else "load_profile", (fa, fr),
                                  f"loads whose ISO 76 static equivalent load stays within C0r = "
                                  f"{bearing.C0r_N / 1e3:g} kN")
    from ..model.scene import check_operating_point  # the scenes' ranges of the loads and the misalignment

    check_operating_point(bearing, g, axial_N=axial_N, axial_offset_m=axial_offset_m, radial_N=radial_N,
                          misalignment_rad=misalignment_rad)
    w_start = float(np.interp(0.0, prof[:, 0], prof[:, 1])) if initial_speed_rad_s is None else initial_speed_rad_s
    loads = np.asarray(load_profile, dtype=float).reshape(-1, 3) if len(load_profile) else np.zeros((0, 3))
    if len(loads) and (not np.all(np.diff(loads[:, 0]) > 0) or not np.isfinite(loads).all()
                       or (loads[:, 1:] < 0).any()):
        raise KegelInputError("<argument>", "load_profile", load_profile,
                              "(time_s, axial_N, radial_N) points with increasing times and loads >= 0")
    if len(loads):  # the initial state is solved for the loads at t = 0
        if axial_N is not None:
            axial_N = float(np.interp(0.0, loads[:, 0], loads[:, 1]))
        radial_N = float(np.interp(0.0, loads[:, 0], loads[:, 2]))
    wall0 = time.perf_counter()
    model, qs_model = dynamic_model(g, bearing, material, lubricant, friction, temperature_K=temperature_K,
                                    slices=slices, method=method, cage=cage, damping_time_s=damping_time_s,
                                    inner_ring_temperature_K=inner_ring_temperature_K,
                                    outer_ring_temperature_K=outer_ring_temperature_K)
    # initial state from the quasi-static solution at the start speed; where that has no
    # solution (a light load at high speed: the centrifugal force lifts the rollers off the
    # inner ring, which is the skidding case), from the load distribution at rest, turning at
    # pure-rolling kinematics: the dynamic run then finds its own state
    qs_data = _core.quasi_static.BearingData(qs_model)
    # a force-controlled load at or below the rollers' centrifugal share has no quasi-static state
    seated = axial_N is None or centrifugal_seating_error(g, float(axial_N), w_start) is None
    start = None  # the converged quasi-static solution at the start speed, where there is one
    if abs(w_start) > 0 and seated:
        try:
            _, start = bearing_friction(g, bearing, material, lubricant, friction, temperature_K=temperature_K,
                                        inner_speed_rad_s=w_start, axial_N=axial_N, axial_offset_m=axial_offset_m,
                                        radial_N=radial_N, misalignment_rad=misalignment_rad, model=qs_model,
                                        data=qs_data, cage=cage, inner_ring_temperature_K=inner_ring_temperature_K,
                                        outer_ring_temperature_K=outer_ring_temperature_K)
        except RuntimeError:  # KegelSolverError: no load distribution or no power at the start
            start = None
    if start is not None and start.converged:
        initial = "quasi_static"
        wc, spins = start.cage_speed_rad_s, list(start.roller_spin_rad_s)
        wc_pure = start.cage_speed_pure_rolling_rad_s
    else:
        wc_pure = _pure_rolling(g, w_start)[0]
        qs_data = _core.quasi_static.BearingData(qs_model)  # a failed attempt's state is no start
        load_distribution(g, bearing, material, axial_N=axial_N, axial_offset_m=axial_offset_m, radial_N=radial_N,
                          misalignment_rad=misalignment_rad, model=qs_model, data=qs_data)
        if abs(w_start) > 0:
            wc, spins = _pure_rolling(g, w_start)
            initial = "load distribution at rest, pure rolling"
        else:
            wc, spins = 0.0, [0.0] * g.roller_count
            initial = "quasi_static"
    y0 = np.asarray(D.initial_state(model, qs_data, wc, spins))
    drive = D.RingDrive()
    drive.time_s = list(prof[:, 0])
    drive.speed_rad_s = list(prof[:, 1])
    if axial_N is not None and not hold_axial:
        drive.axial_N = axial_N
    else:
        drive.free_z = False
    drive.radial_N = radial_N
    if len(loads):
        drive.load_time_s = list(loads[:, 0])
        drive.axial_profile_N = list(loads[:, 1]) if (axial_N is not None and not hold_axial) else [0.0] * len(loads)
        drive.radial_profile_N = list(loads[:, 2])
    drive.tilt_free = tilt_free
    drive.tilt_moment_y_Nm = tilt_moment_Nm
    st = D.IntegratorSettings()
    st.rtol = rtol
    st.threads = threads
    st.atol_velocity_m_s = atol_velocity_m_s
    st.atol_rate_rad_s = atol_velocity_m_s / g.roller_mean_diameter_m * 2.0
    st.atol_position_m = 1e-3 * atol_velocity_m_s / max(abs(w_start), 1.0) + 1e-12
    st.coloured_jacobian = coloured_jacobian
    for key, value in (integrator_options or {}).items():
        if key.startswith("_") or not hasattr(st, key):
            raise KegelInputError("<argument>", f"integrator_options.{key}", value,
                                  "an attribute of kegel._core.dynamics.IntegratorSettings")
        setattr(st, key, value)
    t_start = 0.0
    rows: dict[str, list] = {}
    times: list[float] = []
    states: list[np.ndarray] = []
    quads: list[np.ndarray] = []
    ck = Path(checkpoint) if checkpoint is not None else None
    resumed_from = None
    saved = _load_checkpoint(ck, checkpoint_key, y0.shape) if ck is not None and ck.exists() else None
    if saved is not None:
        t_start, y0 = float(saved["t"]), saved["y"]
        resumed_from = t_start
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
    integration_s = integration_cpu_s = 0.0
    pace = _Pace()
    end_s = duration_s
    while True:
        for tk in grid:
            if tk > sim.time_s:
                t_int, c_int = time.perf_counter(), time.process_time()
                flag = pace.advance(sim, float(tk))
                integration_s += time.perf_counter() - t_int
                integration_cpu_s += time.process_time() - c_int
                if flag != 0:
                    finished, message = False, sim.message
                    break
            out = sim.outputs()
            yr = np.asarray(sim.state)[model.ring_offset:model.ring_offset + 3]
            moved = float(np.linalg.norm(yr - y0[model.ring_offset:model.ring_offset + 3]))
            if moved > max_ring_displacement_m:
                finished = False
                message = (f"the inner ring moved {moved * 1e3:.2f} mm from its initial place by t = {sim.time_s * 1e3:.3f} ms "
                           f"(displacement {np.array2string(yr * 1e3, precision=3)} mm): the bearing comes apart. A single "
                           f"tapered roller bearing needs an axial load above the axial component of the roller "
                           f"loads (centrifugal force at speed, Fr tan(alpha_o) under radial load); hold the ring "
                           f"axially (hold_axial) to model the partner bearing")
                break
            times.append(float(sim.time_s))
            states.append(np.asarray(sim.state))
            quads.append(np.asarray(sim.quadratures))
            _record(rows, out)
            prog.update(sim.time_s, sim.last_step_s, sim.steps)
            if ck is not None and sim.time_s - last_ck >= checkpoint_interval_s - 1e-15:
                _save_checkpoint(ck, sim.time_s, np.asarray(sim.state), times, states, quads, rows, checkpoint_key)
                last_ck = sim.time_s
        # automatic duration: a run that has not settled by duration_s goes on, a quarter of
        # duration_s at a time, until it settles or reaches max_duration_s
        if not finished or max_duration_s is None or end_s >= max_duration_s - 1e-15 or len(times) < 2:
            break
        tt = np.asarray(times)
        if settling(tt, np.asarray(quads), g, float(np.interp(tt[-1], prof[:, 0], prof[:, 1])),
                    output_interval_s=output_interval_s, tol=steady_tolerance).settled:
            break
        new_end = min(end_s + max(0.25 * duration_s, 2.0 * output_interval_s), max_duration_s)
        grid = end_s + output_interval_s * np.arange(1, int((new_end - end_s) / output_interval_s) + 2)
        grid = np.append(grid[grid < new_end - 0.5 * output_interval_s], new_end)
        grid = grid[grid > sim.time_s + 1e-15]
        end_s = new_end
    prog.close()
    t = np.asarray(times)
    series = {k: np.asarray(v, dtype=float) for k, v in rows.items()}
    Q = np.asarray(quads)
    if len(t) > 1:
        series.update(_interval_means(t, Q))
    if finished and ck is not None:
        ck.unlink(missing_ok=True)
    stats = {"initial_state": initial, "resumed_from_s": resumed_from, "integration_wall_s": integration_s,
             "integration_cpu_s": integration_cpu_s,
             "duration_s": float(times[-1]) if times else 0.0, "extended": end_s > duration_s,
             "cage_to_inner_speed_pure_rolling": (wc_pure / w_start if w_start else _pure_rolling(g, 1.0)[0]),
             "steps": sim.steps, "rhs_evaluations": sim.rhs_evaluations,
             "jacobian_evaluations": sim.jacobian_evaluations, "state_size": model.state_size,
             "slices": slices, "method": method, "cage": cage, "rtol": rtol}
    steady: dict[str, Any] = {}
    if len(t) > 1:
        settled = settling(t, Q, g, float(np.interp(t[-1], prof[:, 0], prof[:, 1])),
                           output_interval_s=output_interval_s, tol=steady_tolerance)
        ok = settled.settled and finished
        fallback = t[min(int(np.searchsorted(t, t[0] + (1.0 - average_fraction) * (t[-1] - t[0]))), len(t) - 2)]
        steady = _steady(t, series, Q, settled.start if ok else fallback)
        info = settled.as_dict()
        info["window_s"], info["hold_s"] = info.pop("window"), info.pop("hold")
        info["settled_from_s"], info["end_s"] = info.pop("start"), info.pop("end")
        if not finished:
            info["reason"] = "the run stopped before its end: " + (message or "the integration failed")
        steady["settled"] = ok
        steady["power_balanced"] = power_balanced(steady["power_balance_error"])
        steady["drift_relative"] = info["drift_relative"]
        steady["settling"] = info
    res = DynamicResult(time_s=t, series=series, steady=steady, stats=stats, states=np.asarray(states), quadratures=Q,
                        runtime_s=time.perf_counter() - wall0, finished=finished, message=message)
    if not finished and raise_on_failure:
        raise SimulationDiverged(_divergence_report(res, message))
    return res


def _pure_rolling(g: BearingGeometry, inner_speed_rad_s: float) -> tuple[float, list[float]]:
    """Cage speed and roller spins (relative to the cage) of pure rolling on both raceways: the
    rolling cones share their apex, so the speeds go with the radii at the middle contact."""
    r_i = 0.5 * g.inner_raceway_diameter_mid_m
    wc = cage_speed_rad_s(g, inner_speed_rad_s)
    rho = 0.5 * g.roller_mean_diameter_m
    # radii perpendicular to the axes at the contact: the ring's r, the roller's rho / cos(gamma)
    spin = -(inner_speed_rad_s - wc) * r_i / (rho / math.cos(g.roller_half_angle_rad))
    return wc, [spin] * g.roller_count


def _load_checkpoint(path: Path, key: str, shape: tuple) -> dict[str, Any] | None:
    """The saved state of an interrupted run, or None. A checkpoint written for other inputs, or
    one that cannot be read (cut short by a full disk or a kill), is discarded with a message
    naming the file, and the point starts afresh."""
    import sys
    import zipfile

    names = ("t", "y", "times", "states", "quads", "rows", "key")
    try:
        with np.load(path, allow_pickle=False) as f:
            saved = {k: f[k] for k in names}
    except (OSError, ValueError, KeyError, EOFError, zipfile.BadZipFile) as exc:
        print(f"kegel: checkpoint {path} is unreadable ({type(exc).__name__}: {exc}); discarded, the point "
              "starts afresh", file=sys.stderr)
        path.unlink(missing_ok=True)
        return None
    if str(saved["key"]) != key or saved["y"].shape != shape:
        print(f"kegel: checkpoint {path} was written for other inputs; discarded, the point starts afresh",
              file=sys.stderr)
        return None  # overwritten by this run's first checkpoint
    return saved


class _Pace:
    """Advances the integrator to an output time in pieces of about :attr:`budget_s` of wall time,
    so that Python answers Ctrl-C within that time (the integrator is C++: a KeyboardInterrupt
    waits for it to return; one output interval took 2.4 s). CVODE in normal mode steps past each
    target and interpolates, so the intermediate targets do not change its internal steps: the
    answer is the same as with one call per output (checked in tests/python/test_dynamics.py)."""

    budget_s = 0.2
    FIRST_PIECE_S = 1e-4

    def __init__(self) -> None:
        self.rate = 0.0  # wall seconds per simulated second, from the last piece

    def advance(self, sim: Any, t_end: float) -> int:
        while sim.time_s < t_end:
            t0, w0 = sim.time_s, time.perf_counter()
            # the first piece: a sixteenth of the interval, at most FIRST_PIECE_S of simulated time
            # (the same whatever the budget, so the integrator's first step, which CVODE estimates
            # from it, does not depend on the budget; short, so a long interval still answers
            # Ctrl-C before the rate is known)
            target = t_end if self.rate > 0.0 else t0 + min((t_end - t0) / 16.0, self.FIRST_PIECE_S)
            if self.rate > 0.0:
                target = min(t_end, t0 + self.budget_s / self.rate)
                if t_end - target < 1e-3 * (t_end - t0):
                    target = t_end  # no sliver of a piece before an output
            flag = sim.advance(float(target))
            if flag != 0:
                return flag
            if sim.time_s > t0:
                self.rate = (time.perf_counter() - w0) / (sim.time_s - t0)
        return 0


def _save_checkpoint(path: Path, t: float, y: np.ndarray, times: list, states: list, quads: list,
                     rows: dict, key: str) -> None:
    from ..base.io import atomic_save

    atomic_save(path, lambda tmp: np.savez(tmp, t=t, y=y, times=np.asarray(times), states=np.asarray(states),
                                           quads=np.asarray(quads), rows=json.dumps(rows), key=key),
                suffix=".tmp.npz")


def _divergence_report(res: DynamicResult, message: str) -> str:
    lines = [message or "the integration stopped"]
    if len(res.time_s):
        s = res.series
        lines.append(f"last good output at t = {res.time_s[-1] * 1e3:.4f} ms: inner speed "
                     f"{s['inner_speed_rad_s'][-1]:.2f} rad/s, cage {s['cage_speed_rad_s'][-1]:.2f} rad/s, "
                     f"largest interference {s['max_penetration_m'][-1] * 1e6:.3f} um, kinetic energy "
                     f"{s['kinetic_energy_J'][-1]:.4g} J")
    return "; ".join(lines)


# ------------------------------------------------------------------------------------------
# Result files: JSON + CSV + VTK time series + plots, each written atomically
# ------------------------------------------------------------------------------------------

def _json_safe(x: Any) -> Any:
    if isinstance(x, dict):
        return {k: _json_safe(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_json_safe(v) for v in x]
    if isinstance(x, (np.floating, float)):
        return float(x) if math.isfinite(float(x)) else None
    if isinstance(x, (np.integer,)):
        return int(x)
    if isinstance(x, np.ndarray):
        return _json_safe(x.tolist())
    return x


def write_result(res: DynamicResult, directory: str | Path, meta: dict[str, Any] | None = None, *,
                 g: BearingGeometry | None = None, vtk: bool = True, plots: bool = True,
                 vtk_every: int = 1) -> dict[str, str]:
    """Write a dynamic run: ``dynamic.json`` (steady averages, spreads, power balance, solver
    statistics, runtime, ``meta``: scene, fidelity, provenance), ``series.csv`` (scalars and
    interval means over time), ``roller_series.npz`` (per-roller series), a VTK time series of
    the bodies (``bodies.pvd`` + ``vtk/bodies_NNNN.vtu``, needs ``g``) and ``dynamic.png``."""
    from ..base.io import atomic_write_json, atomic_write_text, provenance

    out = Path(directory)
    out.mkdir(parents=True, exist_ok=True)
    files: dict[str, str] = {}
    doc = {"meta": meta or {}, "provenance": provenance(), "finished": res.finished, "message": res.message,
           "runtime_s": res.runtime_s, "revolutions": res.revolutions,
           "wall_time_per_revolution_s": res.runtime_s / res.revolutions if res.revolutions > 0 else None,
           "steady": res.steady, "stats": res.stats,
           "final": {k: res.series[k][-1] for k in res.series if res.series[k].ndim == 1}}
    files["json"] = str(atomic_write_json(out / "dynamic.json", _json_safe(doc)))
    scal = [k for k in res.series if res.series[k].ndim == 1]
    lines = [",".join(["time_s"] + scal)]
    for i, t in enumerate(res.time_s):
        lines.append(",".join([repr(float(t))] + [repr(float(res.series[k][i])) for k in scal]))
    files["csv"] = str(atomic_write_text(out / "series.csv", "\n".join(lines) + "\n"))
    tmp = out / ".roller_series.tmp.npz"
    np.savez(tmp, time_s=res.time_s, **{k: v for k, v in res.series.items() if v.ndim == 2}, states=res.states)
    os.replace(tmp, out / "roller_series.npz")
    files["roller_series"] = str(out / "roller_series.npz")
    if vtk and g is not None and len(res.states):
        files["vtk"] = str(write_vtk_series(res, g, out, every=vtk_every))
    if plots and len(res.time_s) > 1:
        files["plot"] = plot_result(res, out / "dynamic.png")
    return files


def _roller_surface(g: BearingGeometry, n_seg: int = 16) -> tuple[np.ndarray, np.ndarray]:
    """Triangulated truncated cone of a roller in its own frame (axis z, centre of mass at 0)."""
    L, r_m, tg = g.roller_length_m, 0.5 * g.roller_mean_diameter_m, math.tan(g.roller_half_angle_rad)
    c = g.roller_com_offset_m
    ang = np.linspace(0, 2 * math.pi, n_seg, endpoint=False)
    pts = []
    for xi in (-0.5 * L, 0.5 * L):
        r = r_m + xi * tg
        pts += [(r * math.cos(a), r * math.sin(a), xi - c) for a in ang]
    pts += [(0, 0, -0.5 * L - c), (0, 0, 0.5 * L - c)]
    tri = []
    for k in range(n_seg):
        k1 = (k + 1) % n_seg
        tri += [(k, k1, n_seg + k), (k1, n_seg + k1, n_seg + k)]
        tri += [(2 * n_seg, k1, k), (2 * n_seg + 1, n_seg + k, n_seg + k1)]
    return np.asarray(pts, float), np.asarray(tri, int)


def _cage_surface(g: BearingGeometry, n_seg: int = 96) -> tuple[np.ndarray, np.ndarray]:
    """The cage's conical shell (mid-surface, windows not cut) in the cage frame (origin at
    the cage centre on the axis)."""
    beta, Dw, L = g.roller_axis_angle_rad, g.roller_mean_diameter_m, g.roller_length_m
    rp, off = 0.5 * g.cage_pitch_diameter_m, CAGE_OFFSET_RATIO * Dw
    ang = np.linspace(0, 2 * math.pi, n_seg, endpoint=False)
    pts = []
    for s in (-(0.5 + CAGE_OVERHANG_RATIO) * L, (0.5 + CAGE_OVERHANG_RATIO) * L):
        r = rp + s * math.sin(beta) + off * math.cos(beta)
        z = s * math.cos(beta) - off * math.sin(beta)
        pts += [(r * math.cos(a), r * math.sin(a), z) for a in ang]
    tri = []
    for k in range(n_seg):
        k1 = (k + 1) % n_seg
        tri += [(k, k1, n_seg + k), (k1, n_seg + k1, n_seg + k)]
    return np.asarray(pts, float), np.asarray(tri, int)


def _frame_from_axis(a: np.ndarray) -> np.ndarray:
    a = a / np.linalg.norm(a)
    t = np.array([1.0, 0, 0]) if abs(a[0]) < 0.9 else np.array([0, 1.0, 0])
    e1 = np.cross(a, t)
    e1 /= np.linalg.norm(e1)
    return np.column_stack([e1, np.cross(a, e1), a])


def _quat_matrix(q: np.ndarray) -> np.ndarray:
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def write_vtk_series(res: DynamicResult, g: BearingGeometry, directory: Path, every: int = 1) -> Path:
    """Bodies (rollers and cage; frame R, metres) at each output time as ``.vtu`` files and a
    ParaView collection ``bodies.pvd`` (meshio). Cell data: body id (-1 cage, j roller j);
    point data: velocity. Rollers are bodies of revolution: their spin angle is not a state, so
    their surfaces show position and axis, not the spin."""
    import meshio

    vdir = directory / "vtk"
    vdir.mkdir(parents=True, exist_ok=True)
    Z = g.roller_count
    rp, rt = _roller_surface(g)
    cp, ct = _cage_surface(g)
    entries = []
    for i in range(0, len(res.time_s), max(1, every)):
        y = res.states[i]
        pts, tris, body, vel = [], [], [], []
        n0 = 0
        for j in range(Z):
            yr = y[12 * j:12 * j + 12]
            R = _frame_from_axis(yr[3:6])
            P = yr[:3] + rp @ R.T
            V = yr[6:9] + np.cross(yr[9:12], P - yr[:3])
            pts.append(P)
            vel.append(V)
            tris.append(rt + n0)
            body += [j] * len(rt)
            n0 += len(P)
        yc = y[12 * Z:12 * Z + 13]
        Rc = _quat_matrix(yc[3:7])
        P = yc[:3] + cp @ Rc.T
        wc = Rc @ yc[10:13]
        pts.append(P)
        vel.append(yc[7:10] + np.cross(wc, P - yc[:3]))
        tris.append(ct + n0)
        body += [-1] * len(ct)
        mesh = meshio.Mesh(np.vstack(pts), [("triangle", np.vstack(tris))],
                           point_data={"velocity_m_s": np.vstack(vel)},
                           cell_data={"body": [np.asarray(body, dtype=np.int32)]})
        name = f"bodies_{i:05d}.vtu"
        tmp = vdir / f".{name}.tmp.vtu"
        meshio.write(tmp, mesh)
        os.replace(tmp, vdir / name)
        entries.append((float(res.time_s[i]), f"vtk/{name}"))
    xml = ['<?xml version="1.0"?>', '<VTKFile type="Collection" version="0.1">', "  <Collection>"]
    xml += [f'    <DataSet timestep="{t:.9g}" file="{f}"/>' for t, f in entries]
    xml += ["  </Collection>", "</VTKFile>", ""]
    from ..base.io import atomic_write_text
    return atomic_write_text(directory / "bodies.pvd", "\n".join(xml))


def plot_result(res: DynamicResult, path: str | Path) -> str:
    """Torques (interval means), speeds, roller loads and the power balance over time."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t = res.time_s * 1e3
    s = res.series
    fig, ax = plt.subplots(2, 2, figsize=(11, 7))
    a = ax[0, 0]
    a.plot(t, s["mean_outer_ring_torque_Nm"], label="outer ring (reaction)")
    a.plot(t, s["mean_drive_torque_Nm"], ls="--", label="drive (inner ring)")
    for c in CONTACTS:
        a.plot(t, s[f"mean_torque_{c}_Nm"], lw=0.8, alpha=0.7, label=c.replace("_", " "))
    if res.steady:
        a.axvspan(res.steady["window_start_s"] * 1e3, res.steady["window_end_s"] * 1e3, color="0.9", zorder=0)
    a.set_ylabel("torque [N m] (mean over each output interval)")
    a.legend(fontsize=7)
    a = ax[0, 1]
    a.plot(t, s["inner_speed_rad_s"] * 30 / math.pi, label="inner ring")
    a.plot(t, s["cage_speed_rad_s"] * 30 / math.pi, label="cage")
    a.plot(t, np.mean(s["roller_spin_rad_s"], axis=1) * 30 / math.pi, ls=":", label="roller spin (mean, rel. cage)")
    a.set_ylabel("speed [rpm]")
    a.legend(fontsize=7)
    a = ax[1, 0]
    Z = s["roller_inner_N"].shape[1]
    for j in range(0, Z, max(1, Z // 4)):
        a.plot(t, s["roller_inner_N"][:, j], lw=0.8, label=f"roller {j}, inner")
    a.plot(t, s["roller_cage_N"].max(axis=1), color="k", lw=0.8, label="largest cage-window force")
    a.set_ylabel("load [N]")
    a.set_xlabel("time [ms]")
    a.legend(fontsize=7)
    a = ax[1, 1]
    a.plot(t, s["mean_power_input_W"], label="input (drive)")
    P = sum(s[f"mean_power_{c}_{m}_W"] for c in CONTACTS for m in MECHANISMS) + s["mean_cage_power_W"] + \
        s["mean_damping_power_W"] + s["mean_external_power_W"]
    a.plot(t, P, ls="--", label="dissipated (contacts, cage, damping, oil)")
    a.set_ylabel("power [W]")
    a.set_xlabel("time [ms]")
    a.legend(fontsize=7)
    st = res.steady
    if st:
        what = "steady means" if st.get("settled") else "NOT SETTLED: means"
        fig.suptitle(f"{what} over {st['window_start_s'] * 1e3:.1f}-{st['window_end_s'] * 1e3:.1f} ms: "
                     f"outer-ring torque {st['outer_ring_torque_Nm'] * 1e3:.2f} mN m "
                     f"(std of interval means {st['outer_ring_torque_std'] * 1e3:.2f}), power balance "
                     f"{100 * st['power_balance_error']:+.2f} %; wall {res.runtime_s:.1f} s", fontsize=9)
    fig.tight_layout()
    path = Path(path)
    fd_tmp = path.with_name(f".{path.stem}.tmp{path.suffix}")
    fig.savefig(fd_tmp, dpi=110)
    plt.close(fig)
    os.replace(fd_tmp, path)
    return str(path)
