"""Cage slip and torque of the dynamic 32208 with and without the CFD's flow forces, flooded and
with oil to the shaft centre (issue 29, item 6; docs/cfd.md, "Coupling").

    python benchmarks/coupling_study.py                       # 1 kN, 2000 rpm (the paper's Figure 9 load)
    python benchmarks/coupling_study.py --axial-load "50 N"   # light load: the oil moves the cage

Each variant is examples/32208_dynamic_cfd.toml with its oil level and hydraulic model replaced:

- with flow forces: ``hydraulic = "cfd"``, the CFD's drags on rollers and cage as force laws, the
  oil's torque on the inner ring and shaft added to the drive torque;
- without: ``hydraulic = "none"`` (no oil on the bodies) and the CFD's whole loss torque added to
  the friction afterwards, as the quasi-static solution and the study do.

The run lasts ``--revolutions`` cage revolutions (default 3; see the example for why). Results:
benchmarks/results/coupling_study_<load>_<speed>.json and a Markdown table on stdout.
"""

from __future__ import annotations

import argparse
import math
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

LEVELS = ("flooded", "shaft_center")


def _scene_text(base: str, *, level: str, flow_forces: bool, axial_load: str, speed: str, duration_ms: float,
                out: Path, threads: int, film_limit_m: float = 0.0) -> str:
    text = base.replace('oil_level = "flooded"', f'oil_level = "{level}"')
    text = text.replace('axial_load = "1 kN"', f'axial_load = "{axial_load}"')
    text = text.replace('speed = "2000 rpm"', f'speed = "{speed}"')
    text = text.replace('duration = "220 ms"', f'duration = "{duration_ms:.6g} ms"\nthreads = {threads}')
    text = text.replace('directory = "results/32208_dynamic_cfd"', f'directory = "{out}"')
    if not flow_forces:
        # the CFD's loss is added afterwards; with the real rollers the contact is cut at the CFD's
        # gap, as hydraulic = "cfd" does
        cut = f'\ncontact_film_limit = "{film_limit_m * 1e3!r} mm"' if film_limit_m else ""
        text = text.replace('hydraulic = "cfd"\ncfd_results = "benchmarks/results/cfd"', 'hydraulic = "none"' + cut)
    return text


