"""Write the stored reference of tests/python/test_dynamics.py::test_regression_against_the_stored_reference.

Run only when a change of the dynamic results is intended, and say why in the commit:
    .venv/bin/python tests/python/reference/make_dynamic_reference.py
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import kegel
from kegel.dynamics import simulate
from kegel.io import provenance
from kegel.tribology import load_friction

CASE = dict(temperature_K=323.15, speed_profile=[(0.0, 2000 * math.pi / 30)], duration_s=6e-3, axial_N=8000.0,
            radial_N=4000.0, slices=20, method="independent", output_interval_s=3e-4)
KEYS = ("outer_ring_torque_Nm", "drive_torque_Nm", "cage_speed_rad_s", "torque_outer_raceway_Nm",
        "torque_inner_raceway_Nm", "torque_rib_Nm", "power_contacts_W")


def compute() -> dict:
    b = kegel.load_bearing("32216")
    m = kegel.load_material("bearing_steel")
    g = kegel.derive_geometry(b, m)
    r = simulate(g, b, m, kegel.load_lubricant("FVA3"), load_friction(), **CASE)
    out = {k: r.steady[k] for k in KEYS}
    out["roller_inner_N_final"] = r.series["roller_inner_N"][-1].tolist()
    return out


if __name__ == "__main__":
    ref = {"case": {**CASE, "bearing": "32216", "lubricant": "FVA3"}, "values": compute(),
           "made_by": "tests/python/reference/make_dynamic_reference.py", "provenance": provenance()}
    path = Path(__file__).with_name("dynamic_32216_combined_load.json")
    path.write_text(json.dumps(ref, indent=2) + "\n")
    print(f"wrote {path}")
