"""Lubricant state at a temperature: the properties users and the correlations read.

The property functions themselves live in the C++ core (``kegel._core``; Eq. 7 and 8 of the
seed paper); this module only bundles them for one temperature.
"""

from __future__ import annotations

import math
import numbers
import os
from dataclasses import asdict, dataclass
from typing import Any

from .. import _core
from .data import LubricantData, cragoe_specific_heat_J_kgK, load_lubricant
from ..base.errors import KegelInputError
from ..base.units import parse_quantity

__all__ = ["LubricantState", "lubricant_state", "temperature_domain_degC"]


@dataclass(frozen=True)
class LubricantState:
    """Properties of a lubricant at one temperature and ambient pressure (SI units)."""

    name: str
    temperature_K: float
    temperature_degC: float
    dynamic_viscosity_Pas: float
    kinematic_viscosity_m2_s: float
    density_kg_m3: float
    pressure_viscosity_coefficient_1_Pa: float
    thermal_conductivity_W_mK: float
    specific_heat_J_kgK: float

    def as_dict(self) -> dict[str, float | str]:
        """Plain dictionary (JSON field names carry the units)."""
        return asdict(self)


#: Temperature range accepted for lubricant data [degC], at every entry point (scene files, the
#: command line, the CFD runner and the Python API all evaluate the oil through lubricant_state).
TEMPERATURE_RANGE_DEGC = (-20.0, 150.0)


def temperature_domain_degC(lub: LubricantData) -> tuple[float, float, str]:
    """The temperatures [degC] at which kegel can evaluate a lubricant, and why the lower end.

    Kegel's range :data:`TEMPERATURE_RANGE_DEGC` narrowed to the domain of Dicke's
    pressure-viscosity law (seed paper, Wingertszahn et al. 2023, Eq. 7),
    ``eta = eta0 exp(p / (a1 + a2 theta + (b1 + b2 theta) p))``: its denominator must stay
    positive at every pressure, so ``a1 + a2 theta > 0`` and ``b1 + b2 theta >= 0``. Below
    ``theta = -b1 / b2`` (FVA 3, Table A1: -4.419e-3 / 3.0115e-4 = -14.67 degC) the viscosity
    becomes infinite at the finite pressure ``p = (a1 + a2 theta) / -(b1 + b2 theta)``: the fit
    has no meaning there, and kegel has no other pressure-viscosity law for a cold start.

    Returns
    -------
    tuple[float, float, str]
        Lowest and highest temperature [degC], and the reason for the lowest in words (empty
        when it is kegel's own range).
    """
    lo, hi = TEMPERATURE_RANGE_DEGC
    why = ""
    p = lub.parameters
    a1, a2, b1, b2 = p.dicke_a1_bar, p.dicke_a2_bar_per_K, p.dicke_b1, p.dicke_b2_per_K
    if b2 > 0.0 and -b1 / b2 > lo:
        lo = -b1 / b2
        why = (f"below {lo:.2f} degC Dicke's pressure-viscosity law (seed paper Eq. 7, {lub.name}'s coefficients "
               f"b1 = {b1:g}, b2 = {b2:g} 1/degC) has b1 + b2 theta < 0: its viscosity becomes infinite at a finite "
               f"pressure (p = (a1 + a2 theta) / -(b1 + b2 theta))")
    if a2 > 0.0 and -a1 / a2 > lo:
        lo = -a1 / a2
        why = (f"below {lo:.2f} degC Dicke's pressure-viscosity law (seed paper Eq. 7) has a1 + a2 theta <= 0")
    return lo, hi, why


def _infinite_at_GPa(lub: LubricantData, theta_degC: float) -> float | None:
    """The pressure [GPa] at which Dicke's Eq. 7 is singular at ``theta_degC`` (None if never)."""
    p = lub.parameters
    a = p.dicke_a1_bar + p.dicke_a2_bar_per_K * theta_degC
    b = p.dicke_b1 + p.dicke_b2_per_K * theta_degC
    return a / -b * 1e5 / 1e9 if b < 0.0 < a else None


