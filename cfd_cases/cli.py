"""``kegel cfd ...``: run, sweep, check-solvers, validate."""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

from .geometry import CELLS_ACROSS_GAP, CELLS_ACROSS_GAP_RANGE, CLEARANCE_RATIO, GAP_RATIO, RATIO_RANGES

__all__ = ["add_cfd_parser"]


def _point_from_args(args: argparse.Namespace, speed_text: str, level_text: str):
    from kegel.model.data import load_bearing, load_lubricant, load_material
    from kegel.base.errors import KegelInputError
    from kegel.model.geometry import derive_geometry
    from kegel.model.lubricant import lubricant_state
    from kegel.model.scene import check_speed, resolve_oil_level
    from kegel.base.units import parse_quantity

    from .geometry import MESH_LEVELS
    from .run import CfdPoint

    src = "command line"
    bearing = load_bearing(args.bearing, source=src, key="--bearing")
    # the envelope check of every other command (rollers inside the rings, not overlapping)
    derive_geometry(bearing, load_material("bearing_steel"))
    bearing_file = str(Path(args.bearing).resolve()) if Path(args.bearing).is_file() else None
    speed = parse_quantity(speed_text, "speed", source=src, key="--speed")
    check_speed(speed, bearing, source=src, key="--speed", text=speed_text)  # non-zero, n d_m <= 1e6 rpm mm
    T = parse_quantity(args.temperature, "temperature", source=src, key="--temperature")
    lubricant_state(load_lubricant(args.lubricant, source=src, key="--lubricant"), T, source=src, key="--temperature")
    if getattr(args, "max_iterations", 1) < 1:
        raise KegelInputError(src, "--max-iterations", args.max_iterations, "at least 1 iteration")
    level = None if level_text == "flooded" else resolve_oil_level(level_text, bearing, source=src, key="--oil-level")
    if level is not None and level <= 0.0:
        raise KegelInputError(src, "--oil-level", level_text, "an oil level above 0 (or 'flooded')")
    if args.mesh not in MESH_LEVELS:
        raise KegelInputError(src, "--mesh", args.mesh, f"one of {', '.join(MESH_LEVELS)}")
    if args.np < 1:
        raise KegelInputError(src, "--np", args.np, "at least 1 process")
    end = None
    if getattr(args, "end_time", None):
        end = parse_quantity(args.end_time, "time", source=src, key="--end-time")
        if end <= 0:
            raise KegelInputError(src, "--end-time", args.end_time, "a positive time")
    wall = None
    if getattr(args, "max_wall_time", None):
        wall = parse_quantity(args.max_wall_time, "time", source=src, key="--max-wall-time")
        if wall <= 0:
            raise KegelInputError(src, "--max-wall-time", args.max_wall_time, "a positive time")
    extra: dict[str, Any] = {}
    tol_text = getattr(args, "steady_tolerance", None)
    if tol_text is not None:
        try:
            text = tol_text.strip()
            tol = float(text[:-1]) / 100.0 if text.endswith("%") else float(text)
        except ValueError:
            tol = math.nan
        if not (math.isfinite(tol) and 0.0 <= tol < 1.0):
            raise KegelInputError(src, "--steady-tolerance", tol_text,
                                  'a fraction from 0 to below 1, e.g. 0.02 or "2 %" (0: no steady stop)')
        extra["steady_tolerance"] = tol
    for key, name in (("--max-courant", "max_courant"), ("--max-interface-courant", "max_interface_courant")):
        co = getattr(args, name, None)
        if co is None:
            continue
        if not (math.isfinite(co) and co > 0.0):
            raise KegelInputError(src, key, co, "a positive Courant number")
        extra[name] = co
    init = getattr(args, "initial_from", None)
    start = getattr(args, "start_on", None)
    if start:  # see _start_run
        levels = list(MESH_LEVELS)
        if start not in MESH_LEVELS:
            raise KegelInputError(src, "--start-on", start, f"one of {', '.join(MESH_LEVELS)}")
        if levels.index(start) >= levels.index(args.mesh):
            raise KegelInputError(src, "--start-on", start, f"a mesh level coarser than --mesh {args.mesh}")
        if init:
            raise KegelInputError(src, "--start-on", start, "either --start-on or --initial-from, not both")
    if init:
        if not (Path(init) / "kegel-case.json").is_file():
            raise KegelInputError(src, "--initial-from", init, "a kegel CFD case folder (with kegel-case.json)")
        extra["initial_from"] = str(Path(init).resolve())
    if getattr(args, "housing_clearance", None):
        s_m = parse_quantity(args.housing_clearance, "length", source=src, key="--housing-clearance")
        if not s_m > 0.0:
            raise KegelInputError(src, "--housing-clearance", args.housing_clearance, "a positive length, e.g. '6 mm'")
        extra["housing_clearance_m"] = s_m
    if getattr(args, "frame", "cage") != "cage":
        extra["frame"] = args.frame
    for key, (lo, hi) in RATIO_RANGES.items():
        option = "--" + key.replace("_", "-")
        value = getattr(args, key, None)
        if value is not None:
            if not (math.isfinite(value) and lo <= value <= hi):
                raise KegelInputError(src, option, value, f"a fraction of the roller diameter in [{lo}, {hi}], e.g. 0.02")
            extra[key] = float(value)
    cells = getattr(args, "cells_across_gap", None)
    if cells is not None:
        c_lo, c_hi = CELLS_ACROSS_GAP_RANGE
        if not c_lo <= cells <= c_hi:
            raise KegelInputError(src, "--cells-across-gap", cells, f"a whole number from {c_lo} to {c_hi}")
        extra["cells_across_gap"] = cells
    if getattr(args, "sector", False):
        if level is not None:
            raise KegelInputError(src, "--sector", "given", "a flooded point (an oil bath does not repeat from pocket "
                                  "to pocket)")
        extra["sector"] = True
    if getattr(args, "no_cage", False):
        extra["cage"] = False
    if bearing_file:
        extra["bearing_file"] = bearing_file
    return CfdPoint(bearing=bearing.designation, speed_rad_s=speed, temperature_K=T, oil_level_m=level,
                    mesh=args.mesh, n_procs=args.np, lubricant=args.lubricant, end_time_s=end,
                    max_iterations=args.max_iterations, max_wall_time_s=wall, **extra)


