"""``kegel tribology [--bearing 32216 --speed "2000 rpm" --axial-load "6 kN" ...]``: film state and
friction by mechanism of one roller/raceway contact."""

from __future__ import annotations

import argparse
import math
from typing import Any, Callable

from ..base.errors import KegelInputError
from ..base.units import parse_quantity
from ..model.data import load_bearing, load_lubricant, load_material
from ..model.geometry import derive_geometry
from ..model.lubricant import lubricant_state
from ..model.scene import check_speed
from .common import _json_out, _print_table

__all__ = ["add_parser", "command"]


def command(args: argparse.Namespace) -> int:
    from ..physics.tribology import axial_roller_loads, evaluate_raceway_contact, load_friction

    src = "command line"
    bearing = load_bearing(args.bearing, source=src, key="--bearing")
    material = load_material(args.material, source=src, key="--material")
    lub = load_lubricant(args.lubricant, source=src, key="--lubricant")
    friction = load_friction(args.friction, source=src, key="--friction")
    g = derive_geometry(bearing, material)
    T = parse_quantity(args.temperature, "temperature", source=src, key="--temperature")
    lubricant_state(lub, T, source=src, key="--temperature")
    omega = check_speed(parse_quantity(args.speed, "speed", source=src, key="--speed"), bearing, source=src,
                        key="--speed", text=args.speed)
    if args.contact_load is not None:
        load = parse_quantity(args.contact_load, "force", source=src, key="--contact-load")
        load_note = "given"
    else:
        fa = parse_quantity(args.axial_load, "force", source=src, key="--axial-load")
        if not fa > 0:
            raise KegelInputError(src, "--axial-load", args.axial_load, "a positive axial load")
        load = axial_roller_loads(g, fa)[f"{args.contact}_N"]
        load_note = f"from Fa = {fa / 1e3:g} kN shared by {g.roller_count} rollers"
    if not load > 0:
        raise KegelInputError(src, "--contact-load", args.contact_load, "a positive contact load")
    try:
        res = evaluate_raceway_contact(
            g, bearing, material, lub, friction, temperature_K=T, load_N=load, shaft_speed_rad_s=omega,
            contact=args.contact, slices=args.slices, slide_to_roll=args.slide_to_roll,
        )
    except KegelInputError as exc:
        if exc.key != "load_N":
            raise
        # the API's pressure limit, named as the command line's load
        key, text = (("--contact-load", args.contact_load) if args.contact_load is not None
                     else ("--axial-load", args.axial_load))
        raise KegelInputError(src, key, text, exc.expected) from None
    except ValueError as exc:  # the C++ checks (e.g. temperature outside the lubricant's domain)
        raise KegelInputError(src, "(arguments)", "", str(exc)) from None
    if args.format == "json":
        _json_out({"bearing": bearing.designation, "lubricant": lub.name, "friction": friction.name,
                   "temperature_K": T, "shaft_speed_rad_s": omega, "slide_to_roll": args.slide_to_roll,
                   **res.as_dict()})
        return 0
    t = res.totals
    print(f"{bearing.designation} {args.contact} raceway contact, {lub.name} at {T - 273.15:g} degC, shaft "
          f"{omega * 30 / math.pi:g} rpm (cage {t['cage_speed_rpm']:.1f} rpm), slide-to-roll {args.slide_to_roll:g}")
    print(f"contact load {load:.1f} N ({load_note}), {args.slices} slices over "
          f"{g.roller_effective_length_m * 1e3:.2f} mm, friction parameters {friction.name}")
    print(f"film h = {t['film_m_min'] * 1e6:.3f}-{t['film_m_max'] * 1e6:.3f} um, Lambda = "
          f"{t['Lambda_min']:.2f}-{t['Lambda_max']:.2f}, phi = {t['phi_min']:.3g}-{t['phi_max']:.3g}, "
          f"p0 = {t['max_pressure_Pa_min'] / 1e6:.0f}-{t['max_pressure_Pa_max'] / 1e6:.0f} MPa")
    _print_table(
        ("mechanism", "force [N]", "moment [N mm]", "power [W]"),
        [
            ("EHL sliding (Bair-Winer, Eq. 4-10)", t["F_ehl_sliding_x_N"], None, t["P_ehl_sliding_W"]),
            ("solid sliding (Eq. 21-28)", t["F_solid_sliding_x_N"], None, t["P_solid_sliding_W"]),
            ("EHL rolling (Biboulet-Houpert Part 1)", t["F_ehl_rolling_N"], None, t["P_ehl_rolling_W"]),
            ("solid rolling (Scheuermann, Eq. 19)", None, t["M_solid_rolling_Nm"] * 1e3, t["P_solid_rolling_W"]),
            ("hysteresis (Johnson, Eq. 20)", None, t["M_hysteresis_Nm"] * 1e3, t["P_hysteresis_W"]),
            ("total", None, None, t["P_total_W"]),
        ],
    )
    if args.per_slice:
        _print_table(
            ("xi [mm]", "Q [N]", "R' [mm]", "u [m/s]", "h [um]", "Lambda", "phi", "p0 [MPa]", "tau [MPa]"),
            [(r["xi_m"] * 1e3, r["load_N"], r["reduced_radius_m"] * 1e3, r["entrainment_speed_m_s"],
              r["film_m"] * 1e6, r["Lambda"], r["phi"], r["max_pressure_Pa"] / 1e6, r["tau_ehl_Pa"] / 1e6)
             for r in res.slices],
        )
    return 0


def add_parser(sub: Any, common: Callable[[argparse.ArgumentParser], None]) -> None:
    """The ``tribology`` sub-command on ``sub`` (``common`` adds ``--format``)."""
    tr = sub.add_parser("tribology", help="film and friction of one roller/raceway contact")
    tr.add_argument("--bearing", default="32216", help="bearing designation (default 32216)")
    tr.add_argument("--material", default="bearing_steel", help="roller material (default: bearing_steel)")
    tr.add_argument("--lubricant", default="FVA3", help="lubricant name or .toml file (default FVA3)")
    tr.add_argument("--friction", default="steel_mineral_oil", help="friction parameter set")
    tr.add_argument("--temperature", default="50 degC", help='bulk oil temperature (default "50 degC")')
    tr.add_argument("--speed", default="2000 rpm", help='shaft (inner-ring) speed (default "2000 rpm")')
    tr.add_argument("--axial-load", default="6 kN", help='bearing axial load shared by the rollers (default "6 kN")')
    tr.add_argument("--contact-load", help="normal load of the contact instead of --axial-load")
    tr.add_argument("--contact", choices=("inner", "outer"), default="inner",
                    help="the raceway contact: inner or outer (default inner)")
    tr.add_argument("--slices", type=int, default=30, help="slices along the roller (default 30)")
    tr.add_argument("--slide-to-roll", type=float, default=0.0, help="(u_ring - u_roller)/u_mean, default 0")
    tr.add_argument("--per-slice", action="store_true", help="also print the slice table")
    common(tr)
    tr.set_defaults(func=command)
