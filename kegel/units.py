"""Quantities with units at the input boundary (pint); SI floats everywhere inside kegel.

Scene files and command-line options write quantities as strings with units, such as
``"6 kN"``, ``"2000 rpm"`` or ``"50 degC"``. :func:`parse_quantity` turns one into an SI float
(N, rad/s, K, m, N m, rad, s) and raises :class:`~kegel.errors.KegelInputError` naming the
file, key and value when the text is not a quantity of the expected kind. A speed written as a
frequency without an angle (``"50 Hz"``, ``"3000 1/min"``) counts revolutions per unit time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pint

from .errors import KegelInputError

__all__ = ["KINDS", "parse_quantity", "ureg", "RPM_TO_RAD_S", "K_TO_DEGC_OFFSET"]

ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
RPM_TO_RAD_S = 2.0 * math.pi / 60.0
K_TO_DEGC_OFFSET = 273.15


@dataclass(frozen=True)
class _Kind:
    si_unit: str
    example: str
    description: str


KINDS: dict[str, _Kind] = {
    "force": _Kind("N", "6 kN", "a force"),
    "speed": _Kind("rad/s", "2000 rpm", "a rotational speed"),
    "temperature": _Kind("K", "50 degC", "a temperature"),
    "length": _Kind("m", "20 um", "a length"),
    "moment": _Kind("N*m", "50 N m", "a moment"),
    "angle": _Kind("rad", "2 mrad", "an angle"),
    "time": _Kind("s", "0.1 s", "a time"),
}


def _describe(q: pint.Quantity) -> str:
    dims = q.dimensionality
    for name, kind in KINDS.items():
        if dims == ureg.Quantity(1, kind.si_unit).dimensionality and name != "angle":
            return kind.description
    return f"a quantity of dimension {dims}" if dims else "a dimensionless number"


def parse_quantity(value: Any, kind: str, *, source: str | Path, key: str) -> float:
    """Parse a quantity written with units and return its value in SI units.

    Parameters
    ----------
    value
        The text as written, e.g. ``"6 kN"``.
    kind
        One of :data:`KINDS` (``"force"``, ``"speed"``, ``"temperature"``, ...).
    source, key
        File (or ``"--set"``) and dotted key, for the error message.

    Returns
    -------
    float
        The value in the SI unit of ``kind`` (N, rad/s, K, m, N m, rad, s).

    Raises
    ------
    KegelInputError
        If ``value`` is not a string with a unit of the expected kind, or not finite.
    """
    spec = KINDS[kind]
    expected = f"{spec.description} with its unit, e.g. '{spec.example}'"
    if isinstance(value, bool) or not isinstance(value, str):
        raise KegelInputError(source, key, value, expected + " (a quoted string)")
    try:
        q = ureg.Quantity(value.strip())
    except Exception as exc:  # pint raises several error types for unparsable text
        raise KegelInputError(source, key, value, f"{expected} ({exc})") from None
    if not isinstance(q, pint.Quantity) or q.unitless:
        raise KegelInputError(source, key, value, expected + " (no unit was given)")
    try:
        si = q.to(spec.si_unit).magnitude
    except pint.DimensionalityError:
        raise KegelInputError(
            source, key, value, f"{expected}; got {_describe(q)}"
        ) from None
    si = float(si)
    if kind == "speed" and "radian" not in q.to_root_units()._units:
        # a frequency without an angle (Hz, 1/s, 1/min) counts revolutions per unit time, as
        # for a shaft: 50 Hz is 3000 rpm, not 50 rad/s (pint reads Hz as 1/s = rad/s)
        si *= 2.0 * math.pi
    if not math.isfinite(si):
        raise KegelInputError(source, key, value, expected + " (a finite number)")
    return si
