"""The three answers with the real rollers: flooded 32208, FVA 3 at 50 degC, Fa = 1 kN, over speed.

For each speed: contact + CFD (the contact's rolling force cut off where the film reaches the
gap g that the CFD opens, :func:`kegel.runner.film_limit.contact_loss_at_film_limit`, plus the CFD loss of a
flooded one-pitch sector at g with ``--cells`` cells across each gap, less the CFD's far field on
the unloaded stretch of the lines (:mod:`kegel.coupling.split`), plus the analytic thin-film
terms of the films thinner than the CFD's clearance), contact + Liebrecht and
contact + SKF drag (the uncut flooded contact, the correlation's whole hydraulic loss). The CFD
cases are run as the gap study runs its own (``benchmarks/cfd_gap_study.run_one``, the same names)
but in their own folders: the gap study's stored rows are a record of runs started from oil at
rest, these of the runner's present start (the oil turning with the cage; docs/cfd.md, "Every
wall, and where the oil starts"). Every case resumes where a session left it. The four cases'
results.json are what ``benchmarks/collect_cfd_results.py`` ships as the flooded results
(``benchmarks/results/cfd``).

    .venv/bin/python benchmarks/cfd_three_answers.py [--speeds 500 1000 2000 4000] [--gap 0.08] [--cells 3] [--max-iterations 1500]
    .venv/bin/python benchmarks/cfd_three_answers.py --report     # re-read the stored rows

Output: benchmarks/results/cfd_three_answers.{json,png} (rewritten after every speed; rows of
earlier invocations are kept) and each case's results.json under
benchmarks/results/cfd_three_answers/<case>/ (the case folders: results/cfd/three_answers/).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from cfd_gap_study import AXIAL_LOAD_N, TEMPERATURE_K, run_one, unloaded_wedge_Nm  # noqa: E402  (one study point)

OUT = HERE / "results" / "cfd_three_answers.json"
CASES = HERE.parent / "results" / "cfd" / "three_answers"
STORE = HERE / "results" / "cfd_three_answers"


def run_cfd(speed_rpm: float, gap: float, cells: int, mesh: str, n_procs: int, max_iterations: int) -> dict:
    """The gap study's case at this speed (:func:`cfd_gap_study.run_one`), as a row of this table."""
    r = run_one(gap, cells, mesh, True, n_procs, max_iterations, speed_rpm=speed_rpm, cases=CASES, store=STORE)
    return {k: r[k] for k in ("case", "gap_m", "cells", "runtime_s", "iterations", "steady", "cfd_loss_Nm",
                              "angular_momentum_balance")}


def correlations_and_contact(speed_rpm: float, gap_m: float, oil_level: str = "flooded") -> dict:
    """Contact friction cut at g and uncut, and Liebrecht's and SKF's hydraulic losses, at
    ``oil_level`` (``flooded`` or ``shaft_center``; the contacts' supply follows it)."""
    import kegel
    from kegel.runner.film_limit import contact_loss_at_film_limit

    kw = dict(bearing="32208", speed=f"{speed_rpm:g} rpm", axial_load=f"{AXIAL_LOAD_N:g} N",
              temperature=f"{TEMPERATURE_K - 273.15:g} degC", oil_level=oil_level)
    cut = contact_loss_at_film_limit(gap_m, **kw)
    uncut = contact_loss_at_film_limit(0.0, **kw)
    hyd = {}
    for method in ("liebrecht", "skf"):
        r = kegel.Bearing("32208").friction(speed=f"{speed_rpm:g} rpm", axial_load=f"{AXIAL_LOAD_N:g} N",
                                            temperature=f"{TEMPERATURE_K - 273.15:g} degC",
                                            lubrication=oil_level, hydraulic=method)
        hyd[method] = float(r.hydraulic_torque_Nm)
    return {"contact_cut_at_g_Nm": cut["friction_torque_Nm"], "contact_uncut_Nm": uncut["friction_torque_Nm"],
            "liebrecht_Nm": hyd["liebrecht"], "skf_drag_Nm": hyd["skf"]}


def thin_films_Nm(row: dict) -> float:
    """The analytic thin-film terms of a row's CFD case (roller end / rib film and pockets at
    their real clearances, :mod:`kegel.cfd_cases.thin_films`): from its results.json, or computed
    for a case run before they were written there."""
    from kegel.cfd_cases.run import CfdPoint, thin_film_json

    case = CASES / row["case"]
    data = json.loads((STORE / row["case"] / "results.json").read_text())
    if data.get("thin_film_loss_Nm") is not None:
        return float(data["thin_film_loss_Nm"])
    p = CfdPoint(bearing="32208", speed_rad_s=row["speed_rpm"] * math.pi / 30, temperature_K=TEMPERATURE_K,
                 oil_level_m=None, mesh=row["mesh"], gap_ratio=row["gap_ratio"],
                 cells_across_gap=row["cells_across_gap"], sector=True)
    meta = json.loads((case / "kegel-case.json").read_text())
    return float(thin_film_json(p, meta)["loss_torque_Nm"])


