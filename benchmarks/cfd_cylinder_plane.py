"""How many cells a gap needs: a cylinder rolling near a wall, CFD against the exact answer.

A cylinder of radius R1 turns inside a ring of radius 4 R1 with the smallest gap h0 (the
cylinder-near-a-plane problem in a closed domain; the reduced radius is 4/3 R1). Both surfaces
move together through the gap (pure rolling, as a roller on a raceway in the cage frame). The
mesh is sized ``h / n`` by the local gap h (n cells across it everywhere near the contact),
capped at R1 / 10; triangles (as the bearing's tetrahedra) and recombined quads. simpleFoam at
Re = 0.05 (creeping flow) against Wannier's exact Stokes solution
(:func:`kegel.cfd_cases.validation.eccentric_stokes_loads`): torque on the cylinder (its
rolling resistance times R1), torque on the ring, the force along the gap and the dissipation.

Run (one core, about 30-40 min for the full table; rows already in the file are kept):

    .venv/bin/python benchmarks/cfd_cylinder_plane.py

writes benchmarks/results/cfd_cylinder_plane.json: one row per (h0/R1, n, mesh) and, per h0/R1
and mesh, the smallest n whose torque and dissipation errors are within 1, 2 and 5 %.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from dataclasses import asdict
from pathlib import Path

from kegel.cfd_cases.validation import cylinder_rolling_gap
from kegel.io import atomic_write_json, provenance

OUT = Path(__file__).resolve().parent / "results" / "cfd_cylinder_plane.json"
GAPS = (0.01, 0.02, 0.05, 0.1, 0.2)
CELLS = (2, 3, 4, 6, 8, 12)
COMMAND = ".venv/bin/python benchmarks/cfd_cylinder_plane.py"


def _key(r: dict) -> tuple:
    return (round(r["gap_ratio"], 6), round(r["cells_across_gap"], 6), r["mesh_type"], r["kinematics"])


def needed_cells(rows: list[dict], tolerance: float) -> dict[str, dict[str, float | None]]:
    """Per mesh type and gap ratio: the smallest n from which on every finer row has the inner
    and outer torque and the dissipation within ``tolerance`` (None: not reached)."""
    out: dict[str, dict[str, float | None]] = {}
    for mesh in sorted({r["mesh_type"] for r in rows}):
        per: dict[str, float | None] = {}
        for gap in sorted({r["gap_ratio"] for r in rows}):
            sel = sorted((r for r in rows if r["mesh_type"] == mesh and r["gap_ratio"] == gap),
                         key=lambda r: r["cells_across_gap"])
            ok = [max(abs(r["error_torque_inner"]), abs(r["error_torque_outer"]), abs(r["error_dissipation"])) <= tolerance
                  for r in sel]
            first = None
            for i in range(len(sel)):
                if all(ok[i:]):
                    n = float(sel[i]["cells_across_gap"])
                    first = int(n) if n.is_integer() else n
                    break
            per[f"{gap:g}"] = first
        out[mesh] = per
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--gap", type=float, nargs="+", default=list(GAPS), help="h0 / R1 values")
    ap.add_argument("--cells", type=float, nargs="+", default=list(CELLS), help="cells across the gap")
    ap.add_argument("--mesh", nargs="+", default=["tri", "quad"], choices=("tri", "quad"))
    ap.add_argument("--work", default="/tmp/kegel-cfd-cylinder-plane", help="case folders")
    args = ap.parse_args(argv)
    data = json.loads(OUT.read_text()) if OUT.is_file() else {"rows": []}
    rows = data["rows"]
    done = {_key(r) for r in rows}
    for mesh in args.mesh:
        for gap in args.gap:
            for n in args.cells:
                key = (round(gap, 6), round(float(n), 6), mesh, "rolling")
                if key in done:
                    continue
                t0 = time.monotonic()
                r = cylinder_rolling_gap(gap_ratio=gap, cells_across_gap=n, mesh_type=mesh,
                                         work_dir=Path(args.work) / f"{mesh}_h{gap:g}_n{n:g}")
                row = asdict(r)
                rows.append(row)
                done.add(key)
                print(f"{mesh} h0/R1={gap:<5g} n={n:<4g} cells={r.cells:>6} it={r.iterations:>5} "
                      f"T1 {100 * r.error_torque_inner:+6.2f} % T2 {100 * r.error_torque_outer:+6.2f} % "
                      f"Fx {100 * r.error_force_x:+6.2f} % D {100 * r.error_dissipation:+6.2f} % "
                      f"({time.monotonic() - t0:.0f} s)", file=sys.stderr, flush=True)
                rows.sort(key=_key)
                _write(rows)
    _write(rows)
    print(json.dumps(needed_cells(rows, 0.02), indent=1))
    return 0


def _write(rows: list[dict]) -> None:
    atomic_write_json(OUT, {
        "command": COMMAND,
        "case": "cylinder (R1 = 5 mm) rolling inside a ring (R2 = 4 R1), pure rolling, Re = v R1/nu = 0.05, "
                "simpleFoam laminar, pseudo-2D; mesh size h/n by the local gap h, capped at R1/10",
        "reference": "Wannier 1950 exact Stokes solution (eccentric_stokes_loads)",
        "errors": "(CFD - exact) / |exact|; torques about each cylinder's axis, force along the gap on the "
                  "cylinder, dissipation -(T1 Omega1 + T2 Omega2)",
        "cells_needed": {f"{int(100 * t)}%": needed_cells(rows, t) for t in (0.01, 0.02, 0.05)},
        "rows": rows, "provenance": provenance(),
    })


if __name__ == "__main__":
    raise SystemExit(main())
