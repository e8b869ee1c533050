"""Quantities with units at the input boundary; SI floats everywhere inside kegel.

Every quantity kegel reads (scene files, ``--set``, command-line options, the Python API) goes
through :func:`parse_quantity`, which turns it into an SI float (N, rad/s, K, m, N m, rad, s) or
raises :class:`~kegel.errors.KegelInputError` naming the file, key and value, in one line.

The grammar of a quantity written as text is one number followed by one unit::

    quantity := number [space] unit
    number   := [sign] digits ["." [digits]] [exponent] | [sign] "." digits [exponent]
    sign     := "-" | "+" | "\u2212" (the Unicode minus sign)
    exponent := ("e" | "E") [sign] digits
    unit     := ["1/"] factor {separator factor}
    factor   := name ["^" | "**" [sign] digits]        a name holds letters (and _, °), no digits
    separator:= spaces | "*" | "\u00b7" | "/"

``"6 kN"``, ``"6.5e3 N"``, ``"\u22126 kN"``, ``"2000 rpm"``, ``"2000 1/min"``, ``"50 degC"``,
``"50 N m"`` and ``"20 um"`` are quantities. The decimal separator is the point; a space, comma,
apostrophe or underscore between digits (``"6 500 N"``, ``"6,5 kN"``, ``"1_000 N"``), a number
after the unit or another product (``"6 kN 2"``, ``"2 * 3 kN"``), any other trailing text and a
unit factor without a dimension (``"6 pi N"``, ``"6 percent N"``) are refused: pint alone read
``"6 500 N"`` as 3000 N, ``"6,5 kN"`` as 65 kN and ``"6 kN 2"`` as 12 kN. The number is read by
Python's ``float`` and the unit by pint (:data:`ureg`), separately, so the number is never
multiplied into anything.

A speed written as a frequency without an angle (``"50 Hz"``, ``"3000 1/min"``) counts
revolutions per unit time (a shaft's 50 Hz is 3000 rpm, not 50 rad/s).

pint quantities (``ureg.Quantity(6, "kN")``, also of another registry) are accepted as they are;
numbers without a unit never are: a float carries its unit in its name (``axial_load_N``).
"""

from __future__ import annotations

import math
import numbers
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pint

from .errors import KegelInputError

__all__ = ["KINDS", "RPM_TO_RAD_S", "K_TO_DEGC_OFFSET", "parse_quantity", "split_quantity", "ureg"]

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

#: The powers of an angle unit that each kind's unit may hold (pint counts angles as dimensionless).
_ANGLE_POWERS = {"speed": (0, 1), "angle": (1,), "force": (0,), "temperature": (0,), "length": (0,),
                 "moment": (0,), "time": (0,)}
#: The minus signs of a number: ASCII hyphen-minus and U+2212 (typeset text, spreadsheets).
_MINUS = r"\-\u2212"  # (escaped for character classes)
_NUMBER = rf"[+{_MINUS}]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+{_MINUS}]?[0-9]+)?"
_NAME = r"(?:[^\W\d_]|°)(?:[^\W\d]|°)*"            # letters, _ and °; no digits
_FACTOR = rf"{_NAME}(?:\s*(?:\^|\*\*)\s*[+{_MINUS}]?[0-9]+)?"
_SEPARATOR = r"(?:\s*[*·⋅/]\s*|\s+)"
_UNIT = rf"(?:1\s*/\s*)?{_FACTOR}(?:{_SEPARATOR}{_FACTOR})*"
_QUANTITY_RE = re.compile(rf"\s*(?P<number>{_NUMBER})(?P<unit>.*?)\s*", re.DOTALL)
_UNIT_RE = re.compile(rf"\s*(?P<unit>{_UNIT})")
#: A number continued by a group of digits after a space, comma, apostrophe or underscore.
_DIGIT_GROUP_RE = re.compile(r"[\s,'’_][0-9]")
#: Dashes that look like a minus but are none (en dash, hyphen, figure dash, full-width ...).
_FALSE_MINUS = "\u2010\u2011\u2012\u2013\u2014\u2015\ufe63\uff0d"

#: Longest value shown in a message (a pasted paragraph stays one readable line).
_MAX_SHOWN = 80


def split_quantity(text: str) -> tuple[str, str] | str:
    """Split quantity text into its number and unit by the grammar of this module.

    Parameters
    ----------
    text
        The quantity as written, e.g. ``"6.5 kN"``.

    Returns
    -------
    (str, str) or str
        ``(number, unit)`` as written (``unit`` is ``""`` when there is none), or, when the text
        does not follow the grammar, the reason in words (a string, not a tuple).
    """
    m = _QUANTITY_RE.fullmatch(text)
    if m is None:
        stripped = text.strip()
        if not stripped:
            return "an empty text"
        if stripped[0] in _FALSE_MINUS:
            return f"{stripped[0]!r} (U+{ord(stripped[0]):04X}) is no minus sign: write '-' or U+2212"
        if re.match(r"[+\-\u2212]?(inf|nan)", stripped, re.IGNORECASE):
            return "a finite number"
        return "no number first (a quantity is a number and a unit)"
    number, unit = m.group("number"), m.group("unit")
    if not unit:
        return number, ""
    if _DIGIT_GROUP_RE.match(unit) and not _UNIT_RE.fullmatch(unit):
        group = re.match(r"(?:[\s,'’_]+[0-9]+)+(?:\.[0-9]*)?", unit).group(0)
        joined = number + re.sub(r"[^0-9.]", "", group)
        if group.count(",") == 1 and "." not in number + group and re.fullmatch(r",[0-9]+", group):
            fix = f"'{number}.{group.lstrip(', ')}' (decimal point) or '{joined}' (no thousands separator)"
        else:
            fix = f"'{joined}'"
        return (f"a separator inside the number ({number + group!r}): '.' is the decimal point and a number has "
                f"no thousands separators; write {fix} and its unit")
    if not re.match(r"[^\W\d_]|°|\s", unit):
        return f"no unit after the number but {unit.strip()!r}"
    u = _UNIT_RE.fullmatch(unit)
    if u is None:
        return (f"{unit.strip()!r} after the number: one unit, with no second number, no product with a number "
                "and no other text")
    return number, u.group("unit")


