"""Flow forces on rollers and cage as force elements of the dynamic simulation.

The oil acts on the moving bodies: it drags each roller along its orbit, brakes its spin and
churns against the cage. This module turns a hydraulic result into force laws the dynamic
simulation applies to the bodies (:func:`kegel.simulate`, ``elements=[law.element()]``).

From a correlation (:func:`flow_forces_from_correlation`)
    Liebrecht's roller-set drag (Eq. 38) as the quadratic drag of the C++
    ``kegel._core.dynamics.DragElement`` (F = -1/2 rho C_D A |u| u on every roller), fitted at
    the point's cage speed; the ring churning acts on the rings, whose speeds are prescribed, and
    is added to their torques instead.

From CFD results (:func:`flow_forces_from_cfd`, :class:`CfdFlowForceLaw`)
    Three power laws of the bodies' own speeds, each ``X = -X_ref (|s| / s_ref)^n sign(s)``:

    - roller orbit: the force on each roller against its centre's velocity u (oil at rest),
      ``F = -F_ref (|u| / u_ref)^n_orbit u / |u|``;
    - roller spin: the moment about the roller axis against its spin relative to the cage
      frame (where the oil around the rollers turns: the frame of the CFD),
      ``M = -M_ref (|w_s| / w_s,ref)^n_spin sign(w_s) a``;
    - cage: ``M_z = -M_ref (|w_z| / w_ref)^n_cage sign(w_z)``.

    The levels ``X_ref`` are those of the operating point's own CFD result, so the law gives its
    forces exactly at its kinematics. The exponents ``n`` are fitted by least squares in log-log
    axes over the speed sweep of the same CFD model (bearing, lubricant, temperature, oil level,
    geometry; per speed the finest mesh), and the fit's residuals are part of the law. A
    coefficient of the wrong sign (oil that drives a body instead of braking it) is an error:
    these laws cannot represent it.

What a CFD result must hold (``results.json`` of ``kegel cfd run``, also the compact copies of
``benchmarks/collect_cfd_results.py``): ``kinematics`` (cage and roller-spin speeds),
``torques_Nm.rollers_about_bearing_axis.total`` (sum over the rollers of the moment of the oil's
force and moment about the bearing axis, ``(c x F)_z + M_z``), ``torques_Nm.rollers_spin_sum.total``
(sum of ``M . a``) and ``cage.moment_Nm``. The orbit law's moment is the first less the spin
moments' share ``a_z`` times the second (the roller axis' component along the bearing axis): the
laws then take from the bodies exactly the power the CFD's rollers and cage give the oil,
``-(w_c (M_rollers,z + M_cage,z) + w_s M_spin)``, and the same moment about the bearing axis.
What this leaves out is the rollers' moment about axes normal to their own (skew and tilt
moments); only its share along the bearing axis is kept, inside the orbit law.

The law is a function of each body's own speed; a speed sweep scales the shaft, cage and spin
speeds together, so it identifies the joint exponent, not the partial one at a fixed shaft speed
(the oil swirl set by the inner ring). Near the CFD's kinematics (cage slip of a few per cent)
the difference is of the order of the slip times the exponent; it is stated in docs/cfd.md.
"""

from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from .. import _core
from ..base.errors import KegelInputError
from ..model.geometry import BearingGeometry

__all__ = ["CfdFlowForceLaw", "FlowForceLaw", "PowerLaw", "body_drags", "cfd_model_key", "cfd_sweep", "fit_exponent",
           "flow_forces_from_cfd", "flow_forces_from_correlation", "orbit_radius_m", "roller_axis_z"]

#: Keys of a CFD result's ``point`` that define the CFD model: results that share them (speed
#: aside) form one speed sweep. Every other key (mesh, cells across a gap, a periodic sector,
#: solver limits) sets the discretisation or the run, not the modelled flow.
MODEL_KEYS = ("bearing", "bearing_file", "lubricant", "material", "temperature_K", "oil_level_m", "frame", "cage",
              "housing_clearance_m", "gap_ratio", "clearance_ratio")

