"""The oil bath's frozen rotor against a moving mesh (issue 29; docs/cfd.md, "Oil bath: frozen
rotor or moving mesh").

The oil-bath CFD freezes the rollers and the cage where they stand (MRF in the cage frame):
roller 0 stays at the bottom of the sump for good, and the rollers never pass through the oil
surface. ``frame = "moving_mesh"`` turns the whole mesh with the cage instead, gravity fixed, so
the rollers dip in and out of the sump as in the bearing. This benchmark runs

1. the frozen rotor from rest until its steady test passes (the stored shaft-centre point:
   32208, FVA 3 at 50 degC, 2000 rpm, oil to the shaft centre, tiny mesh, real rollers at
   g = 0.08 D_w, Courant 10 / 3);
2. the moving mesh started from the frozen rotor's state at its steady stop (the rotor
   released), for ``--revolutions`` cage revolutions, not stopped by the steady test;

and compares the loss torque at the shaft, cage revolution by cage revolution after the release,
with the frozen rotor's steady value, beside the rings', the cage's and the rollers' torques
about the axis and the oil volume.

    .venv/bin/python benchmarks/cfd_oil_bath_moving_mesh.py [--revolutions 3] [--np 2]

Each run resumes when its case folder exists (``results/cfd/moving_mesh/``): give the same
command again after a stop. Output: ``benchmarks/results/cfd_oil_bath_moving_mesh.json`` (and a
summary on stdout).
"""

from __future__ import annotations

import json
import math
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
CASES = REPO / "results" / "cfd" / "moving_mesh"
OUT = HERE / "results" / "cfd_oil_bath_moving_mesh.json"
SPEED_RPM = 2000.0
OIL_LEVEL_M = 0.04  # the shaft centre of the 32208 (D = 80 mm)


def _point(frame: str, n_procs: int, **extra):
    from kegel.cfd_cases.run import CfdPoint

    return CfdPoint(bearing="32208", speed_rad_s=SPEED_RPM * math.pi / 30, temperature_K=323.15,
                    oil_level_m=OIL_LEVEL_M, mesh="tiny", n_procs=n_procs, frame=frame, max_courant=10.0,
                    max_interface_courant=3.0, **extra)


def _summary(case: Path) -> dict:
    data = json.loads((case / "results.json").read_text())
    t = data["torques_Nm"]
    vol = data.get("liquid_volume", {}).get("volume_m3") or []
    return {"case": str(case.relative_to(REPO)), "loss_torque_Nm": data["loss_torque_at_shaft_Nm"],
            "inner_ring_Nm": t["inner_ring"]["total"], "outer_ring_Nm": t["outer_ring"]["total"],
            "cage_Nm": t["cage"]["total"], "housing_Nm": t["housing"]["total"],
            "rollers_about_axis_Nm": t["rollers_about_bearing_axis"]["total"],
            "averaging_window_s": data["averaging_window"], "steady": data["steady"],
            "simulated_time_s": data.get("simulated_time_s"), "runtime_s": data["runtime_s"],
            "cells": data["fidelity"]["cells"],
            "angular_momentum_balance": data["angular_momentum_balance"]["relative_to_drive_torque"],
            "oil_volume_change": (vol[-1] / vol[0] - 1.0) if len(vol) > 1 else None}


def main(argv: list[str] | None = None) -> int:
    import argparse

    import numpy as np

    import kegel
    from kegel.cfd_cases.run import loss_torque_series, run_case
    from kegel.io import atomic_write_json, provenance

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--revolutions", type=float, default=3.0,
                    help="cage revolutions the moving mesh runs after the release (default 3)")
    ap.add_argument("--np", type=int, default=2, help="MPI processes (default 2)")
    args = ap.parse_args(argv)

    def log(s: str) -> None:
        print(s, file=sys.stderr)

    frozen_case, moving_case = CASES / "frozen_2000rpm_tiny", CASES / "moving_2000rpm_tiny"
    t0 = time.monotonic()
    run_case(_point("cage", args.np, max_wall_time_s=3600.0), frozen_case, log=log, progress=False)
    frozen = _summary(frozen_case)
    meta = json.loads((frozen_case / "kegel-case.json").read_text())
    cage_rev_s = 2 * math.pi / abs(meta["kinematics"]["cage_rad_s"])
    end = args.revolutions * cage_rev_s
    run_case(_point("moving_mesh", args.np, initial_from=str(frozen_case), end_time_s=end, steady_tolerance=0.0),
             moving_case, log=log, progress=False)
    moving = _summary(moving_case)
    moving_meta = json.loads((moving_case / "kegel-case.json").read_text())
    t, loss = loss_torque_series(moving_case, moving_meta)
    revs = []
    for k in range(int(math.floor(t[-1] / cage_rev_s + 1e-9))):
        sel = (t >= k * cage_rev_s) & (t < (k + 1) * cage_rev_s)
        if sel.sum() < 10:
            continue
        m = float(loss[sel].mean())
        revs.append({"cage_revolution": k + 1, "from_s": k * cage_rev_s, "to_s": (k + 1) * cage_rev_s,
                     "loss_torque_Nm": m, "vs_frozen": m / frozen["loss_torque_Nm"] - 1.0,
                     "min_Nm": float(loss[sel].min()), "max_Nm": float(loss[sel].max())})
    atomic_write_json(OUT, {
        "command": " ".join(["benchmarks/cfd_oil_bath_moving_mesh.py", *(sys.argv[1:] if argv is None else argv)]),
        "point": "32208, FVA 3, 50 degC, 2000 rpm, oil to the shaft centre, tiny, real rollers, g = 0.08 D_w, "
                 "Courant 10 / 3",
        "cage_revolution_s": cage_rev_s, "frozen_rotor": frozen, "moving_mesh": moving,
        "moving_mesh_by_cage_revolution": revs,
        "moving_vs_frozen_last_revolution": revs[-1]["vs_frozen"] if revs else None,
        "session_wall_s": time.monotonic() - t0, "kegel_version": kegel.__version__, "provenance": provenance()})
    print(f"frozen rotor: {1e3 * frozen['loss_torque_Nm']:.2f} mN m (steady: {frozen['steady']}, "
          f"{frozen['runtime_s'] / 60:.0f} min)")
    for r in revs:
        print(f"moving mesh, cage revolution {r['cage_revolution']}: {1e3 * r['loss_torque_Nm']:.2f} mN m "
              f"({100 * r['vs_frozen']:+.1f} %; {1e3 * r['min_Nm']:.1f}-{1e3 * r['max_Nm']:.1f})")
    print(f"moving mesh: {moving['runtime_s'] / 60:.0f} min, oil volume change {moving['oil_volume_change']}")
    return 0 if np.isfinite(moving["loss_torque_Nm"]) else 1


if __name__ == "__main__":
    sys.exit(main())
