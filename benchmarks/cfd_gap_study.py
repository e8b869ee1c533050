"""The contact / CFD split, proved by a gap study: the flooded 32208 at 2000 rpm, 50 degC.

The CFD opens each raceway line contact to a gap ``g`` (the raceways set back by ``g`` from the
real rollers, kegel.cfd_cases.geometry); the contact model owns the film below ``g`` (its rolling
force cut off where the film reaches ``g``). The split is right when contact + CFD stops depending
on ``g``. This script runs (or, when a case folder exists, resumes and re-reads) the flooded case
at each ``g / D_w`` as a one-pitch sector (periodic sides; the flooded flow repeats from pocket to
pocket in the cage frame) with ``--cells`` cells across the narrowest point of each gap, and
writes the CFD loss, its cost and, where kegel's contact model offers the cut-off, the contact
loss at the same ``g`` and the sum against ``1 / sqrt(g)``.

    .venv/bin/python benchmarks/cfd_gap_study.py [--gaps 0.08 0.04 0.02 0.01] [--cells 3] [--mesh tiny]
    .venv/bin/python benchmarks/cfd_gap_study.py --check-sector   # sector against the whole bearing

Case folders: results/cfd/gap_study/<case> (not kept in git; a run interrupted by the end of a
session resumes from its latest iteration). Output: benchmarks/results/cfd_gap_study.json and
each case's results.json under benchmarks/results/cfd_gap_study/<case>/ (rewritten after every
case, so a partial study is kept).
"""

from __future__ import annotations

import argparse
import functools
import json
import math
import shutil
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
CASES = REPO / "results" / "cfd" / "gap_study"
OUT = HERE / "results" / "cfd_gap_study.json"
STORE = HERE / "results" / "cfd_gap_study"

SPEED_RPM = 2000.0
TEMPERATURE_K = 323.15
AXIAL_LOAD_N = 1000.0   # the seed's Figure 9 point (32208, Fa = 1 kN)


def case_name(gap: float, cells: int, mesh: str, sector: bool, speed_rpm: float = SPEED_RPM) -> str:
    return f"32208_{speed_rpm:g}rpm_flooded_50C_{mesh}_g{gap:g}_n{cells}" + ("_sector" if sector else "_full")


def contact_loss_Nm(gap_m: float, axial_load_N: float = AXIAL_LOAD_N) -> dict:
    """kegel's contact friction torque of the study point with the rolling force cut off at a
    film height of ``gap_m`` (kegel.runner.film_limit.contact_loss_at_film_limit)."""
    from kegel.runner.film_limit import contact_loss_at_film_limit  # the contact side of the split

    r = contact_loss_at_film_limit(gap_m, bearing="32208", speed=f"{SPEED_RPM:g} rpm",
                                   axial_load=f"{axial_load_N:g} N", temperature=f"{TEMPERATURE_K - 273.15:g} degC",
                                   oil_level="flooded")
    return {k: r[k] for k in ("friction_torque_Nm", "ehl_rolling_torque_Nm", "converged") if k in r}


@functools.lru_cache(maxsize=None)
def _study_point(axial_load_N: float = AXIAL_LOAD_N):
    """The study point's geometry, loaded lengths and oil viscosity (solved once per process and
    load)."""
    from kegel.model.data import load_bearing, load_material
    from kegel.model.geometry import derive_geometry
    from kegel.model.lubricant import lubricant_state
    from kegel.solutions.quasi_static import load_distribution

    b, m = load_bearing("32208"), load_material("bearing_steel")
    g = derive_geometry(b, m)
    loaded = load_distribution(g, b, m, axial_N=axial_load_N).loaded_length_m
    return g, loaded, lubricant_state("FVA3", TEMPERATURE_K).dynamic_viscosity_Pas


def unloaded_wedge_Nm(gap_m: float, speed_rpm: float = SPEED_RPM, axial_load_N: float = AXIAL_LOAD_N) -> dict:
    """The CFD's far field beyond ``gap_m`` on the unloaded stretch of the raceway lines at the
    study point's load distribution (kegel.coupling.split.unloaded_line_wedge): what contact +
    CFD counts that the contact model's convention does not; ``whole_line_Nm`` the same over the
    whole lines."""
    from kegel.coupling.split import unloaded_line_wedge

    g, loaded, eta = _study_point(axial_load_N)
    w = unloaded_line_wedge(g, viscosity_Pas=eta, inner_speed_rad_s=speed_rpm * math.pi / 30,
                            loaded_length_m=loaded, film_limit_m=gap_m)
    whole = unloaded_line_wedge(g, viscosity_Pas=eta, inner_speed_rad_s=speed_rpm * math.pi / 30,
                                loaded_length_m=0.0 * loaded, film_limit_m=gap_m)
    return {**w.as_dict(), "whole_line_Nm": whole.torque_Nm}