#: Below this fraction of the lowest speed of the sweep, the laws' |s| is smoothed as
#: sqrt(s^2 + s_0^2): an exponent below 1 has an infinite slope at rest, which the integrator's
#: finite-difference Jacobian cannot take. It changes the laws by less than 1e-6 relative at the
#: swept speeds.
SMOOTHING_FRACTION = 1e-3


@dataclass(frozen=True)
class FlowForceLaw:
    """Quadratic roller drag of the C++ ``DragElement`` (SI); ``element()`` gives the element.

    ``fitted_at`` records the operating point the law reproduces exactly and ``source`` where
    its numbers come from. Used for a correlation's roller-set drag.
    """

    oil_density_kg_m3: float
    roller_drag_coefficient: float
    roller_frontal_area_m2: float
    roller_spin_drag_Nms: float = 0.0
    cage_drag_Nms: float = 0.0
    swirl_ratio: float = 0.0
    source: str = ""
    fitted_at: dict[str, float] = field(default_factory=dict)

    def element(self) -> "_core.dynamics.DragElement":
        """The C++ force element for :func:`kegel.simulate` (``elements=[...]``)."""
        v = _core.dynamics.DragElementValues()
        v.oil_density_kg_m3 = self.oil_density_kg_m3
        v.roller_drag_coefficient = self.roller_drag_coefficient
        v.roller_frontal_area_m2 = self.roller_frontal_area_m2
        v.roller_spin_drag_Nms = self.roller_spin_drag_Nms
        v.cage_drag_Nms = self.cage_drag_Nms
        v.swirl_ratio = self.swirl_ratio
        return _core.dynamics.DragElement(v)

    def roller_orbit_force_N(self, orbit_speed_m_s: float) -> float:
        """Drag on one roller moving at ``orbit_speed_m_s`` through oil at rest (signed)."""
        return -0.5 * self.oil_density_kg_m3 * self.roller_drag_coefficient * self.roller_frontal_area_m2 * \
            abs(orbit_speed_m_s) * orbit_speed_m_s

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary."""
        return asdict(self)


@dataclass(frozen=True)
class PowerLaw:
    """``X(s) = -value_ref (|s| / speed_ref)^exponent sign(s)``: a drag that opposes the speed s.

    ``value_ref`` (> 0) is the drag's magnitude at ``speed_ref`` (> 0). ``fit`` holds the
    least-squares fit of the exponent over a speed sweep: its speeds, the magnitudes, the
    relative residuals of the fitted power law at each, and the files.
    """

    value_ref: float
    speed_ref: float
    exponent: float
    smoothing_speed: float = 0.0
    fit: dict[str, Any] = field(default_factory=dict)

    def __call__(self, s: float) -> float:
        """The signed drag at speed ``s`` (opposing it)."""
        a = math.sqrt(s * s + self.smoothing_speed ** 2)
        return -self.value_ref * (a / self.speed_ref) ** self.exponent * (s / a if a > 0 else 0.0)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary."""
        return asdict(self)


