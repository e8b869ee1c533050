"""The oil bath with the real rollers on a finer mesh: tiny against small (issue 29; docs/cfd.md,
"With the real rollers: oil to the shaft centre").

The shipped oil-bath results (32208, FVA 3 at 50 degC, 1 kN, oil to the shaft centre, real
rollers at g = 0.08 D_w) are of the ``tiny`` mesh, whose wall size (0.16 D_w) puts one to two
cells across each 0.8 mm gap. The ``small`` level (wall size 0.09 D_w, 0.30 D_w away from the
walls) is started from the shipped tiny run's last regular write (``--initial-from``, the fields
mapped; the stop rule counts the tiny run's time towards its five cage revolutions) and run to
the same stop rule. Made by, per speed N (2000 and 4000 rpm so far):

    .venv/bin/kegel cfd run --bearing 32208 --speed "N rpm" --oil-level shaft_center --mesh small --np 2 \\
        --gap-ratio 0.08 --max-courant 10 --max-interface-courant 3 --max-wall-time "150 min" \\
        --initial-from results/cfd/oilbath_real/32208_Nrpm_shaft_center_tiny_g0.08 \\
        --output results/cfd/oilbath_real/32208_Nrpm_shaft_center_small_g0.08
    (its results.json and kegel-case.json copied to benchmarks/results/cfd_oil_bath_mesh/<same name>/)
    .venv/bin/python benchmarks/cfd_oil_bath_mesh.py

It compares each small run with the shipped tiny run of its speed
(``benchmarks/results/cfd_oil_bath_runs``): the CFD loss beyond g, the angular-momentum balance,
the cells and the wall time, and the total contact cut at g + CFD + thin films with each, beside
the one-cell factor the shipped table applies as an estimate (``cfd_oil_bath_real_rollers.py``).
The small runs are not shipped to ``benchmarks/results/cfd``: the flow-force laws fit one mesh's
sweep over speed, and a sweep of mixed meshes would fit the mesh's change as a speed dependence.

Output: ``benchmarks/results/cfd_oil_bath_mesh.json`` and a Markdown table on stdout.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
TINY = HERE / "results" / "cfd_oil_bath_runs"
SMALL = HERE / "results" / "cfd_oil_bath_mesh"
SHIPPED_TABLE = HERE / "results" / "cfd_oil_bath_real_rollers.json"
OUT = HERE / "results" / "cfd_oil_bath_mesh.json"


def _run(folder: Path) -> dict:
    """What one run's results.json and kegel-case.json say about its mesh, cost and answer."""
    for name in ("results.json", "kegel-case.json"):
        if not (folder / name).is_file():
            raise SystemExit(f"{folder}: no {name} (expected the run's results.json and kegel-case.json there; "
                             f"see {Path(__file__).name}'s docstring for the command)")
    d = json.loads((folder / "results.json").read_text())
    meta = json.loads((folder / "kegel-case.json").read_text())
    bal = d["angular_momentum_balance"]
    return {"case": folder.name, "mesh": d["fidelity"]["mesh"], "cells": d["fidelity"]["cells"],
            "initial_state": d["fidelity"].get("initial_state"), "steady": d["steady"],
            "stopped_by": d["stopped_by"], "simulated_time_s": d["simulated_time_s"],
            "averaging_window_s": d["averaging_window"], "runtime_s": d["runtime_s"],
            "mesh_time_s": meta.get("mesh_time_s"), "cfd_loss_Nm": d["loss_torque_at_shaft_Nm"],
            "thin_films_Nm": d["thin_film_loss_Nm"], "balance": bal["relative_to_drive_torque"],
            "max_non_orthogonality_deg": d["mesh_quality"]["max_non_orthogonality_deg"]}


def main(argv: list[str] | None = None) -> int:
    import kegel
    from kegel.io import atomic_write_json, provenance

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--small", type=Path, default=SMALL,
                    help="folder of the small runs' folders (default benchmarks/results/cfd_oil_bath_mesh)")
    args = ap.parse_args(argv)
    shipped = {round(r["speed_rpm"]): r for r in json.loads(SHIPPED_TABLE.read_text())["rows"]}
    factor = json.loads(SHIPPED_TABLE.read_text())["one_cell_factor"]
    rows = []
    for folder in sorted(p for p in args.small.glob("32208_*rpm_shaft_center_small_g0.08") if p.is_dir()):
        rpm = int(folder.name.split("_")[1][:-3])
        small = _run(folder)
        tiny = _run(TINY / folder.name.replace("_small_", "_tiny_"))
        if rpm not in shipped:
            raise SystemExit(f"{SHIPPED_TABLE}: no row at {rpm} rpm (expected one per small run: "
                             f"benchmarks/cfd_oil_bath_real_rollers.py --speed {rpm})")
        s = shipped[rpm]
        rest = s["contact_plus_cfd_plus_thin_films_Nm"] - s["cfd_loss_Nm"]  # contact cut at g + thin films
        rows.append({"speed_rpm": rpm, "tiny": tiny, "small": small,
                     "small_over_tiny": small["cfd_loss_Nm"] / tiny["cfd_loss_Nm"],
                     "one_cell_factor": factor,
                     "total_tiny_Nm": rest + tiny["cfd_loss_Nm"], "total_small_Nm": rest + small["cfd_loss_Nm"],
                     "contact_plus_liebrecht_Nm": s["contact_plus_liebrecht_Nm"],
                     "contact_plus_skf_Nm": s["contact_plus_skf_Nm"]})
    if not rows:
        raise SystemExit(f"{args.small}: no small run (expected folders named 32208_<N>rpm_shaft_center_small_g0.08)")
    command = "benchmarks/cfd_oil_bath_mesh.py " + " ".join(sys.argv[1:] if argv is None else argv)
    atomic_write_json(OUT, {"command": command,
                            "point": "32208, FVA 3, 50 degC, 1 kN, oil to the shaft centre, real rollers, g = 0.08 D_w",
                            "rows": rows, "kegel_version": kegel.__version__, "provenance": provenance()})
    print("| speed | mesh | cells | CFD loss [mN m] | balance | wall time "
          "| total (contact cut + CFD + thin films) [mN m] |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for r in rows:
        for k in ("tiny", "small"):
            x = r[k]
            print(f"| {r['speed_rpm']} rpm | {k} | {x['cells']} | {1e3 * x['cfd_loss_Nm']:.2f} | "
                  f"{100 * x['balance']:+.1f} % | {x['runtime_s'] / 60:.0f} min | {1e3 * r[f'total_{k}_Nm']:.1f} |")
        print(f"small / tiny: {r['small_over_tiny']:.3f} (the one-cell factor applied as an estimate: {factor:.3f})")
    print(OUT)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