def loads_table(loads_N: list[float]) -> list[dict]:
    """The split at other axial loads with the stored CFD losses (the CFD's geometry does not
    depend on the load): contact + CFD - wedge over the 3-cell tiny gaps, and its spread with
    and without the wedge. Printed as docs/cfd.md's table "At other loads"."""
    rows = sorted((r for r in json.loads(OUT.read_text())["rows"]
                   if r["sector"] and r["cells_across_gap"] == 3 and r["mesh"] == "tiny"), key=lambda r: -r["gap_ratio"])
    out = []
    for F in loads_N:
        raw = [contact_loss_Nm(r["gap_m"], F)["friction_torque_Nm"] + r["cfd_loss_Nm"] for r in rows]
        sums = [x - unloaded_wedge_Nm(r["gap_m"], axial_load_N=F)["torque_Nm"] for x, r in zip(raw, rows)]
        g, loaded, _ = _study_point(F)
        spread = lambda v: (max(v) - min(v)) / (sum(v) / len(v))  # noqa: E731
        out.append({"axial_load_N": F, "loaded_share": float(loaded[0, 0] / g.roller_length_m), "sums_Nm": sums,
                    "spread": spread(sums), "spread_without_wedge": spread(raw)})
        print(f"| {F:g} N | {100 * out[-1]['loaded_share']:.0f} % | {' / '.join(f'{1e3 * x:.1f}' for x in sums)} | "
              f"{100 * out[-1]['spread']:.2f} % | {100 * out[-1]['spread_without_wedge']:.1f} % |", flush=True)
    return out


def run_one(gap: float, cells: int, mesh: str, sector: bool, n_procs: int, max_iterations: int = 1500,
            speed_rpm: float = SPEED_RPM, cases: Path = CASES, store: Path = STORE) -> dict:
    """Run (or resume) one flooded case of the study point at ``speed_rpm`` in ``cases`` and copy
    its results.json into the repository (``store``); its row (``cfd_cases.run`` figures)."""
    from kegel.cfd_cases.run import CfdPoint, run_case

    p = CfdPoint(bearing="32208", speed_rad_s=speed_rpm * math.pi / 30, temperature_K=TEMPERATURE_K,
                 oil_level_m=None, mesh=mesh, n_procs=n_procs, max_iterations=max_iterations, gap_ratio=gap,
                 cells_across_gap=cells, sector=sector)
    case = cases / case_name(gap, cells, mesh, sector, speed_rpm)
    t0 = time.monotonic()
    run_case(p, case, progress=True, log=lambda s: print(s, file=sys.stderr, flush=True))
    data = json.loads((case / "results.json").read_text())
    meta = json.loads((case / "kegel-case.json").read_text())
    dest = store / case.name
    dest.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(case / "results.json", dest / "results.json")
    t = data["torques_Nm"]
    return {"case": case.name, "gap_ratio": gap, "gap_m": meta["geometry"]["gap_m"], "cells_across_gap": cells,
            "mesh": mesh, "sector": sector, "cells": data["fidelity"]["cells"], "mesh_time_s": meta["mesh_time_s"],
            "runtime_s": data["runtime_s"], "iterations": data["iterations"], "steady": data["steady"],
            "session_wall_s": time.monotonic() - t0,
            "cfd_loss_Nm": data["loss_torque_at_shaft_Nm"],
            "inner_ring_Nm": t["inner_ring"]["total"], "outer_ring_Nm": t["outer_ring"]["total"],
            "cage_Nm": t["cage"]["total"], "rollers_spin_sum_Nm": t["rollers_spin_sum"]["total"],
            "angular_momentum_balance": data["angular_momentum_balance"]["relative_to_drive_torque"]}


def write(rows: list[dict], command: str, note: str) -> None:
    import kegel
    from kegel.io import atomic_write_json, provenance

    for r in rows:
        c = contact_loss_Nm(r["gap_m"])
        r["contact"] = c
        r["unloaded_line_wedge"] = wdg = unloaded_wedge_Nm(r["gap_m"])
        if c is not None:
            r["sum_Nm"] = r["cfd_loss_Nm"] + c["friction_torque_Nm"]
            # the sum at kegel's contact convention: less the CFD's far field on the unloaded stretch
            r["sum_consistent_Nm"] = r["sum_Nm"] - wdg["torque_Nm"]
        r["inv_sqrt_gap"] = 1.0 / math.sqrt(r["gap_ratio"])
    OUT.parent.mkdir(exist_ok=True)
    atomic_write_json(OUT, {"command": command, "point": "32208, FVA 3, 50 degC, 2000 rpm, flooded, Fa = 1 kN",
                            "note": note, "rows": rows, "kegel_version": kegel.__version__,
                            "provenance": provenance()})
    plot(rows, OUT.with_suffix(".png"))


