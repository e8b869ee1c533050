"""Where a flooded CFD run's oil starts, and what it changes: the stored runs (oil at rest, the
runner's start until 2026-11-26) against the same cases started with the oil turning with the
cage (the runner's start since), the steady test taking every wall (issue 29).

The flooded 32208, FVA 3 at 50 degC, one-pitch sectors as in the gap study
(``benchmarks/cfd_gap_study.py``); each point ``SPEED_RPM:GAP_RATIO:CELLS`` (tiny background
mesh) runs, or resumes, in ``results/cfd/start_study/<gap-study case name>_start_cage`` until the
steady test passes (at most ``--max-iterations``), and its results.json is copied to
``benchmarks/results/cfd_start_study/<case>/``. The table sets each beside the gap study's stored
run of the same case (``benchmarks/results/cfd_gap_study/<case>/results.json``, from rest).

    .venv/bin/python benchmarks/cfd_start_study.py 500:0.08:3 1000:0.08:3 4000:0.08:3 0.02:3 ...
    .venv/bin/python benchmarks/cfd_start_study.py --from-rest 4000:0.08:3 --max-iterations 4000
    .venv/bin/python benchmarks/cfd_start_study.py --report
    .venv/bin/python benchmarks/cfd_start_study.py --windows 0.02:4
    .venv/bin/python benchmarks/cfd_start_study.py 0.02:6 --map-from 4 --max-iterations 1500

``--map-from CELLS``: the points start from the flow of the same gap's cage-start case with CELLS
cells across the gap (its latest reconstructed time, mapped by ``mapFieldsPar``; ``initial_from``
in the runner), in ``results/cfd/start_study/<case>_from_n<CELLS>``: a mesh too fine to run from
the start within a session (6 cells across 0.02 D_w: 4.6 M cells, about 18 s an iteration) has
only its gaps' refinement to settle.

``--from-rest``: the gap study's stored run of the point (from rest, ``results/cfd/gap_study/``)
copied to ``results/cfd/start_study/<case>_start_rest`` (once) and run on there until the steady
test, every wall, passes: whether a stored run stopped short of its steady state or found
another one.

(a point without a speed is at 2000 rpm). Output: a Markdown table and
``benchmarks/results/cfd_start_study.json``. The case folders (GB) stay outside the repository.
"""

from __future__ import annotations

import argparse
import json
import math
import shutil
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
sys.path.insert(0, str(HERE))

from cfd_gap_study import SPEED_RPM, STORE as FROM_REST, TEMPERATURE_K, case_name  # noqa: E402  (one study point)

CASES = REPO / "results" / "cfd" / "start_study"
STORE = HERE / "results" / "cfd_start_study"
OUT = HERE / "results" / "cfd_start_study.json"


def parse_point(text: str) -> tuple[float, float, int]:
    """``[speed_rpm:]gap_ratio:cells`` -> (speed_rpm, gap_ratio, cells)."""
    parts = text.split(":")
    try:
        if len(parts) == 2:
            return SPEED_RPM, float(parts[0]), int(parts[1])
        if len(parts) == 3:
            return float(parts[0]), float(parts[1]), int(parts[2])
    except ValueError:
        pass
    raise SystemExit(f"cfd_start_study: point {text!r}: expected [SPEED_RPM:]GAP_RATIO:CELLS, e.g. 500:0.08:3")


def _point(speed_rpm: float, gap: float, cells: int, n_procs: int, max_iterations: int,
           initial_from: Path | None = None):
    """The flooded study point as a :class:`kegel.cfd_cases.run.CfdPoint` (tiny background, sector)."""
    from kegel.cfd_cases.run import CfdPoint

    return CfdPoint(bearing="32208", speed_rad_s=speed_rpm * math.pi / 30, temperature_K=TEMPERATURE_K,
                    oil_level_m=None, mesh="tiny", n_procs=n_procs, max_iterations=max_iterations, gap_ratio=gap,
                    cells_across_gap=cells, sector=True,
                    initial_from=None if initial_from is None else str(initial_from.resolve()))


def _suffix(map_from: int | None) -> str:
    """The case folder's suffix: the runner's start (the oil turning with the cage) or a start
    mapped from the cage-start case with ``map_from`` cells across the gap."""
    return "_start_cage" if map_from is None else f"_from_n{map_from}"


