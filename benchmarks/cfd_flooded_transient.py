"""Which steady state is the flooded bearing's? A transient run from rest decides (issue 29).

The steady solver (simpleFoam) finds two states of the flooded 32208 sector, one from oil at
rest and one from oil turning with the cage, 5 % apart in loss at 4000 rpm
(``benchmarks/cfd_start_study.py``). Steady iterations are not a start-up in time; this script
runs the same case in time: the mesh, walls and initial field (oil at 1 % of the cage's
rotation, i.e. at rest) of the gap study's stored case of the point, copied to
``results/cfd/start_study/<case>_transient``, with pimpleFoam (the same MRF cage frame, Euler in
time, the time step held at a Courant number of ``--max-courant``) from t = 0 to ``--end``, and
the loss torque at the shaft and each wall's torque about the axis over time.

    .venv/bin/python benchmarks/cfd_flooded_transient.py 4000:0.08:3 --end 1.5
    .venv/bin/python benchmarks/cfd_flooded_transient.py 4000:0.08:3 --report

A run cut off by the end of a session resumes from its latest write (every 0.05 s). Output: the
table of window means (0.1 s) on stdout and ``benchmarks/results/cfd_flooded_transient.json``.

Cost, measured 2026-11-26 (4000:0.08:3, 84 k cells, 2 cores shared with a mesher): at Courant 4
the time step is 1.1e-5 s (the smallest cells, where the walls move fastest relative to the cage
frame) and a step takes about 3 s, so the side chambers' spin-up (s^2 / nu = 0.6 s, 1.5 s
simulated) would need about 136 k steps, some 5 days on this machine. Not run to the end: the
question stays open (docs/cfd.md, "Every wall, and where the oil starts").
"""

from __future__ import annotations

import argparse
import json
import re
import shutil
import sys
from pathlib import Path


HERE = Path(__file__).resolve().parent
REPO = HERE.parent
sys.path.insert(0, str(HERE))

from cfd_flooded_convergence import WALLS, wall_histories, window_table  # noqa: E402
from cfd_gap_study import CASES as GAP_CASES, case_name  # noqa: E402
from cfd_start_study import CASES, parse_point  # noqa: E402

OUT = HERE / "results" / "cfd_flooded_transient.json"
WINDOW_S = 0.1
WRITE_S = 0.05


def prepare(src: Path, case: Path, end_s: float, max_courant: float) -> None:
    """The transient copy of the steady case ``src``: mesh, walls and initial fields, with a
    pimpleFoam controlDict, Euler in time and a PIMPLE block (written once; a later call only
    moves the end time)."""
    if not case.exists():
        case.mkdir(parents=True)
        for item in ("constant", "system", "0", "kegel-case.json", "cell_centres.npy"):
            s = src / item
            (shutil.copytree if s.is_dir() else shutil.copyfile)(s, case / item)
        for proc in sorted(src.glob("processor*")):
            (case / proc.name).mkdir()
            for item in ("constant", "0"):
                shutil.copytree(proc / item, case / proc.name / item, symlinks=True)
        ctrl = (case / "system" / "controlDict").read_text()
        ctrl = re.sub(r"^application\s+\S+;", "application     pimpleFoam;", ctrl, flags=re.M)
        ctrl = re.sub(r"^stopAt\s+\S+;", "stopAt          endTime;", ctrl, flags=re.M)
        ctrl = re.sub(r"^deltaT\s+\S+;", "deltaT          1e-05;\nadjustTimeStep  yes;\n"
                      f"maxCo           {max_courant:g};\nmaxDeltaT       1e-3;", ctrl, flags=re.M)
        ctrl = re.sub(r"^writeControl\s+\S+;", "writeControl    adjustableRunTime;", ctrl, flags=re.M)
        ctrl = re.sub(r"^writeInterval\s+\S+;", f"writeInterval   {WRITE_S:g};", ctrl, count=1, flags=re.M)
        ctrl = re.sub(r"^purgeWrite\s+\S+;", "purgeWrite      3;", ctrl, flags=re.M)
        (case / "system" / "controlDict").write_text(ctrl)
        sch = (case / "system" / "fvSchemes").read_text()
        (case / "system" / "fvSchemes").write_text(sch.replace("ddtSchemes { default steadyState; }",
                                                                "ddtSchemes { default Euler; }"))
        sol = (case / "system" / "fvSolution").read_text()
        solvers = ("    pFinal  { solver GAMG; smoother GaussSeidel; tolerance 1e-8; relTol 0; }\n"
                   "    UFinal  { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-9; relTol 0; }\n}")
        sol = sol.replace("\n}\nSIMPLE", "\n" + solvers + "\nSIMPLE", 1)
        sol = sol.replace("SIMPLE\n{", "PIMPLE\n{\n    nOuterCorrectors 2;\n    nCorrectors 2;", 1)
        sol = sol.replace("relaxationFactors { equations { U 0.7; } fields { p 1; } }",
                          "relaxationFactors { equations { \".*\" 1; } }")
        (case / "system" / "fvSolution").write_text(sol)
    ctrl = (case / "system" / "controlDict").read_text()
    (case / "system" / "controlDict").write_text(re.sub(r"^endTime\s+\S+;", f"endTime         {end_s:g};", ctrl,
                                                        flags=re.M))


def report(case: Path) -> dict:
    h = wall_histories(case)
    t = h["iteration"]  # the force files' time: seconds here
    rows = window_table(h, WINDOW_S, "to_time_s")
    print(f"{case.name}: simulated to t = {float(t.max()):.3f} s, {len(t)} steps")
    print("| to t [s] | loss | inner ring | shaft | outer ring | housing | cage | rollers about the axis | balance |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for r in rows:
        print(f"| {r['to_time_s']:.2f} | " + " | ".join(f"{1e3 * r[k + '_Nm']:.2f}" for k in
                                                   ("loss", *WALLS, "rollers_about_axis")) + f" | {100 * r['balance']:+.1f} % |")
    return {"case": case.name, "simulated_s": float(t.max()), "steps": int(len(t)), "window_s": WINDOW_S, "windows": rows}


def main(argv: list[str] | None = None) -> int:
    from kegel.cfd_cases.foam import run_solver
    from kegel.io import atomic_write_json, provenance

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("point", help="[SPEED_RPM:]GAP_RATIO:CELLS (tiny background mesh)")
    ap.add_argument("--end", type=float, default=1.5, help="simulated time [s]")
    ap.add_argument("--max-courant", type=float, default=4.0)
    ap.add_argument("--report", action="store_true")
    args = ap.parse_args(argv)
    speed, gap, cells = parse_point(args.point)
    name = case_name(gap, cells, "tiny", True, speed)
    case = CASES / f"{name}_transient"
    if not args.report:
        prepare(GAP_CASES / name, case, args.end, args.max_courant)
        n_procs = json.loads((case / "kegel-case.json").read_text())["point"]["n_procs"]
        run_solver(case, "pimpleFoam", n_procs=n_procs, end_time=args.end,
                   progress=lambda st, eta: print(f"t = {st.time:.4f} s, ETA {eta / 60:.1f} min", flush=True)
                   if st.steps % 200 == 0 else None)
    result = report(case)
    command = " ".join([".venv/bin/python benchmarks/cfd_flooded_transient.py", *(sys.argv[1:] if argv is None else argv)])
    atomic_write_json(OUT, {"command": command, **result, "provenance": provenance()})
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
