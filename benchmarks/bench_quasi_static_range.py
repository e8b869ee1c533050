"""The quasi-static solution over the load range an engineer asks for: radial load up to the
lift-off limit and misalignment up to the scenes' 10 mrad (32216, Fa 6 kN, 2000 rpm, 50 degC).

Each point is solved cold (a fresh model and state), once, at the default level (30 AST slices,
rib cell model 32 x 32, the walls cage model): the radial loads with ``kegel.Bearing("32216")
.friction`` (half-roller oil level, as docs/models.md's table), the misalignments as the Table 1
scene's 2000 rpm point (``examples/32216_table1.toml``, as
tests/python/test_quasi_static_gates.py). It reports whether the point converged, the friction
torque, the share of time the rollers spend at a pocket wall and the CPU time of the calling
thread (``time.thread_time``; another job on the second core does not count).

Run: .venv/bin/python benchmarks/bench_quasi_static_range.py
writes benchmarks/results/quasi_static_range.json
"""

from __future__ import annotations

import dataclasses
import json
import time
from pathlib import Path

import kegel
from kegel.run import _quasi_static_point
from kegel.scene import load_scene

OUT = Path(__file__).resolve().parent / "results" / "quasi_static_range.json"
ROOT = Path(__file__).resolve().parents[1]
RADIAL_kN = [0, 5, 10, 12, 13, 14, 15, 16, 17, 18, 19, 20]
MISALIGNMENT_mrad = [0, 1, 2, 4, 5, 8, 10]


def _point(scene, op, friction) -> dict:
    c0 = time.thread_time()
    dist, r = _quasi_static_point(scene, scene.fidelity, op, friction)
    cpu = time.thread_time() - c0
    return {"converged": bool(r.converged), "torque_Nm": r.drive_torque_Nm, "wall_share": r.pocket_fraction,
            "cage_model": r.cage_model, "ring_iterations": int(dist.iterations), "cpu_s": cpu,
            "failure": r.failure}


def _bearing_point(radial_kN: float) -> dict:
    c0 = time.thread_time()
    r = kegel.Bearing("32216").friction(speed="2000 rpm", axial_load="6 kN", temperature="50 degC",
                                        radial_load_kN=radial_kN)
    cpu = time.thread_time() - c0
    p = r.points[0]
    return {"converged": bool(r.converged), "torque_Nm": r.friction_torque_Nm, "wall_share": p["pocket_fraction"],
            "cage_model": p["cage_model"], "ring_iterations": None, "cpu_s": cpu, "failure": r.failure}


def main() -> None:
    scene = load_scene(ROOT / "examples" / "32216_table1.toml")
    friction = kegel.load_friction()
    op0 = next(op for op in scene.operating_points if op.speed_rpm == 2000 and op.temperature_degC == 50)
    rows = []
    for fr in RADIAL_kN:
        row = {"radial_kN": fr, "misalignment_mrad": 0.0, **_bearing_point(float(fr))}
        rows.append(row)
        print(f"Fr {fr:5.1f} kN: {row['torque_Nm']:.4f} N m, wall share {row['wall_share']:.2f}, "
              f"{row['cpu_s']:.2f} s CPU, converged {row['converged']}", flush=True)
    for mis in MISALIGNMENT_mrad:
        row = {"radial_kN": 0.0, "misalignment_mrad": mis,
               **_point(scene, dataclasses.replace(op0, misalignment_rad=1e-3 * mis), friction)}
        rows.append(row)
        print(f"tilt {mis:4.1f} mrad: {row['torque_Nm']:.4f} N m, wall share {row['wall_share']:.2f}, "
              f"{row['ring_iterations']} ring iterations, {row['cpu_s']:.2f} s CPU, converged {row['converged']}",
              flush=True)
    OUT.write_text(json.dumps({"command": "benchmarks/bench_quasi_static_range.py",
                               "point": "32216, Fa 6 kN, 2000 rpm, 50 degC, default level, cold; radial: kegel.Bearing, half-roller oil level; misalignment: examples/32216_table1.toml",
                               "rows": rows, "kegel_version": kegel.__version__}, indent=1) + "\n")
    print(f"written: {OUT}")


if __name__ == "__main__":
    main()
