"""The three answers at the shaft centre with the real rollers (issue 29, item 4).

The 32208, FVA 3 at 50 degC, Fa = 1 kN, 500-4000 rpm, oil to the shaft centre. The CFD is the whole
bearing (gravity and the free surface rule out the flooded sector) with the real rollers at the
default gap g = 0.08 D_w and the ``tiny`` level's wall size in the gaps (about one cell across
0.8 mm: 76 k cells; three cells across would need about 1.4 M). Made by, per speed N

    .venv/bin/kegel cfd run --bearing 32208 --speed "N rpm" --oil-level shaft_center --mesh tiny --np 2 \\
        --gap-ratio 0.08 --max-courant 10 --max-interface-courant 3 --max-wall-time "50 min" \\
        --output results/cfd/oilbath_real/32208_Nrpm_shaft_center_tiny_g0.08
    (its results.json and kegel-case.json copied to benchmarks/results/cfd_oil_bath_runs/<same name>/)
    .venv/bin/python benchmarks/cfd_oil_bath_real_rollers.py --speed N

(the JSON keeps one row per speed; ``--cases results/cfd/oilbath_real`` reads the case folders
instead.)

The three totals, as in the flooded table (benchmarks/cfd_three_answers.py): contact cut at g +
CFD + thin films, uncut contact + Liebrecht, uncut contact + SKF drag; the contacts' supply is the
shaft-centre one (kegel.supply). The thin films of the oil bath are the flooded
point's, each times its film's supply factor (full under the oil surface, SKF's kinematic
replenishment above it: the raceway contacts' supply model; ``kegel cfd run`` writes them, and
``kegel cfd thin-films CASE`` evaluates them again for a case run before); the table gives the
all-full value beside them. One cell across a gap
reads the wedge low: the flooded whole bearing with one cell across each gap gave 74.0 mN m
against the 3-cell sector's 84.0 (the gap study's --check-sector run, docs/cfd.md), a factor 1.135
that the table applies beside the raw CFD (an estimate: the oil bath's wall-size mesh has one to
two cells across, and its wedges are partly dry).

Output: ``benchmarks/results/cfd_oil_bath_real_rollers.json`` and a Markdown table on stdout.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(REPO))

from cfd_three_answers import correlations_and_contact  # noqa: E402

#: the runs' results.json and kegel-case.json, kept whole in the repository (the case folders under
#: results/ are not); its README gives the commands that made them
CASES = HERE / "results" / "cfd_oil_bath_runs"
OUT = HERE / "results" / "cfd_oil_bath_real_rollers.json"
#: flooded 32208 at 2000 rpm, g = 0.08 D_w: the 3-cell sector (83.99 mN m) over the whole bearing
#: with one cell across each gap (74.03 mN m, the gap study's --check-sector run; docs/cfd.md)
ONE_CELL_FACTOR = 83.99 / 74.03


def _shown(path: Path) -> str:
    """``path`` relative to the repository where it lies inside it."""
    try:
        return str(path.relative_to(REPO))
    except ValueError:
        return str(path)


def main(argv: list[str] | None = None) -> int:
    import argparse

    from kegel.io import atomic_write_json, provenance

    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--speed", type=float, default=2000.0, help="shaft speed [rpm] of the case (default 2000)")
    ap.add_argument("--cases", type=Path, default=CASES,
                    help="folder of the cases (default benchmarks/results/cfd_oil_bath_runs, the shipped runs' "
                         "results.json and kegel-case.json; a case folder of kegel cfd run will do too)")
    args = ap.parse_args(argv)
    rpm = args.speed
    CASE = args.cases.resolve() / f"32208_{rpm:g}rpm_shaft_center_tiny_g0.08"
    for name in ("results.json", "kegel-case.json"):
        if not (CASE / name).is_file():
            raise SystemExit(f"--cases {args.cases}: no {name} in {_shown(CASE)} (expected the run of "
                             f"{rpm:g} rpm: its kegel cfd run folder, or its two JSON files copied there)")
    data = json.loads((CASE / "results.json").read_text())
    meta = json.loads((CASE / "kegel-case.json").read_text())
    gap_m = meta["geometry"]["gap_m"]
    cc = correlations_and_contact(rpm, gap_m, oil_level="shaft_center")
    cfd = float(data["loss_torque_at_shaft_Nm"])
    flooded = json.loads((REPO / "benchmarks" / "results" / "cfd" / f"32208_{rpm:g}rpm_flooded_50C_tiny_g0.08_n3_sector"
                          / "results.json").read_text())
    thin_full = float(flooded["thin_film_loss_Nm"])  # full films
    if data.get("thin_film_loss_Nm") is None:
        raise SystemExit(f"{CASE}/results.json has no oil-bath thin films: evaluate them with "
                         f"kegel cfd thin-films {_shown(CASE)}")
    thin = float(data["thin_film_loss_Nm"])  # the oil bath's: each film times its supply factor
    row = {"speed_rpm": rpm, "case": _shown(CASE), "cells": data["fidelity"]["cells"], "gap_m": gap_m,
           "runtime_s": data["runtime_s"], "simulated_time_s": data.get("simulated_time_s"),
           "stopped_by": data.get("stopped_by"), "steady": data.get("steady"),
           "angular_momentum_balance": (data.get("angular_momentum_balance") or {}).get("relative_to_drive_torque"),
           "cfd_loss_Nm": cfd, "cfd_loss_one_cell_corrected_Nm": cfd * ONE_CELL_FACTOR, "thin_films_Nm": thin,
           "thin_films_full_Nm": thin_full, "thin_film_supply": data["thin_films"].get("supply"),
           **cc}
    row["thin_films_note"] = ("the flooded point's thin films, each times its supply factor (full under the oil "
                              "surface, SKF's kinematic replenishment above it: kegel.cfd_cases.thin_films."
                              "oil_bath_film_factors); thin_films_full_Nm: all films full")
    row["contact_plus_cfd_Nm"] = cc["contact_cut_at_g_Nm"] + cfd
    row["contact_plus_cfd_plus_thin_films_Nm"] = cc["contact_cut_at_g_Nm"] + cfd + thin
    row["corrected_total_Nm"] = cc["contact_cut_at_g_Nm"] + cfd * ONE_CELL_FACTOR + thin
    row["contact_plus_liebrecht_Nm"] = cc["contact_uncut_Nm"] + cc["liebrecht_Nm"]
    row["contact_plus_skf_Nm"] = cc["contact_uncut_Nm"] + cc["skf_drag_Nm"]
    old = json.loads(OUT.read_text()) if OUT.is_file() else {}
    rows = [r for r in old.get("rows", [old["row"]] if "row" in old else []) if r.get("speed_rpm", 2000.0) != rpm]
    rows = sorted(rows + [row], key=lambda r: r.get("speed_rpm", 2000.0))
    atomic_write_json(OUT, {"command": "benchmarks/cfd_oil_bath_real_rollers.py --speed N",
                            "point": "32208, FVA 3, 50 degC, Fa = 1 kN, oil to the shaft centre",
                            "one_cell_factor": ONE_CELL_FACTOR, "rows": rows, "provenance": provenance()})
    m = {k: 1e3 * v for k, v in row.items() if isinstance(v, float) and k.endswith("_Nm")}
    print("| contact cut at g | CFD (x 1.135 for one cell) | thin films (all full) | **contact + CFD + thin "
          "films** (CFD x 1.135) | contact (uncut) | Liebrecht | **contact + Liebrecht** | SKF drag | **contact + SKF** |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    print(f"| {m['contact_cut_at_g_Nm']:.1f} | {m['cfd_loss_Nm']:.1f} ({m['cfd_loss_one_cell_corrected_Nm']:.1f}) | "
          f"{m['thin_films_Nm']:.1f} ({m['thin_films_full_Nm']:.1f}) | "
          f"**{m['contact_plus_cfd_plus_thin_films_Nm']:.1f}** ({m['corrected_total_Nm']:.1f}) | "
          f"{m['contact_uncut_Nm']:.1f} | {m['liebrecht_Nm']:.1f} | "
          f"**{m['contact_plus_liebrecht_Nm']:.1f}** | {m['skf_drag_Nm']:.1f} | **{m['contact_plus_skf_Nm']:.1f}** |")
    print(f"\nCFD: {row['cells']} cells, {row['runtime_s'] / 60:.0f} min, stopped by {row['stopped_by']}, "
          f"steady {row['steady']}, balance {row['angular_momentum_balance']}\n{OUT}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
