"""Rotor-stator cavity (a side chamber of the bearing) against Daily & Nece (1960).

One face of a disc turning in a closed chamber, axisymmetric (5 deg wedge), laminar simpleFoam;
the moment coefficient of both faces against Daily & Nece's regime I (merged boundary layers,
Couette) and regime II (separate boundary layers) formulas, on a base and a doubled mesh.

Run (one core, a few minutes):

    .venv/bin/python benchmarks/cfd_rotor_stator.py

writes benchmarks/results/cfd_rotor_stator.json.
"""

from __future__ import annotations

import sys
import time
from dataclasses import asdict
from pathlib import Path

from kegel.cfd_cases.validation import rotor_stator
from kegel.io import atomic_write_json, provenance

OUT = Path(__file__).resolve().parent / "results" / "cfd_rotor_stator.json"
#: (regime, Re, G, n_r, n_z)
POINTS = (
    ("I", 300.0, 0.02, 60, 20), ("I", 1000.0, 0.02, 60, 20), ("I", 1000.0, 0.02, 120, 40),
    ("II", 5.0e3, 0.1, 60, 50), ("II", 1.0e4, 0.1, 60, 50), ("II", 2.0e4, 0.1, 60, 50), ("II", 1.0e4, 0.1, 120, 100),
)


def main() -> int:
    rows = []
    for regime, re, g, n_r, n_z in POINTS:
        t0 = time.monotonic()
        r = rotor_stator(regime=regime, reynolds=re, gap_ratio=g, n_r=n_r, n_z=n_z,
                         work_dir=f"/tmp/kegel-cfd-rotor-stator/{regime}_{re:g}_{n_r}")
        rows.append({**asdict(r), "n_r": n_r, "n_z": n_z})
        print(f"regime {regime} Re {re:g} G {g:g} mesh {n_r}x{n_z}: C_M {r.moment_coefficient_sim:.5g} "
              f"Daily-Nece {r.moment_coefficient_ref:.5g} error {100 * r.relative_error:+.2f} % "
              f"(iterations {r.iterations}, converged {r.converged}, {time.monotonic() - t0:.0f} s)", file=sys.stderr, flush=True)
        atomic_write_json(OUT, {"command": ".venv/bin/python benchmarks/cfd_rotor_stator.py",
                                "reference": "Daily & Nece 1960: regime I C_M = 2 pi/(G Re); regime II C_M = 3.70 G^0.1 Re^-0.5 "
                                             "(both faces, C_M = M/(0.5 rho Omega^2 a^5), Re = Omega a^2/nu, G = s/a)",
                                "rows": rows, "provenance": provenance()})
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
