"""``kegel lubricant FVA3 --temperature "50 degC"``: dynamic and kinematic viscosity, density,
pressure-viscosity coefficient and specific heat at temperatures."""

from __future__ import annotations

import argparse
from typing import Any, Callable

from ..base.units import parse_quantity
from ..model.data import load_lubricant
from ..model.lubricant import lubricant_state
from .common import _json_out, _print_table

__all__ = ["add_parser", "command"]


def command(args: argparse.Namespace) -> int:
    lub = load_lubricant(args.name, source="command line", key="lubricant")
    temps = args.temperature or ["40 degC", "50 degC", "100 degC"]
    states = [
        lubricant_state(lub, parse_quantity(t, "temperature", source="command line", key="--temperature"),
                        source="command line", key="--temperature")
        for t in temps
    ]
    if args.format == "json":
        _json_out({"lubricant": lub.name, "data_file": lub.source_file, "states": [s.as_dict() for s in states]})
        return 0
    print(f"{lub.name}: {lub.description} (data: {lub.source_file})")
    _print_table(
        ("temperature [degC]", "eta [mPa s]", "nu [mm2/s]", "rho [kg/m3]", "alpha_p [1/GPa]", "c_p [J/(kg K)]"),
        [(s.temperature_degC, s.dynamic_viscosity_Pas * 1e3, s.kinematic_viscosity_m2_s * 1e6,
          s.density_kg_m3, s.pressure_viscosity_coefficient_1_Pa * 1e9, s.specific_heat_J_kgK) for s in states],
    )
    return 0


def add_parser(sub: Any, common: Callable[[argparse.ArgumentParser], None]) -> None:
    """The ``lubricant`` sub-command on ``sub`` (``common`` adds ``--format``)."""
    lu = sub.add_parser("lubricant", help="lubricant properties at temperatures")
    lu.add_argument("name", help="lubricant name (e.g. FVA3) or a lubricant .toml file")
    lu.add_argument("--temperature", action="append", metavar="T",
                    help='temperature with unit, e.g. "50 degC" (repeatable; default 40, 50, 100 degC)')
    common(lu)
    lu.set_defaults(func=command)
