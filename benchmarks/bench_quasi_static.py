"""Speed against error of the quasi-static bearing solution (32216, Table 1 conditions).

For each fidelity level (slice model and slice count) it reports the median runtime of one
operating point (load distribution + friction, cold: a fresh model each time, and warm: the
next point of a sweep) and the deviation of the friction torque from the finest level; a 50-point
speed sweep at the default level; the combined-load point (Fa 6 kN, Fr 6.5 kN) at the default and
the fine level, and along a speed and a radial-load sweep; writes
benchmarks/results/quasi_static.{json,png}.

Times are medians of repeated runs, as wall time and as the CPU time of the calling thread
(``time.thread_time``). On a machine that runs another job (the CFD studies run OpenFOAM on both
cores at a raised priority) the wall time measures the scheduler, not kegel: the CPU time is the
figure to compare.

Run: .venv/bin/python benchmarks/bench_quasi_static.py
"""

from __future__ import annotations

import json
import math
import statistics
import time
from pathlib import Path

import kegel
from kegel.quasi_static import bearing_friction, bearing_model
from kegel.tribology import load_friction
from kegel import _core

OUT = Path(__file__).resolve().parent / "results"
RPM = math.pi / 30
# (label, slice model, slices, rib cells; 0 = one closed-form ellipse)
LEVELS = [("fast", "independent", 10, 0), ("", "independent", 30, 0), ("", "alternative_slicing", 10, 0),
          ("", "alternative_slicing", 30, 0), ("default", "alternative_slicing", 30, 32),
          ("", "alternative_slicing", 60, 32), ("fine", "alternative_slicing", 100, 64)]
FINEST = ("fine", "alternative_slicing", 100, 64)
DEFAULT = ("default", "alternative_slicing", 30, 32)


def _cold_warm(g, b, m, lub, fr, kw: dict, n: int, method: str, cells: int, repeats: int) -> tuple:
    """Medians of ``repeats`` cold points (a fresh model and state) and warm points (the next
    point, 2050 rpm, from the cold point's state): wall and thread CPU time [ms]."""
    out: dict[str, list[float]] = {"cold_ms": [], "warm_ms": [], "cold_cpu_ms": [], "warm_cpu_ms": []}
    f = None
    for _ in range(repeats):
        t0, c0 = time.perf_counter(), time.thread_time()
        model = bearing_model(g, b, m, slices=n, method=method)
        data = _core.quasi_static.BearingData(model)
        _, f = bearing_friction(g, b, m, lub, fr, model=model, data=data, rib_cells=cells, **kw)
        t1, c1 = time.perf_counter(), time.thread_time()
        _, f2 = bearing_friction(g, b, m, lub, fr, model=model, data=data, rib_cells=cells,
                                 **{**kw, "inner_speed_rad_s": 2050 * RPM})
        t2, c2 = time.perf_counter(), time.thread_time()
        if not (f.converged and f2.converged):
            raise RuntimeError(f"not converged at {kw}: {f.failure or f2.failure}")
        out["cold_ms"].append(t1 - t0)
        out["warm_ms"].append(t2 - t1)
        out["cold_cpu_ms"].append(c1 - c0)
        out["warm_cpu_ms"].append(c2 - c1)
    return f, {k: 1e3 * statistics.median(v) for k, v in out.items()}