def write(rows: list[dict], command: str) -> None:
    import kegel
    from kegel.io import atomic_write_json, provenance

    for r in rows:
        if "thin_films_Nm" not in r:
            r["thin_films_Nm"] = thin_films_Nm(r)
        # the contact side afresh (the cut's law may have changed since the CFD ran), and the CFD's
        # far field on the unloaded stretch of the lines, which the contact convention does not count
        r.update(correlations_and_contact(r["speed_rpm"], r["gap_m"]))
        r["unloaded_line_wedge_Nm"] = unloaded_wedge_Nm(r["gap_m"], r["speed_rpm"])["torque_Nm"]
        r.pop("contact_plus_cfd_plus_thin_films_Nm", None)  # the name before the wedge term
        r["contact_plus_cfd_Nm"] = r["contact_cut_at_g_Nm"] + r["cfd_loss_Nm"]
        r["contact_plus_cfd_less_wedge_Nm"] = r["contact_plus_cfd_Nm"] - r["unloaded_line_wedge_Nm"]
        r["contact_plus_cfd_less_wedge_plus_thin_films_Nm"] = r["contact_plus_cfd_less_wedge_Nm"] + r["thin_films_Nm"]
        r["contact_plus_liebrecht_Nm"] = r["contact_uncut_Nm"] + r["liebrecht_Nm"]
        r["contact_plus_skf_Nm"] = r["contact_uncut_Nm"] + r["skf_drag_Nm"]
    atomic_write_json(OUT, {"command": command, "point": "32208, FVA 3, 50 degC, flooded, Fa = 1 kN",
                            "rows": rows, "kegel_version": kegel.__version__, "provenance": provenance()})
    plot(rows, OUT.with_suffix(".png"))


def plot(rows: list[dict], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from kegel.outputs.plots import save_figure

    rows = sorted(rows, key=lambda r: r["speed_rpm"])
    n = [r["speed_rpm"] for r in rows]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(n, [1e3 * r["contact_plus_cfd_less_wedge_plus_thin_films_Nm"] for r in rows], "o-",
            label="contact (cut at g) + CFD - wedge + thin films")
    ax.plot(n, [1e3 * r["contact_plus_cfd_less_wedge_Nm"] for r in rows], "o--", label="contact (cut at g) + CFD - wedge")
    ax.plot(n, [1e3 * r["contact_plus_liebrecht_Nm"] for r in rows], "s--", label="contact + Liebrecht")
    ax.plot(n, [1e3 * r["contact_plus_skf_Nm"] for r in rows], "^--", label="contact + SKF drag")
    ax.plot(n, [1e3 * r["cfd_loss_Nm"] for r in rows], "o:", label="CFD alone (beyond g)")
    ax.set_xlabel("shaft speed [rpm]")
    ax.set_ylabel("torque at the shaft [mN m]")
    ax.set_title("32208 flooded, 50 degC, Fa 1 kN: three answers (real rollers)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save_figure(fig, path)  # atomic, the temporary file removed on failure
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--speeds", type=float, nargs="+", default=[500.0, 1000.0, 2000.0, 4000.0])
    ap.add_argument("--gap", type=float, default=0.08)
    ap.add_argument("--cells", type=int, default=3)
    ap.add_argument("--mesh", default="tiny")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--max-iterations", type=int, default=1500,
                    help="iteration limit of each case (default 1500; from the runner's start the "
                         "default gap's cases pass their steady test within 614-947 iterations)")
    ap.add_argument("--report", action="store_true", help="only re-read the stored rows")
    args = ap.parse_args(argv)
    command = "benchmarks/cfd_three_answers.py " + " ".join(sys.argv[1:] if argv is None else argv)
    previous = json.loads(OUT.read_text()).get("rows", []) if OUT.is_file() else []
    if args.report:
        write(previous, json.loads(OUT.read_text())["command"] if OUT.is_file() else command)
        return 0
    rows: list[dict] = []
    for rpm in args.speeds:
        t0 = time.monotonic()
        r = {"speed_rpm": rpm, "gap_ratio": args.gap, "cells_across_gap": args.cells, "mesh": args.mesh,
             **run_cfd(rpm, args.gap, args.cells, args.mesh, args.np, args.max_iterations)}
        r.update(correlations_and_contact(rpm, r["gap_m"]))
        r["session_wall_s"] = time.monotonic() - t0
        rows.append(r)
        keep = [p for p in previous if p["case"] not in {x["case"] for x in rows}]
        write(sorted(keep + rows, key=lambda x: (x["gap_ratio"], x["cells_across_gap"], x["speed_rpm"])), command)
        print(f"{rpm:6g} rpm  CFD {1e3 * r['cfd_loss_Nm']:.1f} mN m  contact+CFD-wedge {1e3 * r['contact_plus_cfd_less_wedge_Nm']:.1f}  "
              f"contact+Liebrecht {1e3 * r['contact_plus_liebrecht_Nm']:.1f}  contact+SKF {1e3 * r['contact_plus_skf_Nm']:.1f}",
              flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
