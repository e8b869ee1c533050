"""Hydraulic-loss correlations of tapered roller bearings in an oil bath.

Mapped into the import package as ``kegel.correlations``. Every correlation answers the same
question through :func:`hydraulic_torques`: given a bearing's derived geometry, the lubricant
state, the shaft speed and the oil level, the hydraulic torques on inner ring, outer ring and
cage, by component (:class:`HydraulicTorques`).

Available: ``"liebrecht"`` (seed paper Eq. 38-40, speeds in 1/min, see :mod:`.liebrecht`) and
``"skf"`` (the drag moment of the SKF catalogue model, :mod:`.skf`, with V_M digitised from the
catalogue's diagram; it is one moment of the bearing, which :func:`hydraulic_torques` puts on the
inner ring). :mod:`.skf` also gives the catalogue's rolling and sliding moments
(:func:`skf_friction`), an independent check of kegel's contact friction; :mod:`.aihara` gives
Aihara's running-torque formula for a pure axial load (NSK, 1987), a second one.
"""

from __future__ import annotations

import math

from ..model.geometry import BearingGeometry
from ..model.lubricant import LubricantState
from ..physics.tribology import cage_speed_rad_s as pure_rolling_cage_speed
from .aihara import AiharaTorque, aihara_running_torque
from .common import HydraulicTorques, immersed_fraction
from .liebrecht import (
    LiebrechtInput,
    cylinder_drag_coefficient,
    fractions_for_oil_level,
    free_disc_moment_coefficient,
    implied_coefficients,
    liebrecht_torques,
)
from .skf import (
    SkfBearing,
    SkfDrag,
    SkfFriction,
    drag_loss_variable,
    skf_bearing,
    skf_drag_moment,
    skf_friction,
    skf_oil_level_H_m,
    skf_rolling_moment,
    skf_sliding_moment,
)

__all__ = [
    "AiharaTorque",
    "CORRELATIONS",
    "HydraulicTorques",
    "LiebrechtInput",
    "SkfBearing",
    "SkfDrag",
    "SkfFriction",
    "aihara_running_torque",
    "cylinder_drag_coefficient",
    "drag_loss_variable",
    "free_disc_moment_coefficient",
    "hydraulic_torques",
    "immersed_fraction",
    "implied_coefficients",
    "liebrecht_torques",
    "skf_bearing",
    "skf_drag_moment",
    "skf_friction",
    "skf_oil_level_H_m",
    "skf_rolling_moment",
    "skf_sliding_moment",
]

CORRELATIONS = ("liebrecht", "skf")

_TWO_PI = 6.283185307179586


def hydraulic_torques(
    correlation: str,
    geometry: BearingGeometry,
    lubricant: LubricantState,
    *,
    shaft_speed_rad_s: float,
    oil_level_m: float,
    cage_speed_rad_s: float | None = None,
) -> HydraulicTorques:
    """Hydraulic torques of a bearing by one correlation.

    Parameters
    ----------
    correlation
        One of :data:`CORRELATIONS`.
    geometry
        Derived bearing geometry (:func:`kegel.derive_geometry`).
    lubricant
        Lubricant state at the oil temperature (:func:`kegel.lubricant_state`).
    shaft_speed_rad_s
        Inner-ring speed (outer ring fixed).
    oil_level_m
        Oil surface above the lowest point of the bearing's outer diameter, in [0, D].
    cage_speed_rad_s
        Cage speed (Liebrecht); default: pure rolling of the apex-matched geometry.

    Raises
    ------
    ValueError
        Unknown correlation, an oil level outside [0, D] or a speed beyond the scenes' limit
        n d_m (:class:`kegel.KegelInputError`).
    """
    if correlation not in CORRELATIONS:
        raise ValueError(f"correlation = {correlation!r}: expected one of {', '.join(CORRELATIONS)}")
    # the scenes' speed limit n d_m (0 allowed: a dynamic run starts from rest)
    from ..base.errors import KegelInputError
    from ..model.scene import _speed_limit_text, max_speed_rpm

    if not (math.isfinite(shaft_speed_rad_s) and abs(shaft_speed_rad_s) * 30.0 / math.pi <= max_speed_rpm(geometry)):
        raise KegelInputError("<argument>", "shaft_speed_rad_s", shaft_speed_rad_s,
                              f"a speed with {_speed_limit_text(geometry)}")
    D = geometry.outer_diameter_m
    if not 0.0 <= oil_level_m <= D:
        raise ValueError(f"oil_level_m = {oil_level_m}: expected a level in [0, D] = [0, {D}] m")
    if correlation == "skf":
        return _skf_hydraulic(geometry, lubricant, shaft_speed_rad_s, oil_level_m)
    if cage_speed_rad_s is None:
        cage_speed_rad_s = pure_rolling_cage_speed(geometry, shaft_speed_rad_s)
    fractions = fractions_for_oil_level(oil_level_m, D, geometry.pitch_diameter_m, geometry.roller_mean_diameter_m,
                                        geometry.outer_raceway_diameter_mid_m, geometry.inner_raceway_diameter_mid_m)
    x = LiebrechtInput(
        density_kg_m3=lubricant.density_kg_m3,
        kinematic_viscosity_m2_s=lubricant.kinematic_viscosity_m2_s,
        roller_length_m=geometry.roller_length_m,
        roller_diameter_m=geometry.roller_mean_diameter_m,
        pitch_diameter_m=geometry.pitch_diameter_m,
        outer_raceway_diameter_m=geometry.outer_raceway_diameter_mid_m,
        inner_raceway_diameter_m=geometry.inner_raceway_diameter_mid_m,
        inner_ring_speed_rev_s=shaft_speed_rad_s / _TWO_PI,
        cage_speed_rev_s=cage_speed_rad_s / _TWO_PI,
        **fractions,
    )
    return liebrecht_torques(x)


def _skf_hydraulic(g: BearingGeometry, lubricant: LubricantState, speed_rad_s: float,
                   oil_level_m: float) -> HydraulicTorques:
    """SKF drag moment (2013 edition) from the geometry's d, D and B; no series constants are
    needed for the drag. One moment of the whole bearing: put on the inner ring (the shaft pays
    it), signed like the speed."""
    bearing = SkfBearing(designation=g.designation, bore_diameter_m=g.bore_diameter_m,
                         outer_diameter_m=g.outer_diameter_m, width_m=g.cone_width_m)
    drag = skf_drag_moment(bearing, speed_rad_s=abs(speed_rad_s),
                           kinematic_viscosity_m2_s=lubricant.kinematic_viscosity_m2_s, oil_level_m=oil_level_m)
    m = math.copysign(drag.drag_Nm, speed_rad_s)
    return HydraulicTorques(correlation="skf", inner_ring_Nm=m, outer_ring_Nm=0.0, cage_Nm=0.0,
                            components={"drag_Nm": m})