def _case_name(point, level_text: str) -> str:
    lvl = level_text.replace(" ", "")
    extra = "" if point.frame == "cage" else f"_{point.frame}"
    if not point.cage:
        extra += "_nocage"
    if point.housing_clearance_m is not None:
        extra += f"_s{point.housing_clearance_m * 1e3:g}mm"
    if (point.gap_ratio, point.clearance_ratio, point.cells_across_gap) != (GAP_RATIO, CLEARANCE_RATIO, CELLS_ACROSS_GAP):
        extra += f"_g{point.gap_ratio:g}_c{point.clearance_ratio:g}" + (
            "" if point.cells_across_gap is None else f"_n{point.cells_across_gap}")
    if point.sector:
        extra += "_sector"
    return (f"{point.bearing}_{point.speed_rad_s * 30 / math.pi:.0f}rpm_{lvl}_"
            f"{point.temperature_K - 273.15:.0f}C_{point.mesh}{extra}")


def _liebrecht(point) -> dict[str, float]:
    from kegel.correlations import hydraulic_torques
    from kegel.model.data import load_lubricant, load_material
    from kegel.model.geometry import derive_geometry
    from kegel.model.lubricant import lubricant_state

    from .run import point_bearing

    bearing = point_bearing(point)
    g = derive_geometry(bearing, load_material(point.material))
    state = lubricant_state(load_lubricant(point.lubricant), point.temperature_K)
    level = bearing.outer_diameter_m if point.oil_level_m is None else point.oil_level_m
    t = hydraulic_torques("liebrecht", g, state, shaft_speed_rad_s=point.speed_rad_s, oil_level_m=level)
    return {"inner_ring_Nm": t.inner_ring_Nm, "outer_ring_Nm": t.outer_ring_Nm, "cage_Nm": t.cage_Nm,
            "total_Nm": t.total_Nm}