def _stored_as(name: str, map_from: int | None) -> str:
    """The folder in ``STORE`` of a case: the gap-study case name, with the suffix for a mapped start."""
    return name if map_from is None else f"{name}{_suffix(map_from)}"


def run_point(speed_rpm: float, gap: float, cells: int, n_procs: int, max_iterations: int,
              map_from: int | None = None) -> Path:
    """Run (or resume) one case from the runner's start, or from the flow of the same gap with
    ``map_from`` cells across it; copy its results.json into ``STORE``."""
    from kegel.cfd_cases.run import run_case

    name = case_name(gap, cells, "tiny", True, speed_rpm)
    source = None if map_from is None else CASES / f"{case_name(gap, map_from, 'tiny', True, speed_rpm)}_start_cage"
    p = _point(speed_rpm, gap, cells, n_procs, max_iterations, source)
    case = CASES / f"{name}{_suffix(map_from)}"
    run_case(p, case, progress=True, log=lambda s: print(s, file=sys.stderr, flush=True))
    dest = STORE / _stored_as(name, map_from)
    dest.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(case / "results.json", dest / "results.json")
    store_windows(speed_rpm, gap, cells, map_from)
    return dest / "results.json"


def store_windows(speed_rpm: float, gap: float, cells: int, map_from: int | None = None) -> Path:
    """The 100-iteration window means of every wall's torque, the loss and the balance of the
    point's cage-start case (``benchmarks/cfd_flooded_convergence.py``'s table), stored beside its
    results.json: how far a run that stopped short of the steady test still had to go."""
    from cfd_flooded_convergence import wall_histories, window_table
    from kegel.io import atomic_write_json

    name = case_name(gap, cells, "tiny", True, speed_rpm)
    case = f"{name}{_suffix(map_from)}"
    rows = window_table(wall_histories(CASES / case))
    dest = STORE / _stored_as(name, map_from)
    dest.mkdir(parents=True, exist_ok=True)
    atomic_write_json(dest / "windows.json", {"case": case, "window_iterations": 100, "rows": rows})
    return dest / "windows.json"


def continue_from_rest(speed_rpm: float, gap: float, cells: int, max_iterations: int) -> Path:
    """The gap study's stored run of the point, copied once and run on until steady."""
    from cfd_gap_study import CASES as GAP_CASES
    from kegel.cfd_cases.run import run_case

    name = case_name(gap, cells, "tiny", True, speed_rpm)
    case = CASES / f"{name}_start_rest"
    if not case.exists():
        CASES.mkdir(parents=True, exist_ok=True)
        shutil.copytree(GAP_CASES / name, case, symlinks=True)
    n_procs = json.loads((case / "kegel-case.json").read_text())["point"]["n_procs"]
    run_case(_point(speed_rpm, gap, cells, n_procs, max_iterations), case, progress=True, log=lambda s: print(s, file=sys.stderr, flush=True))
    _store_run_on(name, json.loads((case / "results.json").read_text()))
    return case / "results.json"


def _store_run_on(name: str, data: dict) -> Path:
    """The summary of a from-rest run run on (its case folder is outside git), beside the point's
    stored results: the report reads it when the folder is gone."""
    from kegel.io import atomic_write_json

    dest = STORE / name / "start_rest_run_on.json"
    dest.parent.mkdir(parents=True, exist_ok=True)
    atomic_write_json(dest, {"case": f"{name}_start_rest", "summary": _summary(data)})
    return dest


def _summary(data: dict) -> dict:
    t = data["torques_Nm"]
    return {"iterations": data["iterations"], "steady": data["steady"], "stopped_by": data.get("stopped_by"),
            "runtime_s": data["runtime_s"], "cfd_loss_Nm": data["loss_torque_at_shaft_Nm"],
            "cage_Nm": t["cage"]["total"], "outer_ring_Nm": t["outer_ring"]["total"],
            "housing_Nm": t["housing"]["total"],
            "rollers_about_axis_Nm": t.get("rollers_about_bearing_axis", {}).get("total"),
            "balance": data["angular_momentum_balance"]["relative_to_drive_torque"]}


