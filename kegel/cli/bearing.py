"""``kegel bearing --bearing 32216``: the derived internal geometry of a bearing, as a table."""

from __future__ import annotations

import argparse
from typing import Any, Callable

from ..model.data import load_bearing, load_material
from ..model.geometry import apex_residual, derive_geometry, envelope_violations, geometry_table
from .common import _json_out, _print_table

__all__ = ["add_parser", "command"]


def command(args: argparse.Namespace) -> int:
    bearing = load_bearing(args.bearing, source="command line", key="--bearing")
    material = load_material(args.material, source="command line", key="--material")
    g = derive_geometry(bearing, material, check_envelope=False)  # lists the violations below
    if args.format == "json":
        _json_out({"bearing": g.as_dict(), "apex_residual": apex_residual(g),
                   "envelope_violations": envelope_violations(g), "data_file": bearing.source_file})
        return 0
    print(f"Tapered roller bearing {g.designation} (data: {bearing.source_file})")
    _print_table(("quantity", "value", "unit"), geometry_table(g))
    problems = envelope_violations(g)
    print("catalogue envelope: " + ("respected" if not problems else "; ".join(problems)))
    return 0


def add_parser(sub: Any, common: Callable[[argparse.ArgumentParser], None]) -> None:
    """The ``bearing`` sub-command on ``sub`` (``common`` adds ``--format``)."""
    b = sub.add_parser("bearing", help="derived internal geometry of a bearing")
    b.add_argument("--bearing", required=True, help="bearing designation (e.g. 32216) or a bearing .toml file")
    b.add_argument("--material", default="bearing_steel", help="roller material (default: bearing_steel)")
    common(b)
    b.set_defaults(func=command)