def _start_run(point, case: Path, args) -> tuple[Any, dict[str, Any] | None]:
    """``--start-on MESH``: run the point on the coarser mesh first and start the requested mesh
    from its state at the steady stop (``initial_from``; the regular write before the stop
    point, see :func:`~kegel.cfd_cases.run.mapping_source_time`). The spin-up of the oil (and, in
    an oil bath, its transport around the housing: tenths of a second of simulated time) then
    costs the coarse mesh's time; the fine mesh only has to settle. Returns the point to
    run and a summary of the start run (``None`` when the case already exists and resumes)."""
    import dataclasses
    import time

    from .foam import FoamError
    from .run import run_case

    start = getattr(args, "start_on", None)
    if not start:
        return point, None
    start_case = case.with_name(f"{case.name}_start_{start}")
    fine = dataclasses.replace(point, initial_from=str(start_case.resolve()))
    if (case / "kegel-case.json").is_file():
        return fine, None  # the case was started from it before: it resumes
    t0 = time.monotonic()
    done = start_case / "results.json"
    if done.is_file() and json.loads(done.read_text()).get("steady"):
        print(f"cfd: start run {start_case} is steady; starting mesh {point.mesh} from it", file=sys.stderr)
    else:
        print(f"cfd: start run on mesh {start} in {start_case}", file=sys.stderr)
        run_case(dataclasses.replace(point, mesh=start), start_case, progress=not args.quiet,
                 log=lambda s: print(s, file=sys.stderr))
    data = json.loads(done.read_text())
    wall = time.monotonic() - t0
    if point.max_wall_time_s is not None:
        left = point.max_wall_time_s - wall
        if left <= 0.0:
            raise FoamError(f"the start run on mesh {start} ({start_case}) used the whole wall-time budget "
                            f"of {point.max_wall_time_s:.0f} s; run again with a larger --max-wall-time "
                            "(both runs resume)")
        fine = dataclasses.replace(fine, max_wall_time_s=left)
    summary = {"case": str(start_case.resolve()), "mesh": start, "cells": data["fidelity"]["cells"],
               "steady": data["steady"], "stopped_by": data.get("stopped_by"),
               "simulated_time_s": data.get("simulated_time_s"), "iterations": data.get("iterations"),
               "runtime_s": data["runtime_s"],
               "wall_time_s": wall, "loss_torque_at_shaft_Nm": data["loss_torque_at_shaft_Nm"]}
    return fine, summary


def _run_one(point, case: Path, args) -> dict[str, Any]:
    import time

    from kegel.base.io import atomic_write_json

    from .foam import time_dirs
    from .plots import plot_oil_distribution, plot_torque_history
    from .run import run_case

    t0 = time.monotonic()
    point, start = _start_run(point, case, args)
    res = run_case(point, case, progress=not args.quiet, log=lambda s: print(s, file=sys.stderr))
    meta = json.loads((case / "kegel-case.json").read_text())
    pictures = {"torque_history": str(plot_torque_history(case, res.window_s, case / "torque_history.png",
                                                          steady_solver=point.flooded))}
    if not point.flooded:
        times = [p for p in time_dirs(case) if (p / "alpha.oil").is_file()]
        if times:
            zc = float(np.mean([r["centre_m"][2] for r in meta["rollers"]]))
            from .run import mesh_rotation_rad_s, point_bearing

            R = 0.5 * point_bearing(point).outer_diameter_m
            turned = mesh_rotation_rad_s(meta) * float(times[-1].name)
            pictures["oil_distribution"] = str(plot_oil_distribution(case, times[-1], zc, case / "oil_distribution.png",
                                                                     housing_radius_m=R, mesh_angle_rad=turned))
    lieb = _liebrecht(point)
    data = json.loads((case / "results.json").read_text())
    data["liebrecht_Nm"] = lieb
    data["pictures"] = pictures
    if start is not None:  # the chain of this call: start run, mapping, this run
        data["start_run"] = start
        data["chain_wall_time_s"] = time.monotonic() - t0
    atomic_write_json(case / "results.json", data)
    return data


