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
3. the control: the frozen rotor run on from the same state for as long (a frozen oil bath's
   loss itself wanders by a few per cent from revolution to revolution, docs/cfd.md "Oil bath:
   how steady"), so that the difference of 2 and 3 is the moving mesh's alone;

and compares the loss torque at the shaft, cage revolution by cage revolution after the release,
with the frozen rotor's, beside the rings', the cage's and the rollers' torques about the axis
and the oil volume.

    .venv/bin/python benchmarks/cfd_oil_bath_moving_mesh.py [--revolutions 2] [--np 2] [--control-np 1] [--no-run]

Each run resumes when its case folder exists and is not finished (``results/cfd/moving_mesh/``):
give the same command again after a stop; a finished run is read, not run again. Output: ``benchmarks/results/cfd_oil_bath_moving_mesh.json`` (and a
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


def _point(frame: str, n_procs: int, speed_rpm: float = SPEED_RPM, **extra):
    from kegel.cfd_cases.run import CfdPoint

    return CfdPoint(bearing="32208", speed_rad_s=speed_rpm * math.pi / 30, temperature_K=323.15,
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


def _finished(case: Path, end_s: float | None = None) -> bool:
    """Whether the run in ``case`` reached its own end (its steady stop or its end time) and, when
    ``end_s`` is given, ran that far (a longer ``--revolutions`` runs it on)."""
    f = case / "results.json"
    if not f.is_file():
        return False
    data = json.loads(f.read_text())
    if data.get("stopped_by") not in ("steady torque", "end time / iteration limit"):
        return False
    return end_s is None or float(data.get("simulated_time_s") or 0.0) >= end_s * (1.0 - 1e-3)


def _by_quarter_revolution(moving: Path, control: Path, rev_s: float, reference_Nm: float) -> list[dict]:
    """The loss torque at the shaft of the moving mesh and of the frozen rotor run on, over each
    quarter cage revolution after the release that both runs have covered."""
    from kegel.cfd_cases.run import loss_torque_series

    def series(case: Path):
        return loss_torque_series(case, json.loads((case / "kegel-case.json").read_text()))

    (tm, lm), (tc, lc) = series(moving), series(control)
    q = 0.25 * rev_s
    rows = []
    for k in range(int(math.floor(min(tm[-1], tc[-1]) / q + 0.01))):  # a run ends within a step of its end time
        sm, sc = (tm >= k * q) & (tm < (k + 1) * q), (tc >= k * q) & (tc < (k + 1) * q)
        if sm.sum() < 5 or sc.sum() < 5:
            continue
        m, c = float(lm[sm].mean()), float(lc[sc].mean())
        rows.append({"cage_revolutions": [0.25 * k, 0.25 * (k + 1)], "from_s": k * q, "to_s": (k + 1) * q,
                     "moving_mesh_Nm": m, "moving_mesh_range_Nm": [float(lm[sm].min()), float(lm[sm].max())],
                     "frozen_run_on_Nm": c, "frozen_run_on_range_Nm": [float(lc[sc].min()), float(lc[sc].max())],
                     "moving_vs_frozen_run_on": m / c - 1.0, "moving_vs_frozen_steady": m / reference_Nm - 1.0})
    return rows


def _harmonic_amplitude(t, y, f_hz: float) -> float:
    """The amplitude of the component of frequency ``f_hz`` in the series ``y(t)``, over a span of
    a whole number of its periods (trapezoidal Fourier coefficient on the solver's own steps)."""
    import numpy as np

    span = t[-1] - t[0]
    e = np.exp(-2j * math.pi * f_hz * t)
    return float(2.0 * abs(np.trapezoid(y * e, t)) / span)


def _last_revolution(moving: Path, control: Path, rev_s: float) -> dict:
    """Over the last cage revolution both runs covered: the mean of the loss torque at the shaft
    and of each body's torque about the bearing axis (the rollers summed: their orbit drag), and
    the amplitude of each at the roller-pass frequency (rollers x cage revolutions per second),
    the ripple a roller passing through the oil surface makes on a moving mesh. A frozen rotor's
    rollers pass nothing, so its amplitude there is the noise floor."""
    import numpy as np

    from kegel.cfd_cases.run import (BALANCE_WALLS, angular_momentum_balance, fluid_gravity_torque,
                                     loss_torque_series, wall_torque_series)

    out: dict = {}
    metas = {c: json.loads((c / "kegel-case.json").read_text()) for c in (moving, control)}
    losses = {c: loss_torque_series(c, m) for c, m in metas.items()}
    t_end = min(float(t[-1]) for t, _ in losses.values())
    z = len(metas[moving]["rollers"])
    f_pass = z / rev_s
    for label, case in (("moving_mesh", moving), ("frozen_run_on", control)):
        meta = metas[case]
        t, loss = losses[case]
        k = (t > t_end - rev_s) & (t <= t_end)
        tk = t[k]
        _, walls = wall_torque_series(case, meta)  # at the same (inner ring's) sample times as the loss
        series = {"loss_torque_at_shaft": loss[k], "rollers_about_axis": walls["rollers_about_bearing_axis"][k]}
        for body in BALANCE_WALLS:
            series[body] = walls[body][k]
        out[label] = {name: {"mean_Nm": float(np.mean(y)), "roller_pass_amplitude_Nm": _harmonic_amplitude(tk, y, f_pass),
                             "std_Nm": float(np.std(y))} for name, y in series.items()}
        # the angular-momentum balance over the revolution: the frozen rotor's MRF term is the
        # difference between the two runs' equations
        n_procs = int(json.loads((case / "results.json").read_text())["fidelity"]["n_procs"])
        out.setdefault("balance", {})[label] = angular_momentum_balance(
            {name: {"total": float(np.mean(walls[name][k]))} for name in walls},
            fluid_gravity_torque(case, meta, (t_end - rev_s, t_end), n_procs))
    out.update({"from_s": t_end - rev_s, "to_s": t_end, "roller_pass_hz": f_pass, "rollers": z})
    return out


def main(argv: list[str] | None = None) -> int:
    import argparse

    import numpy as np

    import kegel
    from kegel.cfd_cases.run import run_case
    from kegel.io import atomic_write_json, provenance

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--revolutions", type=float, default=2.0,
                    help="cage revolutions the moving mesh (and the control) run after the release (default 2: "
                         "0.143 s at 2000 rpm, about 30 min each on 2 cores alone)")
    ap.add_argument("--speed", type=float, default=SPEED_RPM, help="shaft speed [rpm] (default 2000)")
    ap.add_argument("--np", type=int, default=2, help="MPI processes (default 2)")
    ap.add_argument("--control-np", type=int,
                    help="MPI processes of the control run (default --np; a resumed run keeps its own)")
    ap.add_argument("--work", type=Path, default=CASES,
                    help="folder of the three case folders (default results/cfd/moving_mesh); a finished frozen "
                         "run copied there as frozen_<N>rpm_tiny is the start, not run again")
    ap.add_argument("--output", type=Path,
                    help="the JSON written (default benchmarks/results/cfd_oil_bath_moving_mesh.json at 2000 rpm, "
                         "..._<N>rpm.json at another speed, so that no speed overwrites another's)")
    ap.add_argument("--no-run", action="store_true",
                    help="run nothing: compare what the case folders hold so far (an unfinished run's force files)")
    args = ap.parse_args(argv)

    def log(s: str) -> None:
        print(s, file=sys.stderr)

    work = args.work.resolve()
    rpm = args.speed
    frozen_case, moving_case = work / f"frozen_{rpm:g}rpm_tiny", work / f"moving_{rpm:g}rpm_tiny"
    control_case = work / f"frozen_run_on_{rpm:g}rpm_tiny"
    t0 = time.monotonic()
    if not _finished(frozen_case) and not args.no_run:
        run_case(_point("cage", args.np, rpm, max_wall_time_s=3600.0), frozen_case, log=log, progress=False)
    frozen = _summary(frozen_case)
    meta = json.loads((frozen_case / "kegel-case.json").read_text())
    cage_rev_s = 2 * math.pi / abs(meta["kinematics"]["cage_rad_s"])
    end = args.revolutions * cage_rev_s
    for frame, case, n in (("moving_mesh", moving_case, args.np), ("cage", control_case, args.control_np or args.np)):
        if not _finished(case, end) and not args.no_run:
            run_case(_point(frame, n, rpm, initial_from=str(frozen_case), end_time_s=end, steady_tolerance=0.0),
                     case, log=log, progress=False)
    done = _finished(moving_case) and _finished(control_case)
    moving = _summary(moving_case) if _finished(moving_case) else None
    control = _summary(control_case) if _finished(control_case) else None
    rows = _by_quarter_revolution(moving_case, control_case, cage_rev_s, frozen["loss_torque_Nm"])
    both = [r for r in rows if r["from_s"] >= rows[-1]["from_s"] - 0.75 * cage_rev_s - 1e-12] if rows else []
    last_rev = (sum(r["moving_mesh_Nm"] for r in both) / sum(r["frozen_run_on_Nm"] for r in both) - 1.0
                if len(both) == 4 else None)
    by_body = _last_revolution(moving_case, control_case, cage_rev_s) if rows else None
    output = args.output or (OUT if rpm == SPEED_RPM else OUT.with_name(f"{OUT.stem}_{rpm:g}rpm.json"))
    atomic_write_json(output, {
        "command": " ".join(["benchmarks/cfd_oil_bath_moving_mesh.py", *(sys.argv[1:] if argv is None else argv)]),
        "point": f"32208, FVA 3, 50 degC, {rpm:g} rpm, oil to the shaft centre, tiny, real rollers, g = 0.08 D_w, "
                 "Courant 10 / 3",
        "partial": not done, "released_for_s": rows[-1]["to_s"] if rows else 0.0,
        "cage_revolution_s": cage_rev_s, "frozen_rotor": frozen, "moving_mesh": moving,
        "frozen_rotor_run_on": control, "by_quarter_cage_revolution": rows,
        "moving_vs_frozen_run_on_last_revolution": last_rev,
        "last_revolution_by_body": by_body,
        "session_wall_s": time.monotonic() - t0, "kegel_version": kegel.__version__, "provenance": provenance()})
    print(f"frozen rotor: {1e3 * frozen['loss_torque_Nm']:.2f} mN m (steady: {frozen['steady']}, "
          f"{frozen['runtime_s'] / 60:.0f} min)" + ("" if done else "; the released runs are not finished"))
    for r in rows:
        a, b = r["cage_revolutions"]
        print(f"cage revolutions {a:.2f}-{b:.2f}: moving mesh {1e3 * r['moving_mesh_Nm']:.2f} mN m, frozen run on "
              f"{1e3 * r['frozen_run_on_Nm']:.2f}: {100 * r['moving_vs_frozen_run_on']:+.1f} %")
    if last_rev is not None:
        print(f"last cage revolution: moving mesh {100 * last_rev:+.1f} % against the frozen rotor run on")
    if by_body is not None:
        lr = by_body
        print(f"last cage revolution ({lr['from_s']:.3f}-{lr['to_s']:.3f} s), mean and amplitude at the roller "
              f"pass ({lr['roller_pass_hz']:.0f} Hz), moving mesh | frozen run on, mN m:")
        for name, m in lr["moving_mesh"].items():
            c = lr["frozen_run_on"][name]
            print(f"  {name:22s} {1e3 * m['mean_Nm']:8.3f} {1e3 * m['roller_pass_amplitude_Nm']:7.3f} | "
                  f"{1e3 * c['mean_Nm']:8.3f} {1e3 * c['roller_pass_amplitude_Nm']:7.3f}")
        for label, b in lr["balance"].items():
            rel = b["relative_to_drive_torque"]
            print(f"  balance, {label}: walls sum to {1e3 * b['sum_of_wall_torques_Nm']:+.3f} mN m, weight's moment "
                  + ("?" if b["weight_moment_on_fluid_Nm"] is None else f"{1e3 * b['weight_moment_on_fluid_Nm']:+.3f}")
                  + " mN m: " + ("?" if rel is None else f"{100 * rel:+.1f} % of the drive torque"))
    if moving is None:
        return 0
    print(f"moving mesh: {moving['runtime_s'] / 60:.0f} min, oil volume change {moving['oil_volume_change']}")
    return 0 if np.isfinite(moving["loss_torque_Nm"]) else 1


if __name__ == "__main__":
    sys.exit(main())
