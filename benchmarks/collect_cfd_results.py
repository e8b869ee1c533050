"""Copy kegel CFD results into the repository, compact: benchmarks/results/cfd/<case>/results.json,
and fit the flow-force laws of every stored CFD sweep: benchmarks/results/cfd/flow_force_laws.json.

    python benchmarks/collect_cfd_results.py results/cfd/sweep_flooded_small results/cfd/sweep_shaft_center_tiny
    python benchmarks/collect_cfd_results.py          # only refit the stored results

Each ``results.json`` under the given folders (``kegel cfd run`` / ``kegel cfd sweep`` output) is
copied without its time series (``liquid_volume``) and its per-roller list (``rollers``), which
make up 95 % of its size. Everything ``kegel losses --cfd``, a scene's ``[study]`` and the
flow-force laws (:func:`kegel.coupling.flow_forces_from_cfd`) read stays: point, fidelity,
kinematics, torques (with ``rollers_about_bearing_axis`` and ``rollers_spin_sum``, the rollers'
sums the laws are fitted to), cage force and moment, loss torque, steady flag, balances, wall time,
provenance. In place of the per-roller list, ``roller_summary`` keeps per quantity the mean,
smallest and largest value over the rollers (the oil bath's spread around the sump) and the mean
skew/tilt moment along the bearing axis that the flow-force law folds into its orbit part
(``M_z - (M . a) a_z``). The case folders themselves (meshes, fields: hundreds of MB) stay outside
the repository.

``flow_force_laws.json``: per CFD model (bearing, lubricant, temperature, oil level, geometry) with
results at two or more speeds, the laws at each computed speed, with the fitted speed exponents,
the fit's relative residuals and the files they come from.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

DROP = ("liquid_volume", "rollers", "pictures")


def roller_summary(data: dict[str, Any], roller_axis_z: float) -> dict[str, Any] | None:
    """Means, smallest and largest values over the rollers of a full ``kegel cfd run`` result
    (None when it holds no per-roller list). ``roller_axis_z``: the roller axis' component along
    the bearing axis (:func:`kegel.coupling.flow_forces.roller_axis_z`)."""
    rollers = data.get("rollers")
    if not rollers:
        return None
    cols: dict[str, list[float]] = {k: [] for k in (
        "moment_about_bearing_axis_Nm", "orbit_force_moment_Nm", "moment_z_Nm", "spin_torque_Nm",
        "skew_moment_z_Nm", "force_xy_N", "axial_force_N", "power_W")}
    for r in rollers:
        M, F = r["moment_about_centre_Nm"], r["force_N"]
        spin = r["spin_torque_Nm"]["total"]
        cols["moment_about_bearing_axis_Nm"].append(r["moment_about_bearing_axis_Nm"])
        cols["orbit_force_moment_Nm"].append(r["moment_about_bearing_axis_Nm"] - M[2])   # (c x F)_z
        cols["moment_z_Nm"].append(M[2])
        cols["spin_torque_Nm"].append(spin)
        # the share of the skew and tilt moments along the bearing axis, which the flow-force
        # law folds into its orbit part
        cols["skew_moment_z_Nm"].append(M[2] - spin * roller_axis_z)
        cols["force_xy_N"].append(math.hypot(F[0], F[1]))
        cols["axial_force_N"].append(F[2])
        if "power_W" in r:
            cols["power_W"].append(r["power_W"])
    out: dict[str, Any] = {"count": len(rollers), "roller_axis_z": roller_axis_z}
    for k, v in cols.items():
        if v:
            out[k] = {"mean": sum(v) / len(v), "min": min(v), "max": max(v)}
    return out


def _geometry(point: dict[str, Any]):
    import kegel

    if point.get("bearing_file"):
        b = kegel.load_bearing(point["bearing_file"])
    else:
        b = kegel.load_bearing(point["bearing"])
    m = kegel.load_material(point.get("material") or "bearing_steel")
    return kegel.derive_geometry(b, m)


def fit_laws(out_root: Path) -> Path:
    """Fit the flow-force laws of every stored CFD model with two or more speeds; write
    ``flow_force_laws.json`` beside the results and return its path."""
    from kegel.coupling import read_cfd_results
    from kegel.coupling.flow_forces import MODEL_KEYS, body_drags, cfd_model_key, cfd_sweep, flow_forces_from_cfd
    from kegel.errors import KegelInputError
    from kegel.io import atomic_write_json

    runs = read_cfd_results(out_root, source="command line", key="folder")
    models: dict[tuple, list] = {}
    for f, data in runs:
        models.setdefault(cfd_model_key(data["point"]), []).append((f, data))
    doc: dict[str, Any] = {"made_by": "python benchmarks/collect_cfd_results.py", "models": []}
    for key, members in models.items():
        sweep = cfd_sweep(members, members[0][1]["point"])
        pt = sweep[0][1]["point"]
        g = _geometry(pt)
        entry: dict[str, Any] = {"model": {k: pt.get(k) for k in MODEL_KEYS},
                                 "speeds_rpm": [d["point"]["speed_rad_s"] * 30 / math.pi for _, d in sweep],
                                 "drags": [], "laws": []}
        for f, d in sweep:
            entry["drags"].append({"file": str(f.relative_to(REPO) if f.is_absolute() else f),
                                   **body_drags(d, g, source=str(f))})
        for f, d in sweep:
            try:
                law = flow_forces_from_cfd(d, g, sweep=sweep, source=str(f.relative_to(REPO) if f.is_absolute() else f))
            except KegelInputError as exc:
                entry["laws"].append({"file": str(f), "error": str(exc)})
                continue
            entry["laws"].append(law.as_dict())
        doc["models"].append(entry)
    return atomic_write_json(out_root / "flow_force_laws.json", doc)


def main(argv: list[str]) -> int:
    from kegel.coupling import read_cfd_results
    from kegel.coupling.flow_forces import roller_axis_z
    from kegel.io import atomic_write_json

    out_root = REPO / "benchmarks" / "results" / "cfd"
    n = 0
    for folder in argv:
        for f, data in read_cfd_results(folder, source="command line", key="folder"):
            meta = f.parent / "kegel-case.json"
            if meta.is_file() and "mesh_time_s" not in data:
                data["mesh_time_s"] = json.loads(meta.read_text()).get("mesh_time_s")
            slim = {k: v for k, v in data.items() if k not in DROP}
            summary = roller_summary(data, roller_axis_z(_geometry(data["point"])))
            if summary is not None:
                slim["roller_summary"] = summary
            slim["collected_from"] = str(f)
            atomic_write_json(out_root / f.parent.name / "results.json", slim)
            n += 1
            print(f"{f} -> {out_root / f.parent.name / 'results.json'}")
    if argv:
        print(f"{n} result(s) collected")
    print(f"flow-force laws: {fit_laws(out_root)}")
    return 0 if n or not argv else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
