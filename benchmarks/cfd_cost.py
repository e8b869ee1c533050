"""What a flooded CFD answer costs, beside how far it is from the finest one (issue 29, item 7).

The flooded 32208 at 2000 rpm, 50 degC, 1 kN (the gap study's point), every case of the gap study
that has run (``results/cfd/gap_study/32208_2000rpm_*``: the gaps g / D_w, the cells across each
gap, the background mesh level). For each case, from its own loss history (the loss torque at the
shaft after every SIMPLE iteration, window means of 100 iterations):

- the wall time per iteration on 2 cores (the run's ``runtime_s`` / iterations; the runs shared
  the machine with other work, so read them as upper bounds), and the wall time until the window
  mean stays within 5 % and within 1 % of the run's final loss;
- the CFD loss, and its deviation from the finest discretisation of the same gap (the finest
  background mesh level, then the most cells across each gap);
- contact (cut at g) + CFD less the CFD's far field on the unloaded stretch of the lines, and its
  deviation from the finest gap's total (the quantity that does not depend on where the split
  lies; the contact part and the wedge are computed live, ~1 s).

    .venv/bin/python benchmarks/cfd_cost.py

Output: a Markdown table on stdout and ``benchmarks/results/cfd_cost.json``. The case folders (GB)
stay outside the repository; the table keeps what they gave.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from cfd_gap_study import CASES, contact_loss_Nm, unloaded_wedge_Nm  # noqa: E402  (the study point and its contact part)

OUT = HERE / "results" / "cfd_cost.json"
WINDOW = 100  # iterations, as the flooded steady test


def time_to_within(it: np.ndarray, loss: np.ndarray, final: float, tol: float) -> float | None:
    """The first iteration from which every trailing window mean (``WINDOW`` iterations) stays
    within ``tol`` of ``final``; None when it never does."""
    c = np.concatenate([[0.0], np.cumsum(loss)])
    k = np.arange(WINDOW, len(loss) + 1)
    means = (c[k] - c[k - WINDOW]) / WINDOW
    bad = np.abs(means / final - 1.0) > tol
    if bad[-1]:
        return None
    last_bad = np.nonzero(bad)[0]
    j = 0 if len(last_bad) == 0 else last_bad[-1] + 1
    return float(it[k[j] - 1])


def case_row(case: Path) -> dict | None:
    from kegel.cfd_cases.run import loss_torque_series

    f = case / "results.json"
    if not f.is_file():
        return None
    data = json.loads(f.read_text())
    meta = json.loads((case / "kegel-case.json").read_text())
    pt = data["point"]
    it, loss = loss_torque_series(case, meta)
    loss = loss * meta["geometry"].get("copies", 1)  # a sector's loss for the whole bearing
    final = float(data["loss_torque_at_shaft_Nm"])
    per_it = float(data["runtime_s"]) / float(data["iterations"])
    row = {"case": case.name, "gap_ratio": pt["gap_ratio"], "cells_across_gap": pt["cells_across_gap"],
           "mesh": pt["mesh"], "cells": data["fidelity"]["cells"], "gap_m": meta["geometry"]["gap_m"],
           "iterations": data["iterations"], "runtime_s": data["runtime_s"], "s_per_iteration": per_it,
           "cfd_loss_Nm": final, "steady": data["steady"]}
    for tol in (0.05, 0.01):
        n = time_to_within(it, loss, final, tol)
        row[f"iterations_to_{round(100 * tol)}pct"] = n
        row[f"wall_to_{round(100 * tol)}pct_s"] = None if n is None else n * per_it
    return row


def main() -> int:
    from kegel.io import atomic_write_json, provenance

    rows = [r for c in sorted(CASES.glob("32208_2000rpm_flooded_50C_*_sector")) if (r := case_row(c))]
    if not rows:
        print(f"no finished gap-study case under {CASES}", file=sys.stderr)
        return 1
    contact, wedge = {}, {}
    for r in rows:
        g = r["gap_m"]
        if g not in contact:
            contact[g] = contact_loss_Nm(g)["friction_torque_Nm"]
            wedge[g] = unloaded_wedge_Nm(g)["torque_Nm"]
        r["contact_cut_at_g_Nm"] = contact[g]
        r["unloaded_line_wedge_Nm"] = wedge[g]
        # less the CFD's far field on the unloaded stretch of the lines (kegel.coupling.split)
        r["total_Nm"] = contact[g] + r["cfd_loss_Nm"] - wedge[g]
    # the finest discretisation of a gap: the finest background mesh level, then the most cells
    # across the gaps (two directions of refinement; the table shows both)
    level = {"tiny": 0, "small": 1, "fine": 2}
    finest_mesh = {}
    for r in rows:
        best = finest_mesh.get(r["gap_ratio"])
        key = (level.get(r["mesh"], -1), r["cells_across_gap"])
        if best is None or key > (level.get(best["mesh"], -1), best["cells_across_gap"]):
            finest_mesh[r["gap_ratio"]] = r
    finest_gap = min(finest_mesh)
    ref_total = finest_mesh[finest_gap]["total_Nm"]
    for r in rows:
        ref = finest_mesh[r["gap_ratio"]]
        r["cfd_vs_finest_mesh"] = r["cfd_loss_Nm"] / ref["cfd_loss_Nm"] - 1.0
        r["finest_mesh_case"] = ref["case"]
        r["total_vs_finest_gap"] = r["total_Nm"] / ref_total - 1.0
    rows.sort(key=lambda r: (-r["gap_ratio"], r["cells"]))
    doc = {"command": "benchmarks/cfd_cost.py", "point": "32208, flooded, 2000 rpm, 50 degC, Fa 1 kN, FVA 3",
           "finest_gap_case": finest_mesh[finest_gap]["case"], "rows": rows, "provenance": provenance()}
    atomic_write_json(OUT, doc)

    def t(s):
        return "never" if s is None else f"{s / 60:.1f} min"

    print("| g / D_w | cells across | mesh | cells | s / iteration | to 5 % | to 1 % | run | CFD loss [mN m] "
          "| vs finest mesh | contact + CFD [mN m] | vs finest gap |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for r in rows:
        print(f"| {r['gap_ratio']:g} | {r['cells_across_gap']} | {r['mesh']} | {r['cells'] / 1e3:.0f} k | "
              f"{r['s_per_iteration']:.2f} | {t(r['wall_to_5pct_s'])} | {t(r['wall_to_1pct_s'])} | "
              f"{r['runtime_s'] / 60:.0f} min ({r['iterations']:.0f} it.) | {1e3 * r['cfd_loss_Nm']:.2f} | "
              f"{100 * r['cfd_vs_finest_mesh']:+.1f} % | {1e3 * r['total_Nm']:.1f} | "
              f"{100 * r['total_vs_finest_gap']:+.2f} % |")
    print(f"\n{OUT}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
