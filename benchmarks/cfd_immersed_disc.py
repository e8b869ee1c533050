"""A disc dipped in an oil bath against Changenet & Velex's churning-loss correlation (2007).

A smooth disc (R = 20 mm, b = 8 mm) half immersed in an oil bath in a closed box, started from
rest (interFoam, VOF, laminar, half the box by symmetry); the churning torque averaged over the
end of the run against :func:`kegel.cfd_cases.validation.changenet_velex_churning_torque`: at
150 rad/s (Re = 3000, Fr = 46) 10 revolutions, the last 4 averaged, on the base mesh, a mesh 1.5
times finer and (with ``--fine``) twice finer; at 50 rad/s (Re = 1000, Fr = 5.1) 24 revolutions,
the last 6 averaged, on the base mesh.

Run (one core; on an idle core the base mesh takes about 1 min of solver time, 1.5x about 6 min,
2x about 18 min; the 50 rad/s point about 3 min):

    .venv/bin/python benchmarks/cfd_immersed_disc.py [--fine]

writes benchmarks/results/cfd_immersed_disc.json (after every point).
"""

from __future__ import annotations

import argparse
import sys
import time
from dataclasses import asdict
from pathlib import Path

from kegel.cfd_cases.validation import IMMERSED_DISC_TOLERANCE, immersed_disc
from kegel.io import atomic_write_json, provenance

OUT = Path(__file__).resolve().parent / "results" / "cfd_immersed_disc.json"
#: (omega rad/s, mesh scale, revolutions, averaged fraction of the run)
POINTS = ((150.0, 1.0, 10.0, 0.4), (150.0, 1.5, 10.0, 0.4), (50.0, 1.0, 24.0, 0.25))
FINE_POINTS = ((150.0, 2.0, 10.0, 0.4),)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fine", action="store_true", help="also the mesh twice finer at 50 rad/s")
    args = ap.parse_args(argv)
    rows = []
    for omega, scale, revs, frac in POINTS + (FINE_POINTS if args.fine else ()):
        t0 = time.monotonic()
        r = immersed_disc(omega_rad_s=omega, mesh_scale=scale, revolutions=revs, average_fraction=frac,
                          work_dir=f"/tmp/kegel-cfd-immersed-disc/w{omega:g}_s{scale:g}")
        rows.append({**asdict(r), "omega_rad_s": omega})
        print(f"omega {omega:g} rad/s, mesh x{scale:g} ({r.cells} cells): torque {r.torque_sim_Nm:.4g} N m, "
              f"Changenet-Velex {r.torque_ref_Nm:.4g} N m, error {100 * r.relative_error:+.1f} % "
              f"(window drift {100 * r.torque_window_drift:+.2f} %, oil volume change {r.volume_change:.1e}, "
              f"{time.monotonic() - t0:.0f} s)", file=sys.stderr, flush=True)
        atomic_write_json(OUT, {
            "command": ".venv/bin/python benchmarks/cfd_immersed_disc.py" + (" --fine" if args.fine else ""),
            "reference": "Changenet & Velex 2007 (ASME J. Mech. Des. 129, 128-133), low-speed regime "
                         "(Omega R b/nu < 6000): T = 0.5 rho Omega^2 S_m R^3 C_m, C_m = 1.366 (h/D)^0.45 "
                         "(V0/D^3)^0.1 Fr^-0.6 Re^-0.21, Fr = Omega^2 R/g, Re = Omega R^2/nu; constants as "
                         "reproduced in the gear-churning literature (the paper itself was not readable here)",
            "tolerance": IMMERSED_DISC_TOLERANCE,
            "rows": rows, "provenance": provenance()})
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
