"""``kegel run SCENE [--set KEY=VALUE ...] [--output DIR]``: run a scene and print its table;
results.json, results.csv and plots in the output folder."""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path
from typing import Any, Callable, Sequence

from ..model.scene import load_scene
from .common import MAX_TABLE_ROWS, _json_out, _print_table, printable

__all__ = ["add_parser", "command"]


TORQUE_SPLIT_NOTE = ("sliding + rolling = M_fric (split by mechanism); of which rib: the roller end / rib "
                     "contact's share of M_fric (split by contact), already inside sliding and rolling")


def command(args: argparse.Namespace) -> int:
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
    cut = [r for p in points for r in p.get("study") or () if r.get("contact_film_limit_m")]
    if cut:
        g = cut[0]["contact_film_limit_m"]
        print(f"  CFD with the real rollers: contact cut at the CFD's gap g = {1e3 * g:.3g} mm (its friction below "
              "M_fric by the oil beyond g, in study.csv) + the CFD beyond g (flooded: less its far field on the "
              "unloaded stretch of the lines, unloaded_line_wedge_Nm in study.csv; an oil bath keeps it, 0.4-0.6 % "
              "of its total) + the analytic thin films (in brackets; docs/cfd.md)")
    if missing:
        print(f"  {len(missing)} CFD point(s) missing; they are computed by (see study.csv for all):")
        for c in missing[:5]:
            print(f"    {c}")


def add_parser(sub: Any, common: Callable[[argparse.ArgumentParser], None]) -> None:
    """The ``run`` sub-command on ``sub`` (``common`` adds ``--format``)."""
    sp = sub.add_parser("run", help="run a scene")
    sp.add_argument("scene", help="scene .toml file")
    sp.add_argument("--set", action="append", metavar="KEY=VALUE",
                    help='override a scene value, e.g. --set operating.axial_load="6.5 kN" (repeatable)')
    common(sp)
    sp.set_defaults(func=command)
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