def main() -> None:
    b = kegel.load_bearing("32216")
    m = kegel.load_material("bearing_steel")
    g = kegel.derive_geometry(b, m)
    lub, fr = kegel.load_lubricant("FVA3"), load_friction()
    kw = dict(temperature_K=323.15, inner_speed_rad_s=2000 * RPM, axial_N=6000.0)
    rows = []
    torque = {}
    for level in LEVELS:
        label, method, n, cells = level
        repeats = 5 if n <= 30 and cells <= 32 else 3
        f, t = _cold_warm(g, b, m, lub, fr, kw, n, method, cells, repeats)
        torque[level] = f.drive_torque_Nm
        rows.append({"level": label, "method": method, "slices": n, "rib_cells": cells, **t,
                     "torque_Nm": f.drive_torque_Nm})
    ref = torque[FINEST]
    for r in rows:
        r["deviation_from_finest"] = r["torque_Nm"] / ref - 1
    # 50-point speed sweep at the default level (warm-started along the sweep)
    model = bearing_model(g, b, m, slices=DEFAULT[2], method=DEFAULT[1])
    data = _core.quasi_static.BearingData(model)
    t0, c0 = time.perf_counter(), time.thread_time()
    for k in range(50):
        bearing_friction(g, b, m, lub, fr, model=model, data=data, rib_cells=DEFAULT[3],
                         **{**kw, "inner_speed_rad_s": (500 + 3500 * k / 49) * RPM})
    sweep_s, sweep_cpu_s = time.perf_counter() - t0, time.thread_time() - c0

    print("quasi-static solution, 32216, Fa = 6 kN, 2000 rpm, 50 degC "
          "(medians; finest = AST, 100 slices, rib cell model 64 x 64)")
    print(f"{'level':8s} {'slice model':20s} {'slices':>6s} {'rib':>8s} {'cold CPU [ms]':>14s} {'warm CPU [ms]':>14s} "
          f"{'torque [N m]':>13s} {'vs finest':>10s}")
    for r in rows:
        rib = f"{r['rib_cells']}x{r['rib_cells']}" if r["rib_cells"] else "ellipse"
        print(f"{r['level']:8s} {r['method']:20s} {r['slices']:6d} {rib:>8s} {r['cold_cpu_ms']:14.1f} {r['warm_cpu_ms']:14.1f} "
              f"{r['torque_Nm']:13.5f} {100 * r['deviation_from_finest']:9.3f}%")
    # the combined load (no symmetry to exploit) at the default and the fine level
    kw_c = {**kw, "radial_N": 6500.0}
    fc, comb = _cold_warm(g, b, m, lub, fr, kw_c, DEFAULT[2], DEFAULT[1], DEFAULT[3], 5)
    ff, comb_fine = _cold_warm(g, b, m, lub, fr, kw_c, FINEST[2], FINEST[1], FINEST[3], 2)
    comb.update(torque_Nm=fc.drive_torque_Nm, fine_torque_Nm=ff.drive_torque_Nm,
                deviation_from_fine=fc.drive_torque_Nm / ff.drive_torque_Nm - 1, cage_model=fc.cage_model,
                fine_cold_cpu_ms=comb_fine["cold_cpu_ms"], fine_warm_cpu_ms=comb_fine["warm_cpu_ms"])
    # the combined load along a sweep: 50 speeds from 1500 to 2500 rpm (20 rpm apart), warm-started
    # point after point, and 10 radial loads from 6 to 7 kN (as a load-spectrum study walks)
    model = bearing_model(g, b, m, slices=DEFAULT[2], method=DEFAULT[1])
    data = _core.quasi_static.BearingData(model)
    bearing_friction(g, b, m, lub, fr, model=model, data=data, rib_cells=DEFAULT[3], **{**kw_c, "inner_speed_rad_s": 1500 * RPM})
    sweeps = {}
    for name, points in (("speed", [{**kw_c, "inner_speed_rad_s": (1500 + 20 * k) * RPM} for k in range(1, 51)]),
                         ("radial_load", [{**kw_c, "inner_speed_rad_s": 2500 * RPM, "radial_N": 6000.0 + 100.0 * k}
                                          for k in range(1, 11)])):
        c0 = time.thread_time()
        for p in points:
            _, f = bearing_friction(g, b, m, lub, fr, model=model, data=data, rib_cells=DEFAULT[3], **p)
            if not f.converged:
                raise RuntimeError(f"not converged along the {name} sweep: {f.failure}")
        sweeps[name] = 1e3 * (time.thread_time() - c0) / len(points)
    comb.update(sweep_speed_cpu_ms_per_point=sweeps["speed"], sweep_radial_cpu_ms_per_point=sweeps["radial_load"])
    print(f"50-point speed sweep (500-4000 rpm) at the default level: {sweep_s:.2f} s "
          f"({1e3 * sweep_s / 50:.0f} ms per point; CPU {1e3 * sweep_cpu_s / 50:.1f} ms per point); target per point: 20 ms")
    print(f"combined load Fa = 6 kN, Fr = 6.5 kN at the default level (no symmetry): "
          f"cold {comb['cold_ms']:.0f} ms wall / {comb['cold_cpu_ms']:.1f} ms CPU, warm {comb['warm_ms']:.0f} ms wall / "
          f"{comb['warm_cpu_ms']:.1f} ms CPU; {fc.drive_torque_Nm:.5f} N m, "
          f"{100 * comb['deviation_from_fine']:+.3f} % from fine ({ff.drive_torque_Nm:.5f} N m)")
    print(f"  along a sweep (CPU per point): speed 1500-2500 rpm in 20 rpm steps {sweeps['speed']:.1f} ms, "
          f"radial load 6-7 kN in 100 N steps {sweeps['radial_load']:.1f} ms")
    OUT.mkdir(exist_ok=True)
    (OUT / "quasi_static.json").write_text(json.dumps({"levels": rows, "sweep_50_points_s": sweep_s, "sweep_50_points_cpu_s": sweep_cpu_s,
                                                       "combined_load": comb,
                                                       "note": "medians; wall and thread CPU time; a CFD job (OpenFOAM on "
                                                               "both cores) ran in the background"}, indent=2))
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    for r in rows:
        x, y = r["warm_cpu_ms"], max(abs(r["deviation_from_finest"]), 1e-5)
        ax.loglog([x], [y], marker="s" if r["method"] == "independent" else ("o" if not r["rib_cells"] else "^"),
                  color="C0" if not r["rib_cells"] else "C1")
        rib = f", rib {r['rib_cells']}" if r["rib_cells"] else ""
        ax.annotate(f"{r['level'] or ''} {r['method'][:3]} {r['slices']}{rib}", (x, y), fontsize=7)
    ax.set_xlabel("CPU time per operating point, warm [ms]")
    ax.set_ylabel("|torque / finest - 1|")
    ax.set_title("quasi-static 32216: speed against error (ind/alt slices, rib cells)", fontsize=9)
    fig.tight_layout()
    fig.savefig(OUT / "quasi_static.png", dpi=110)
    print(f"table and plot: {OUT / 'quasi_static.json'}, {OUT / 'quasi_static.png'}")


if __name__ == "__main__":
    main()
