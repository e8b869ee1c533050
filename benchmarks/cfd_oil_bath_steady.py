"""CFD speed against error at steady state: the oil bath's Courant limit, run to a steady loss torque.

``cfd_oil_bath_courant.py`` compares the limits on the first 7.5 ms of the start-up, where a
time-step error shows as a time shift. What a user reads is the steady loss torque, reached after
tenths of a second. This runs the tiny 32208 point (2000 rpm, 50 degC, oil to the shaft centre,
2 cores, from rest) to the runner's steady test at each limit and reports, side by side, the solver
runtime, the simulated time to steady, the steady loss torque at the shaft and its deviation from
the first setting (the smallest limit given: the finest fidelity of the comparison).

    .venv/bin/python benchmarks/cfd_oil_bath_steady.py [--work DIR] [5/1 10/3 ...]

Each argument is ``max_courant/max_interface_courant``. Cases go to ``DIR/co_<a>_<b>`` (default: a
temporary folder, removed afterwards); a case there that already holds a steady ``results.json``
of the same point is reported as it is (so a run of ``kegel cfd run ... --output DIR/co_5_1``
counts). Not part of ``make bench``: 13 min at 10/3 on 2 cores (steady after 0.308 s, measured
once) and, by the start-up benchmark's step counts, about three times that at 5/1 (an estimate;
not yet run to the end). Output: benchmarks/results/cfd_oil_bath_steady.json.
"""

from __future__ import annotations

import argparse
import json
import math
import shutil
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent


def _row(case: Path) -> dict:
    d = json.loads((case / "results.json").read_text())
    drift = d["loss_torque_drift"]
    return {"max_courant": d["fidelity"]["max_courant"], "max_interface_courant": d["fidelity"]["max_interface_courant"],
            "cells": d["fidelity"]["cells"], "solver_runtime_s": d["runtime_s"], "steady": d["steady"],
            "simulated_time_s": d["simulated_time_s"], "loss_torque_Nm": d["loss_torque_at_shaft_Nm"],
            "remaining_change_Nm": drift.get("remaining_change_Nm"),
            "inner_ring_Nm": d["torques_Nm"]["inner_ring"]["total"],
            "outer_ring_Nm": d["torques_Nm"]["outer_ring"]["total"], "cage_Nm": d["torques_Nm"]["cage"]["total"],
            "kegel_version": d["provenance"].get("kegel_version"), "case": str(case)}


def main(argv: list[str]) -> int:
    from kegel.cfd_cases.run import CfdPoint, run_case
    from kegel.data import load_bearing
    from kegel.io import atomic_write_json

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--work", help="folder for the cases (kept); default: a temporary folder")
    ap.add_argument("settings", nargs="*", default=["5/1", "10/3"])
    args = ap.parse_args(argv)
    level = 0.5 * load_bearing("32208").outer_diameter_m
    work = Path(args.work) if args.work else Path(tempfile.mkdtemp(prefix="kegel-steady-"))
    rows = []
    try:
        for s in args.settings:
            co, alpha_co = (float(x) for x in s.split("/"))
            case = work / f"co_{co:g}_{alpha_co:g}"
            done = case / "results.json"
            if not (done.is_file() and json.loads(done.read_text()).get("steady")):
                p = CfdPoint(bearing="32208", speed_rad_s=2000 * math.pi / 30, temperature_K=323.15,
                             oil_level_m=level, mesh="tiny", n_procs=2, max_courant=co, max_interface_courant=alpha_co)
                run_case(p, case, progress=False, log=lambda m: print(m, file=sys.stderr))
            row = _row(case)
            if (row["max_courant"], row["max_interface_courant"]) != (co, alpha_co):
                raise SystemExit(f"{case}: a run at Courant {row['max_courant']}/{row['max_interface_courant']}, "
                                 f"expected {co:g}/{alpha_co:g}")
            rows.append(row)
    finally:
        if not args.work:
            shutil.rmtree(work, ignore_errors=True)
    ref = rows[0]
    for r in rows:
        r["deviation"] = r["loss_torque_Nm"] / ref["loss_torque_Nm"] - 1
        r["speed_up"] = ref["solver_runtime_s"] / r["solver_runtime_s"]
    out = HERE / "results"
    out.mkdir(exist_ok=True)
    atomic_write_json(out / "cfd_oil_bath_steady.json", {"reference": args.settings[0], "rows": rows})
    print("tiny 32208 oil bath to a steady loss torque; deviation from the first row")
    print(f"{'Co/alphaCo':<11}{'cells':>8}{'run s':>8}{'speed-up':>9}{'steady at s':>12}{'loss mN m':>11}{'deviation':>11}"
          f"{'inner':>8}{'outer':>8}{'cage':>8}")
    for r in rows:
        print(f"{r['max_courant']:g}/{r['max_interface_courant']:<7g}{r['cells']:>8}{r['solver_runtime_s']:>8.0f}"
              f"{r['speed_up']:>9.1f}{r['simulated_time_s']:>12.3f}{1e3 * r['loss_torque_Nm']:>11.2f}"
              f"{100 * r['deviation']:>+10.1f}%{1e3 * r['inner_ring_Nm']:>8.2f}{1e3 * r['outer_ring_Nm']:>8.2f}"
              f"{1e3 * r['cage_Nm']:>8.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
