"""How a flooded (steady, SIMPLE) CFD run converges, wall by wall: what its angular-momentum
balance says (issue 29).

For every finished flooded case of the gap study (``results/cfd/gap_study/32208_*``), the two
runs of the default sector that differ only in where the oil starts (``results/cfd/start_study/``:
at rest, the runner's start until this study, and turning with the cage; the default sector's two ran
about 3000 iterations with the steady test off, the others until it passed,
``benchmarks/cfd_start_study.py``), or the case folders named on the command line, the window means (100 iterations, as the flooded steady test) of
each wall's torque about the bearing axis (inner ring, shaft, outer ring, housing, cage, the
rollers' orbit moments), of the loss torque at the shaft and of the balance (sum of the wall
torques / |drive torque|), whole-bearing values; and the flooded steady test replayed on the
stored history (:class:`kegel.cfd_cases.run._SteadyMonitor`, one call over the whole history
applies it at every check point in order): where it stops.

    .venv/bin/python benchmarks/cfd_flooded_convergence.py [CASE_DIR ...]

Output: a Markdown summary on stdout and ``benchmarks/results/cfd_flooded_convergence.json``.
The case folders (GB) stay outside the repository; the JSON keeps what they gave.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
sys.path.insert(0, str(REPO))
CASES = REPO / "results" / "cfd" / "gap_study"
STARTS = REPO / "results" / "cfd" / "start_study"  # benchmarks/cfd_start_study.py and the two long runs
OUT = HERE / "results" / "cfd_flooded_convergence.json"
WINDOW = 100  # iterations
WALLS = ("inner_ring", "shaft", "outer_ring", "housing", "cage")


def wall_histories(case: Path) -> dict[str, np.ndarray]:
    """Each wall's torque about the bearing axis after every iteration (whole bearing, N m),
    the rollers' orbit moments summed, the loss torque at the shaft; ``iteration`` the index."""
    from kegel.cfd_cases.run import _forces, loss_torque_series, rollers_about_axis

    meta = json.loads((case / "kegel-case.json").read_text())
    copies = meta["geometry"].get("copies", 1)
    it, loss = loss_torque_series(case, meta)
    out = {"iteration": np.asarray(it), "loss": copies * np.asarray(loss)}
    for w in WALLS:
        f = _forces(case, w)
        out[w] = copies * np.interp(it, f.time, f.moment_total[:, 2])
    out["rollers_about_axis"] = copies * rollers_about_axis(case, meta, np.asarray(it))
    return out


def window_table(h: dict[str, np.ndarray], width: float = WINDOW, key: str = "to_iteration") -> list[dict]:
    """Means over consecutive windows of ``width`` (iterations; seconds for a transient run's
    force times, ``key`` naming the window's end: the run's last sample for a last window the run
    did not finish, whose row then says ``partial``), with the balance."""
    rows = []
    it = h["iteration"]
    last = float(it.max())
    for a in np.arange(0.0, last, width):
        m = (it > a) & (it <= a + width)
        if not m.any():
            continue
        end = min(a + width, last)
        row = {key: int(round(end)) if key == "to_iteration" else round(float(end), 6)}
        if end < a + width:
            row["partial"] = True
        for k in ("loss", *WALLS, "rollers_about_axis"):
            row[f"{k}_Nm"] = float(h[k][m].mean())
        total = sum(row[f"{k}_Nm"] for k in (*WALLS, "rollers_about_axis"))
        drive = abs(row["inner_ring_Nm"] + row["shaft_Nm"])
        row["balance"] = total / drive if drive else None
        rows.append(row)
    return rows


def replay_stop(case: Path, tolerance: float = 0.02) -> dict:
    """The flooded steady test replayed on the whole stored history: the iteration it stops at
    (None: it does not stop) and its last status line."""
    import kegel.cfd_cases.run as run

    meta = json.loads((case / "kegel-case.json").read_text())
    mon = run._SteadyMonitor(case, True, 1.0, tolerance, meta)
    mon.last_check = -1e9
    stopped = mon(None)
    return {"bodies": list(mon.BODIES), "tolerance": tolerance,
            "stop_iteration": mon.window[1] if stopped else None, "status": mon.status}


def main(argv: list[str] | None = None) -> int:
    from kegel.io import atomic_write_json, provenance

    argv = sys.argv[1:] if argv is None else argv
    cases = [Path(a) for a in argv] or [c for c in sorted(CASES.glob("32208_*rpm_flooded_*"))
                                         if (c / "results.json").is_file()] + sorted(STARTS.glob("*"))
    cases = [c for c in cases if (c / "kegel-case.json").is_file()]
    if not cases:
        print(f"no flooded case under {CASES}", file=sys.stderr)
        return 1
    result = []
    print("| case | iterations | loss, last window | housing: last window, change over it | balance, last window | steady test stops at |")
    print("| --- | --- | --- | --- | --- | --- |")
    for c in cases:
        h = wall_histories(c)
        rows = window_table(h)
        if len(rows) < 2:
            continue
        stop = replay_stop(c)
        last, prev = rows[-1], rows[-2]
        drive = abs(last["inner_ring_Nm"] + last["shaft_Nm"])
        dh = (last["housing_Nm"] - prev["housing_Nm"]) / drive
        result.append({"case": c.name, "iterations": int(h["iteration"].max()), "windows": rows, "replayed_stop": stop})
        print(f"| {c.name} | {int(h['iteration'].max())} | {1e3 * last['loss_Nm']:.2f} mN m | "
              f"{1e3 * last['housing_Nm']:.1f} mN m, {100 * dh:+.1f} % of the drive | "
              f"{100 * last['balance']:+.1f} % | {stop['stop_iteration'] or 'no stop'} |", flush=True)
    starts = [r for r in result if "_start_" in r["case"]]
    if starts:
        print("\nWhere the oil starts (whole-bearing mN m, window means of 100 iterations):\n")
        print("| case, start | to iteration | loss | inner ring | shaft | outer ring | housing | cage | rollers about the axis | balance |")
        print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
        for r in starts:
            for w in r["windows"]:
                if w["to_iteration"] % 500 == 0:
                    print(f"| {r['case'].split('rpm_flooded_50C_', 1)[0]} rpm, {r['case'].rsplit('_start_', 1)[1]} | "
                          f"{w['to_iteration']} | "
                          + " | ".join(f"{1e3 * w[k + '_Nm']:.2f}" for k in ("loss", *WALLS, "rollers_about_axis"))
                          + f" | {100 * w['balance']:+.1f} % |")
    atomic_write_json(OUT, {"command": " ".join([".venv/bin/python benchmarks/cfd_flooded_convergence.py", *argv]),
                            "window_iterations": WINDOW, "cases": result, "provenance": provenance()})
    print(f"wrote {OUT.relative_to(REPO)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
