"""Friction laws of the seed paper (SI units)."""

import enum

import kegel._core


def moes_line_film_thickness_m(eta0_Pas: float, u_sum_m_s: float, R_m: float, w_N_m: float, alpha_p_1_Pa: float, E_reduced_Pa: float) -> float:
    """Moes central film thickness of a line contact [m] (u_sum = u1 + u2)."""

def elliptic_film_thickness_m(eta0_Pas: float, u_av_m_s: float, Rx_m: float, Ry_m: float, Q_N: float, alpha_p_1_Pa: float, E_reduced_Pa: float) -> float:
    """Eq. 31-35: central film thickness of an elliptic contact [m]."""

def zhu_cheng_factor(p0_Pa: float, E_reduced_Pa: float, u_rel_m_s: float, u_sum_m_s: float, deta_dtheta_Pas_K: float, u_av_m_s: float, thermal_conductivity_W_mK: float) -> float:
    """Eq. 11-14: thermal film reduction factor."""

def asperity_load_ratio(Lambda: float, B: float, C: float) -> float:
    """Eq. 29: Zhou-Hoeprich asperity load ratio phi."""

def bair_winer_shear_stress_Pa(eta_Pas: float, u_rel_m_s: float, h_m: float, tau_L_Pa: float) -> float:
    """Eq. 4-6, 10: limiting-shear lubricant shear stress (odd in u_rel)."""

def biboulet_houpert_rolling_force_N(eta0_Pas: float, u_mean_m_s: float, R_m: float, L_m: float, Q_N: float, E_reduced_Pa: float) -> float:
    """
    EHL rolling resistance force of a line-contact slice (Biboulet-Houpert Part 1, Eq. 40-42; the seed's Eq. 16 is misprinted).
    """

def biboulet_houpert_line_force(U: float, W: float) -> float:
    """
    Dimensionless rolling force F~ of Biboulet-Houpert Part 1 (U = 2 eta0 u_m/(E' R), W = w/(E' R)).
    """

def aihara_thermal_factor(L: float) -> float:
    """
    Aihara (1987) Eq. 21: phi_T = 1/(1 + 0.29 L^0.78), L the thermal loading parameter.
    """

def thermal_loading_parameter(deta_dtheta_Pas_K: float, u_m_s: float, thermal_conductivity_W_mK: float) -> float:
    """L = |d eta/d theta| u^2 / k (Murch-Wilson, Aihara)."""

def rolling_force_beyond_film_N_m(eta0_Pas: float, u_mean_m_s: float, R_m: float, g_m: float) -> float:
    """
    Rolling force per unit length [N/m] of the isoviscous-rigid film beyond the film height g (Reynolds, Biboulet-Houpert's rigid gap and flooded inlet X = -1): 6 eta0 u_m I(g/R), I(G) = sqrt(2/G - 1) + 2 asin(sqrt(G/2)) - 1 - pi/2, 0 for G >= 1; the contact / hydraulic boundary's cut.
    """

def biboulet_houpert_starvation_factor(S: float) -> float:
    """
    Biboulet-Houpert Part 1 Eq. 44: starved over flooded rolling force, S >= 2 (0: flooded).
    """

def cubic_friction_coefficient(v_m_s: float, mu_s: float, mu_d: float, v_s_m_s: float, v_d_m_s: float) -> float:
    """Eq. 21-27: regularised Coulomb coefficient mu(v), odd in v."""

def damping_coefficient(delta_m: float, d_max_Ns_m: float, delta_max_m: float) -> float:
    """Eq. 2-3: parametric damping coefficient."""

class RollingThermal(enum.Enum):
    """Thermal reduction of the EHL rolling force."""

    off = 0

    aihara = 1

    zhu_cheng = 2

class FrictionParameterValues:
    """Friction-law parameters (see kegel/data/friction)."""

    def __init__(self) -> None: ...

    @property
    def tau_L0_Pa(self) -> float: ...

    @tau_L0_Pa.setter
    def tau_L0_Pa(self, arg: float, /) -> None: ...

    @property
    def gamma_L(self) -> float: ...

    @gamma_L.setter
    def gamma_L(self, arg: float, /) -> None: ...

    @property
    def mu_s(self) -> float: ...

    @mu_s.setter
    def mu_s(self, arg: float, /) -> None: ...

    @property
    def mu_d(self) -> float: ...

    @mu_d.setter
    def mu_d(self, arg: float, /) -> None: ...

    @property
    def v_s_m_s(self) -> float: ...

    @v_s_m_s.setter
    def v_s_m_s(self, arg: float, /) -> None: ...

    @property
    def v_d_m_s(self) -> float: ...

    @v_d_m_s.setter
    def v_d_m_s(self, arg: float, /) -> None: ...

    @property
    def c_r(self) -> float: ...

    @c_r.setter
    def c_r(self, arg: float, /) -> None: ...

    @property
    def e_r(self) -> float: ...

    @e_r.setter
    def e_r(self, arg: float, /) -> None: ...

    @property
    def a_v(self) -> float: ...

    @a_v.setter
    def a_v(self, arg: float, /) -> None: ...

    @property
    def d_max_Ns_m(self) -> float: ...

    @d_max_Ns_m.setter
    def d_max_Ns_m(self, arg: float, /) -> None: ...

    @property
    def delta_max_m(self) -> float: ...

    @delta_max_m.setter
    def delta_max_m(self, arg: float, /) -> None: ...

    @property
    def gold_C1_Pa_K2(self) -> float: ...

    @gold_C1_Pa_K2.setter
    def gold_C1_Pa_K2(self, arg: float, /) -> None: ...

    @property
    def gold_C2_Pa_K(self) -> float: ...

    @gold_C2_Pa_K.setter
    def gold_C2_Pa_K(self, arg: float, /) -> None: ...

    @property
    def rolling_thermal(self) -> RollingThermal: ...

    @rolling_thermal.setter
    def rolling_thermal(self, arg: RollingThermal, /) -> None: ...

    @property
    def inlet_gap_ratio_inner(self) -> float: ...

    @inlet_gap_ratio_inner.setter
    def inlet_gap_ratio_inner(self, arg: float, /) -> None: ...

    @property
    def inlet_gap_ratio_outer(self) -> float: ...

    @inlet_gap_ratio_outer.setter
    def inlet_gap_ratio_outer(self, arg: float, /) -> None: ...

    @property
    def contact_film_limit_m(self) -> float: ...

    @contact_film_limit_m.setter
    def contact_film_limit_m(self, arg: float, /) -> None: ...

