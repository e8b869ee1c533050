"""The ``kegel`` command.

Commands
--------
``kegel bearing --bearing 32216``
    Derived internal geometry of a bearing, as a table.
``kegel lubricant FVA3 --temperature "50 degC"``
    Dynamic and kinematic viscosity, density and pressure-viscosity coefficient.
``kegel check SCENE [--set KEY=VALUE ...]``
    Validate a scene file.
``kegel tribology [--bearing 32216 --speed "2000 rpm" --axial-load "6 kN" ...]``
    Film state and friction by mechanism of one roller/raceway contact.
``kegel losses --bearing 32208 [--oil-level flooded ...] [--plot losses.png]``
    Hydraulic losses by correlation against speed and oil level: Liebrecht and the SKF drag
    moment side by side, with the SKF rolling + sliding moment as a check of contact friction.
``kegel run SCENE [--set KEY=VALUE ...] [--output DIR]``
    Run a scene: quasi-static load distribution, friction by contact and mechanism, hydraulic
    loss of an oil bath; a table, results.json, results.csv and plots.

Every command takes ``--format json`` for machine-readable output on stdout (field names carry
their units, see README.md). Input errors print one line naming the file, key, value and
expectation to stderr and exit with status 2.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path
from typing import Any, Sequence

from ..model.data import load_bearing, load_lubricant, load_material
from ..base.errors import KegelInputError, KegelSolverError
from ..model.geometry import apex_residual, derive_geometry, envelope_violations, geometry_table
from ..model.lubricant import lubricant_state
from ..model.scene import Scene, check_speed, load_scene
from ..base.units import parse_quantity

__all__ = ["main"]


#: A run's table shows at most this many rows (the first and the last half); every row is in
#: results.csv and results.json.
MAX_TABLE_ROWS = 100


def _print_table(headers: Sequence[str], rows: Sequence[Sequence[Any]], out=None, *,
                 max_rows: int | None = None, where: str = "") -> None:
    out = out if out is not None else sys.stdout  # at call time (a redirected stdout included)
    def fmt(v: Any) -> str:
        if isinstance(v, float):
            return f"{v:.4g}"  # engineers read 3-4 figures; every digit is in --format json
        return "" if v is None else str(v)

    hidden = 0
    if max_rows is not None and len(rows) > max_rows:
        hidden = len(rows) - max_rows
        rows = [*rows[:max_rows // 2], *rows[len(rows) - (max_rows - max_rows // 2):]]
    cells = [[fmt(v) for v in row] for row in rows]
    widths = [max(len(h), *(len(r[i]) for r in cells)) if cells else len(h) for i, h in enumerate(headers)]
    print("  ".join(h.ljust(w) for h, w in zip(headers, widths)).rstrip(), file=out)
    print("  ".join("-" * w for w in widths), file=out)
    for k, r in enumerate(cells):
        if hidden and k == max_rows // 2:
            print(f"... {hidden} rows not shown (every row: {where or 'the result files'})", file=out)
        print("  ".join(c.rjust(w) if i else c.ljust(w) for i, (c, w) in enumerate(zip(r, widths))).rstrip(), file=out)


_BIDI_CONTROLS = frozenset("\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069")


def printable(text: str) -> str:
    """``text`` safe for a terminal: control characters (escape sequences, carriage returns, C1
    controls) and bidirectional overrides written as Python escapes (``\\x1b``), the rest kept
    (scene names and descriptions come from files a user may not have written)."""
    import unicodedata

    return "".join(ch.encode("unicode_escape").decode("ascii")
                   if unicodedata.category(ch) == "Cc" or ch in _BIDI_CONTROLS else ch for ch in str(text))


def _json_out(data: Any) -> None:
    json.dump(data, sys.stdout, indent=2, allow_nan=False)
    sys.stdout.write("\n")


#: Most speeds of `kegel losses --points` (1000 take about a second and print 3000 rows).
MAX_LOSS_POINTS = 1000

TORQUE_SPLIT_NOTE = ("sliding + rolling = M_fric (split by mechanism); of which rib: the roller end / rib "
                     "contact's share of M_fric (split by contact), already inside sliding and rolling")


def _cmd_bearing(args: argparse.Namespace) -> int:
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


def _cmd_lubricant(args: argparse.Namespace) -> int:
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



def _cmd_tribology(args: argparse.Namespace) -> int:
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


def _cmd_losses(args: argparse.Namespace) -> int:
    import numpy as np

    from ..correlations import hydraulic_torques
    from ..correlations.skf import SkfBearing, skf_bearing, skf_friction, skf_oil_level_H_m
    from ..outputs.plots import check_figure_path
    from ..model.scene import resolve_oil_level

    src = "command line"
    if args.plot:
        check_figure_path(args.plot, source=src, key="--plot")  # before the work, not after it
    bearing = load_bearing(args.bearing, source=src, key="--bearing")
    g = derive_geometry(bearing, load_material(args.material, source=src, key="--material"))
    lub = load_lubricant(args.lubricant, source=src, key="--lubricant")
    T = parse_quantity(args.temperature, "temperature", source=src, key="--temperature")
    state = lubricant_state(lub, T, source=src, key="--temperature")
    # --speed means one speed (repeatable: a list), as in `kegel cfd sweep`; a range is --speed-range
    if args.speed and args.speed_range:
        raise KegelInputError(src, "--speed", args.speed, "either --speed (a list) or --speed-range FROM TO, not both")
    if args.points is not None and args.speed:
        raise KegelInputError(src, "--points", args.points, "--points only with --speed-range (or the default range)")
    points = 8 if args.points is None else args.points
    if not 1 <= points <= MAX_LOSS_POINTS:
        # each speed is a table row per oil level (and per correlation): a million took minutes
        # and 5 GB before printing anything
        raise KegelInputError(src, "--points", points, f"an integer in [1, {MAX_LOSS_POINTS}] (each speed is a "
                              "printed row per oil level; for more, call kegel.correlations.hydraulic_torques)")
    key = "--speed" if args.speed else "--speed-range"
    speeds_text = args.speed or args.speed_range or ["500 rpm", "4000 rpm"]
    values = [check_speed(parse_quantity(t, "speed", source=src, key=key), bearing, source=src, key=key, text=t)
              for t in speeds_text]
    loads = {}
    for key, text in (("--axial-load", args.axial_load), ("--radial-load", args.radial_load)):
        loads[key] = parse_quantity(text, "force", source=src, key=key)
        if not loads[key] >= 0.0:
            raise KegelInputError(src, key, text, "a force >= 0, e.g. '6 kN'")
    fa, fr = loads["--axial-load"], loads["--radial-load"]
    if args.speed:
        speeds = np.array(values)
    else:
        speeds = np.linspace(values[0], values[1], points) if points > 1 else np.array(values[:1])
    levels_text = args.oil_level or ["half_roller", "shaft_center", "flooded"]
    levels = [(t, resolve_oil_level(t, bearing, source=src, key="--oil-level")) for t in levels_text]
    try:
        sb = skf_bearing(bearing)
        contact_check = True
    except KegelInputError:  # no SKF series constants for this bearing: drag only
        sb = SkfBearing(designation=bearing.designation, bore_diameter_m=bearing.bore_diameter_m,
                        outer_diameter_m=bearing.outer_diameter_m, width_m=bearing.cone_width_m)
        contact_check = False
    rows, skf_rows, side = [], [], []
    for text, h in levels:
        for w in speeds:
            w = float(w)
            rpm = w * 30 / math.pi
            t = hydraulic_torques("liebrecht", g, state, shaft_speed_rad_s=w, oil_level_m=h)
            rows.append({"correlation": "liebrecht", "oil_level": text, "oil_level_m": h, "speed_rpm": rpm,
                         **t.components, "inner_ring_Nm": t.inner_ring_Nm, "outer_ring_Nm": t.outer_ring_Nm,
                         "cage_Nm": t.cage_Nm, "total_Nm": t.total_Nm})
            if contact_check:
                f = skf_friction(sb, speed_rad_s=abs(w), kinematic_viscosity_m2_s=state.kinematic_viscosity_m2_s,
                                 axial_load_N=fa, radial_load_N=fr, oil_level_m=h, edition=args.skf_edition)
                d, contact = f.drag, {"rolling_Nm": math.copysign(f.rolling_Nm, w),
                                      "sliding_Nm": math.copysign(f.sliding_Nm, w),
                                      "rolling_sliding_Nm": math.copysign(f.rolling_sliding_Nm, w),
                                      "phi_ish": f.phi_ish, "phi_rs": f.phi_rs, "phi_bl": f.phi_bl, "mu_sl": f.mu_sl}
            else:
                from ..correlations.skf import skf_drag_moment

                d = skf_drag_moment(sb, speed_rad_s=abs(w), kinematic_viscosity_m2_s=state.kinematic_viscosity_m2_s,
                                    oil_level_m=h, edition=args.skf_edition)
                contact = {"rolling_Nm": None, "sliding_Nm": None, "rolling_sliding_Nm": None,
                           "phi_ish": None, "phi_rs": None, "phi_bl": None, "mu_sl": None}
            drag = math.copysign(d.drag_Nm, w)
            skf_rows.append({"correlation": "skf", "oil_level": text, "oil_level_m": h,
                             "oil_level_H_m": skf_oil_level_H_m(h, sb.outer_diameter_m, sb.mean_diameter_m),
                             "flooded": d.flooded, "speed_rpm": rpm, "drag_Nm": drag,
                             "drag_first_term_Nm": math.copysign(d.first_term_Nm, w),
                             "drag_second_term_Nm": math.copysign(d.second_term_Nm, w), "V_M": d.V_M,
                             "inner_ring_Nm": drag, "outer_ring_Nm": 0.0, "cage_Nm": 0.0, "total_Nm": drag, **contact})
            side.append({"oil_level": text, "oil_level_m": h, "speed_rpm": rpm, "liebrecht_total_Nm": t.total_Nm,
                         "liebrecht_drag_rollers_Nm": t.components["drag_rollers_Nm"], "skf_drag_Nm": drag,
                         "skf_rolling_sliding_Nm": contact["rolling_sliding_Nm"]})
    skf_note = {"edition": args.skf_edition, "axial_load_N": fa, "radial_load_N": fr, "lubrication": "oil_bath",
                "mean_diameter_m": sb.mean_diameter_m, "width_B_m": sb.width_m,
                "rolling_sliding": "computed" if contact_check else "no SKF series constants for this bearing",
                "verify": True}
    # the cost of each answer: the correlations' evaluation time per point (median of 200)
    import statistics
    import time as _time

    def _cost(fn) -> float:
        times = []
        for _ in range(200):
            t0 = _time.perf_counter()
            fn()
            times.append(_time.perf_counter() - t0)
        return statistics.median(times)

    w_mid, h_mid = float(speeds[len(speeds) // 2]), levels[0][1]
    costs = {"liebrecht_s": _cost(lambda: hydraulic_torques("liebrecht", g, state, shaft_speed_rad_s=w_mid,
                                                            oil_level_m=h_mid))}
    if contact_check:
        costs["skf_s"] = _cost(lambda: skf_friction(sb, speed_rad_s=abs(w_mid),
                                                    kinematic_viscosity_m2_s=state.kinematic_viscosity_m2_s,
                                                    axial_load_N=fa, radial_load_N=fr, oil_level_m=h_mid,
                                                    edition=args.skf_edition))
    cfd_rows = _cfd_loss_rows(args.cfd or [], bearing, lub.name, T, g, state, sb, contact_check, args.skf_edition,
                              [(t, h) for t, h in levels])
    plot_path = None
    if args.plot:
        plot_path = _plot_losses(rows, skf_rows, g, lub.name, T, Path(args.plot), cfd_rows)
    if args.format == "json":
        _json_out({"bearing": bearing.designation, "lubricant": lub.name, "temperature_K": T,
                   "units": "SI (N m, m); Liebrecht's Eq. 38-40 take the speeds in 1/min; SKF in catalogue units inside",
                   "skf": skf_note, "points": rows + skf_rows, "side_by_side": side, "cfd": cfd_rows,
                   "cost_per_point_s": costs, "plot": str(plot_path) if plot_path else None})
        return 0
    print(f"Hydraulic losses of a {bearing.designation} in {lub.name} at {T - 273.15:g} degC, torques in N mm")
    print("  Liebrecht: seed paper Eq. 38-40, speeds in 1/min. SKF: catalogue drag moment "
          f"({args.skf_edition} edition), H = oil level - D/2 + 0.6 d_m, flooded at H >= 1.2 d_m.")
    if contact_check:
        print(f"  SKF rolling+sliding: the catalogue's contact friction at Fa = {fa / 1e3:g} kN, Fr = {fr / 1e3:g} kN "
              "(oil bath), an independent check of kegel's contact friction, not a hydraulic loss.")
    else:
        print(f"  SKF rolling+sliding: no SKF series constants for bearing {bearing.designation}.")

    def mm(v):
        return None if v is None else v * 1e3

    _print_table(("oil level", "n [rpm]", "Liebrecht drag (38)", "churning OR (39)", "churning IR (40)",
                  "Liebrecht total", "SKF drag", "SKF rolling+sliding"),
                 [(f"{r['oil_level']} ({r['oil_level_m'] * 1e3:.1f} mm)", r["speed_rpm"], mm(r["drag_rollers_Nm"]),
                   mm(r["churning_outer_ring_Nm"]), mm(r["churning_inner_ring_Nm"]), mm(r["total_Nm"]),
                   mm(k["drag_Nm"]), mm(k["rolling_sliding_Nm"])) for r, k in zip(rows, skf_rows)])
    cost_text = f"Liebrecht {1e6 * costs['liebrecht_s']:.0f} us"
    if "skf_s" in costs:
        cost_text += f", SKF {1e6 * costs['skf_s']:.0f} us"
    print(f"  cost per point (median of 200 evaluations): {cost_text}")
    if cfd_rows:
        print("CFD results at the same bearing, lubricant and temperature (kegel cfd run; the correlations "
              "evaluated at each result's own speed and oil level), torques in N mm:")
        _print_table(("oil level", "n [rpm]", "mesh", "cells", "CFD loss", "balance [%]", "Liebrecht", "SKF drag",
                      "CFD wall time [min]", "file"),
                     [(c["oil_level"], c["speed_rpm"], c["mesh"], c["cells"], mm(c["loss_torque_Nm"]),
                       None if c["angular_momentum_balance"] is None else 100 * c["angular_momentum_balance"],
                       mm(c["liebrecht_total_Nm"]), mm(c["skf_drag_Nm"]),
                       None if c["wall_time_s"] is None else c["wall_time_s"] / 60, c["file"]) for c in cfd_rows])
        from ..coupling.cfd_results import BALANCE_LIMIT

        off = [c for c in cfd_rows if c["angular_momentum_balance"] is not None
               and abs(c["angular_momentum_balance"]) > BALANCE_LIMIT]
        for c in off:
            print(f"  not settled: {c['oil_level']} at {c['speed_rpm']:.0f} rpm, its angular-momentum balance "
                  f"misses by {100 * c['angular_momentum_balance']:+.0f} % of the drive torque (settled: within "
                  f"{100 * BALANCE_LIMIT:.0f} %): the oil was still gaining or losing angular momentum; "
                  "read this loss as unconfirmed")
    elif args.cfd:
        print(f"no CFD result of a {bearing.designation} in {lub.name} at {T - 273.15:g} degC under {', '.join(args.cfd)}")
    if plot_path:
        print(f"plot written to {plot_path}")
    return 0


def _cfd_loss_rows(paths: list[str], bearing, lubricant: str, T: float, g, state, sb, contact_check: bool,
                   edition: str, levels: list[tuple[str, float]]) -> list[dict[str, Any]]:
    """The ``kegel cfd run`` results under ``paths`` for this bearing, lubricant and temperature,
    each with the Liebrecht and SKF answers at its own speed and oil level and its wall time
    (solver run plus meshing; the whole chain for a run started on a coarser mesh)."""
    import json as _json

    from ..correlations import hydraulic_torques
    from ..correlations.skf import skf_drag_moment
    from ..coupling.cfd_results import TEMPERATURE_TOLERANCE_K, balance_of, read_cfd_results

    out = []
    for path in paths:
        for f, data in read_cfd_results(path, source="command line", key="--cfd"):
            pt = data["point"]
            if (pt.get("bearing") != bearing.designation or pt.get("lubricant") != lubricant
                    or abs(pt.get("temperature_K", 0.0) - T) > TEMPERATURE_TOLERANCE_K):
                continue
            w = float(pt["speed_rad_s"])
            h_cfd = pt.get("oil_level_m")
            flooded = h_cfd is None
            h = bearing.outer_diameter_m if flooded else float(h_cfd)  # the correlations' flooded level
            name = "flooded" if flooded else next(
                (t for t, lv in levels if lv is not None and abs(lv - h) <= 1e-4), f"{1e3 * h:.1f} mm")
            lie = hydraulic_torques("liebrecht", g, state, shaft_speed_rad_s=w, oil_level_m=h)
            skf = skf_drag_moment(sb, speed_rad_s=abs(w), kinematic_viscosity_m2_s=state.kinematic_viscosity_m2_s,
                                  oil_level_m=h, edition=edition)
            meta_file = f.parent / "kegel-case.json"
            wall = data.get("chain_wall_time_s")
            if wall is None and data.get("runtime_s") is not None:
                mesh_s = 0.0
                if meta_file.is_file():
                    try:
                        mesh_s = float(_json.loads(meta_file.read_text()).get("mesh_time_s") or 0.0)
                    except (OSError, ValueError):
                        mesh_s = 0.0
                wall = float(data["runtime_s"]) + mesh_s
            bal = balance_of(data)
            out.append({"file": str(f), "oil_level": name, "oil_level_m": None if flooded else h,
                        "speed_rpm": w * 30 / math.pi, "mesh": data["fidelity"].get("mesh"),
                        "cells": data["fidelity"].get("cells"), "loss_torque_Nm": data["loss_torque_at_shaft_Nm"],
                        "steady": data.get("steady"), "angular_momentum_balance": bal,
                        "liebrecht_total_Nm": lie.total_Nm, "skf_drag_Nm": math.copysign(skf.drag_Nm, w),
                        "wall_time_s": wall})
    out.sort(key=lambda c: (c["oil_level"], c["speed_rpm"], c["cells"] or 0))
    return out


def _plot_losses(rows: list[dict[str, Any]], skf_rows: list[dict[str, Any]], g, lubricant: str, T: float,
                 path: Path, cfd_rows: list[dict[str, Any]] | None = None) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    for i, level in enumerate(dict.fromkeys(r["oil_level"] for r in rows)):
        sel = [r for r in rows if r["oil_level"] == level]
        ks = [r for r in skf_rows if r["oil_level"] == level]
        colour = f"C{i % 10}"
        ax1.plot([r["speed_rpm"] for r in sel], [r["total_Nm"] * 1e3 for r in sel], marker="o", color=colour,
                 label=f"Liebrecht, {level} ({sel[0]['oil_level_m'] * 1e3:.1f} mm)")
        ax1.plot([r["speed_rpm"] for r in ks], [r["drag_Nm"] * 1e3 for r in ks], marker="s", ls="--", color=colour,
                 label=f"SKF drag, {level}")
    level_names = list(dict.fromkeys(r["oil_level"] for r in rows))
    markers = {"tiny": "v", "small": "D", "fine": "*"}
    for c in cfd_rows or []:
        i = level_names.index(c["oil_level"]) if c["oil_level"] in level_names else len(level_names)
        wall = "" if c["wall_time_s"] is None else f", {c['wall_time_s'] / 60:.0f} min"
        ax1.plot([c["speed_rpm"]], [c["loss_torque_Nm"] * 1e3], ls="none", marker=markers.get(c["mesh"], "x"),
                 ms=8, mfc="none", color=f"C{i % 10}", label=f"CFD {c['mesh']}, {c['oil_level']}{wall}")
    ax1.set_xlabel("shaft speed [rpm]")
    ax1.set_ylabel("hydraulic torque [N mm]")
    ax1.set_title("total vs speed (CFD: open markers)" if cfd_rows else "total vs speed")
    ax1.legend(fontsize=7)
    last = max(r["speed_rpm"] for r in rows)
    sel = [r for r in rows if r["speed_rpm"] == last]
    ks = [r for r in skf_rows if r["speed_rpm"] == last]
    x = [2 * i for i in range(len(sel))]
    bottom = [0.0] * len(sel)
    for key, label in (("drag_rollers_Nm", "roller drag (38)"), ("churning_outer_ring_Nm", "churning OR (39)"),
                       ("churning_inner_ring_Nm", "churning IR (40)")):
        vals = [r[key] * 1e3 for r in sel]
        ax2.bar(x, vals, bottom=bottom, label=label)
        bottom = [b + v for b, v in zip(bottom, vals)]
    ax2.bar([v + 0.8 for v in x], [r["drag_Nm"] * 1e3 for r in ks], width=0.8, color="0.5", label="SKF drag")
    ax2.set_xticks([v + 0.4 for v in x], [r["oil_level"] for r in sel])
    ax2.set_ylabel("hydraulic torque [N mm]")
    ax2.set_title(f"components at {last:.0f} rpm")
    ax2.legend(fontsize=7)
    fig.suptitle(f"{g.designation}, {lubricant} at {T - 273.15:g} degC: Liebrecht (Eq. 38-40, 1/min), SKF drag"
                 + (" and kegel CFD" if cfd_rows else ""))
    fig.tight_layout()
    from ..base.io import atomic_save

    try:
        atomic_save(path, lambda tmp: fig.savefig(tmp, dpi=120))
    finally:
        plt.close(fig)
    return path


def _scene_summary(scene: Scene) -> dict[str, Any]:
    g = scene.geometry
    states = {}
    for p in scene.operating_points:
        if p.temperature_K not in states:
            states[p.temperature_K] = lubricant_state(scene.lubricant, p.temperature_K, source=scene.source,
                                                      key="operating.temperature")
    return {
        "scene": {"name": scene.name, "description": scene.description, "file": scene.source,
                  "resolved": scene.resolved},
        "bearing": scene.bearing.designation,
        "material": scene.material.name,
        "lubricant": scene.lubricant.name,
        "lubrication": {"mode": scene.lubrication.mode, "oil_level_m": scene.lubrication.oil_level_m,
                        "oil_level_as_written": scene.lubrication.oil_level_as_written},
        "fidelity": scene.fidelity.as_dict(),
        "swept": list(scene.swept),
        "geometry": g.as_dict(),
        "operating_points": [
            {**p.as_dict(), "lubricant_state": states[p.temperature_K].as_dict()} for p in scene.operating_points
        ],
    }


def _cmd_validate(args: argparse.Namespace) -> int:
    from ..runner.validation import print_report, run_validation

    result = run_validation(args.output, progress=sys.stderr.isatty())
    print_report(result)
    return 0


def _cmd_list(args: argparse.Namespace) -> int:
    from ..model.inventory import KINDS, inventory

    kinds = [args.kind] if args.kind else list(KINDS)
    data = {k: inventory(k) for k in kinds}
    if args.format == "json":
        _json_out(data)
        return 0
    for k in kinds:
        print(f"{k}: {KINDS[k]}")
        rows = data[k]
        if not rows:
            print("  (none)")
        for r in rows:
            text = r.get("title", "")
            text = f"{text}: {r['description']}" if text and r.get("description") else (text or r.get("description", ""))
            print(printable(f"  {r['name']:<34} {text}".rstrip()))
    return 0


def _cmd_init(args: argparse.Namespace) -> int:
    from ..model.inventory import write_scene_template

    path = write_scene_template(args.file, bearing=args.bearing, lubricant=args.lubricant, force=args.force)
    if args.format == "json":
        _json_out({"file": str(path)})
        return 0
    print(f"wrote {path}: check it with `kegel check {path}`, run it with `kegel run {path}`")
    return 0


def _cmd_check(args: argparse.Namespace) -> int:
    from ..runner.run import preflight

    scene = load_scene(args.scene, args.set or ())
    preflight(scene)  # what kegel run checks before its first point (each point's CFD result)
    summary = _scene_summary(scene)  # evaluates the lubricant at every temperature, too
    if args.format == "json":
        _json_out({"valid": True, "file": str(args.scene), "name": scene.name,
                   "operating_point_count": len(scene.operating_points), "swept": list(scene.swept),
                   "fidelity": summary["fidelity"]})
        return 0
    print(f"{printable(args.scene)}: valid scene '{printable(scene.name)}': bearing {scene.bearing.designation}, "
          f"lubricant {scene.lubricant.name}, {len(scene.operating_points)} operating point(s)"
          + (f" sweeping {', '.join(scene.swept)}" if scene.swept else "")
          + f", fidelity {scene.fidelity.name}")
    return 0


def _cmd_run(args: argparse.Namespace) -> int:
    from ..runner.run import run_scene

    scene = load_scene(args.scene, args.set or ())
    out_dir = Path(args.output) if args.output else scene.output_directory
    options = None
    if args.uncertainty:
        from ..runner.uncertainty import UncertaintyOptions

        options = UncertaintyOptions(crown_drop_fraction=args.crown_drop)
    client = None
    if args.scheduler:  # a Dask cluster solves the points (kegel.parallel)
        from ..runner.parallel import connect

        client = connect(args.scheduler)
    try:
        result = run_scene(scene, out_dir, progress=args.format != "json", force=args.force,
                           uncertainty=options or False, jobs=args.jobs, client=client)
    finally:
        if client is not None:
            client.close()
    if args.format == "json":
        _json_out({"scene": scene.name, "files": result.files, "runtime_s": result.runtime_s,
                   "points": result.points})
        return _run_status(result.points)
    g = scene.geometry
    f = scene.fidelity
    print(f"Scene '{printable(scene.title)}' ({printable(scene.source)})")
    if scene.description:
        print(f"  {printable(scene.description)}" + (" (as written in the scene file, before --set)" if scene.overridden else ""))
    print(f"  bearing {g.designation} (Z = {g.roller_count}, contact angle {math.degrees(g.cup_angle_rad):.2f} deg), "
          f"lubricant {scene.lubricant.name}, {scene.lubrication_label}"
          + (f" at {scene.lubrication.oil_level_m * 1e3:.1f} mm" if scene.lubrication.oil_level_m else ""))
    rib = f"rib cell model {f.rib_cells}x{f.rib_cells}" if f.rib_model == "cell" else "rib closed-form Hertz"
    solution = "quasi-static" if f.solution == "quasi_static" else f"dynamic ({scene.dynamic.duration_s * 1e3:g} ms)"
    hydraulic = (f"hydraulic loss by the study's methods ({', '.join(scene.study.methods)})"
                 if scene.study is not None else f"hydraulic {f.hydraulic}")
    print(f"  fidelity {f.name}: {solution}, {f.slices} slices ({f.slice_model.replace('_', ' ')}), {rib}, "
          f"{hydraulic}")
    rows = []
    for p in result.points:
        if not p.get("solved", True):
            rows.append((p["index"], p["speed_rpm"], p["temperature_degC"],
                         f"{p['axial_load_N'] / 1e3:g}" if p["axial_load_N"] is not None else "",
                         p["radial_load_N"] / 1e3, *([None] * 10), "FAILED"))
            continue
        mech = p["torque_by_mechanism_Nm"]
        axial = f"{p['axial_load_N'] / 1e3:g}" if p["axial_load_N"] is not None else f"{p['axial_force_N'] / 1e3:.2f}*"
        rows.append((p["index"], p["speed_rpm"], p["temperature_degC"], axial, p["radial_load_N"] / 1e3,
                     p["friction_torque_Nm"], p["hydraulic_torque_Nm"], p["total_torque_Nm"],
                     abs(p["total_torque_Nm"] * p["speed_rad_s"]), 100 * p["cage_slip"], mech["ehl_sliding"] + mech["solid_sliding"],
                     mech["ehl_rolling"] + mech["solid_rolling"] + mech["hysteresis"],
                     p["torque_by_contact_Nm"]["rib"], min(p["Lambda_min"].values()),
                     (p.get("skf_catalogue_model") or {}).get("rolling_sliding_Nm", float("nan")),
                     "yes" if p["converged"] else "FAILED"))
    header = ("#", "n [rpm]", "T [degC]", "Fa [kN]", "Fr [kN]", "M_fric [Nm]", "M_hyd [Nm]", "M_total [Nm]",
              "P_loss [W]", "cage slip [%]", "sliding [Nm]", "rolling [Nm]", "of which rib [Nm]", "Lambda_min",
              "SKF rr+sl [Nm]", "converged")
    if scene.study is not None:
        # a study's hydraulic losses and supplies are in its own table below: this one is the
        # contact friction of flooded contacts alone (no M_hyd / M_total / P_loss of "none")
        keep = [k for k, h in enumerate(header) if h not in ("M_hyd [Nm]", "M_total [Nm]", "P_loss [W]")]
        header = tuple(header[k] for k in keep)
        rows = [tuple(r[k] for k in keep) for r in rows]
        print("Contact friction of flooded contacts (each lubrication's supply and hydraulic loss: the study "
              "table below)")
    _print_table(header, rows, max_rows=MAX_TABLE_ROWS, where="results.csv")
    print("  " + TORQUE_SPLIT_NOTE)
    if any(p.get("skf_catalogue_model") for p in result.points):
        print("  SKF rr+sl: the SKF catalogue model's rolling + sliding moment (an independent engineering model; "
              "kegel.correlations.skf), beside M_fric")
    failed = [p for p in result.points if not p["converged"]]
    for p in failed[:10]:
        print(f"  point {p['index']} FAILED its plausibility gates: {p.get('failure')}")
    if len(failed) > 10:
        print(f"  ... and {len(failed) - 10} more failed points (results.csv: columns converged, failure)")
    if any(p["axial_load_N"] is None for p in result.points):
        print("  * axial force carried at the prescribed axial offset")
    if options is not None:
        _print_band(result.points, options)
    if scene.study is not None:
        _print_study(result.points)
    print(f"results: {', '.join(v for k, v in result.files.items() if not k.endswith('plot'))}")
    print(f"plots:   {', '.join(v for k, v in result.files.items() if k.endswith('plot'))}")
    if f.solution == "dynamic":
        for p in result.points:
            d = p.get("dynamic")
            if not p.get("solved", True) or not d:
                print(f"  point {p['index']}: no dynamic result ({(p.get('failure') or 'failed').splitlines()[0]})")
                continue
            print(f"  point {p['index']}: outer-ring torque {p['outer_ring_torque_Nm']:.4f} N m "
                  f"(std {p['outer_ring_torque_std_Nm']:.1e}), power balance {100 * p['power_balance_error']:+.2f} %, "
                  f"{d['revolutions']:.2f} rev in {p['runtime_s']:.1f} s; series, VTK, plot: "
                  f"{Path(d['files']['json']).parent}")
    print(f"runtime: {result.runtime_s:.2f} s for {len(result.points)} operating point(s)")
    return _run_status(result.points)


def _print_band(points: Sequence[dict[str, Any]], options: Any) -> None:
    """The uncertainty band of each point (``kegel run --uncertainty``)."""
    print(f"  uncertainty (kegel.uncertainty): crown drop a_p x (1 -+ {options.crown_drop_fraction:g}), "
          f"{'the other slice model' if options.slice_model_variant else 'no slice-model variant'}; "
          "band = smallest / largest friction torque of the nominal point and the variants")
    for p in points[:MAX_TABLE_ROWS]:
        u = p.get("uncertainty") or {}
        if "friction_torque_low_Nm" not in u:
            print(f"  point {p['index']}: no band ({u.get('note') or 'not solved'})")
            continue
        lo, hi = u["band_relative"]
        ll = u.get("nominal_loaded_length_m")
        length = (f", loaded length {ll * 1e3:.1f} of {u['roller_length_m'] * 1e3:.1f} mm" if ll else "")
        print(f"  point {p['index']}: M_fric {p['friction_torque_Nm']:.4g} N m in [{u['friction_torque_low_Nm']:.4g}, "
              f"{u['friction_torque_high_Nm']:.4g}] ({100 * lo:+.1f} / {100 * hi:+.1f} %){length}")
    if len(points) > MAX_TABLE_ROWS:
        print(f"  ... every point's band: results.csv (friction_torque_low_Nm, friction_torque_high_Nm)")


def _run_status(points: Sequence[dict[str, Any]]) -> int:
    """Exit status of a finished run: 1 (with one line on stderr) when the solver raised at any
    point (the results of every other point are written), 0 otherwise."""
    unsolved = [p for p in points if not p.get("solved", True)]
    if not unsolved:
        return 0
    first = unsolved[0]
    reason = (first.get("failure") or "").splitlines()[0] if first.get("failure") else "no answer"
    print(f"kegel: solver failed at {len(unsolved)} of {len(points)} point(s) (point {first['index']}: {reason}); "
          "the other points' results are written", file=sys.stderr)
    return 1


def _print_study(points: list[dict[str, Any]]) -> None:
    """A study's answers side by side: per operating point and lubrication, the total torque by
    each hydraulic method (hydraulic loss in brackets, N mm); missing CFD points with their command."""
    methods: list[str] = []
    for p in points:
        for r in p.get("study") or ():
            if r["method"] not in methods and r["method"] != "none":
                methods.append(r["method"])
    label = {"liebrecht": "Liebrecht", "skf": "SKF", "cfd": "CFD"}
    rows, missing = [], []
    for p in points:
        cases: dict[str, dict[str, Any]] = {}
        for r in p.get("study") or ():
            cases.setdefault(r["lubrication"], {})[r["method"]] = r
        for case, by in cases.items():
            cells = []
            for m in methods:
                r = by.get(m) or by.get("none")
                if r is None or r.get("total_torque_Nm") is None:
                    cells.append("missing" if r is not None else "")
                    if r is not None and r.get("command"):
                        missing.append(r["command"])
                    continue
                mark = {"interpolated": "~", "computed": ""}.get(r.get("status"), "")
                err = f" +-{100 * r['error_rel']:.0f}%" if r.get("error_rel") else ""
                if any(w["code"] in ("cfd_unbalanced", "cfd_not_steady") for w in r.get("warnings", ())):
                    err += " !"
                cells.append(f"{mark}{r['total_torque_Nm']:.4g} ({1e3 * r['hydraulic_torque_Nm']:.3g}){err}")
            first = next(iter(by.values()))
            fi, fo = first.get("supply_rolling_force_factor_inner"), first.get("supply_rolling_force_factor_outer")
            supply = f"{fi:.3f}/{fo:.3f}" if fi is not None and fo is not None else ""
            rows.append((p["index"], f"{p['speed_rpm']:.0f}", f"{p['temperature_degC']:g}", case.replace("_", " "),
                         supply, f"{first.get('friction_torque_Nm', p['friction_torque_Nm']):.4g}", *cells))
    print("\nStudy: total torque at the shaft [N m] (hydraulic loss [N mm]) by lubrication and method; "
          "~ CFD interpolated (+- its stated error); ! CFD not settled (see its warning)")
    _print_table(("#", "n [rpm]", "T [degC]", "lubrication", "supply in/out", "M_fric [Nm]",
                  *(label[m] for m in methods)), rows, max_rows=MAX_TABLE_ROWS, where="study.csv")
    print("  supply in/out: the oil supply's factor on the flooded EHL rolling force of the inner / outer raceway "
          "contacts (1: flooded; kegel.supply)")
    if missing:
        print(f"  {len(missing)} CFD point(s) missing; they are computed by (see study.csv for all):")
        for c in missing[:5]:
            print(f"    {c}")


def _parser() -> argparse.ArgumentParser:
    from ..base.version import __version__

    p = argparse.ArgumentParser(prog="kegel", description="Power losses of tapered roller bearings.")
    p.add_argument("--version", action="version", version=f"kegel {__version__}")
    sub = p.add_subparsers(dest="command", required=True)

    def common(sp: argparse.ArgumentParser) -> None:
        sp.add_argument("--format", choices=("table", "json"), default="table",
                        help="table for people, json for programs (default: table)")

    from ..model.inventory import KINDS

    li = sub.add_parser("list", help="what kegel ships with: bearings, lubricants, materials, friction sets, "
                                     "validation data, example scenes")
    li.add_argument("kind", nargs="?", choices=tuple(KINDS), help="one kind only (default: all)")
    common(li)
    li.set_defaults(func=_cmd_list)

    it = sub.add_parser("init", help="write a commented scene file to start from")
    it.add_argument("file", help="the scene .toml file to write")
    it.add_argument("--bearing", default="32216", help="bearing designation or .toml file (default 32216)")
    it.add_argument("--lubricant", default="FVA3", help="lubricant name or .toml file (default FVA3)")
    it.add_argument("--force", action="store_true", help="replace an existing file")
    common(it)
    it.set_defaults(func=_cmd_init)

    b = sub.add_parser("bearing", help="derived internal geometry of a bearing")
    b.add_argument("--bearing", required=True, help="bearing designation (e.g. 32216) or a bearing .toml file")
    b.add_argument("--material", default="bearing_steel", help="roller material (default: bearing_steel)")
    common(b)
    b.set_defaults(func=_cmd_bearing)

    lu = sub.add_parser("lubricant", help="lubricant properties at temperatures")
    lu.add_argument("name", help="lubricant name (e.g. FVA3) or a lubricant .toml file")
    lu.add_argument("--temperature", action="append", metavar="T",
                    help='temperature with unit, e.g. "50 degC" (repeatable; default 40, 50, 100 degC)')
    common(lu)
    lu.set_defaults(func=_cmd_lubricant)

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
    tr.set_defaults(func=_cmd_tribology)

    lo = sub.add_parser("losses", help="hydraulic losses by correlation (Liebrecht, SKF), against speed and oil level")
    lo.add_argument("--bearing", required=True, help="bearing designation (e.g. 32208) or a bearing .toml file")
    lo.add_argument("--material", default="bearing_steel", help="roller material (default: bearing_steel)")
    lo.add_argument("--lubricant", default="FVA3", help="lubricant name or .toml file (default FVA3)")
    lo.add_argument("--temperature", default="50 degC", help='oil temperature (default "50 degC")')
    lo.add_argument("--speed", action="append", metavar="N",
                    help='a shaft speed, e.g. "2000 rpm" (repeatable: a list, as in `kegel cfd sweep`)')
    lo.add_argument("--speed-range", nargs=2, metavar=("FROM", "TO"),
                    help='a speed range, e.g. --speed-range "500 rpm" "4000 rpm" (the default) with --points')
    lo.add_argument("--points", type=int, help=f"speeds in --speed-range, ends included (default 8, at most "
                                               f"{MAX_LOSS_POINTS})")
    lo.add_argument("--oil-level", action="append", metavar="LEVEL",
                    help="none, half_roller, shaft_center, flooded or a length (repeatable)")
    lo.add_argument("--plot", metavar="PNG", help="write torque vs speed and components to this file")
    lo.add_argument("--axial-load", default="6 kN",
                    help='axial load of the SKF rolling and sliding moments (default "6 kN")')
    lo.add_argument("--radial-load", default="0 kN",
                    help='radial load of the SKF rolling and sliding moments (default "0 kN")')
    lo.add_argument("--skf-edition", choices=("2013", "2005"), default="2013",
                    help="SKF catalogue edition of the drag equation (default 2013)")
    lo.add_argument("--cfd", action="append", metavar="RESULTS",
                    help="a kegel cfd results.json or a folder of them (repeatable): every result of this "
                         "bearing, lubricant and temperature joins the table and the plot, with its wall time")
    common(lo)
    lo.set_defaults(func=_cmd_losses)

    from ..cfd_cases.cli import add_cfd_parser

    add_cfd_parser(sub, common)

    va = sub.add_parser("validate", help="kegel's bearing torque against measured data and the SKF catalogue model")
    va.add_argument("--output", default="results/validation", help="result folder (default: results/validation)")
    common(va)
    va.set_defaults(func=_cmd_validate)

    for name, func, text in (("check", _cmd_check, "validate a scene file"), ("run", _cmd_run, "run a scene")):
        sp = sub.add_parser(name, help=text)
        sp.add_argument("scene", help="scene .toml file")
        sp.add_argument("--set", action="append", metavar="KEY=VALUE",
                        help='override a scene value, e.g. --set operating.axial_load="6.5 kN" (repeatable)')
        common(sp)
        sp.set_defaults(func=func)
        if name == "run":
            sp.add_argument("--output", help="result folder (default: the scene's [output] directory)")
            sp.add_argument("--force", action="store_true",
                            help="write into an output folder that holds files kegel did not write (they are kept; "
                                 "one with a name kegel writes is moved to kegel-replaced-<run id>/)")
            sp.add_argument("--uncertainty", action="store_true",
                            help="add each point's friction torque band: the point solved again with the crown "
                                 "drop -+ CROWN_DROP and with the other slice model (3 extra solves per point; "
                                 "quasi-static points)")
            sp.add_argument("--crown-drop", type=float, default=0.25, metavar="FRACTION",
                            help="relative change of the crown drop for --uncertainty (default 0.25: assumed, no "
                                 "source gives a tolerance)")
            sp.add_argument("--jobs", type=int, metavar="N",
                            help="processes solving independent points at once (default: every core; 1: one "
                                 "process). The results equal a run in one process")
            sp.add_argument("--scheduler", metavar="ADDRESS",
                            help="solve the points on a Dask cluster: its scheduler's address (tcp://host:8786) or "
                                 "scheduler file (needs dask.distributed: pip install 'kegel[dask]')")
    return p


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``kegel`` command; returns the exit status."""
    from ..outputs.point_warnings import warnings_once_per_command

    args = _parser().parse_args(argv)
    try:
        with warnings_once_per_command():
            return args.func(args)
    except KegelInputError as exc:
        print(f"kegel: error: {printable(str(exc))}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as exc:
        signum = getattr(exc, "signum", 2)  # kegel.io.Terminated: SIGTERM, SIGHUP
        print("kegel: interrupted" if signum == 2 else f"kegel: terminated ({exc})", file=sys.stderr)
        return 128 + signum
    except KegelSolverError as exc:
        print(f"kegel: solver failed: {exc}", file=sys.stderr)
        return 1
    except BrokenPipeError:
        # `kegel ... | head`: the reader has gone; no traceback, and none at exit either
        import os

        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 141
    except OSError as exc:
        # a full disk, a vanished or read-only output folder: one line naming the file
        where = f"{exc.filename}: " if exc.filename else ""
        print(f"kegel: error: cannot write {where}{exc.strerror or exc}", file=sys.stderr)
        return 1
    except RuntimeError as exc:
        from ..cfd_cases.foam import FoamError, FoamInterrupted

        if not isinstance(exc, FoamError):
            raise
        if isinstance(exc, FoamInterrupted):
            print(f"kegel: {str(exc).splitlines()[0]}\n  case: {exc.case}", file=sys.stderr)
            return 130
        print(f"kegel: OpenFOAM error: {exc}", file=sys.stderr)
        return 1


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
