"""CFD modelling choices that could move the flooded loss by a factor of two (issue 19, item 3),
each measured on the tiny mesh of the flooded 32208 at 2000 rpm and 50 degC against the
reference tiny run (MRF in the cage frame, housing walls at 0.25 T = 4.9 mm):

- frame: no MRF, the same frozen geometry in the inertial frame with the walls' absolute
  velocities (``--frame absolute``);
- housing wall distance: 2.5 mm and 10 mm instead of 4.9 mm (``--housing-clearance``).

The cage's presence is not varied (the geometry has no cage-less variant); its direct share is
the cage torque times the cage speed in each run's power balance.

Runs (or, when a case folder exists, resumes and re-reads) each case on 2 cores:

    .venv/bin/python benchmarks/cfd_modelling_choices.py

Output: benchmarks/results/cfd_modelling_choices.json (loss torque, its deviation from the
reference, the angular-momentum balance, runtime; the command and kegel version).
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent

CASES = [
    ("reference (MRF, housing 0.25 T)", {}, "results/cfd/32208_2000rpm_flooded_50C_tiny"),
    ("no MRF (inertial frame)", {"frame": "absolute"}, "results/cfd/choices/frame_absolute_tiny"),
    ("housing walls at 2.5 mm", {"housing_clearance_m": 2.5e-3}, "results/cfd/choices/housing_2.5mm_tiny"),
    ("housing walls at 10 mm", {"housing_clearance_m": 10e-3}, "results/cfd/choices/housing_10mm_tiny"),
]


def main() -> int:
    import kegel
    from kegel.cfd_cases.run import CfdPoint, run_case
    from kegel.io import atomic_write_json, provenance

    rows = []
    for label, extra, folder in CASES:
        p = CfdPoint(bearing="32208", speed_rad_s=2000 * math.pi / 30, temperature_K=323.15, oil_level_m=None,
                     mesh="tiny", n_procs=2, max_iterations=2000, **extra)
        case = REPO / folder
        run_case(p, case, progress=False, log=lambda s: print(s, file=sys.stderr))
        data = json.loads((case / "results.json").read_text())
        t = data["torques_Nm"]
        rows.append({"case": label, "settings": extra, "folder": folder, "cells": data["fidelity"]["cells"],
                     "runtime_s": data["runtime_s"], "iterations": data["iterations"], "steady": data["steady"],
                     "loss_torque_Nm": data["loss_torque_at_shaft_Nm"],
                     "inner_ring_Nm": t["inner_ring"]["total"], "outer_ring_Nm": t["outer_ring"]["total"],
                     "cage_Nm": t["cage"]["total"],
                     "angular_momentum_balance": data["angular_momentum_balance"]["relative_to_drive_torque"]})
    ref = rows[0]["loss_torque_Nm"]
    for r in rows:
        r["deviation_from_reference"] = r["loss_torque_Nm"] / ref - 1.0
    atomic_write_json(HERE / "results" / "cfd_modelling_choices.json", {
        "command": "benchmarks/cfd_modelling_choices.py", "point": "32208, FVA 3, 50 degC, 2000 rpm, flooded, tiny",
        "rows": rows, "kegel_version": kegel.__version__, "provenance": provenance()})
    print(f"{'case':<34}{'loss mN m':>10}{'vs ref':>9}{'IR mN m':>9}{'OR mN m':>9}{'cage':>7}{'balance':>9}{'run s':>7}")
    for r in rows:
        print(f"{r['case']:<34}{1e3 * r['loss_torque_Nm']:>10.2f}{100 * r['deviation_from_reference']:>8.1f}%"
              f"{1e3 * r['inner_ring_Nm']:>9.2f}{1e3 * r['outer_ring_Nm']:>9.2f}{1e3 * r['cage_Nm']:>7.2f}"
              f"{100 * r['angular_momentum_balance']:>8.1f}%{r['runtime_s']:>7.0f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
