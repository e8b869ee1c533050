"""CFD modelling choices that could move the flooded loss, each measured on the whole bearing's
tiny mesh of the flooded 32208 at 2000 rpm and 50 degC (real rollers, contacts opened by the
default slab g = 0.08 D_w) against the reference tiny run (MRF in the cage frame, housing side
walls at 0.25 T = 6.19 mm):

- frame: no MRF, the same frozen geometry in the inertial frame with the walls' absolute
  velocities (``--frame absolute``);
- housing wall distance: half and twice the default (``--housing-clearance``);
- the cage's presence: the same bearing without its cage (``--no-cage``; its space is oil).

The whole bearing, not the sector, because the inertial frame has no repeating sector. Runs (or,
when a case folder exists, resumes and re-reads) each case on 2 cores:

    .venv/bin/python benchmarks/cfd_modelling_choices.py
    .venv/bin/python benchmarks/cfd_modelling_choices.py --only no_cage --np 1

``--only KEY`` runs the named cases and keeps the other rows of the stored JSON as they are
(each row records its own kegel version and core count).

Output: benchmarks/results/cfd_modelling_choices.json (loss torque, its deviation from the
reference, the angular-momentum balance, runtime; the command and kegel version). The same
checks of the old geometry (rollers shrunk by 0.8 mm) are kept in
benchmarks/results/cfd_shrunk_rollers/cfd_modelling_choices.json.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent



def _default_housing_m() -> float:
    """The 32208's housing side-wall distance by default (0.25 T = 6.19 mm)."""
    from kegel.cfd_cases.geometry import HOUSING_CLEARANCE_RATIO
    from kegel.model.data import load_bearing

    return HOUSING_CLEARANCE_RATIO * load_bearing("32208").total_width_m


_DEFAULT_HOUSING_M = _default_housing_m()
CASES = [  # key, label, CfdPoint settings, case folder
    ("reference", "reference (MRF, housing 0.25 T)", {}, "results/cfd/choices/reference_tiny"),
    ("frame_absolute", "no MRF (inertial frame)", {"frame": "absolute"}, "results/cfd/choices/frame_absolute_tiny"),
    ("housing_half", "housing walls at 0.125 T", {"housing_clearance_m": 0.5 * _DEFAULT_HOUSING_M},
     "results/cfd/choices/housing_half_tiny"),
    ("housing_double", "housing walls at 0.5 T", {"housing_clearance_m": 2.0 * _DEFAULT_HOUSING_M},
     "results/cfd/choices/housing_double_tiny"),
    ("no_cage", "without the cage", {"cage": False}, "results/cfd/choices/no_cage_tiny"),
]
OUT = HERE / "results" / "cfd_modelling_choices.json"


def main(argv: list[str] | None = None) -> int:
    import argparse

    import kegel
    from kegel.cfd_cases.run import CfdPoint, run_case
    from kegel.io import atomic_write_json, provenance

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", action="append", choices=[c[0] for c in CASES],
                    help="run only this case (repeatable); the other rows are kept from the stored JSON")
    ap.add_argument("--np", type=int, default=2, help="MPI processes per case (default 2)")
    args = ap.parse_args(argv)
    stored = {r.get("key", r["case"]): r for r in json.loads(OUT.read_text())["rows"]} if OUT.is_file() else {}
    stored = {next((c[0] for c in CASES if c[1] == k), k): r for k, r in stored.items()}  # rows stored by label
    rows = []
    for key, label, extra, folder in CASES:
        if args.only and key not in args.only:
            if key in stored:
                rows.append({**stored[key], "key": key})
            continue
        p = CfdPoint(bearing="32208", speed_rad_s=2000 * math.pi / 30, temperature_K=323.15, oil_level_m=None,
                     mesh="tiny", n_procs=args.np, max_iterations=2000, **extra)
        case = REPO / folder
        run_case(p, case, progress=False, log=lambda s: print(s, file=sys.stderr))
        data = json.loads((case / "results.json").read_text())
        t = data["torques_Nm"]
        rows.append({"key": key, "case": label, "settings": extra, "folder": folder, "n_procs": args.np,
                     "kegel_version": kegel.__version__, "cells": data["fidelity"]["cells"],
                     "runtime_s": data["runtime_s"], "iterations": data["iterations"], "steady": data["steady"],
                     "loss_torque_Nm": data["loss_torque_at_shaft_Nm"],
                     "inner_ring_Nm": t["inner_ring"]["total"], "outer_ring_Nm": t["outer_ring"]["total"],
                     "cage_Nm": t["cage"]["total"],
                     "angular_momentum_balance": data["angular_momentum_balance"]["relative_to_drive_torque"]})
    if not rows or rows[0]["key"] != "reference":
        raise SystemExit("the reference row is neither stored nor run: run without --only first")
    ref = rows[0]["loss_torque_Nm"]
    for r in rows:
        r["deviation_from_reference"] = r["loss_torque_Nm"] / ref - 1.0
    atomic_write_json(OUT, {
        "command": " ".join(["benchmarks/cfd_modelling_choices.py", *(sys.argv[1:] if argv is None else argv)]), "point": "32208, FVA 3, 50 degC, 2000 rpm, flooded, tiny, whole bearing, real rollers, g = 0.08 D_w",
        "rows": rows, "kegel_version": kegel.__version__, "provenance": provenance()})
    print(f"{'case':<34}{'loss mN m':>10}{'vs ref':>9}{'IR mN m':>9}{'OR mN m':>9}{'cage':>7}{'balance':>9}{'run s':>7}")
    for r in rows:
        print(f"{r['case']:<34}{1e3 * r['loss_torque_Nm']:>10.2f}{100 * r['deviation_from_reference']:>8.1f}%"
              f"{1e3 * r['inner_ring_Nm']:>9.2f}{1e3 * r['outer_ring_Nm']:>9.2f}{1e3 * r['cage_Nm']:>7.2f}"
              f"{100 * r['angular_momentum_balance']:>8.1f}%{r['runtime_s']:>7.0f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
