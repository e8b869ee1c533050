"""CFD speed against error: the flooded 32208 at 2000 rpm and 50 degC on each mesh level.

Runs (or, when the case folder exists, resumes and re-reads) the flooded case at each level on
2 cores and reports cells, meshing time, solver runtime, time per iteration and the torques,
with the deviation from the finest level that was run. Not part of ``make bench`` (the small
level takes about 15 minutes); run it as

    .venv/bin/python benchmarks/cfd_mesh_levels.py [tiny small ...]

With three or more levels, the three finest give the Richardson extrapolation and the grid
convergence index of the loss torque, the inner ring's torque and the angular-momentum balance
(:mod:`kegel.cfd_cases.richardson`, Celik et al. 2008).

Output: benchmarks/results/cfd_mesh_levels.json and .png. The case folders are the ones
``kegel cfd run`` uses (results/cfd/32208_2000rpm_flooded_50C_<level>, not kept in git), so
cases already run are resumed and only re-read.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent


def main(levels: list[str]) -> int:
    from kegel.cfd_cases.run import CfdPoint, run_case
    from kegel.io import atomic_write_json

    rows = []
    for level in levels:
        p = CfdPoint(bearing="32208", speed_rad_s=2000 * math.pi / 30, temperature_K=323.15,
                     oil_level_m=None, mesh=level, n_procs=2, max_iterations=1000)
        case = REPO / "results" / "cfd" / f"32208_2000rpm_flooded_50C_{level}"  # as kegel cfd run names it
        run_case(p, case, progress=False, log=lambda s: print(s, file=sys.stderr))
        data = json.loads((case / "results.json").read_text())
        meta = json.loads((case / "kegel-case.json").read_text())
        it = data["iterations"]
        rows.append({"level": level, "cells": data["fidelity"]["cells"], "mesh_time_s": meta["mesh_time_s"],
                     "runtime_s": data["runtime_s"], "iterations": it,
                     "s_per_iteration": data["runtime_s"] / max(it, 1),
                     "inner_ring_Nm": data["torques_Nm"]["inner_ring"]["total"],
                     "loss_torque_Nm": data["loss_torque_at_shaft_Nm"], "steady": data["steady"],
                     "angular_momentum_balance": data["angular_momentum_balance"]["relative_to_drive_torque"]})
    ref = rows[-1]
    for r in rows:
        r["deviation_inner_ring"] = r["inner_ring_Nm"] / ref["inner_ring_Nm"] - 1
        r["deviation_loss_torque"] = r["loss_torque_Nm"] / ref["loss_torque_Nm"] - 1
    richardson = {}
    if len(rows) >= 3:
        from kegel.cfd_cases.richardson import richardson_three_levels

        three = rows[-3:][::-1]  # finest first
        for key in ("loss_torque_Nm", "inner_ring_Nm", "angular_momentum_balance"):
            try:
                richardson[key] = richardson_three_levels([r[key] for r in three], [r["cells"] for r in three]).as_dict()
            except ValueError as exc:
                richardson[key] = {"error": str(exc)}
    out = HERE / "results"
    out.mkdir(exist_ok=True)
    import kegel
    from kegel.io import provenance

    atomic_write_json(out / "cfd_mesh_levels.json", {
        "command": "benchmarks/cfd_mesh_levels.py " + " ".join(levels), "point": "32208, FVA 3, 50 degC, 2000 rpm, flooded",
        "reference_level": ref["level"], "rows": rows, "richardson": richardson,
        "kegel_version": kegel.__version__, "provenance": provenance()})
    print(f"{'level':<7}{'cells':>9}{'mesh s':>8}{'run s':>8}{'s/it':>7}{'iters':>7}"
          f"{'M_IR mN m':>11}{'loss mN m':>11}{'dev loss':>10}{'balance':>9}")
    for r in rows:
        print(f"{r['level']:<7}{r['cells']:>9}{r['mesh_time_s']:>8.1f}{r['runtime_s']:>8.0f}{r['s_per_iteration']:>7.2f}"
              f"{r['iterations']:>7.0f}{1e3 * r['inner_ring_Nm']:>11.2f}{1e3 * r['loss_torque_Nm']:>11.2f}"
              f"{100 * r['deviation_loss_torque']:>9.1f}%{100 * r['angular_momentum_balance']:>8.1f}%")
    for key, rr in richardson.items():
        if "error" in rr:
            print(f"Richardson {key}: {rr['error']}")
            continue
        print(f"Richardson {key}: finest {rr['phi'][0]:.5g}, extrapolated {rr['phi_extrapolated']:.5g}, apparent order "
              f"{rr['apparent_order']:.3g} ({rr['convergence']}), GCI_fine {100 * rr['gci_fine']:.2f} % "
              f"(+-{rr['uncertainty']:.3g}){'; ' + '; '.join(rr['notes']) if rr['notes'] else ''}")
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6, 4), constrained_layout=True)
        ax.plot([r["runtime_s"] for r in rows], [100 * abs(r["deviation_loss_torque"]) for r in rows], "o-")
        for r in rows:
            ax.annotate(f"{r['level']} ({r['cells'] // 1000} k cells)", (r["runtime_s"], 100 * abs(r["deviation_loss_torque"])))
        ax.set_xlabel("solver runtime on 2 cores (s)")
        ax.set_ylabel(f"|deviation of the loss torque| from '{ref['level']}' (%)")
        ax.set_title("flooded 32208, 2000 rpm, 50 degC", fontsize=9)
        fig.savefig(out / "cfd_mesh_levels.png", dpi=120)
    except ImportError:
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:] or ["tiny", "small"]))
