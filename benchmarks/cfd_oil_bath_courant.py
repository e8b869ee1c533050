"""CFD speed against error: the oil bath's time step (Courant limit) on the tiny 32208 case.

The oil-bath run is transient and its time step is set by the Courant number in the oil-filled
gaps and at the free surface. This runs the same start-up (32208, 2000 rpm, 50 degC, oil to the
shaft centre, tiny mesh, 2 cores, from rest to a quarter of a shaft revolution, 7.5 ms) at several
limits and reports, side by side, the solver runtime, the number of time steps and the loss torque
at the shaft averaged over four windows of the start-up, with the deviation from the smallest
limit (0.5 / 0.5, the finest fidelity; the template's limits before the solver settings allowed
more). Comparing a steep
start-up is the hard case: a time-step error shows as a time shift there.

    .venv/bin/python benchmarks/cfd_oil_bath_courant.py [0.5/0.5 2/1 5/1 10/3 ...]

Each argument is ``max_courant/max_interface_courant``. Not part of ``make bench`` (about 15
minutes, most of it the 0.5 run). Output: benchmarks/results/cfd_oil_bath_courant.json.
"""

from __future__ import annotations

import json
import math
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent

#: Averaging windows of the start-up (s).
WINDOWS = ((0.001, 0.002), (0.003, 0.004), (0.0045, 0.006), (0.006, 0.0075))


def main(settings: list[str]) -> int:
    from kegel.cfd_cases.run import CfdPoint, loss_torque_series, run_case
    from kegel.data import load_bearing
    from kegel.io import atomic_write_json

    level = 0.5 * load_bearing("32208").outer_diameter_m
    rows = []
    work = Path(tempfile.mkdtemp(prefix="kegel-courant-"))
    try:
        for s in settings:
            co, alpha_co = (float(x) for x in s.split("/"))
            p = CfdPoint(bearing="32208", speed_rad_s=2000 * math.pi / 30, temperature_K=323.15, oil_level_m=level,
                         mesh="tiny", n_procs=2, end_time_s=0.0075, max_courant=co, max_interface_courant=alpha_co,
                         force_sample_steps=1)
            case = work / f"co_{co:g}_{alpha_co:g}"
            t0 = time.monotonic()
            res = run_case(p, case, progress=False, log=lambda m: print(m, file=sys.stderr))
            wall = time.monotonic() - t0
            meta = json.loads((case / "kegel-case.json").read_text())
            t, loss = loss_torque_series(case, meta)
            means = []
            for lo, hi in WINDOWS:
                sel = (t >= lo) & (t <= hi)
                means.append(float(np.trapezoid(loss[sel], t[sel]) / (t[sel][-1] - t[sel][0])))
            vol = np.array(res.liquid_volume["volume_m3"])
            rows.append({"max_courant": co, "max_interface_courant": alpha_co, "cells": res.cells,
                         "solver_runtime_s": res.runtime_s, "wall_s": wall, "time_steps": int(len(t)),
                         "loss_torque_window_means_Nm": means,
                         "oil_volume_change": float(vol[-1] / vol[0] - 1)})
    finally:
        shutil.rmtree(work, ignore_errors=True)
    ref = rows[0]
    for r in rows:
        r["deviation"] = [m / m0 - 1 for m, m0 in zip(r["loss_torque_window_means_Nm"], ref["loss_torque_window_means_Nm"])]
        r["speed_up"] = ref["solver_runtime_s"] / r["solver_runtime_s"]
    out = HERE / "results"
    out.mkdir(exist_ok=True)
    atomic_write_json(out / "cfd_oil_bath_courant.json", {"windows_s": WINDOWS, "reference": settings[0], "rows": rows})
    print("loss torque at the shaft (mN m) averaged over " + ", ".join(f"{1e3 * a:g}-{1e3 * b:g}" for a, b in WINDOWS)
          + " ms, deviation from the first row")
    print(f"{'Co/alphaCo':<11}{'steps':>7}{'run s':>8}{'speed-up':>9}   " + "".join(f"{'window ' + str(i + 1):>17}" for i in range(len(WINDOWS)))
          + f"{'oil volume':>12}")
    for r in rows:
        cells = "".join(f"{1e3 * m:>9.2f} ({100 * d:+.1f}%)" for m, d in zip(r["loss_torque_window_means_Nm"], r["deviation"]))
        print(f"{r['max_courant']:g}/{r['max_interface_courant']:<7g}{r['time_steps']:>7}{r['solver_runtime_s']:>8.0f}"
              f"{r['speed_up']:>9.1f}   {cells}{r['oil_volume_change']:>12.1e}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:] or ["0.5/0.5", "2/1", "5/1", "10/3"]))
