"""Run every benchmark in this folder (``bench_*.py``) and print their reports.

Benchmarks are kept apart from tests: they measure, they do not pass or fail. Each reports
medians of repeated runs (the machines are noisy) and, where a fidelity choice exists, the
deviation from the finest fidelity beside the runtime.
"""

from __future__ import annotations

import runpy
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent


def main() -> int:
    for path in sorted(HERE.glob("bench_*.py")):
        print(f"== {path.name}")
        sys.stdout.flush()
        runpy.run_path(str(path), run_name="__main__")
    return 0


if __name__ == "__main__":
    sys.exit(main())