@dataclass(frozen=True)
class CfdFlowForceLaw:
    """Flow-force laws fitted to CFD results (SI): roller orbit force, roller spin moment, cage
    moment, each a :class:`PowerLaw` of the body's own speed (see the module docstring).

    ``orbit`` maps the roller centre's speed (m/s) to the force on one roller (N); ``spin`` the
    roller's spin relative to the cage frame (rad/s) to its moment about its axis (N m); ``cage``
    the cage speed (rad/s) to its moment about the bearing axis (N m). ``source`` names the
    operating point's CFD result, ``provenance`` the sweep the exponents come from.
    """

    orbit: PowerLaw
    spin: PowerLaw
    cage: PowerLaw
    orbit_radius_m: float
    roller_count: int
    source: str = ""
    fitted_at: dict[str, float] = field(default_factory=dict)
    provenance: dict[str, Any] = field(default_factory=dict)

    def element(self) -> "_core.dynamics.PythonForceElement":
        """The force element for :func:`kegel.simulate` (``elements=[...]``).

        A Python element (the C++ ``DragElement`` has fixed exponents); it costs about 1.6 times
        the C++ one's run time (32208, 2000 rpm, 50 N: 6.1 s against 3.8 s for 10 ms, one thread).
        """
        orbit, spin, cage = self.orbit, self.spin, self.cage

        def wrench(body: int, p: Any, axis: Any, v: Any, w: Any, t: float, w_inner: float, w_cage: float):
            if body < 0:
                return _ZERO, np.array((0.0, 0.0, cage(float(w[2]))))
            vx, vy, vz = float(v[0]), float(v[1]), float(v[2])
            u = math.sqrt(vx * vx + vy * vy + vz * vz)
            f = orbit(u) / u if u > 0 else 0.0        # signed magnitude per unit velocity
            ax, ay, az = float(axis[0]), float(axis[1]), float(axis[2])
            s = float(w[0]) * ax + float(w[1]) * ay + (float(w[2]) - w_cage) * az
            m = spin(s)
            return np.array((f * vx, f * vy, f * vz)), np.array((m * ax, m * ay, m * az))

        return _core.dynamics.PythonForceElement(wrench)

    def roller_orbit_force_N(self, orbit_speed_m_s: float) -> float:
        """Drag on one roller whose centre moves at ``orbit_speed_m_s`` through oil at rest (signed)."""
        return self.orbit(orbit_speed_m_s)

    def body_power_W(self, cage_speed_rad_s: float, roller_spin_rad_s: float, roller_axis_z: float) -> float:
        """The power the laws take from the rollers and the cage when every roller orbits at the
        cage speed on the orbit radius and spins at ``roller_spin_rad_s`` relative to the cage
        (> 0: the oil takes it). ``roller_axis_z``: the roller axis' component along the bearing
        axis (:func:`roller_axis_z`)."""
        wc, ws = cage_speed_rad_s, roller_spin_rad_s
        F = self.orbit(wc * self.orbit_radius_m)
        M = self.spin(ws)
        per_roller = F * wc * self.orbit_radius_m + M * (ws + wc * roller_axis_z)
        return -(self.roller_count * per_roller + self.cage(wc) * wc)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary."""
        return {"kind": "cfd power laws", "orbit": self.orbit.as_dict(), "spin": self.spin.as_dict(),
                "cage": self.cage.as_dict(), "orbit_radius_m": self.orbit_radius_m,
                "roller_count": self.roller_count, "source": self.source, "fitted_at": dict(self.fitted_at),
                "provenance": dict(self.provenance)}


_ZERO = np.zeros(3)


def flow_forces_from_correlation(hydraulic, g: BearingGeometry, *, density_kg_m3: float,
                                 cage_speed_rad_s: float) -> FlowForceLaw:
    """Fit the roller drag law to a correlation's roller-set drag torque at a cage speed.

    Parameters
    ----------
    hydraulic
        :class:`kegel.correlations.HydraulicTorques`; its ``cage_Nm`` is the drag of the roller
        set against the cage rotation (Liebrecht Eq. 38).
    g
        Derived bearing geometry.
    density_kg_m3, cage_speed_rad_s
        Oil density and the cage speed the torque was computed at.
    """
    if not (math.isfinite(cage_speed_rad_s) and cage_speed_rad_s != 0.0):
        raise KegelInputError("<argument>", "cage_speed_rad_s", cage_speed_rad_s, "a finite, non-zero cage speed")
    if not density_kg_m3 > 0:
        raise KegelInputError("<argument>", "density_kg_m3", density_kg_m3, "a density > 0")
    r = orbit_radius_m(g)
    u = cage_speed_rad_s * r
    A = g.roller_mean_diameter_m * g.roller_length_m
    F = abs(hydraulic.cage_Nm) / (g.roller_count * r)  # per roller, against its orbit
    cd = 2.0 * F / (density_kg_m3 * A * u * u)
    return FlowForceLaw(oil_density_kg_m3=density_kg_m3, roller_drag_coefficient=cd, roller_frontal_area_m2=A,
                        source=f"correlation {hydraulic.correlation}: roller-set drag {hydraulic.cage_Nm:.6g} N m",
                        fitted_at={"cage_speed_rad_s": cage_speed_rad_s, "roller_set_drag_Nm": abs(hydraulic.cage_Nm)})


# ------------------------------------------------------------------------------------------
# CFD: the bodies' drag at one result, the sweep, the fit
# ------------------------------------------------------------------------------------------

def roller_axis_z(g: BearingGeometry) -> float:
    """The roller axis' component along the bearing axis in the CFD (``cos`` of the roller
    axis angle; the CFD's axis runs from the small to the large end, its z along the bearing
    axis, see :mod:`kegel.cfd_cases.geometry`)."""
    return math.cos(g.roller_axis_angle_rad)


def cfd_model_key(point: dict[str, Any]) -> tuple:
    """The CFD model of a result's ``point`` (:data:`MODEL_KEYS`; a key a result does not state
    is None, so older results do not join newer ones that state it; a result without ``frame``
    or ``cage`` ran in the cage frame with the cage)."""
    defaults = {"frame": "cage", "cage": True}  # what a result that does not state them ran with
    out = []
    for k in MODEL_KEYS:
        v = point.get(k, defaults.get(k))
        out.append(round(float(v), 9) if isinstance(v, (int, float)) and not isinstance(v, bool) else v)
    return tuple(out)


def _get(data: dict[str, Any], path: str, src: str) -> float:
    cur: Any = data
    for part in path.split("."):
        if isinstance(cur, list):
            try:
                cur = cur[int(part)]
            except (ValueError, IndexError):
                cur = None
        else:
            cur = cur.get(part) if isinstance(cur, dict) else None
        if cur is None:
            raise KegelInputError(src, path, None, "a CFD result of kegel cfd run (results.json) holding this key")
    try:
        x = float(cur)
    except (TypeError, ValueError):
        raise KegelInputError(src, path, cur, "a number") from None
    if not math.isfinite(x):
        raise KegelInputError(src, path, cur, "a finite number")
    return x


def body_drags(data: dict[str, Any], g: BearingGeometry, *, source: str = "<dict>") -> dict[str, float]:
    """The drags of one CFD result on the bodies, signed as the CFD gives them (SI).

    Returns ``cage_rad_s``, ``roller_spin_rad_s``, ``inner_ring_rad_s``, ``orbit_moment_Nm``
    (per roller: the moment of the oil's force about the bearing axis, with the share of the skew
    and tilt moments along it), ``orbit_force_N`` (that moment over the orbit radius),
    ``spin_torque_Nm`` (per roller), ``cage_moment_Nm``.
    """
    if data.get("point", {}).get("cage") is False:
        raise KegelInputError(source, "point.cage", False, "a CFD result with the cage (this run left it out)")
    wc = _get(data, "kinematics.cage_rad_s", source)
    ws = _get(data, "kinematics.roller_spin_rad_s", source)
    wi = _get(data, "kinematics.inner_ring_rad_s", source)
    R = _get(data, "torques_Nm.rollers_about_bearing_axis.total", source)
    S = _get(data, "torques_Nm.rollers_spin_sum.total", source)
    Mc = _get(data, "cage.moment_Nm.2", source)
    Z = g.roller_count
    orbit = (R - S * roller_axis_z(g)) / Z
    return {"inner_ring_rad_s": wi, "cage_rad_s": wc, "roller_spin_rad_s": ws, "orbit_moment_Nm": orbit,
            "orbit_force_N": orbit / orbit_radius_m(g), "spin_torque_Nm": S / Z, "cage_moment_Nm": Mc}


_COMPONENTS = {
    # name: (speed key, drag key, what the drag is, the CFD keys it comes from)
    "orbit": ("cage_rad_s", "orbit_moment_Nm", "the oil's moment on each roller about the bearing axis",
              "(torques_Nm.rollers_about_bearing_axis.total - cos(roller axis angle) "
              "torques_Nm.rollers_spin_sum.total) / Z"),
    "spin": ("roller_spin_rad_s", "spin_torque_Nm", "the spin torque on each roller",
             "torques_Nm.rollers_spin_sum.total / Z"),
    "cage": ("cage_rad_s", "cage_moment_Nm", "the cage torque", "cage.moment_Nm[2]"),
}


def _check_sign(name: str, d: dict[str, float], src: str) -> None:
    sk, dk, what, keys = _COMPONENTS[name]
    s, x = d[sk], d[dk]
    if s == 0.0 or x == 0.0 or math.copysign(1.0, x) == math.copysign(1.0, s):
        raise KegelInputError(
            src, keys, x,
            f"{what} against the body's motion ({sk.replace('_rad_s', '')} speed {s:.6g} rad/s, so a moment of the "
            f"opposite sign): here the oil drives the body or leaves it alone, which the flow-force law (a drag "
            f"that opposes the body's own speed) cannot represent; check the run (steady, balance) or leave the "
            f"flow forces out (hydraulic = \"none\")")


def cfd_sweep(runs: Sequence[tuple[Path, dict[str, Any]]], point: dict[str, Any]) -> list[tuple[Path, dict[str, Any]]]:
    """The results among ``runs`` of the same CFD model as ``point`` (:func:`cfd_model_key`),
    one per speed (within 0.5 %; the finest mesh, by cells), sorted by speed."""
    key = cfd_model_key(point)
    rows: list[tuple[float, Path, dict[str, Any]]] = []
    for f, data in runs:
        pt = data.get("point") or {}
        if cfd_model_key(pt) != key:
            continue
        w = abs(float(pt.get("speed_rad_s") or 0.0))
        if w <= 0:
            continue
        cells = (data.get("fidelity") or {}).get("cells") or 0
        for i, (w2, _, d2) in enumerate(rows):
            if abs(w / w2 - 1.0) <= 0.005:
                if cells > ((d2.get("fidelity") or {}).get("cells") or 0):
                    rows[i] = (w, f, data)
                break
        else:
            rows.append((w, f, data))
    return [(f, d) for _, f, d in sorted(rows, key=lambda r: r[0])]


def fit_exponent(speeds: Sequence[float], values: Sequence[float]) -> tuple[float, float, list[float]]:
    """Least-squares fit of ``|value| = c |speed|^n`` in log-log axes.

    Returns ``(n, c, residuals)`` with the relative residual ``c |s|^n / |value| - 1`` at each
    point (zeros for two points, which the line passes through).
    """
    x = np.log(np.abs(np.asarray(speeds, dtype=float)))
    y = np.log(np.abs(np.asarray(values, dtype=float)))
    n, lnc = np.polyfit(x, y, 1)
    res = np.exp(lnc + n * x - y) - 1.0
    return float(n), float(math.exp(lnc)), [float(r) for r in res]


def flow_forces_from_cfd(anchor: dict[str, Any] | str | Path, g: BearingGeometry, *,
                         sweep: Sequence[tuple[Path, dict[str, Any]]] | str | Path | None = None,
                         source: str | None = None) -> CfdFlowForceLaw:
    """The flow-force laws of an operating point from its CFD result and a speed sweep.

    Parameters
    ----------
    anchor
        The operating point's CFD result (``results.json`` of ``kegel cfd run``, its path, or its
        contents with ``source`` naming where they came from): the laws' levels.
    g
        Derived bearing geometry of the bearing the CFD modelled.
    sweep
        CFD results (as :func:`kegel.coupling.read_cfd_results` gives them, or a file or folder
        of them) of which those of the anchor's CFD model give the exponents (at least two
        speeds). Default: the anchor alone, which is not enough.
    source
        Where ``anchor`` came from, for messages.

    Raises
    ------
    KegelInputError
        A key the laws need is missing; a drag of the wrong sign (at the anchor or at any speed of
        the sweep); fewer than two speeds in the sweep.
    """
    from .cfd_results import read_cfd_results

    src = source or "<dict>"
    if not isinstance(anchor, dict):
        src = str(anchor)
        try:
            anchor = json.loads(Path(anchor).read_text())
        except (OSError, json.JSONDecodeError) as exc:
            raise KegelInputError(src, "(file)", "", f"a readable CFD results.json ({exc})") from None
    if not isinstance(anchor.get("point"), dict):
        raise KegelInputError(src, "point", None, "a CFD result of kegel cfd run (results.json)")
    if sweep is None:
        runs: list[tuple[Path, dict[str, Any]]] = [(Path(src), anchor)]
    elif isinstance(sweep, (str, Path)):
        runs = read_cfd_results(sweep, source=src, key="sweep")
    else:
        runs = list(sweep)
    a = body_drags(anchor, g, source=src)
    for name in _COMPONENTS:
        _check_sign(name, a, src)
    members = cfd_sweep(runs, anchor["point"])
    drags = []
    for f, data in members:
        d = body_drags(data, g, source=str(f))
        for name in _COMPONENTS:
            _check_sign(name, d, str(f))
        drags.append((f, data, d))
    speeds_rpm = [abs(d["inner_ring_rad_s"]) * 30 / math.pi for _, _, d in drags]
    if len(drags) < 2:
        pt = anchor["point"]
        raise KegelInputError(
            src, "point.speed_rad_s", pt.get("speed_rad_s"),
            f"CFD results of the same model ({', '.join(f'{k} = {pt.get(k)!r}' for k in MODEL_KEYS if k in pt)}) "
            f"at two or more speeds, to fit the flow-force law's speed exponents (found "
            f"{', '.join(f'{s:.0f}' for s in speeds_rpm) or 'none'} rpm); run `kegel cfd run` (or `kegel cfd "
            f"sweep`) for this model at another speed")
    r = orbit_radius_m(g)
    laws = {}
    for name, (sk, dk, what, keys) in _COMPONENTS.items():
        s = [d[sk] for _, _, d in drags]
        x = [d[dk] for _, _, d in drags]
        n, _, res = fit_exponent(s, x)
        scale = r if name == "orbit" else 1.0        # the orbit law: force against the centre's speed
        ref_speed = abs(a[sk]) * scale
        ref_value = abs(a[dk]) / (r if name == "orbit" else 1.0)
        laws[name] = PowerLaw(value_ref=ref_value, speed_ref=ref_speed, exponent=n,
                              smoothing_speed=SMOOTHING_FRACTION * min(abs(v) for v in s) * scale,
                              fit={"speeds": [abs(v) * scale for v in s], "values": [abs(v) / scale for v in x],
                                   "relative_residuals": res, "max_abs_residual": max(abs(v) for v in res),
                                   "from": keys})
    files = [str(f) for f, _, _ in drags]
    return CfdFlowForceLaw(
        orbit=laws["orbit"], spin=laws["spin"], cage=laws["cage"], orbit_radius_m=r, roller_count=g.roller_count,
        source=f"CFD {src}",
        fitted_at={"inner_ring_rad_s": a["inner_ring_rad_s"], "cage_speed_rad_s": a["cage_rad_s"],
                   "roller_spin_rad_s": a["roller_spin_rad_s"], "roller_orbit_moment_Nm": a["orbit_moment_Nm"],
                   "roller_spin_torque_Nm": a["spin_torque_Nm"], "cage_moment_Nm": a["cage_moment_Nm"]},
        provenance={"sweep_files": files, "sweep_speeds_rpm": speeds_rpm,
                    "meshes": [(d.get("fidelity") or {}).get("mesh") for _, d, _ in drags],
                    "exponents": {k: laws[k].exponent for k in laws},
                    "max_abs_residual": {k: laws[k].fit["max_abs_residual"] for k in laws}})


def orbit_radius_m(g: BearingGeometry) -> float:
    """Radius of the roller's centre of mass about the bearing axis, where the element's force
    acts (the mid-point is on the pitch circle; the centre of mass lies along the axis from it)."""
    return 0.5 * g.pitch_diameter_m + g.roller_com_offset_m * math.sin(g.roller_axis_angle_rad)
