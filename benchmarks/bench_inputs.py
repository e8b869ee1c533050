"""Cost of the input stage: scene validation, geometry derivation, lubricant properties.

Reports medians over repeated runs (time.perf_counter) and the spread (min-max).
Run: .venv/bin/python benchmarks/bench_inputs.py
"""

from __future__ import annotations

import statistics
import time
from pathlib import Path

import kegel
from kegel import _core
from kegel.geometry import derive_geometry

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def median_time(fn, repeats: int = 7, number: int = 1) -> tuple[float, float, float]:
    samples = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        samples.append((time.perf_counter() - t0) / number)
    return statistics.median(samples), min(samples), max(samples)


def main() -> None:
    scene_file = EXAMPLES / "32216_table1.toml"
    bearing = kegel.load_bearing("32216")
    steel = kegel.load_material("bearing_steel")
    lub = kegel.load_lubricant("FVA3").core
    rows = [
        ("load_scene (32216 Table 1, 16 points)", median_time(lambda: kegel.load_scene(scene_file), number=20)),
        ("derive_geometry (32216)", median_time(lambda: derive_geometry(bearing, steel), number=200)),
        ("viscosity_Pas (Dicke, one call via Python)", median_time(lambda: _core.viscosity_Pas(lub, 323.15, 1e9), number=20000)),
    ]
    print(f"{'stage':48s} {'median':>12s} {'min':>12s} {'max':>12s}")
    for name, (med, lo, hi) in rows:
        print(f"{name:48s} {med*1e6:10.2f} us {lo*1e6:10.2f} us {hi*1e6:10.2f} us")


if __name__ == "__main__":
    main()
