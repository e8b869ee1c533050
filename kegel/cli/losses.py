"""``kegel losses --bearing 32208 [--oil-level flooded ...] [--plot losses.png]``: hydraulic losses by
correlation against speed and oil level, Liebrecht and the SKF drag moment side by side, with
the SKF rolling + sliding moment as a check of contact friction (and ``--cfd`` results beside them)."""

from __future__ import annotations

import argparse
import math
from pathlib import Path
from typing import Any, Callable

from ..base.errors import KegelInputError
from ..base.units import parse_quantity
from ..model.data import load_bearing, load_lubricant, load_material
from ..model.geometry import derive_geometry
from ..model.lubricant import lubricant_state
from ..model.scene import check_speed
from .common import _json_out, _print_table

__all__ = ["add_parser", "command"]


#: Most speeds of `kegel losses --points` (1000 take about a second and print 3000 rows).
MAX_LOSS_POINTS = 1000


def command(args: argparse.Namespace) -> int:
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
        _print_table(("oil level", "n [rpm]", "mesh", "cells", "g / D_w", "CFD loss", "thin films", "balance [%]",
                      "Liebrecht", "SKF drag", "CFD wall time [min]", "file"),
                     [(c["oil_level"], c["speed_rpm"], c["mesh"], c["cells"],
                       "shrunk rollers" if c["gap_ratio"] is None else c["gap_ratio"], mm(c["loss_torque_Nm"]),
                       mm(c["thin_films_Nm"]),
                       None if c["angular_momentum_balance"] is None else 100 * c["angular_momentum_balance"],
                       mm(c["liebrecht_total_Nm"]), mm(c["skf_drag_Nm"]),
                       None if c["wall_time_s"] is None else c["wall_time_s"] / 60, c["file"]) for c in cfd_rows])
        if any(c["gap_ratio"] is not None for c in cfd_rows):
            print("  real rollers (g / D_w given): the CFD owns the oil beyond the gap g, the contact model the oil "
                  "within it (cut at g, kegel run does it), and the films thinner than the CFD's clearance are "
                  "the thin-film terms; compare CFD + thin films + the contact's cut, less the CFD's far field on "
                  "the unloaded stretch of the lines (it needs the load: kegel run takes it off a flooded result), "
                  "with a correlation (docs/cfd.md, three answers). Shrunk rollers: the old geometry, its level "
                  "set by that gap.")
        from ..coupling.cfd_results import is_unbalanced, unbalanced_reason

        for c in cfd_rows:
            if is_unbalanced(c["angular_momentum_balance"]):
                print(f"  unbalanced: {c['oil_level']} at {c['speed_rpm']:.0f} rpm, "
                      f"{unbalanced_reason(c['angular_momentum_balance'])}")
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
    from ..coupling.cfd_results import TEMPERATURE_TOLERANCE_K, balance_of, cfd_boundary, read_cfd_results

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
            bnd = cfd_boundary(data, g.roller_mean_diameter_m, source=str(f))
            out.append({"file": str(f), "oil_level": name, "oil_level_m": None if flooded else h,
                        "speed_rpm": w * 30 / math.pi, "mesh": data["fidelity"].get("mesh"),
                        "cells": data["fidelity"].get("cells"), "loss_torque_Nm": data["loss_torque_at_shaft_Nm"],
                        "gap_ratio": bnd.gap_ratio, "thin_films_Nm": bnd.thin_films_Nm,
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


def add_parser(sub: Any, common: Callable[[argparse.ArgumentParser], None]) -> None:
    """The ``losses`` sub-command on ``sub`` (``common`` adds ``--format``)."""
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
    lo.set_defaults(func=command)
