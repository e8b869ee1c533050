"""Liebrecht's drag and churning torques of a tapered roller bearing in an oil bath
(seed paper, Eq. 38-40; derived by Liebrecht from 32208 measurements with a vertical shaft).

    M_drag        = 0.86 rho l_RB d_RB^0.164  nu^0.836 d_m^2.164 n_C^1.164              (38)
    M_churning,OR = 0.32 rho A_ORL d_ORL^0.287 nu^0.713 (d_m n_C)^1.287                  (39)
    M_churning,IR = 0.52 rho A_IRL d_IRL^0.265 nu^0.735 (d_IRL n_IR - d_m n_C)^1.265     (40)

Units: SI throughout (rho kg/m^3, lengths m, areas m^2, nu m^2/s, speeds n in revolutions per
second), torques in N m. Each equation has the form rho A d^(1-a) nu^a U^(2-a) of a drag with
C_d ~ Re^-a, which is dimensionally homogeneous only with these consistent units; Eq. 38 as
printed is homogeneous, and Eq. 39 and 40 are made so by the exponents 1 - a on d_ORL (0.287)
and d_IRL (0.265) that the printed copy lost ("d_ORL", "d_IRL . 0.265"). The speed is the
rotational frequency (German "Drehzahl", revolutions per unit time).

Oil level (kegel's reading of "the oil level is taken into account indirectly via the
effective surfaces"): each torque is scaled by the immersed fraction of its circle - the outer
raceway for Eq. 39 (A_ORL = pi d_ORL l_RB f_OR), the inner raceway for Eq. 40
(A_IRL = pi d_IRL l_RB f_IR), and for the roller drag of Eq. 38 the share of the roller set in
the oil: the mean of the immersed fractions of the circles through the rollers' outermost and
innermost points (d_m +- D_w)/2, so that partly dipping rollers count in part. No oil gives no loss; a flooded bearing gives the full values.
The raceway diameters are those at the roller mid-length (kegel.geometry).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .common import HydraulicTorques, immersed_fraction

__all__ = ["LiebrechtInput", "liebrecht_torques"]


@dataclass(frozen=True)
class LiebrechtInput:
    """Geometry, lubricant and speeds of Eq. 38-40, in SI units (speeds in rev/s)."""

    density_kg_m3: float
    kinematic_viscosity_m2_s: float
    roller_length_m: float
    roller_diameter_m: float
    pitch_diameter_m: float
    outer_raceway_diameter_m: float
    inner_raceway_diameter_m: float
    inner_ring_speed_rev_s: float
    cage_speed_rev_s: float
    fraction_outer: float = 1.0   # immersed fraction of the outer raceway circle
    fraction_inner: float = 1.0   # immersed fraction of the inner raceway circle
    fraction_pitch: float = 1.0   # immersed share of the roller set


def _signed_pow(x: float, p: float) -> float:
    return math.copysign(abs(x) ** p, x)


def liebrecht_torques(x: LiebrechtInput) -> HydraulicTorques:
    """Evaluate Eq. 38-40.

    Returns
    -------
    HydraulicTorques
        ``components``: ``drag_rollers_Nm`` (Eq. 38, against the cage rotation),
        ``churning_outer_ring_Nm`` (Eq. 39, on the outer ring), ``churning_inner_ring_Nm``
        (Eq. 40, against the inner ring rotation relative to the cage). Torques keep the sign of
        the speed they come from (a reversed shaft reverses them).
    """
    rho, nu = x.density_kg_m3, x.kinematic_viscosity_m2_s
    l, d, dm = x.roller_length_m, x.roller_diameter_m, x.pitch_diameter_m
    d_o, d_i = x.outer_raceway_diameter_m, x.inner_raceway_diameter_m
    n_c, n_i = x.cage_speed_rev_s, x.inner_ring_speed_rev_s
    drag = 0.86 * rho * l * d**0.164 * nu**0.836 * dm**2.164 * _signed_pow(n_c, 1.164)  # Eq. 38
    A_or = math.pi * d_o * l * x.fraction_outer
    churn_or = 0.32 * rho * A_or * d_o**0.287 * nu**0.713 * _signed_pow(dm * n_c, 1.287)  # Eq. 39
    A_ir = math.pi * d_i * l * x.fraction_inner
    churn_ir = 0.52 * rho * A_ir * d_i**0.265 * nu**0.735 * _signed_pow(d_i * n_i - dm * n_c, 1.265)  # Eq. 40
    drag *= x.fraction_pitch
    return HydraulicTorques(
        correlation="liebrecht",
        inner_ring_Nm=churn_ir,
        outer_ring_Nm=churn_or,
        cage_Nm=drag,
        components={
            "drag_rollers_Nm": drag,
            "churning_outer_ring_Nm": churn_or,
            "churning_inner_ring_Nm": churn_ir,
        },
    )


def fractions_for_oil_level(oil_level_m: float, outer_diameter_m: float, pitch_diameter_m: float,
                            roller_diameter_m: float, outer_raceway_diameter_m: float,
                            inner_raceway_diameter_m: float) -> dict[str, float]:
    """Immersed fractions for an oil level above the lowest point of the bearing's outer
    diameter (horizontal axis; all circles concentric with it)."""
    h = oil_level_m - 0.5 * outer_diameter_m
    rollers = 0.5 * (immersed_fraction(h, 0.5 * (pitch_diameter_m + roller_diameter_m))
                     + immersed_fraction(h, 0.5 * (pitch_diameter_m - roller_diameter_m)))
    return {
        "fraction_outer": immersed_fraction(h, 0.5 * outer_raceway_diameter_m),
        "fraction_inner": immersed_fraction(h, 0.5 * inner_raceway_diameter_m),
        "fraction_pitch": rollers,
    }