def plot(rows: list[dict], path: Path) -> None:
    """CFD, contact and their sum against 1/sqrt(g / D_w) (the tiny 3-cell sectors), and the
    other discretisations of the mesh study as markers (their sums in grey)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from kegel.outputs.plots import save_figure

    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    # the gap study: the tiny background with 3 cells across each gap, contact and sum with it
    sel = sorted((r for r in rows if r["sector"] and r["cells_across_gap"] == 3 and r["mesh"] == "tiny"),
                 key=lambda r: r["inv_sqrt_gap"])
    x = [r["inv_sqrt_gap"] for r in sel]
    ax.plot(x, [1e3 * r["cfd_loss_Nm"] for r in sel], "o-", label="CFD (tiny, 3 cells across)")
    with_contact = [r for r in sel if r.get("contact")]
    if with_contact:
        xc = [r["inv_sqrt_gap"] for r in with_contact]
        ax.plot(xc, [1e3 * r["contact"]["friction_torque_Nm"] for r in with_contact], "s--",
                label="contact friction, cut at g")
        ax.plot(xc, [1e3 * r["sum_Nm"] for r in with_contact], "D:", color="0.5", label="contact + CFD")
        ax.plot(xc, [1e3 * r["sum_consistent_Nm"] for r in with_contact], "D-",
                label="contact + CFD - far field on the unloaded stretch")
    # the mesh study at the default gap: the other discretisations, as markers
    marks = {("tiny", 6): "^", ("small", 3): "v", ("fine", 3): "P"}
    colours = {("tiny", 6): "C4", ("small", 3): "C3", ("fine", 3): "C5"}
    labelled: set = set()
    for r in rows:
        key = (r["mesh"], r["cells_across_gap"])
        if r["sector"] and key in marks:
            ax.plot([r["inv_sqrt_gap"]], [1e3 * r["cfd_loss_Nm"]], marks[key], ms=7, color=colours[key],
                    label=None if key in labelled else f"CFD ({key[0]}, {key[1]} cells across)")
            labelled.add(key)
            if r.get("sum_consistent_Nm") is not None:
                ax.plot([r["inv_sqrt_gap"]], [1e3 * r["sum_consistent_Nm"]], marks[key], ms=7, color="0.4")
    ax.set_xlabel("1 / sqrt(g / D_w)")
    ax.set_ylabel("torque at the shaft [mN m]")
    ax.set_title("32208 flooded, 2000 rpm, 50 degC, 1 kN: the contact / CFD split")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save_figure(fig, path)  # atomic, the temporary file removed on failure
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--gaps", type=float, nargs="+", default=[0.08, 0.04, 0.02, 0.01])
    ap.add_argument("--cells", type=int, default=3)
    ap.add_argument("--mesh", default="tiny")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--max-iterations", type=int, default=1500,
                    help="SIMPLE iterations at most (default 1500); a case resumes from its latest state")
    ap.add_argument("--report", action="store_true", help="only re-read the stored rows: contact losses and plot")
    ap.add_argument("--loads", type=float, nargs="+", default=None, metavar="N",
                    help="only print the split at these axial loads [N] with the stored CFD losses")
    ap.add_argument("--check-sector", action="store_true",
                    help="run g = 0.08 with one cell across as a sector and as the whole bearing")
    args = ap.parse_args(argv)
    command = "benchmarks/cfd_gap_study.py " + " ".join(sys.argv[1:] if argv is None else argv)
    rows: list[dict] = []
    previous = json.loads(OUT.read_text()).get("rows", []) if OUT.is_file() else []
    if args.loads:
        loads_table(args.loads)
        return 0
    if args.report:
        write(previous, json.loads(OUT.read_text())["command"] if OUT.is_file() else command,
              "rows of earlier invocations are kept; each row names its case")
        return 0
    if args.check_sector:
        plan = [(0.08, 1, args.mesh, True), (0.08, 1, args.mesh, False)]
    else:
        plan = [(g, args.cells, args.mesh, True) for g in args.gaps]
    for gap, cells, mesh, sector in plan:
        rows.append(run_one(gap, cells, mesh, sector, args.np, args.max_iterations))
        keep = [r for r in previous if r["case"] not in {x["case"] for x in rows}]
        write(sorted(keep + rows, key=lambda r: (not r["sector"], r["cells_across_gap"], -r["gap_ratio"])), command,
              "rows of earlier invocations are kept; each row names its case")
        r = rows[-1]
        print(f"g/Dw {r['gap_ratio']:<6g} n {r['cells_across_gap']} {'sector' if r['sector'] else 'full  '} "
              f"cells {r['cells']:>8} run {r['runtime_s']:>7.0f} s  CFD loss {1e3 * r['cfd_loss_Nm']:.2f} mN m  "
              f"balance {100 * r['angular_momentum_balance']:+.1f} %", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
