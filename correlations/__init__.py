"""Hydraulic-loss correlations of tapered roller bearings in an oil bath.

Mapped into the import package as ``kegel.correlations``. Every correlation answers the same
question through :func:`hydraulic_torques`: given a bearing's derived geometry, the lubricant
state, the shaft speed and the oil level, the hydraulic torques on inner ring, outer ring and
cage, by component (:class:`HydraulicTorques`).

Available: ``"liebrecht"`` (seed paper Eq. 38-40). The SKF drag-loss model is planned: it needs
the drag-loss factor V_M, which SKF publishes only as a diagram of oil level.
"""

from __future__ import annotations

from ..geometry import BearingGeometry
from ..lubricant import LubricantState
from ..tribology import cage_speed_rad_s as pure_rolling_cage_speed
from .common import HydraulicTorques, immersed_fraction
from .liebrecht import LiebrechtInput, fractions_for_oil_level, liebrecht_torques

__all__ = [
    "CORRELATIONS",
    "HydraulicTorques",
    "LiebrechtInput",
    "hydraulic_torques",
    "immersed_fraction",
    "liebrecht_torques",
]

CORRELATIONS = ("liebrecht",)

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
        Cage speed; default: pure rolling of the apex-matched geometry.

    Raises
    ------
    ValueError
        Unknown correlation or an oil level outside [0, D].
    """
    if correlation not in CORRELATIONS:
        raise ValueError(f"correlation = {correlation!r}: expected one of {', '.join(CORRELATIONS)}")
    D = geometry.outer_diameter_m
    if not 0.0 <= oil_level_m <= D:
        raise ValueError(f"oil_level_m = {oil_level_m}: expected a level in [0, D] = [0, {D}] m")
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