def main(argv: list[str]) -> int:
    import kegel
    from kegel.coupling import find_cfd_result, read_cfd_results
    from kegel.coupling.cfd_results import cfd_boundary
    from kegel.coupling.split import unloaded_line_wedge
    from kegel.model.lubricant import lubricant_state
    from kegel.solutions.quasi_static import load_distribution
    from kegel.run import run_scene
    from kegel.scene import load_scene
    from kegel.tribology import cage_speed_rad_s
    from kegel.units import parse_quantity

    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--axial-load", default="1 kN")
    ap.add_argument("--speed", default="2000 rpm")
    ap.add_argument("--revolutions", type=float, default=3.0, help="cage revolutions simulated (default 3)")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--only", choices=LEVELS, default=None)
    args = ap.parse_args(argv)

    base = (REPO / "examples" / "32208_dynamic_cfd.toml").read_text()
    w = parse_quantity(args.speed, "speed", source="--speed", key="speed")
    b = kegel.load_bearing("32208")
    g = kegel.derive_geometry(b, kegel.load_material("bearing_steel"))
    duration_ms = 1e3 * args.revolutions * 2 * math.pi / cage_speed_rad_s(g, w)
    runs = read_cfd_results(REPO / "benchmarks" / "results" / "cfd")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for level in (args.only,) if args.only else LEVELS:
            for ff in (False, True):
                out = Path(tmp) / f"{level}_{ff}"
                path = Path(tmp) / f"{level}_{ff}.toml"
                path.write_text(_scene_text(base, level=level, flow_forces=True, axial_load=args.axial_load,
                                            speed=args.speed, duration_ms=duration_ms, out=out, threads=args.threads))
                first = load_scene(path)  # the scene with the flow forces: its CFD point and boundary
                lub = first.lubrication
                cfd, f = find_cfd_result(REPO / "benchmarks" / "results" / "cfd", bearing="32208", lubricant="FVA3",
                                         speed_rad_s=w, temperature_K=first.operating_points[0].temperature_K,
                                         oil_level_m=lub.oil_level_m, flooded=lub.oil_level_m >= b.outer_diameter_m,
                                         results=runs)
                bnd = cfd_boundary(cfd, g.roller_mean_diameter_m, source=str(f))
                if cfd["point"].get("oil_level_m") is None and bnd.contact_film_limit_m:
                    # flooded: less the CFD's far field on the unloaded stretch of the lines, as
                    # hydraulic = "cfd" takes it off (kegel.coupling.split)
                    op = first.operating_points[0]
                    dist = load_distribution(g, b, first.material, axial_N=op.axial_load_N,
                                             slices=first.fidelity.slices, method=first.fidelity.slice_model)
                    eta = lubricant_state(first.lubricant, op.temperature_K).dynamic_viscosity_Pas
                    bnd = bnd.with_unloaded_line_wedge(unloaded_line_wedge(
                        g, viscosity_Pas=eta, inner_speed_rad_s=w, loaded_length_m=dist.loaded_length_m,
                        film_limit_m=bnd.contact_film_limit_m).torque_Nm)
                path.write_text(_scene_text(base, level=level, flow_forces=ff, axial_load=args.axial_load,
                                            speed=args.speed, duration_ms=duration_ms, out=out, threads=args.threads,
                                            film_limit_m=bnd.contact_film_limit_m))
                scene = load_scene(path)
                t0 = time.perf_counter()
                res = run_scene(scene, out, progress=False)
                wall = time.perf_counter() - t0
                p = res.points[0]
                cfd_loss = cfd["loss_torque_at_shaft_Nm"]
                hyd = p["hydraulic_torque_Nm"] if ff else bnd.hydraulic_Nm
                h = p.get("hydraulic") or {}
                st = p["dynamic"]["steady"]
                rows.append({"oil_level": level, "flow_forces": ff, "cage_slip": p["cage_slip"],
                             "cage_speed_rpm": p["cage_speed_rpm"], "friction_torque_Nm": p["friction_torque_Nm"],
                             "hydraulic_torque_Nm": hyd, "total_torque_Nm": p["friction_torque_Nm"] + hyd,
                             "bodies_Nm": h.get("roller_drag_on_the_bodies_Nm"),
                             "rings_Nm": h.get("inner_ring_and_shaft_Nm"), "cfd_loss_Nm": cfd_loss,
                             "thin_films_Nm": bnd.thin_films_Nm, "contact_film_limit_m": bnd.contact_film_limit_m,
                             "unloaded_line_wedge_Nm": bnd.unloaded_line_wedge_Nm,
                             "cfd_geometry": bnd.geometry,
                             "cfd_bodies_share_Nm": cfd_loss + cfd["torques_Nm"]["inner_ring"]["total"]
                             + cfd["torques_Nm"]["shaft"]["total"],
                             "power_balance_error": p["power_balance_error"], "converged": p["converged"],
                             "window_s": [st.get("window_start_s"), st.get("window_end_s")],
                             "exponents": (h.get("flow_force_law") or {}).get("provenance", {}).get("exponents"),
                             "wall_s": wall})
                print(f"{level}, flow forces {ff}: cage slip {100 * p['cage_slip']:.4f} %, total "
                      f"{1e3 * rows[-1]['total_torque_Nm']:.2f} mN m ({wall:.0f} s)", file=sys.stderr)
    meta = {"command": "python benchmarks/coupling_study.py " + " ".join(argv), "axial_load": args.axial_load,
            "speed": args.speed, "duration_ms": duration_ms, "cage_revolutions": args.revolutions,
            "scene": "examples/32208_dynamic_cfd.toml", "rows": rows}
    tag = f"{args.axial_load}_{args.speed}".replace(" ", "") + (f"_{args.only}" if args.only else "")
    out_file = REPO / "benchmarks" / "results" / f"coupling_study_{tag}.json"
    from kegel.io import atomic_write_json
    atomic_write_json(out_file, meta)
    print(f"32208, Fa = {args.axial_load}, {args.speed}, 50 degC, {duration_ms:.0f} ms ({args.revolutions:g} cage "
          f"revolutions), steady means over the dynamic solution's window\n")
    print("| oil level | flow forces | cage slip [%] | friction [mN m] | hydraulic [mN m] (bodies + rings + thin films - wedge) | "
          "total [mN m] |")
    print("| --- | --- | --- | --- | --- | --- |")
    for r in rows:
        thin = f" + {1e3 * r['thin_films_Nm']:.2f}" if r["thin_films_Nm"] else ""
        if r.get("unloaded_line_wedge_Nm"):
            thin += f" - {1e3 * r['unloaded_line_wedge_Nm']:.2f}"
        split = (f" ({1e3 * r['bodies_Nm']:.2f} + {1e3 * r['rings_Nm']:.2f}{thin})" if r["flow_forces"] else
                 " (CFD loss" + (" + thin films" if thin else "") + (" - wedge" if r.get("unloaded_line_wedge_Nm") else "")
                 + " added)")
        print(f"| {r['oil_level'].replace('_', ' ')} | {'on' if r['flow_forces'] else 'off'} | "
              f"{100 * r['cage_slip']:.3f} | {1e3 * r['friction_torque_Nm']:.2f} | "
              f"{1e3 * r['hydraulic_torque_Nm']:.2f}{split} | {1e3 * r['total_torque_Nm']:.2f} |")
    print(f"\n{out_file}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
