"""How much oil the oil-bath CFD has in the raceway wedges (issue 29; docs/cfd.md, "The contact / CFD
split"): what the CFD's far field on the unloaded stretch of the lines would be in an oil bath.

For each stored oil-bath case of the real rollers (``results/cfd/oilbath_real/32208_*``, the
whole bearing, oil to the shaft centre, g = 0.08 D_w): the volume-weighted oil fraction
(``alpha.oil``, mean of the last three written times) of the cells in each raceway wedge, where
the sum of the distances to the roller's cone and to the raceway cone (the local gap, as the
mesh's gap sizing measures it) is below 3 g, along the roller's length, over every roller. The
wedge term in the bath is then estimated as those fractions times the flooded term of each
raceway (kegel.coupling.split.unloaded_line_wedge at the study point, 1 kN). ``kegel run`` does not
take it off in an oil bath; this says how large it would be.

    .venv/bin/python benchmarks/cfd_wedge_oil_fraction.py

Output: a table on stdout and benchmarks/results/cfd_wedge_oil_fraction.json.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
CASES = REPO / "results" / "cfd" / "oilbath_real"
OUT = HERE / "results" / "cfd_wedge_oil_fraction.json"
WEDGE_GAPS = 3.0  # cells whose local gap is below this many g


def wedge_oil_fractions(case: Path, cg) -> dict[str, float]:
    """Volume-weighted oil fraction in the inner and outer raceway wedges of every roller."""
    from kegel.cfd_cases.foam import read_field, time_dirs

    from kegel.cfd_cases.geometry import raceway_gap_m

    C = np.load(case / "cell_centres.npy")
    V = np.load(case / "cell_volumes.npy")
    times = [t for t in time_dirs(case) if (t / "alpha.oil").is_file()][-3:]
    alpha = np.mean([read_field(t / "alpha.oil") for t in times], axis=0)
    out = {}
    for name, line in (("inner", cg.inner_raceway_line_m), ("outer", cg.outer_raceway_line_m)):
        sel = np.zeros(len(C), bool)
        for k in cg.modelled_rollers:
            gap, along = raceway_gap_m(cg, k, line, C)
            sel |= (gap < WEDGE_GAPS * cg.gap_m) & (along > 0.0) & (along < cg.roller_length_m)
        out[name] = float(np.sum(alpha[sel] * V[sel]) / np.sum(V[sel]))
        out[f"{name}_cells"] = int(sel.sum())
    return out


def main() -> int:
    from kegel.cfd_cases.geometry import cfd_geometry
    from kegel.coupling.split import unloaded_line_wedge
    from kegel.io import atomic_write_json, provenance
    from kegel.model.data import load_bearing, load_material
    from kegel.model.geometry import derive_geometry
    from kegel.model.lubricant import lubricant_state
    from kegel.solutions.quasi_static import load_distribution

    b, m = load_bearing("32208"), load_material("bearing_steel")
    g = derive_geometry(b, m)
    dist = load_distribution(g, b, m, axial_N=1000.0)
    rows = []
    for case in sorted(CASES.glob("32208_*rpm_shaft_center_tiny_g*"), key=lambda p: int(p.name.split("_")[1][:-3])):
        meta = json.loads((case / "kegel-case.json").read_text())
        pt = meta["point"]
        cg = cfd_geometry(g, gap_ratio=pt["gap_ratio"])
        f = wedge_oil_fractions(case, cg)
        w = unloaded_line_wedge(g, viscosity_Pas=meta["lubricant"]["dynamic_viscosity_Pas"],
                                inner_speed_rad_s=pt["speed_rad_s"], loaded_length_m=dist.loaded_length_m,
                                film_limit_m=cg.gap_m)
        res = json.loads((case / "results.json").read_text())
        rows.append({"case": case.name, "speed_rpm": pt["speed_rad_s"] * 30 / math.pi, **f,
                     "flooded_wedge_Nm": w.torque_Nm, "bath_wedge_estimate_Nm": f["inner"] * w.inner_Nm + f["outer"] * w.outer_Nm,
                     "cfd_loss_Nm": res["loss_torque_at_shaft_Nm"]})
    if not rows:
        print(f"no oil-bath case under {CASES}", file=sys.stderr)
        return 1
    atomic_write_json(OUT, {"command": "benchmarks/cfd_wedge_oil_fraction.py", "wedge": f"local gap < {WEDGE_GAPS:g} g",
                            "rows": rows, "provenance": provenance()})
    print("| n [rpm] | oil in the inner / outer wedges | flooded wedge term [mN m] | in the bath, estimated [mN m] | bath CFD loss [mN m] |")
    print("| --- | --- | --- | --- | --- |")
    for r in rows:
        print(f"| {r['speed_rpm']:.0f} | {100 * r['inner']:.0f} / {100 * r['outer']:.0f} % | {1e3 * r['flooded_wedge_Nm']:.1f} | "
              f"{1e3 * r['bath_wedge_estimate_Nm']:.1f} | {1e3 * r['cfd_loss_Nm']:.1f} |")
    print(f"\n{OUT}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
