"""Aihara's running-torque formula for tapered roller bearings under axial load (NSK, 1987).

S. Aihara, "A New Running Torque Formula for Tapered Roller Bearings Under Axial Load", ASME J.
Tribol. 109 (1987) 471-477, doi:10.1115/1.3261475 (full text read; its equations are transcribed,
as printed and as read, in ``kegel/data/validation/FORMULAS.md``, section 1). The formula was
checked by its author against the measured running torque of "nearly two hundred" tapered roller
bearings of 17-120 mm bore (Sec. 5). kegel uses it as an **independent engineering model** beside
the SKF catalogue model (:mod:`.skf`): nothing in it comes from kegel's own friction laws, and
nothing in kegel is fitted to it.

The formula (Eq. 26, 27):

    M = (z / D_a) (R_o M_i + R_i M_o) + e mu_0 cos(beta) F_a exp(-1.8 Lambda_r^1.2)
    M_i,o = 1.76e2 / (1 + 0.29 L^0.78) (1/alpha_0) (G U)^0.658 W^0.31 R_e^2 l

with, per raceway contact, U = eta_0 u / (E' R_e), G = alpha_0 E', W = w / (E' R_e) (w = Q / l, the
load per unit length, Q = F_a / (z sin alpha) the roller load of Eq. 2), L = eta_0 beta u^2 / k'
(beta = -d ln eta / d theta, k' the oil's thermal conductivity), R_e the equivalent radius in the
rolling direction and l the effective roller length; mu_0 = 0.2 (Eq. 15); Lambda_r the film
parameter of the rib contact from the Hamrock-Dowson minimum film (Eq. 16, 17: h_0 = 1.25 h_min).

How the printed formula is read (each reading with its evidence):

- The trailing "1" of Eq. 27 is the roller length l: Manjunath et al., Machines 11 (2023) 801,
  Table 1, reprint the formula with "R_e^2 l", and without it the moment has the unit N m / m.
- The constant is consistent with the equations it merges: 2 (Eq. 22, M = 2 R_e t_r) x 4.318
  (Crook / Goksem-Hargreaves, Eq. 19) x 20.4 (the measured load correction f(W), Eq. 25) = 176.2;
  the exponent 0.31 = 0.0126 (Eq. 19) + 0.3 (Eq. 25). The merge takes Eq. 25's bearing parameter
  W = 2 F_a / (D_a l z sin alpha E') (radius D_a / 2) as the contact's W = w / (E' R_e); kegel
  uses the contact's W of each raceway, as Eq. 19 defines it.
- u is the rolling (mean surface) speed of each raceway contact, here at pure rolling about the
  roller's mid-length (the paper neglects the cage and drag terms, Sec. 2.1).

What kegel had to choose because the paper does not say:

- The rib contact's radii: the roller's end sphere against the rib taken as a sphere on a plane
  (R_x = R_y = the end radius). The rib term only matters in mixed lubrication: at Lambda_r >= 2
  it is below 1.6 % of e mu_0 F_a (Eq. 13), and the result records Lambda_r.
- The rib contact's entrainment speed: the mean of the rib's speed and the roller end's speed at
  the contact point, both relative to the cage at pure rolling.

Scope stated by the paper: pure axial load (every roller equally loaded), speeds at which the
cage friction and the oil's drag are small. :func:`aihara_running_torque` refuses a radial load.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Any

from ..base.errors import KegelInputError
from ..model.geometry import BearingGeometry
from ..model.lubricant import LubricantState

__all__ = ["AiharaTorque", "MU_0", "aihara_moment_per_roller_Nm", "aihara_running_torque", "aihara_thermal_factor",
           "vogel_viscosity_temperature_coefficient_1_K",
           "hamrock_dowson_min_film_m"]

#: Coulomb coefficient of the rib's asperity contact (Eq. 15: "around 0.2").
MU_0 = 0.2
#: Eq. 27's constant: 2 x 4.318 x 20.4 (Eq. 22, 19, 25).
CONSTANT = 1.76e2
CITATION = ("S. Aihara, A New Running Torque Formula for Tapered Roller Bearings Under Axial Load, "
            "ASME J. Tribol. 109 (1987) 471-477")


def aihara_thermal_factor(L: float) -> float:
    """Eq. 21: the inlet-shear-heating reduction 1 / (1 + 0.29 L^0.78) of the rolling resistance."""
    if not L >= 0.0:
        raise KegelInputError("<argument>", "L", L, "a thermal loading parameter >= 0")
    return 1.0 / (1.0 + 0.29 * L ** 0.78)


def aihara_moment_per_roller_Nm(*, U: float, G: float, W: float, L: float, alpha0_1_Pa: float, Re_m: float,
                                length_m: float) -> float:
    """Eq. 27: the rolling-resistance moment of one raceway contact, N m.

    ``1.76e2 / (1 + 0.29 L^0.78) (1/alpha_0) (G U)^0.658 W^0.31 R_e^2 l`` (SI: alpha_0 in 1/Pa,
    R_e and l in m).
    """
    for name, v in (("U", U), ("G", G), ("W", W), ("alpha0_1_Pa", alpha0_1_Pa), ("Re_m", Re_m), ("length_m", length_m)):
        if not (math.isfinite(v) and v > 0.0):
            raise KegelInputError("<argument>", name, v, "a finite number > 0")
    return (CONSTANT * aihara_thermal_factor(L) / alpha0_1_Pa * (G * U) ** 0.658 * W ** 0.31
            * Re_m ** 2 * length_m)


def hamrock_dowson_min_film_m(*, U: float, G: float, W: float, k: float, Rx_m: float) -> float:
    """Eq. 17: Hamrock-Dowson minimum film 3.63 U^0.68 G^0.49 W^-0.073 (1 - e^(-0.68 k)) R_x, m."""
    return 3.63 * U ** 0.68 * G ** 0.49 * W ** -0.073 * (1.0 - math.exp(-0.68 * k)) * Rx_m


@dataclass(frozen=True)
class AiharaTorque:
    """Aihara's running torque of a tapered roller bearing under axial load and its parts."""

    rolling_Nm: float                  # M_R, Eq. 26's first term (both raceways, every roller)
    rib_Nm: float                      # M_S, Eq. 15
    thermal_factor_inner: float        # Eq. 21 at the inner / outer raceway
    thermal_factor_outer: float
    thermal_loading_inner: float       # L at the inner / outer raceway
    thermal_loading_outer: float
    Lambda_rib: float                  # film parameter of the rib contact (Eq. 16, 17)

    @property
    def total_Nm(self) -> float:
        """Eq. 26: M = M_R + M_S (the moment on the outer ring)."""
        return self.rolling_Nm + self.rib_Nm

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary (names carry units)."""
        return {**asdict(self), "total_Nm": self.total_Nm, "citation": CITATION}


def aihara_running_torque(g: BearingGeometry, lub: LubricantState, *, speed_rad_s: float, axial_load_N: float,
                          radial_load_N: float = 0.0, E_reduced_Pa: float, sigma_rib_m: float,
                          viscosity_temperature_coefficient_1_K: float) -> AiharaTorque:
    """Aihara's running torque (Eq. 26, 27) of a tapered roller bearing under a pure axial load.

    Parameters
    ----------
    g
        The bearing's derived geometry (:func:`kegel.derive_geometry`).
    lub
        The oil at the bearing temperature (:func:`kegel.lubricant_state`).
    speed_rad_s
        Inner-ring speed (its magnitude is used).
    axial_load_N
        ``F_a`` > 0.
    radial_load_N
        Must be 0: the formula is for a pure axial load.
    E_reduced_Pa
        ``E'`` = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2).
    sigma_rib_m
        Composite RMS roughness of the rib and roller end (for Lambda_r).
    viscosity_temperature_coefficient_1_K
        ``beta = -d ln eta / d theta`` of the oil at the bearing temperature.

    Returns
    -------
    AiharaTorque

    Raises
    ------
    KegelInputError
        A radial load, a load or speed that is not positive and finite.
    """
    from ..physics.tribology import cage_speed_rad_s

    if radial_load_N != 0.0:
        raise KegelInputError("<argument>", "radial_load_N", radial_load_N,
                              "0: Aihara's formula is for a pure axial load")
    for name, v in (("axial_load_N", axial_load_N), ("speed_rad_s", abs(speed_rad_s)), ("E_reduced_Pa", E_reduced_Pa),
                    ("sigma_rib_m", sigma_rib_m)):
        if not (math.isfinite(v) and v > 0.0):
            raise KegelInputError("<argument>", name, v, "a finite number > 0")
    w = abs(speed_rad_s)
    z, Da, l = g.roller_count, g.roller_mean_diameter_m, g.roller_effective_length_m
    a_o, a_i, gam = g.cup_angle_rad, g.cone_angle_rad, g.roller_half_angle_rad
    R_o, R_i = 0.5 * g.outer_raceway_diameter_mid_m, 0.5 * g.inner_raceway_diameter_mid_m
    eta, a0, k_th = lub.dynamic_viscosity_Pas, lub.pressure_viscosity_coefficient_1_Pa, lub.thermal_conductivity_W_mK
    beta = viscosity_temperature_coefficient_1_K
    w_c = abs(cage_speed_rad_s(g, w))            # pure rolling
    r_roll = 0.5 * Da / math.cos(gam)            # roller's radius of curvature normal to its generator
    G = a0 * E_reduced_Pa
    parts = {}
    for name, R_race, u in (("inner", R_i / math.cos(a_i), (w - w_c) * R_i), ("outer", -R_o / math.cos(a_o), w_c * R_o)):
        Re = 1.0 / (1.0 / r_roll + 1.0 / R_race)
        Q = axial_load_N / (z * math.sin(a_o))   # Eq. 2: Q_e = Q_i = F_a / (z sin alpha)
        U = eta * u / (E_reduced_Pa * Re)
        W = Q / l / (E_reduced_Pa * Re)
        L = eta * beta * u ** 2 / k_th
        parts[name] = (aihara_moment_per_roller_Nm(U=U, G=G, W=W, L=L, alpha0_1_Pa=a0, Re_m=Re, length_m=l), L)
    M_R = z / Da * (R_o * parts["inner"][0] + R_i * parts["outer"][0])   # Eq. 26 (Eq. 7)
    # rib (Eq. 13-17): roller end sphere on a plane; load Q_f = F_a sin(2 gamma) / (z sin alpha) (Eq. 3)
    Rs = g.roller_end_radius_m
    e = g.rib_contact_height_m
    Q_f = axial_load_N * math.sin(2.0 * gam) / (z * math.sin(a_o))
    r_c = g.rib_contact_point_m[1]
    spin = (w - w_c) * R_i / (0.5 * Da)            # roller spin relative to the cage at pure rolling
    rho = 0.5 * g.roller_large_end_diameter_m - e  # contact point's distance from the roller axis
    u_rib = 0.5 * ((w - w_c) * r_c + spin * rho)
    if Q_f > 0.0 and u_rib > 0.0:
        h0 = 1.25 * hamrock_dowson_min_film_m(U=eta * u_rib / (E_reduced_Pa * Rs), G=G,
                                              W=Q_f / (E_reduced_Pa * Rs ** 2), k=1.03, Rx_m=Rs)
        Lam = h0 / sigma_rib_m
    else:
        Lam = 0.0
    M_S = e * MU_0 * math.cos(gam) * axial_load_N * math.exp(-1.8 * Lam ** 1.2)   # Eq. 15 with cos(beta), Eq. 26
    return AiharaTorque(rolling_Nm=M_R, rib_Nm=M_S, thermal_factor_inner=aihara_thermal_factor(parts["inner"][1]),
                        thermal_factor_outer=aihara_thermal_factor(parts["outer"][1]),
                        thermal_loading_inner=parts["inner"][1], thermal_loading_outer=parts["outer"][1],
                        Lambda_rib=Lam)


def vogel_viscosity_temperature_coefficient_1_K(vogel_B_K: float, vogel_C_degC: float, temperature_K: float) -> float:
    """``beta = -d ln eta / d theta = B / (theta + C)^2`` of Vogel's law eta = K exp(B / (theta + C))."""
    theta = temperature_K - 273.15
    return vogel_B_K / (theta + vogel_C_degC) ** 2
