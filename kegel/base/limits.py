"""The ranges kegel accepts, in one place: the scene model's validation (:mod:`kegel.scene`)
and the public functions that take SI floats (:mod:`kegel.correlations`,
:func:`kegel.tribology.cage_speed_rad_s`, ...) check against the same numbers.

This module imports nothing of kegel but :mod:`kegel.errors`, so every layer may use it.
"""

from __future__ import annotations

import math
import numbers
from typing import Any

from .errors import KegelInputError

__all__ = [
    "KINEMATIC_VISCOSITY_RANGE_M2_S",
    "MAX_SPEED_FACTOR_RPM_MM",
    "RPM_PER_RAD_S",
    "check_kinematic_viscosity",
    "check_speed_factor",
    "max_speed_rpm_for",
]

#: Largest speed factor n * d_m accepted [rpm * mm]: about twice the usual limit of
#: oil-lubricated tapered roller bearings, beyond which kegel's models are not meant to be used.
MAX_SPEED_FACTOR_RPM_MM = 1.0e6
#: rad/s -> rpm
RPM_PER_RAD_S = 30.0 / math.pi
#: Kinematic viscosities accepted by the functions that take one [m^2/s]: 0.1 mm^2/s (thinner
#: than water at 20 degC, 1 mm^2/s) to 1e5 mm^2/s (an ISO VG 1000 gear oil near -20 degC is
#: about 1e5 mm^2/s). A value in mm^2/s passed as m^2/s (220 for ISO VG 220) falls outside.
KINEMATIC_VISCOSITY_RANGE_M2_S = (1e-7, 0.1)


def max_speed_rpm_for(mean_diameter_m: float) -> float:
    """The largest |n| [rpm] accepted for a bearing of mean (pitch) diameter ``mean_diameter_m``:
    ``|n| d_m <= MAX_SPEED_FACTOR_RPM_MM``."""
    return MAX_SPEED_FACTOR_RPM_MM / (mean_diameter_m * 1e3)


def check_speed_factor(speed_rad_s: Any, mean_diameter_m: float, *, source: str, key: str,
                       designation: str = "", allow_zero: bool = True, signed: bool = True) -> float:
    """A finite speed [rad/s] with ``|n| d_m <= MAX_SPEED_FACTOR_RPM_MM``; returns it as float.

    Parameters
    ----------
    speed_rad_s
        The speed in rad/s.
    mean_diameter_m
        The bearing's mean (pitch) diameter d_m [m].
    source, key
        Named in the error.
    designation
        The bearing, named in the error.
    allow_zero
        Whether 0 is accepted (a start from rest).
    signed
        Whether a negative speed is accepted (else: ``>= 0``, a magnitude).

    Raises
    ------
    KegelInputError
        Naming ``source``, ``key`` and the value, with the accepted range.
    """
    n_max = max_speed_rpm_for(mean_diameter_m)
    what = f" for bearing {designation}" if designation else ""
    expected = (f"a finite speed in rad/s with |n| <= {n_max:.0f} rpm (n*d_m <= {MAX_SPEED_FACTOR_RPM_MM:.0e} rpm mm"
                f"{what}, d_m = {mean_diameter_m * 1e3:.4g} mm)")
    if isinstance(speed_rad_s, bool) or not isinstance(speed_rad_s, numbers.Real):
        raise KegelInputError(source, key, speed_rad_s, expected)
    try:
        w = float(speed_rad_s)
    except (TypeError, ValueError):
        raise KegelInputError(source, key, speed_rad_s, expected) from None
    if not math.isfinite(w) or abs(w) * RPM_PER_RAD_S > n_max:
        raise KegelInputError(source, key, speed_rad_s, expected)
    if not signed and w < 0.0:
        raise KegelInputError(source, key, speed_rad_s, "a speed magnitude >= 0 in rad/s")
    if not allow_zero and w == 0.0:
        raise KegelInputError(source, key, speed_rad_s, "a non-zero speed in rad/s")
    return w


def check_kinematic_viscosity(nu_m2_s: Any, *, source: str, key: str) -> float:
    """A kinematic viscosity [m^2/s] in :data:`KINEMATIC_VISCOSITY_RANGE_M2_S`; returns it.

    Raises
    ------
    KegelInputError
        Naming ``source``, ``key`` and the value (a value above the range is probably in mm^2/s).
    """
    lo, hi = KINEMATIC_VISCOSITY_RANGE_M2_S
    expected = f"a kinematic viscosity in [{lo:g}, {hi:g}] m^2/s ({lo * 1e6:g} to {hi * 1e6:g} mm^2/s)"
    if isinstance(nu_m2_s, bool) or not isinstance(nu_m2_s, numbers.Real):
        raise KegelInputError(source, key, nu_m2_s, expected)
    try:
        nu = float(nu_m2_s)
    except (TypeError, ValueError):
        raise KegelInputError(source, key, nu_m2_s, expected) from None
    if not (math.isfinite(nu) and lo <= nu <= hi):
        if math.isfinite(nu) and hi < nu <= 1e6:
            expected += f"; {nu:g} looks like mm^2/s: {nu:g} mm^2/s = {nu * 1e-6:g} m^2/s"
        raise KegelInputError(source, key, nu_m2_s, expected)
    return nu