def _float(number: str) -> float:
    return float(number.replace("\u2212", "-"))


def _shown(value: Any) -> Any:
    if isinstance(value, str) and len(value) > _MAX_SHOWN:
        return value[:_MAX_SHOWN] + "..."
    return value


def _describe(q: pint.Quantity) -> str:
    dims = q.dimensionality
    for name, kind in KINDS.items():
        if dims == ureg.Quantity(1, kind.si_unit).dimensionality and name != "angle":
            return kind.description
    return f"a quantity of dimension {dims}" if dims else "a dimensionless number"


def _one_line(text: str) -> str:
    return " ".join(str(text).split())


def _parse_units(unit: str, source: str | Path, key: str, value: Any, expected: str) -> pint.Unit:
    try:
        units = ureg.parse_units(unit)
    except Exception as exc:  # pint raises several error types for unknown names
        raise KegelInputError(source, key, _shown(value), f"{expected} ({_one_line(exc)})") from None
    # every factor carries a dimension or is an angle: "pi", "percent" and other pure numbers
    # spelt as units would multiply the number ("6 pi N" is 18.8 N)
    for name in units._units:
        root = ureg.Quantity(1.0, name).to_root_units()
        if not root._units:
            raise KegelInputError(source, key, _shown(value),
                                  f"{expected} ({name!r} is a number spelt as a unit, not a unit)")
    return units


def parse_quantity(value: Any, kind: str, *, source: str | Path, key: str) -> float:
    """Parse a quantity written with units and return its value in SI units.

    Parameters
    ----------
    value
        The text as written (``"6 kN"``; grammar in the module docstring), or a scalar pint
        quantity (of :data:`ureg` or another registry).
    kind
        One of :data:`KINDS` (``"force"``, ``"speed"``, ``"temperature"``, ...).
    source, key
        File (or ``"--set"``, or the function) and dotted key or argument, for the error message.

    Returns
    -------
    float
        The value in the SI unit of ``kind`` (N, rad/s, K, m, N m, rad, s).

    Raises
    ------
    KegelInputError
        If ``value`` is not a quantity of the expected kind written by the grammar, or not
        finite. The message is one line: source, key, value, what was expected with an example.
    """
    spec = KINDS[kind]
    expected = f"{spec.description} with its unit, e.g. '{spec.example}'"
    if isinstance(value, pint.Quantity):
        magnitude = value.magnitude
        if isinstance(magnitude, bool) or not isinstance(magnitude, numbers.Real):
            raise KegelInputError(source, key, _shown(str(value)), expected + " (a pint quantity with one real value)")
        try:
            q = ureg.Quantity(float(magnitude), ureg.parse_units(str(value.units)))
        except Exception as exc:
            raise KegelInputError(source, key, _shown(str(value)), f"{expected} ({_one_line(exc)})") from None
        shown: Any = str(value)
    elif isinstance(value, bool) or not isinstance(value, str):
        raise KegelInputError(source, key, _shown(value), expected + " (a quoted string)")
    else:
        parts = split_quantity(value)
        if isinstance(parts, str):
            raise KegelInputError(source, key, _shown(value), f"{expected}; here {parts}")
        number, unit = parts
        if not unit:
            raise KegelInputError(source, key, _shown(value), expected + " (no unit was given)")
        magnitude = _float(number)
        if not math.isfinite(magnitude):
            raise KegelInputError(source, key, _shown(value), expected + " (a finite number)")
        q = ureg.Quantity(magnitude, _parse_units(unit, source, key, value, expected))
        shown = value
    try:
        si = float(q.to(spec.si_unit).magnitude)
    except pint.DimensionalityError:
        hint = " (write 'N m' for newton metres: pint reads 'Nm' as number-metres)" if "number_meter" in str(
            q.units) else ""
        raise KegelInputError(source, key, _shown(shown), f"{expected}; got {_describe(q)}{hint}") from None
    except Exception as exc:  # e.g. an offset unit inside a product ("50 degC*m")
        raise KegelInputError(source, key, _shown(shown), f"{expected} ({_one_line(exc)})") from None
    # angles are dimensionless in pint, so "6 kN deg" converted to 104.7 N and "2000 rpm deg" to
    # 3.7 rad/s: an angle may appear only where the kind has one (a speed: once or, as a
    # frequency, not at all; an angle: once)
    angle_power = q.to_root_units()._units.get("radian", 0)
    if angle_power not in _ANGLE_POWERS[kind]:
        raise KegelInputError(source, key, _shown(shown), f"{expected}; got {_describe(q)} times an angle"
                              if angle_power else f"{expected}; got {_describe(q)} without an angle")
    if kind == "speed" and angle_power == 0:
        # a frequency without an angle (Hz, 1/s, 1/min) counts revolutions per unit time, as
        # for a shaft: 50 Hz is 3000 rpm, not 50 rad/s (pint reads Hz as 1/s = rad/s)
        si *= 2.0 * math.pi
    if not math.isfinite(si):
        raise KegelInputError(source, key, _shown(shown), expected + " (a finite number)")
    return si
