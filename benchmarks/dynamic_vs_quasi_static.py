"""Validation of the dynamic simulation against the quasi-static solution over the 32216's
Table 1 conditions (Fa = 6 kN, 42 and 50 degC, 500-4000 rpm): steady mean torque of each and
the power balance of the dynamic run, at the same contact fidelity (default dynamic level:
20 independent slices, rib as one ellipse, cage on). Writes
benchmarks/results/dynamic_vs_quasi_static.json.

Run: .venv/bin/python benchmarks/dynamic_vs_quasi_static.py
"""

from __future__ import annotations

import json
import math
import os
from pathlib import Path

import numpy as np

import kegel
from kegel.dynamics import simulate
from kegel.quasi_static import bearing_friction
from kegel.io import provenance
from kegel.tribology import load_friction

OUT = Path(__file__).resolve().parent / "results"


def main() -> None:
    b = kegel.load_bearing("32216")
    m = kegel.load_material("bearing_steel")
    g = kegel.derive_geometry(b, m)
    lub, fr = kegel.load_lubricant("FVA3"), load_friction()
    rows = []
    for T in (42.0, 50.0):
        for n in np.linspace(500, 4000, 8):
            w = n * math.pi / 30
            _, q = bearing_friction(g, b, m, lub, fr, temperature_K=T + 273.15, inner_speed_rad_s=w, axial_N=6000.0,
                                    slices=20, method="independent")
            # at least half a revolution, averaged over its second half
            dur = max(0.02, math.pi / w)
            r = simulate(g, b, m, lub, fr, temperature_K=T + 273.15, speed_profile=[(0.0, w)], duration_s=dur,
                         axial_N=6000.0, slices=20, method="independent", output_interval_s=dur / 50)
            st = r.steady
            rows.append({"temperature_degC": T, "speed_rpm": float(n), "quasi_static_Nm": q.outer_ring_torque_Nm,
                         "dynamic_Nm": st["outer_ring_torque_Nm"], "dynamic_std_Nm": st["outer_ring_torque_std"],
                         "deviation": st["outer_ring_torque_Nm"] / q.outer_ring_torque_Nm - 1.0,
                         "power_balance_error": st["power_balance_error"], "wall_s": r.runtime_s,
                         "revolutions": r.revolutions})
            print(f"{T:4.0f} degC {n:6.0f} rpm: QS {q.outer_ring_torque_Nm * 1e3:8.3f} mN m, dynamic "
                  f"{st['outer_ring_torque_Nm'] * 1e3:8.3f} mN m ({100 * rows[-1]['deviation']:+.2f} %), power balance "
                  f"{100 * st['power_balance_error']:+.2f} %, {r.runtime_s:.1f} s", flush=True)
    worst = max(rows, key=lambda r: abs(r["deviation"]))
    worst_b = max(rows, key=lambda r: abs(r["power_balance_error"]))
    print(f"largest deviation {100 * worst['deviation']:+.2f} % ({worst['speed_rpm']:.0f} rpm, "
          f"{worst['temperature_degC']:.0f} degC); largest power-balance error {100 * worst_b['power_balance_error']:+.2f} %")
    OUT.mkdir(exist_ok=True)
    tmp = OUT / ".dynamic_vs_quasi_static.json.tmp"
    tmp.write_text(json.dumps({"rows": rows, "provenance": provenance()}, indent=2) + "\n")
    os.replace(tmp, OUT / "dynamic_vs_quasi_static.json")


if __name__ == "__main__":
    main()
