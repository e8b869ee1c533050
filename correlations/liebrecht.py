"""Liebrecht's drag and churning torques of a tapered roller bearing in an oil bath
(seed paper, Eq. 38-40; derived by Liebrecht from 32208 measurements with a vertical shaft).

    M_drag        = 0.86 rho l_RB d_RB^0.164  nu^0.836 d_m^2.164 n_C^1.164              (38)
    M_churning,OR = 0.32 rho A_ORL d_ORL^0.287 nu^0.713 (d_m n_C)^1.287                  (39)
    M_churning,IR = 0.52 rho A_IRL d_IRL^0.265 nu^0.735 (d_IRL n_IR - d_m n_C)^1.265     (40)

Units (decided in issue 19): rho in kg/m^3, lengths in m, areas in m^2, nu in m^2/s, the speeds
n_C (cage) and n_IR (inner ring) in revolutions per MINUTE (1/min), torques in N m. The public
interface stays SI: :class:`LiebrechtInput` takes the speeds in rev/s and
:func:`liebrecht_torques` multiplies them by 60 before Eq. 38-40 (``speed_reading="rev/s"``
evaluates the superseded reading, for comparison only). Each equation has the form
rho A d^(1-a) nu^a U^(2-a) of a drag with C ~ Re^-a; it stays homogeneous in mass and length
(the printed copy lost the exponents 1 - a on d_ORL, 0.287, and d_IRL, 0.265, which kegel
restores), and its coefficients 0.86, 0.32, 0.52 carry the minute as the unit of time.

Evidence for 1/min (32208, FVA 3 at 50 degC: rho = 866.6 kg/m^3, nu = 60.6 mm^2/s, flooded,
pure-rolling cage speed 0.4185 n_IR; figures at 500 / 2000 / 4000 rpm, N mm):

* Totals: rev/s reading 0.14 / 0.81 / 1.95; 1/min reading 25 / 145 / 349. At 2000 rpm kegel's
  flooded CFD gives 65 (small mesh, README "CFD") and the SKF catalogue drag model 128
  (:mod:`.skf`): the rev/s reading is 80 times below the CFD and 160 times below SKF, the 1/min
  reading 2.2 times above the CFD and 1.1 times SKF. Over 500-4000 rpm at kegel's oil levels
  half_roller, shaft_center and flooded, the 1/min totals are 0.75-1.22 times the SKF drag
  moment (two independent empirical models agreeing in level, in speed dependence and in the
  effect of the oil level), the rev/s totals 0.004-0.01 times. The seed paper (Section 4, Figure 9) says
  Liebrecht's method "greatly underestimates" the measured flooded losses; it does not give its
  numbers, so this is no check of either reading (read literally it sits better with small
  values: under the 1/min reading the measured flooded 32208 torque would have to lie well above
  the 0.145 N m of Eq. 38-40 at 2000 rpm, which the text kegel has cannot confirm or refute).
* A lower bound from the rotating disc: the two side faces of the cone alone (bore 40 mm to the
  rib top, 61.4 mm, and to the small raceway end, 47.3 mm), taken as free discs in laminar flow
  (von Karman; Cochran's solution, one face ``M = 0.308 pi rho sqrt(nu omega^3) (r_o^4 - r_i^4)``,
  both faces of a disc ``C_M = 2M / (0.5 rho omega^2 R^5) = 3.87 Re^-1/2``, ``Re = omega R^2 / nu``;
  Schlichting, Boundary-Layer Theory, the rotating disc), need 2.2 / 17.5 / 49 N mm. The rev/s
  totals are 15-25 times below what these faces alone dissipate; the 1/min totals are 7-12
  times above it. An enclosure does not lower this bound much: Daily and Nece's regime II
  (laminar, separate boundary layers; ASME J. Basic Eng. 82 (1960) 217-232) gives
  ``C_M = 3.70 (s/a)^0.1 Re^-1/2``, 0.81 of the free disc at an axial gap of s/a = 0.2 (the
  constants as the literature quotes Daily and Nece; their paper itself was read only in its abstract).
* Eq. 40 as the moment coefficient of a disc of the inner raceway radius turning at the speed
  relative to the cage (``d_IRL n_IR - d_m n_C`` over ``d_IRL/2``, Re 270 / 1090 / 2180):
  rev/s 0.020 / 0.0073 / 0.0044, 12-19 times below the free disc's 3.87 Re^-1/2 = 0.23 /
  0.12 / 0.083; 1/min 3.6 / 1.3 / 0.78, 9-15 times above it (a ring turning between rollers,
  ribs and cage in a narrow annulus, with Daily and Nece's merged boundary layers,
  ``C_M = 2 pi / ((s/a) Re)``, is far above the free disc). Eq. 39 as a skin friction
  coefficient on the outer raceway, the oil passing at the cage speed: rev/s 0.0019-0.0004,
  13-20 times below a laminar flat plate (Blasius, 1.328 Re_L^-1/2 over the raceway's
  circumference), 1/min 0.37-0.085, 9-15 times above it.
* Eq. 38 as a drag coefficient of the rollers: torque -> force per roller at the pitch radius
  (Z = 17) -> ``C_D = F / (0.5 rho v^2 D_w l)`` with v the rollers' orbital speed (0.66 / 2.6 /
  5.3 m/s, ``Re = v D_w / nu`` = 108 / 434 / 868): rev/s 1.1e-3 / 3.3e-4 / 1.9e-4; 1/min
  0.125 / 0.039 / 0.022. An isolated circular cylinder in cross flow has C_D about 1.4 / 1.2 /
  1.1 at these Re (the experimental curve, e.g. Katz, Automotive Aerodynamics, Wiley 2016,
  Fig. 6.19, read for this note; and the fit ``C_D = 1 + 10 Re^-2/3`` of F. M. White's Fluid
  Mechanics, not re-read). v is the speed relative to oil at rest,
  the largest relative speed in a housing at rest, so an implied C_D must stay below the
  cylinder's; the oil carried with the roller set (the rollers fill 90 % of the pitch circle,
  and pure rolling moves the roller centres at the mean of the raceway speeds, as a Couette
  profile does) lowers it. Matching the cylinder curve at the relative speed k v needs
  k = 0.24 / 0.16 / 0.12 in the 1/min reading and k = 0.010 / 0.008 / 0.007 (Re_rel 1-6) in the
  rev/s reading. kegel's flooded CFD puts 2.1-4.1 mN m on rollers and cage at 2000 rpm,
  ``C_D = 0.008-0.016``: 24-48 times the rev/s value, 0.2-0.4 times the 1/min value. The roller
  drag alone therefore bounds the reading only loosely; the ring terms and the disc bound decide.
* Per roller or for the set: Eq. 38 has no roller count. Read per roller (x 17) with 1/min, the
  set's C_D at 500 rpm would be 2.1, above the isolated cylinder at the full orbital speed
  (1.44), and the 2000 rpm total 308 N mm, 2.4 times SKF; so Eq. 38 is read, as before, as the
  torque of the whole roller set (Liebrecht fitted one bearing, the 32208, so Z may sit in 0.86).

Liebrecht's own publications (J. Liebrecht, X. Si, B. Sauer, H. Schwarze, "Investigation of Drag
and Churning Losses on Tapered Roller Bearings", Strojniski vestnik - J. Mech. Eng. 61 (2015)
399-408; his Kaiserslautern dissertation, "Technisch-Mathematischer Ansatz zur Berechnung der
hydraulischen Verluste in Waelzlagern", 2018): not found in the stored public material that kegel's
developers could search (web pages, documentation, repositories), so the original equations and
their stated units could not be read, and Eq. 38-40 could not be compared with them term by term.
The decision rests on the physics above; it should be checked against the paper when it can be
read.

Oil level (kegel's reading of "the oil level is taken into account indirectly via the
effective surfaces"; not checked against the original either): each torque is scaled by the
immersed fraction of its circle - the outer raceway for Eq. 39 (A_ORL = pi d_ORL l_RB f_OR), the
inner raceway for Eq. 40 (A_IRL = pi d_IRL l_RB f_IR), and for the roller drag of Eq. 38 the share
of the roller set in the oil: the mean of the immersed fractions of the circles through the
rollers' outermost and innermost points (d_m +- D_w)/2, so that partly dipping rollers count in
part. No oil gives no loss; a flooded bearing gives the full values. The raceway diameters are
those at the roller mid-length (kegel.geometry).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from .common import HydraulicTorques, immersed_fraction

__all__ = [
    "SPEED_READINGS",
    "LiebrechtInput",
    "cylinder_drag_coefficient",
    "free_disc_moment_coefficient",
    "implied_coefficients",
    "liebrecht_torques",
]

#: Factor from rev/s to the speed unit of Eq. 38-40, by reading: "1/min" (kegel's, issue 19) and
#: the superseded "rev/s" (kept for comparison).
SPEED_READINGS: dict[str, float] = {"1/min": 60.0, "rev/s": 1.0}


@dataclass(frozen=True)
class LiebrechtInput:
    """Geometry, lubricant and speeds of Eq. 38-40, in SI units (speeds in rev/s; the
    correlation converts them to 1/min)."""

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


def _speed_factor(speed_reading: str) -> float:
    if speed_reading not in SPEED_READINGS:
        raise ValueError(f"speed_reading = {speed_reading!r}: expected one of {', '.join(SPEED_READINGS)}")
    return SPEED_READINGS[speed_reading]


def liebrecht_torques(x: LiebrechtInput, *, speed_reading: str = "1/min") -> HydraulicTorques:
    """Evaluate Eq. 38-40.

    Parameters
    ----------
    x
        Inputs in SI units, speeds in rev/s.
    speed_reading
        ``"1/min"`` (default: the speeds enter Eq. 38-40 in revolutions per minute, see the
        module docstring) or ``"rev/s"`` (the superseded reading, for comparison).

    Returns
    -------
    HydraulicTorques
        ``components``: ``drag_rollers_Nm`` (Eq. 38, against the cage rotation),
        ``churning_outer_ring_Nm`` (Eq. 39, on the outer ring), ``churning_inner_ring_Nm``
        (Eq. 40, against the inner ring rotation relative to the cage). Torques keep the sign of
        the speed they come from (a reversed shaft reverses them).
    """
    f = _speed_factor(speed_reading)
    rho, nu = x.density_kg_m3, x.kinematic_viscosity_m2_s
    l, d, dm = x.roller_length_m, x.roller_diameter_m, x.pitch_diameter_m
    d_o, d_i = x.outer_raceway_diameter_m, x.inner_raceway_diameter_m
    n_c, n_i = f * x.cage_speed_rev_s, f * x.inner_ring_speed_rev_s
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


def cylinder_drag_coefficient(reynolds_number: float) -> float:
    """Drag coefficient of an isolated circular cylinder in cross flow,
    ``C_D = 1 + 10 Re^(-2/3)`` (F. M. White's fit of the experimental curve, 1 < Re < 2e5:
    1.46 at Re = 100, 1.10 at Re = 1000)."""
    return 1.0 + 10.0 * reynolds_number ** (-2.0 / 3.0)


def free_disc_moment_coefficient(reynolds_number: float) -> float:
    """Moment coefficient of a disc turning in fluid at rest, both faces, laminar:
    ``C_M = 2M / (0.5 rho omega^2 R^5) = 3.87 Re^-1/2`` with ``Re = omega R^2 / nu``
    (von Karman's similarity solution, Cochran's numbers)."""
    return 3.87 / math.sqrt(reynolds_number)


def implied_coefficients(x: LiebrechtInput, roller_count: int, *, speed_reading: str = "1/min") -> dict[str, float]:
    """Dimensionless coefficients that Eq. 38-40 imply for a flooded bearing.

    The fractions of ``x`` are set to 1 (the coefficients are per wetted surface).

    Parameters
    ----------
    x
        Inputs of Eq. 38-40 (speeds in rev/s).
    roller_count
        Number of rollers Z.
    speed_reading
        As in :func:`liebrecht_torques`.

    Returns
    -------
    dict
        ``roller_drag_coefficient``: ``F / (0.5 rho v^2 D_w l)`` with ``F = M_38 / (Z d_m / 2)``
        and v the rollers' orbital speed (relative to oil at rest), ``roller_reynolds_number``
        ``v D_w / nu``; ``inner_ring_moment_coefficient``: ``M_40 / (0.5 rho w^2 R^5)`` with
        ``R = d_IRL / 2`` and ``w = 2 pi (d_IRL n_IR - d_m n_C) / d_IRL``,
        ``inner_ring_reynolds_number`` ``w R^2 / nu``; ``outer_ring_friction_coefficient``:
        ``M_39 / (0.5 rho U^2 A_ORL d_ORL / 2)`` with ``U = pi d_ORL n_C``,
        ``outer_ring_reynolds_number`` ``U pi d_ORL / nu``.
    """
    if roller_count < 1:
        raise ValueError(f"roller_count = {roller_count}: expected at least 1")
    flooded = replace(x, fraction_outer=1.0, fraction_inner=1.0, fraction_pitch=1.0)
    t = liebrecht_torques(flooded, speed_reading=speed_reading).components
    rho, nu = x.density_kg_m3, x.kinematic_viscosity_m2_s
    d, l, dm = x.roller_diameter_m, x.roller_length_m, x.pitch_diameter_m
    d_o, d_i = x.outer_raceway_diameter_m, x.inner_raceway_diameter_m
    v = math.pi * dm * x.cage_speed_rev_s
    force = t["drag_rollers_Nm"] / (roller_count * 0.5 * dm)
    w = 2.0 * math.pi * (d_i * x.inner_ring_speed_rev_s - dm * x.cage_speed_rev_s) / d_i
    R = 0.5 * d_i
    U = math.pi * d_o * x.cage_speed_rev_s
    return {
        "roller_drag_coefficient": force / (0.5 * rho * v * v * d * l),
        "roller_reynolds_number": v * d / nu,
        "inner_ring_moment_coefficient": t["churning_inner_ring_Nm"] / (0.5 * rho * w * w * R**5),
        "inner_ring_reynolds_number": w * R * R / nu,
        "outer_ring_friction_coefficient":
            t["churning_outer_ring_Nm"] / (0.5 * rho * U * U * math.pi * d_o * l * 0.5 * d_o),
        "outer_ring_reynolds_number": U * math.pi * d_o / nu,
    }


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
