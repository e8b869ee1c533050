"""Copy kegel CFD results into the repository, compact: benchmarks/results/cfd/<case>/results.json.

    python benchmarks/collect_cfd_results.py results/cfd/sweep_flooded_small results/cfd/sweep_shaft_center_tiny

Each ``results.json`` under the given folders (``kegel cfd run`` / ``kegel cfd sweep`` output) is
copied without its time series (``liquid_volume``) and per-roller detail (``rollers``), which
make up 95 % of its size; everything ``kegel losses --cfd`` and a scene's ``[study]`` read stays
(point, fidelity, kinematics, torques, loss torque, steady flag, balances, wall time, provenance).
The case folders themselves (meshes, fields: hundreds of MB) stay outside the repository.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

DROP = ("liquid_volume", "rollers", "pictures")


def main(argv: list[str]) -> int:
    from kegel.coupling import read_cfd_results
    from kegel.io import atomic_write_json

    out_root = REPO / "benchmarks" / "results" / "cfd"
    n = 0
    for folder in argv:
        for f, data in read_cfd_results(folder, source="command line", key="folder"):
            meta = f.parent / "kegel-case.json"
            if meta.is_file() and "mesh_time_s" not in data:
                data["mesh_time_s"] = json.loads(meta.read_text()).get("mesh_time_s")
            slim = {k: v for k, v in data.items() if k not in DROP}
            slim["collected_from"] = str(f)
            atomic_write_json(out_root / f.parent.name / "results.json", slim)
            n += 1
            print(f"{f} -> {out_root / f.parent.name / 'results.json'}")
    print(f"{n} result(s) collected")
    return 0 if n else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