def _cmd_run(args: argparse.Namespace) -> int:
    point = _point_from_args(args, args.speed, args.oil_level)
    case = Path(args.output) if args.output else Path("results") / "cfd" / _case_name(point, args.oil_level)
    data = _run_one(point, case, args)
    if args.format == "json":
        print(json.dumps(data, indent=2))
        return 0
    t = data["torques_Nm"]
    print(f"CFD {point.bearing}, {point.speed_rad_s * 30 / math.pi:g} rpm, oil level {args.oil_level}, "
          f"{point.temperature_K - 273.15:g} degC, mesh {point.mesh} ({data['fidelity']['cells']} cells), "
          f"{point.n_procs} core(s): {data['runtime_s']:.0f} s, steady: {data['steady']}")
    if "start_run" in data:
        st = data["start_run"]
        print(f"started from a run on mesh {st['mesh']} ({st['cells']} cells, {st['runtime_s']:.0f} s, "
              f"steady: {st['steady']}, loss torque {st['loss_torque_at_shaft_Nm']:.4g} N m); "
              f"the chain took {data['chain_wall_time_s'] / 60:.1f} min wall time")
    print(f"{'body':<28}{'total':>12}{'pressure':>12}{'viscous':>12}   (torque about the axis, N m)")
    for name in ("inner_ring", "outer_ring", "cage", "rollers_spin_sum"):
        v = t[name]
        print(f"{name:<28}{v['total']:>12.4g}{v['pressure']:>12.4g}{v['viscous']:>12.4g}")
    print(f"{'rollers about the bearing axis':<28}{t['rollers_about_bearing_axis']['total']:>12.4g}")
    print(f"hydraulic power loss {data['power_loss_W']:.4g} W = {data['loss_torque_at_shaft_Nm']:.4g} N m at the shaft;"
          f" Liebrecht (Eq. 38-40): {data['liebrecht_Nm']['total_Nm']:.4g} N m")
    print(f"results: {case / 'results.json'}")
    for p in data["pictures"].values():
        print(f"picture: {p}")
    return 0