def lubricant_state(lub: LubricantData | str | os.PathLike, temperature_K: float | str, *, source: str = "<argument>",
                    key: str = "temperature") -> LubricantState:
    """Evaluate a lubricant's properties at a temperature and ambient pressure.

    Parameters
    ----------
    lub
        The lubricant (:func:`kegel.load_lubricant`) or its name (``"FVA3"``, or a data file).
    temperature_K
        The temperature: kelvin as a number, or a string with its unit (``"50 degC"``,
        ``"323.15 K"``).
    source, key
        Where the temperature came from, for the error message.

    Raises
    ------
    KegelInputError
        If the temperature is not a temperature, or outside the domain of the lubricant's
        formulas; if ``lub`` is not a lubricant.
    """
    if isinstance(lub, (str, os.PathLike)):
        lub = load_lubricant(str(lub), source=source, key="lub")
    elif not isinstance(lub, LubricantData):
        raise KegelInputError(source, "lub", type(lub).__name__,
                              "a lubricant (kegel.load_lubricant) or its name, e.g. 'FVA3'")
    temperature_K = _temperature_K(temperature_K, source=source, key=key)
    core = lub.core
    lo, hi = TEMPERATURE_RANGE_DEGC
    if not lo <= temperature_K - 273.15 <= hi:
        raise KegelInputError(source, key, f"{temperature_K - 273.15:g} degC",
                              f"a temperature in [{lo:g}, {hi:g}] degC (the range of kegel's lubricant data)")
    d_lo, d_hi, why = temperature_domain_degC(lub)
    theta = temperature_K - 273.15
    if theta < d_lo:
        p_inf = _infinite_at_GPa(lub, theta)
        at = f" (at {theta:g} degC: {p_inf:.3g} GPa)" if p_inf is not None else ""
        raise KegelInputError(source, key, f"{theta:g} degC",
                              f"a temperature in [{d_lo:.2f}, {d_hi:g}] degC, the domain of lubricant {lub.name}'s "
                              f"formulas: {why}{at}; "
                              "kegel has no cold-start pressure-viscosity law (a lubricant file whose Dicke "
                              "coefficients were fitted down to this temperature extends the range)")
    try:
        eta = _core.viscosity_ambient_Pas(core, temperature_K)
        # the contact models' pressure-viscosity law (Eq. 7) must stay finite at this temperature
        _core.tribology.make_contact_lubricant_state(core, temperature_K)
    except ValueError as exc:
        raise KegelInputError(source, key, f"{temperature_K - 273.15:g} degC",
                              f"a temperature inside the domain of lubricant {lub.name}'s formulas ({exc})") from None
    return LubricantState(
        name=lub.name,
        temperature_K=temperature_K,
        temperature_degC=temperature_K - 273.15,
        dynamic_viscosity_Pas=eta,
        kinematic_viscosity_m2_s=_core.kinematic_viscosity_m2_s(core, temperature_K),
        density_kg_m3=_core.density_kg_m3(core, temperature_K),
        pressure_viscosity_coefficient_1_Pa=_core.pressure_viscosity_coefficient_per_Pa(core, temperature_K),
        thermal_conductivity_W_mK=lub.parameters.thermal_conductivity_W_mK,
        specific_heat_J_kgK=cragoe_specific_heat_J_kgK(lub, temperature_K),
    )


def _temperature_K(value: Any, *, source: str, key: str) -> float:
    """A temperature in kelvin from a number (kelvin) or a string with its unit."""
    if isinstance(value, str):
        return parse_quantity(value, "temperature", source=source, key=key)
    scalar = isinstance(value, numbers.Real) or (getattr(value, "ndim", None) == 0 and hasattr(value, "__float__"))
    if isinstance(value, bool) or not scalar:  # (numbers and 0-d numpy arrays)
        raise KegelInputError(source, key, value, "a temperature: kelvin as a number, or a string with its unit, "
                              "e.g. '50 degC'")
    t = float(value)
    if not math.isfinite(t):
        raise KegelInputError(source, key, value, "a finite temperature")
    return t