class FrictionParameters:
    """Checked friction-law parameters."""

    def __init__(self, values: FrictionParameterValues) -> None: ...

    @property
    def values(self) -> FrictionParameterValues: ...

    @property
    def compression_heating(self) -> bool: ...

class SurfacePair:
    """Roughness and Zhou-Hoeprich constants of a contact."""

    def __init__(self, sigma_m: float, zhou_hoeprich_B: float, zhou_hoeprich_C: float, E_reduced_Pa: float) -> None: ...

    @property
    def sigma_m(self) -> float: ...

    @property
    def E_reduced_Pa(self) -> float: ...

class ContactLubricantState:
    """Lubricant at a bulk temperature."""

    @property
    def temperature_K(self) -> float: ...

    @property
    def eta0_Pas(self) -> float: ...

    @property
    def alpha_p_1_Pa(self) -> float: ...

    @property
    def deta_dtheta_Pas_K(self) -> float: ...

def make_contact_lubricant_state(lubricant: kegel._core.Lubricant, temperature_K: float) -> ContactLubricantState: ...

class SliceInput:
    """One slice's load, geometry and surface velocities."""

    def __init__(self) -> None: ...

    @property
    def load_N(self) -> float: ...

    @load_N.setter
    def load_N(self, arg: float, /) -> None: ...

    @property
    def width_m(self) -> float: ...

    @width_m.setter
    def width_m(self, arg: float, /) -> None: ...

    @property
    def reduced_radius_m(self) -> float: ...

    @reduced_radius_m.setter
    def reduced_radius_m(self, arg: float, /) -> None: ...

    @property
    def u1_x_m_s(self) -> float: ...

    @u1_x_m_s.setter
    def u1_x_m_s(self, arg: float, /) -> None: ...

    @property
    def u1_y_m_s(self) -> float: ...

    @u1_y_m_s.setter
    def u1_y_m_s(self, arg: float, /) -> None: ...

    @property
    def u2_x_m_s(self) -> float: ...

    @u2_x_m_s.setter
    def u2_x_m_s(self, arg: float, /) -> None: ...

    @property
    def u2_y_m_s(self) -> float: ...

    @u2_y_m_s.setter
    def u2_y_m_s(self, arg: float, /) -> None: ...

    @property
    def penetration_m(self) -> float: ...

    @penetration_m.setter
    def penetration_m(self, arg: float, /) -> None: ...

    @property
    def normal_velocity_m_s(self) -> float: ...

    @normal_velocity_m_s.setter
    def normal_velocity_m_s(self, arg: float, /) -> None: ...

    @property
    def outer_ring(self) -> bool: ...

    @outer_ring.setter
    def outer_ring(self, arg: bool, /) -> None: ...

class SliceResult:
    """Forces and moments of one slice by mechanism (on the roller)."""

    @property
    def in_contact(self) -> bool: ...

    @property
    def half_width_m(self) -> float: ...

    @property
    def max_pressure_Pa(self) -> float: ...

    @property
    def mean_pressure_Pa(self) -> float: ...

    @property
    def area_m2(self) -> float: ...

    @property
    def film_isothermal_m(self) -> float: ...

    @property
    def thermal_factor(self) -> float: ...

    @property
    def film_m(self) -> float: ...

    @property
    def Lambda(self) -> float: ...

    @property
    def phi(self) -> float: ...

    @property
    def contact_temperature_K(self) -> float: ...

    @property
    def eta_contact_Pas(self) -> float: ...

    @property
    def tau_L_Pa(self) -> float: ...

    @property
    def tau_ehl_Pa(self) -> float: ...

    @property
    def mu_solid(self) -> float: ...

    @property
    def sliding_speed_m_s(self) -> float: ...

    @property
    def entrainment_speed_m_s(self) -> float: ...

    @property
    def F_ehl_sliding_N(self) -> tuple[float, float]: ...

    @property
    def F_solid_sliding_N(self) -> tuple[float, float]: ...

    @property
    def F_ehl_rolling_N(self) -> float: ...

    @property
    def rolling_thermal_factor(self) -> float: ...

    @property
    def rolling_starvation_factor(self) -> float: ...

    @property
    def inlet_gap_ratio(self) -> float: ...

    @property
    def M_solid_rolling_Nm(self) -> float: ...

    @property
    def M_hysteresis_Nm(self) -> float: ...

    @property
    def F_damping_N(self) -> float: ...

    @property
    def P_ehl_sliding_W(self) -> float: ...

    @property
    def P_solid_sliding_W(self) -> float: ...

def evaluate_slice(slice: SliceInput, surfaces: SurfacePair, lubricant_state: ContactLubricantState, parameters: FrictionParameters) -> SliceResult:
    """
    Evaluate one slice: film state and every friction force and moment by mechanism.
    """