def _cmd_sweep(args: argparse.Namespace) -> int:
    from kegel.base.io import atomic_write_json, atomic_write_text

    from .plots import plot_sweep

    out = Path(args.output or "results/cfd/sweep")
    rows = []
    # every case of the sweep checked before the first one runs (a bad second speed used to be
    # found only after the first case's hour of CFD)
    planned = [(level, _point_from_args(args, speed, level))
               for level in args.oil_level or ["flooded"] for speed in args.speed or ["2000 rpm"]]
    for level, point in planned:
        try:
            point.validate()
        except ValueError as exc:
            from kegel.base.errors import KegelInputError

            raise KegelInputError("command line", "--speed/--oil-level", f"{level}, "
                                  f"{point.speed_rad_s * 30 / math.pi:.0f} rpm", str(exc)) from None
    # the cases run one after another, in --jobs local processes or as one task each on a Dask
    # cluster (--scheduler); each keeps its own MPI decomposition (--np cores: the task's
    # resources on a cluster whose workers declare "cores", see kegel.parallel.task_resources)
    from kegel.runner.parallel import connect, default_jobs, map_tasks

    if args.jobs is not None and args.jobs < 1:
        from kegel.base.errors import KegelInputError

        raise KegelInputError("command line", "--jobs", args.jobs, "at least 1 case at a time")
    jobs = args.jobs if args.jobs is not None else max(1, default_jobs() // max(1, args.np))
    cases = [(point, out / _case_name(point, level), args) for level, point in planned]
    client = connect(args.scheduler) if args.scheduler else None
    finished: dict[int, dict[str, Any]] = {}
    try:
        for n, data in map_tasks(_run_one, cases, jobs=jobs, client=client, cores_per_task=args.np,
                                 name="kegel-cfd-case"):
            finished[n] = data
    finally:
        if client is not None:
            client.close()
    for n, (level, point) in enumerate(planned):  # the rows in the order of the command line
        case, data = cases[n][1], finished[n]
        rows.append({"oil_level": level, "speed_rpm": point.speed_rad_s * 30 / math.pi,
                     "cfd_loss_torque_Nm": data["loss_torque_at_shaft_Nm"],
                     "cfd_inner_ring_Nm": data["torques_Nm"]["inner_ring"]["total"],
                     "cfd_outer_ring_Nm": data["torques_Nm"]["outer_ring"]["total"],
                     "liebrecht_total_Nm": data["liebrecht_Nm"]["total_Nm"],
                     "runtime_s": data["runtime_s"], "cells": data["fidelity"]["cells"],
                     "start_run": data.get("start_run"), "chain_wall_time_s": data.get("chain_wall_time_s"),
                     "case": str(case)})
    out.mkdir(parents=True, exist_ok=True)
    atomic_write_json(out / "sweep.json", {"rows": rows})
    header = "oil_level,speed_rpm,cfd_loss_torque_Nm,liebrecht_total_Nm,cfd_inner_ring_Nm,cfd_outer_ring_Nm,runtime_s,cells\n"
    atomic_write_text(out / "sweep.csv", header + "".join(
        f"{r['oil_level']},{r['speed_rpm']:.6g},{r['cfd_loss_torque_Nm']:.6g},{r['liebrecht_total_Nm']:.6g},"
        f"{r['cfd_inner_ring_Nm']:.6g},{r['cfd_outer_ring_Nm']:.6g},{r['runtime_s']:.1f},{r['cells']}\n" for r in rows))
    plot = plot_sweep(rows, out / "sweep.png", title=f"{args.bearing}, {args.temperature}, mesh {args.mesh}")
    if args.format == "json":
        print(json.dumps({"rows": rows, "plot": str(plot)}, indent=2))
        return 0
    print(f"{'oil level':<14}{'rpm':>8}{'CFD (N m)':>12}{'Liebrecht':>12}{'ratio':>8}{'runtime s':>11}")
    for r in rows:
        ratio = r["cfd_loss_torque_Nm"] / r["liebrecht_total_Nm"] if r["liebrecht_total_Nm"] else float("nan")
        print(f"{r['oil_level']:<14}{r['speed_rpm']:>8.0f}{r['cfd_loss_torque_Nm']:>12.4g}"
              f"{r['liebrecht_total_Nm']:>12.4g}{ratio:>8.2f}{r['runtime_s']:>11.0f}")
    print(f"table: {out / 'sweep.csv'}\nplot: {plot}")
    return 0


def _cmd_thin_films(args: argparse.Namespace) -> int:
    from .run import refresh_thin_films

    for case in args.case:
        data = refresh_thin_films(case)
        t = data["thin_films"]
        sup = t.get("supply")
        how = ("flooded: full films" if sup is None else
               f"oil bath: rib x {sup['rib']:.3f}, pockets x {sup['pockets']:.3f} (immersed {sup['immersed_rib']:.2f}, "
               f"phi_rs {sup['phi_rs']:.3f})")
        print(f"{case}: thin films {1e3 * data['thin_film_loss_Nm']:.2f} mN m ({how}); CFD "
              f"{1e3 * data['loss_torque_at_shaft_Nm']:.2f} mN m; together "
              f"{1e3 * data['loss_torque_at_shaft_with_thin_films_Nm']:.2f} mN m")
    return 0


def _cmd_check_solvers(args: argparse.Namespace) -> int:
    from .checks import rotation_check
    from .foam import SOLVERS

    ok = True
    rows = []
    for s in SOLVERS:
        for stock in ((False, True) if args.stock else (False,)):
            r = rotation_check(s, stock=stock)
            tol = 1e-4 if s == "interFoam" else 1e-8
            passed = r.passed(tol)
            ok &= passed or stock
            rows.append({"solver": s, "binary": "Debian" if stock else "kegel rebuild",
                         "velocity_error": r.velocity_error, "diverged": r.diverged, "passed": passed})
    if args.format == "json":
        print(json.dumps(rows, indent=2))
    else:
        print("rotation check: case rotated by 30 deg about z against the unrotated case")
        for r in rows:
            print(f"{r['solver']:<12}{r['binary']:<15}error {r['velocity_error']:.3g}"
                  f"{'  diverged' if r['diverged'] else ''}  {'PASS' if r['passed'] else 'FAIL'}")
    return 0 if ok else 1


#: ``kegel cfd validate`` cases, in the order they run.
VALIDATE_CASES = ("taylor_couette", "rotating_tank", "rolling_gap", "rotor_stator", "immersed_disc")
#: Cases that run only when named with ``--case``: the immersed disc is a 3-D two-phase run
#: (about a minute of solver time on an idle core, several under load).
VALIDATE_OPT_IN = ("immersed_disc",)


def _cmd_validate(args: argparse.Namespace) -> int:
    from dataclasses import asdict

    from .validation import (IMMERSED_DISC_TOLERANCE, cylinder_rolling_gap, immersed_disc, rotating_tank, rotor_stator,
                             taylor_couette)

    chosen = [c for c in VALIDATE_CASES if c in (args.case or [c for c in VALIDATE_CASES if c not in VALIDATE_OPT_IN])]
    # small OpenFOAM runs: say what runs, so minutes of silence are not mistaken for a hang
    t0 = time.monotonic()
    out: dict[str, Any] = {}
    lines: list[str] = []
    ok = True

    def step(i: int, text: str) -> None:
        print(f"cfd validate: {i}/{len(chosen)} {text} ... ({time.monotonic() - t0:.0f} s so far)",
              file=sys.stderr, flush=True)

    for i, name in enumerate(chosen, 1):
        if name == "taylor_couette":
            step(i, "Taylor-Couette annulus (simpleFoam, steady)")
            tc = taylor_couette()
            passed = abs(tc.relative_error) < 0.02
            out[name] = tc
            lines.append(f"Taylor-Couette (Re {tc.reynolds:.0f}, {tc.cells} cells): torque {tc.torque_simulated_Nm:.6g} N m, "
                         f"analytic {tc.torque_analytic_Nm:.6g} N m, error {100 * tc.relative_error:+.3f} % "
                         f"({'PASS' if passed else 'FAIL'}, limit 2 %)")
        elif name == "rotating_tank":
            step(i, "rotating tank (interFoam, VOF)")
            tank = rotating_tank()
            passed = tank.max_height_error_m < 0.25 * tank.cell_height_m and abs(tank.volume_change) < 1e-4
            out[name] = tank
            lines.append(f"rotating tank (VOF, {tank.cells} cells): free surface within {tank.max_height_error_m * 1e3:.3f} mm "
                         f"of the paraboloid (cell height {tank.cell_height_m * 1e3:.1f} mm), oil volume change "
                         f"{tank.volume_change:.2e} ({'PASS' if passed else 'FAIL'})")
        elif name == "rolling_gap":
            step(i, "cylinder rolling in a ring, h0/R1 = 0.05, 6 cells across the gap (simpleFoam, creeping flow)")
            rg = cylinder_rolling_gap(gap_ratio=0.05, cells_across_gap=6.0)
            errs = (rg.error_torque_inner, rg.error_torque_outer, rg.error_dissipation)
            passed = max(abs(e) for e in errs) < 0.02
            out[name] = rg
            mag1 = abs(rg.torque_inner_sim_N) / abs(rg.torque_inner_exact_N) - 1.0  # negative: CFD too low
            mag2 = abs(rg.torque_outer_sim_N) / abs(rg.torque_outer_exact_N) - 1.0
            lines.append(f"cylinder rolling near a wall (h0/R1 {rg.gap_ratio:g}, {rg.cells_across_gap:g} cells across the gap, "
                         f"{rg.cells} cells) against Wannier's exact Stokes flow: torque on the cylinder "
                         f"{100 * mag1:+.2f} %, on the ring {100 * mag2:+.2f} %, "
                         f"dissipation {100 * rg.error_dissipation:+.2f} % ({'PASS' if passed else 'FAIL'}, limit 2 %)")
        elif name == "rotor_stator":
            for regime, limit in (("I", 0.05), ("II", 0.10)):
                step(i, f"rotor-stator cavity, Daily-Nece regime {regime} (simpleFoam, axisymmetric)")
                rs = rotor_stator(regime=regime)
                p = abs(rs.relative_error) < limit
                passed = p if regime == "I" else passed and p
                out[f"{name}_{regime}"] = rs
                lines.append(f"rotor-stator regime {regime} (Re {rs.reynolds:.0f}, s/a {rs.gap_ratio:g}, {rs.cells} cells): "
                             f"C_M {rs.moment_coefficient_sim:.5g}, Daily & Nece {rs.moment_coefficient_ref:.5g}, error "
                             f"{100 * rs.relative_error:+.2f} % ({'PASS' if p else 'FAIL'}, limit {100 * limit:.0f} %)")
        elif name == "immersed_disc":
            step(i, "disc half immersed in an oil bath, 10 revolutions from rest (interFoam, VOF, 3-D)")
            dc = immersed_disc()
            passed = abs(dc.relative_error) < IMMERSED_DISC_TOLERANCE
            out[name] = dc
            lines.append(f"immersed disc (Re {dc.reynolds:.0f}, Fr {dc.froude:.1f}, h/D {dc.immersion_ratio:g}, {dc.cells} cells): "
                         f"churning torque {dc.torque_sim_Nm:.4g} N m, Changenet & Velex {dc.torque_ref_Nm:.4g} N m, error "
                         f"{100 * dc.relative_error:+.1f} % ({'PASS' if passed else 'FAIL'}, limit "
                         f"{100 * IMMERSED_DISC_TOLERANCE:.0f} %); oil volume change {dc.volume_change:.1e}")
        ok &= passed
    print(f"cfd validate: done in {time.monotonic() - t0:.0f} s", file=sys.stderr, flush=True)
    if args.format == "json":
        print(json.dumps({k: asdict(v) for k, v in out.items()}, indent=2))
    else:
        print("\n".join(lines))
    return 0 if ok else 1


def add_cfd_parser(sub, common) -> None:
    """Add ``kegel cfd`` and its subcommands to the main parser."""
    cfd = sub.add_parser("cfd", help="OpenFOAM cases of the bearing (run, sweep, checks)")
    csub = cfd.add_subparsers(dest="cfd_command", required=True)

    def point_args(sp, many: bool) -> None:
        sp.add_argument("--bearing", default="32208", help="bearing designation (default 32208)")
        sp.add_argument("--lubricant", default="FVA3", help="lubricant name or .toml file (default FVA3)")
        sp.add_argument("--temperature", default="50 degC", help='oil temperature (default "50 degC")')
        if many:
            sp.add_argument("--speed", action="append", help='shaft speed (repeatable), e.g. "2000 rpm"')
            sp.add_argument("--oil-level", action="append",
                            help="flooded, half_roller, shaft_center or a length above the lowest point of the "
                                 "outer diameter (repeatable)")
        else:
            sp.add_argument("--speed", default="2000 rpm", help='shaft speed (default "2000 rpm")')
            sp.add_argument("--oil-level", default="flooded",
                            help="flooded (single phase), half_roller, shaft_center or a length above the "
                                 "lowest point of the outer diameter (default flooded)")
        sp.add_argument("--mesh", default="tiny", help="mesh level: tiny, small, fine (default tiny)")
        sp.add_argument("--np", type=int, default=2, help="MPI processes (default 2)")
        sp.add_argument("--end-time", help='oil bath: simulated time limit (default 20 shaft revolutions)')
        sp.add_argument("--max-iterations", type=int, default=2000, help="flooded: SIMPLE iteration limit")
        sp.add_argument("--max-courant", type=float,
                        help="oil bath: time-step limit as a Courant number in the oil-filled gaps (default 5)")
        sp.add_argument("--max-interface-courant", type=float,
                        help="oil bath: time-step limit as a Courant number at the free surface (default 1)")
        sp.add_argument("--initial-from",
                        help="start from the last state of a run of the same point on another mesh "
                             "(case folder), e.g. the tiny run before a small one")
        sp.add_argument("--start-on", metavar="MESH",
                        help="run the point on this coarser mesh first (to a steady loss torque) "
                             "and start --mesh from its last state; e.g. --mesh small --start-on tiny")
        sp.add_argument("--steady-tolerance",
                        help='relative tolerance of the steady-torque stop, e.g. 0.02 or "2 %%" (default 0.02); '
                             "0 runs to --end-time (oil bath) or --max-iterations (flooded)")
        sp.add_argument("--max-wall-time", help='stop a run (writing its state) after this long, e.g. "45 min"')
        sp.add_argument("--frame", choices=("cage", "absolute", "moving_mesh"), default="cage",
                        help="frozen-rotor frame: cage (MRF at the cage speed, default) or absolute (no MRF; "
                             "a modelling-choice check); moving_mesh (oil bath only): no frozen rotor, the mesh "
                             "turns with the cage while gravity stays put (the check of the frozen rotor)")
        sp.add_argument("--no-cage", action="store_true",
                        help="leave the cage out of the geometry (a modelling-choice check: the cage's share "
                             "of the loss)")
        sp.add_argument("--housing-clearance",
                        help='axial distance from the bearing faces to the housing walls, e.g. "6 mm" '
                             "(default 0.25 T of the bearing)")
        sp.add_argument("--gap-ratio", type=float,
                        help="contact gap g / D_w: the raceways set back by g from the real rollers (default 0.08)")
        sp.add_argument("--clearance-ratio", type=float,
                        help="roller end / rib and cage pocket clearance / D_w (default 0.08)")
        sp.add_argument("--cells-across-gap", type=int,
                        help="cells across the narrowest point of each raceway contact gap (default: the mesh level's wall size)")
        sp.add_argument("--sector", action="store_true",
                        help="flooded: one roller pitch with periodic sides (the flow repeats in the cage frame)")
        sp.add_argument("--output", help="case folder (sweep: parent folder)")
        sp.add_argument("--quiet", action="store_true", help="no progress lines")
        common(sp)

    r = csub.add_parser("run", help="prepare, mesh, run and post-process one case")
    point_args(r, False)
    r.set_defaults(func=_cmd_run)
    s = csub.add_parser("sweep", help="run cases over speeds and oil levels, compare with Liebrecht")
    point_args(s, True)
    s.add_argument("--jobs", type=int, metavar="N",
                   help="cases run at once, each on --np cores (default: the cores / --np)")
    s.add_argument("--scheduler", metavar="ADDRESS",
                   help="run each case as one task on a Dask cluster: its scheduler's address or scheduler file "
                        "(workers started with --resources \"cores=N\" run a case only where --np cores are free)")
    s.set_defaults(func=_cmd_sweep)
    t = csub.add_parser("thin-films", help="evaluate the thin-film terms of finished cases again (after a change of "
                                           "the thin-film model) and rewrite their results.json; the CFD's figures stay")
    t.add_argument("case", nargs="+", help="case folder of a finished kegel cfd run")
    common(t)
    t.set_defaults(func=_cmd_thin_films)
    c = csub.add_parser("check-solvers", help="rotation check of the rebuilt OpenFOAM solvers")
    c.add_argument("--stock", action="store_true", help="also check Debian's binaries (interFoam fails)")
    common(c)
    c.set_defaults(func=_cmd_check_solvers)
    v = csub.add_parser("validate", help="cases with published answers through the CFD pipeline: Taylor-Couette torque, "
                                         "rotating-tank free surface, cylinder rolling near a wall, rotor-stator cavity, disc dipped in an oil bath")
    v.add_argument("--case", action="append", choices=VALIDATE_CASES,
                   help="run only this case (repeatable; default: all but immersed_disc, which runs only when named)")
    common(v)
    v.set_defaults(func=_cmd_validate)
