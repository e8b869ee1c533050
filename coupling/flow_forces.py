"""Flow forces on rollers and cage as force elements of the dynamic simulation.

The oil acts on the moving bodies: it drags each roller along its orbit, brakes its spin and
churns against the cage. This module turns a hydraulic result into the closed-form law of
``kegel._core.dynamics.DragElement`` (see ``mbs_core/include/kegel/core/dynamics.hpp``):

- roller orbit: F = -1/2 rho C_D A |u| u, u the roller centre's velocity relative to oil at rest
  (swirl ratio 0), A = D_w L; C_D is fitted so that the law gives the result's drag at its
  operating point (a quadratic law: the correlations' drag grows with U^(2 - a), a ~ 0.1-0.3, so
  the law is exact at the fitted speed and close to it in a transient around it);
- roller spin: M = -c_spin (w . a) a, c_spin from the spin torque of the CFD result;
- cage: M_z = -c_cage w_z, c_cage from the cage torque of the CFD result.

Sources: :func:`flow_forces_from_correlation` (a correlation's roller-set drag, e.g. Liebrecht's
Eq. 38; its ring churning acts on the rings, whose speeds are prescribed, and is added to their
torques instead) and :func:`flow_forces_from_cfd` (a ``kegel cfd run`` result: mean force and
spin torque of every roller, the cage torque).
"""

from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from .. import _core
from ..errors import KegelInputError
from ..geometry import BearingGeometry

__all__ = ["FlowForceLaw", "flow_forces_from_cfd", "flow_forces_from_correlation", "orbit_radius_m"]


@dataclass(frozen=True)
class FlowForceLaw:
    """Closed-form flow forces on rollers and cage (SI); ``element()`` gives the force element.

    ``fitted_at`` records the operating point the law reproduces exactly and ``source`` where
    its numbers come from.
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


def flow_forces_from_cfd(result: dict[str, Any] | str | Path, g: BearingGeometry, *,
                         source: str | None = None) -> FlowForceLaw:
    """Fit the flow-force law to a CFD result (``results.json`` of ``kegel cfd run``, or its
    contents with ``source`` naming where they came from).

    The rollers' mean force moment about the bearing axis gives the orbit drag, their mean spin
    torque the spin drag, the cage's axial moment the cage drag, each at the run's kinematics.
    (A frozen-rotor CFD run has no roller-to-roller variation of the oil around the sump; the
    means over the rollers stand for every roller.)
    """
    src = source or "<dict>"
    if not isinstance(result, dict):
        src = str(result)
        try:
            result = json.loads(Path(result).read_text())
        except (OSError, json.JSONDecodeError) as exc:
            raise KegelInputError(src, "(file)", "", f"a readable CFD results.json ({exc})") from None
    for key in ("kinematics", "rollers", "cage", "point"):
        if key not in result:
            raise KegelInputError(src, key, None, "a CFD result of kegel cfd run")
    kin = result["kinematics"]
    w_c, w_s = kin["cage_rad_s"], kin["roller_spin_rad_s"]
    rollers = result["rollers"]
    if len(rollers) != g.roller_count:
        raise KegelInputError(src, "rollers", len(rollers), f"{g.roller_count} rollers of the {g.designation}")
    r = orbit_radius_m(g)
    u = w_c * r
    A = g.roller_mean_diameter_m * g.roller_length_m
    # the force's moment about the bearing axis, (c x F)_z: the roller's own moment (its spin
    # torque) is taken by the spin law
    orbit = sum(x["moment_about_bearing_axis_Nm"] - x["moment_about_centre_Nm"][2] for x in rollers) / len(rollers)
    spin = sum(x["spin_torque_Nm"]["total"] for x in rollers) / len(rollers)
    rho = _density(result)
    F = -orbit / r * math.copysign(1.0, u)
    cd = max(0.0, 2.0 * F / (rho * A * u * u)) if u else 0.0
    c_spin = max(0.0, -spin / w_s) if w_s else 0.0
    c_cage = max(0.0, -result["cage"]["moment_Nm"][2] / w_c) if w_c else 0.0
    return FlowForceLaw(oil_density_kg_m3=rho, roller_drag_coefficient=cd, roller_frontal_area_m2=A,
                        roller_spin_drag_Nms=c_spin, cage_drag_Nms=c_cage, source=f"CFD {src}",
                        fitted_at={"cage_speed_rad_s": w_c, "roller_spin_rad_s": w_s,
                                   "roller_orbit_moment_Nm": orbit, "roller_spin_torque_Nm": spin,
                                   "cage_moment_Nm": result["cage"]["moment_Nm"][2]})


def orbit_radius_m(g: BearingGeometry) -> float:
    """Radius of the roller's centre of mass about the bearing axis, where the element's force
    acts (the mid-point is on the pitch circle; the centre of mass lies along the axis from it)."""
    return 0.5 * g.pitch_diameter_m + g.roller_com_offset_m * math.sin(g.roller_axis_angle_rad)


def _density(result: dict[str, Any]) -> float:
    """Oil density of a CFD result (its lubricant at its temperature)."""
    from ..data import load_lubricant
    from ..lubricant import lubricant_state

    p = result["point"]
    lub = load_lubricant(p.get("lubricant", "FVA3"))
    return lubricant_state(lub, p["temperature_K"]).density_kg_m3
