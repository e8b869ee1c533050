"""
kegel's C++ core (mbs_core): SI units in and out; invalid input raises ValueError.
"""

from kegel._core import (
    contact as contact,
    dynamics as dynamics,
    quasi_static as quasi_static,
    tribology as tribology
)


def core_version() -> str:
    """Version of the C++ core."""

def eigen_version() -> str:
    """Eigen version the core was built with."""

def sundials_version() -> str:
    """Version of the linked SUNDIALS library."""

class LubricantParameters:
    """Published lubricant parameters (units in the field names)."""

    def __init__(self) -> None: ...

    @property
    def vogel_K_Pas(self) -> float: ...

    @vogel_K_Pas.setter
    def vogel_K_Pas(self, arg: float, /) -> None: ...

    @property
    def vogel_B_K(self) -> float: ...

    @vogel_B_K.setter
    def vogel_B_K(self, arg: float, /) -> None: ...

    @property
    def vogel_C_degC(self) -> float: ...

    @vogel_C_degC.setter
    def vogel_C_degC(self, arg: float, /) -> None: ...

    @property
    def dicke_a1_bar(self) -> float: ...

    @dicke_a1_bar.setter
    def dicke_a1_bar(self, arg: float, /) -> None: ...

    @property
    def dicke_a2_bar_per_K(self) -> float: ...

    @dicke_a2_bar_per_K.setter
    def dicke_a2_bar_per_K(self, arg: float, /) -> None: ...

    @property
    def dicke_b1(self) -> float: ...

    @dicke_b1.setter
    def dicke_b1(self, arg: float, /) -> None: ...

    @property
    def dicke_b2_per_K(self) -> float: ...

    @dicke_b2_per_K.setter
    def dicke_b2_per_K(self, arg: float, /) -> None: ...

    @property
    def density_ref_kg_m3(self) -> float: ...

    @density_ref_kg_m3.setter
    def density_ref_kg_m3(self, arg: float, /) -> None: ...

    @property
    def density_ref_temperature_K(self) -> float: ...

    @density_ref_temperature_K.setter
    def density_ref_temperature_K(self, arg: float, /) -> None: ...

    @property
    def density_slope_kg_m3_K(self) -> float: ...

    @density_slope_kg_m3_K.setter
    def density_slope_kg_m3_K(self, arg: float, /) -> None: ...

    @property
    def thermal_conductivity_W_mK(self) -> float: ...

    @thermal_conductivity_W_mK.setter
    def thermal_conductivity_W_mK(self, arg: float, /) -> None: ...

class Lubricant:
    """A lubricant with checked parameters."""

    def __init__(self, parameters: LubricantParameters) -> None: ...

    @property
    def parameters(self) -> LubricantParameters: ...

    @property
    def vogel_pole_K(self) -> float: ...

def viscosity_ambient_Pas(lubricant: Lubricant, temperature_K: float) -> float:
    """Eq. 8 (Vogel): dynamic viscosity at ambient pressure."""

def viscosity_Pas(lubricant: Lubricant, temperature_K: float, pressure_Pa: float) -> float:
    """Eq. 7 (Dicke): dynamic viscosity at pressure."""

def pressure_viscosity_coefficient_per_Pa(lubricant: Lubricant, temperature_K: float) -> float:
    """alpha_p0 = d ln(eta)/dp at p = 0, from Eq. 7."""

def density_kg_m3(lubricant: Lubricant, temperature_K: float) -> float:
    """Density, linear in temperature."""

def kinematic_viscosity_m2_s(lubricant: Lubricant, temperature_K: float) -> float:
    """Kinematic viscosity at ambient pressure."""

class ElasticMaterial:
    """Isotropic elastic solid (checked)."""

    def __init__(self, youngs_modulus_Pa: float, poisson_ratio: float, density_kg_m3: float) -> None: ...

    @property
    def youngs_modulus_Pa(self) -> float: ...

    @property
    def poisson_ratio(self) -> float: ...

    @property
    def density_kg_m3(self) -> float: ...

def reduced_modulus_Pa(a: ElasticMaterial, b: ElasticMaterial) -> float:
    """E' = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)."""