def report() -> list[dict]:
    rows = []
    for f in sorted(STORE.glob("*/results.json")):
        new = _summary(json.loads(f.read_text()))
        old_f = FROM_REST / f.parent.name / "results.json"
        old = _summary(json.loads(old_f.read_text())) if old_f.is_file() else None
        on_f = CASES / f"{f.parent.name}_start_rest" / "results.json"
        kept = f.parent / "start_rest_run_on.json"
        on = (_summary(json.loads(on_f.read_text())) if on_f.is_file() else
              json.loads(kept.read_text())["summary"] if kept.is_file() else None)
        mapped = "_from_n" in f.parent.name  # started from another run's flow (--map-from), not with the cage
        rows.append({"case": f.parent.name, "start": "mapped" if mapped else "cage",
                     "start_cage": new, "start_rest": old, "start_rest_run_on": on})
    print("| case | from rest: iterations, loss | with the cage (or mapped: _from_nN): iterations (stopped by), loss | loss change | "
          "cage torque change | balance (rest / cage) |")
    print("| --- | --- | --- | --- | --- | --- |")
    for r in rows:
        n, o = r["start_cage"], r["start_rest"]
        stop = n["stopped_by"] or ("steady" if n["steady"] else "limit")
        if o is None:
            print(f"| {r['case']} | | {n['iterations']:.0f} ({stop}), {1e3 * n['cfd_loss_Nm']:.2f} mN m | | | "
                  f"/ {100 * n['balance']:+.1f} % |")
            continue
        print(f"| {r['case']} | {o['iterations']:.0f}, {1e3 * o['cfd_loss_Nm']:.2f} mN m | {n['iterations']:.0f} "
              f"({stop}), {1e3 * n['cfd_loss_Nm']:.2f} mN m | {100 * (n['cfd_loss_Nm'] / o['cfd_loss_Nm'] - 1):+.2f} % | "
              f"{100 * (n['cage_Nm'] / o['cage_Nm'] - 1):+.1f} % | {100 * o['balance']:+.1f} / {100 * n['balance']:+.1f} % |")
    for r in rows:
        on = r["start_rest_run_on"]
        if on is not None:
            n = r["start_cage"]
            print(f"\n{r['case']}, from rest run on: {on['iterations']:.0f} iterations "
                  f"({on['stopped_by'] or ('steady' if on['steady'] else 'limit')}), loss {1e3 * on['cfd_loss_Nm']:.2f} mN m "
                  f"({100 * (n['cfd_loss_Nm'] / on['cfd_loss_Nm'] - 1):+.2f} % from it with the cage), cage torque "
                  f"{1e3 * on['cage_Nm']:.2f} mN m ({100 * (n['cage_Nm'] / on['cage_Nm'] - 1):+.1f} %), "
                  f"balance {100 * on['balance']:+.1f} %")
    return rows


def main(argv: list[str] | None = None) -> int:
    from kegel.io import atomic_write_json, provenance

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("points", nargs="*", help="[SPEED_RPM:]GAP_RATIO:CELLS")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--max-iterations", type=int, default=3000)
    ap.add_argument("--report", action="store_true", help="only re-read the stored results")
    ap.add_argument("--from-rest", nargs="+", default=[], metavar="POINT",
                    help="run the gap study's stored run (from rest) of these points on until steady")
    ap.add_argument("--windows", nargs="+", default=[], metavar="POINT",
                    help="only store the window means of these points' cases (windows.json)")
    ap.add_argument("--map-from", type=int, metavar="CELLS",
                    help="start the points from the same gap's cage-start case with CELLS cells across it")
    args = ap.parse_args(argv)
    if args.windows:
        for text in args.windows:
            print(store_windows(*parse_point(text), args.map_from), file=sys.stderr)
        return 0
    for text in [] if args.report else args.from_rest:
        continue_from_rest(*parse_point(text), args.max_iterations)
    for text in [] if args.report else args.points:
        t0 = time.monotonic()
        run_point(*parse_point(text), args.np, args.max_iterations, args.map_from)
        print(f"cfd_start_study: {text} done in {time.monotonic() - t0:.0f} s", file=sys.stderr, flush=True)
    rows = report()
    command = " ".join([".venv/bin/python benchmarks/cfd_start_study.py", *(argv if argv is not None else sys.argv[1:])])
    atomic_write_json(OUT, {"command": command, "rows": rows, "provenance": provenance()})
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
