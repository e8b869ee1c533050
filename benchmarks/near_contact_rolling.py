"""How much EHL rolling resistance kegel leaves out by counting only the Hertz-loaded slices.

kegel's rolling resistance (Biboulet-Houpert, Part 1) acts on every slice of a roller/raceway
contact that carries load in the slice model. A crowned roller under a light load touches over
part of its length only (32216, Table 1: about half of it), while the oil still fills the narrow
gap beside the contact, where a rigid, isoviscous, fully flooded film carries a little load and
resists the rolling. This script *estimates* that left-out part; kegel does not model it.

The estimate, per unloaded slice at gap g = profile drop - approach + h (h: kegel's central film
of the contact, the smallest gap the oil keeps):

- load per unit length the film would carry there (Martin 1916, rigid cylinder on a plane, fully
  flooded, Reynolds outlet condition): w = 4.9 eta0 u_m R / g;
- rolling force per unit length at that load: Biboulet-Houpert's blend (kegel's own law), which in
  this regime is its isoviscous-rigid asymptote 1.42 E' R sqrt(U W).

Both the gap (the elastic deflection beside the contact is ignored) and the fully flooded inlet
are assumptions: the figures are an order of magnitude, printed with the gap floor h and 2 h to
show how much they depend on it. They are not used anywhere in kegel.

Run: .venv/bin/python benchmarks/near_contact_rolling.py  (writes results/near_contact_rolling.json)
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

import kegel
from kegel import _core
from kegel.io import atomic_write_json, provenance
from kegel.tribology import axial_roller_loads, evaluate_raceway_contact, load_friction

OUT = Path(__file__).resolve().parent / "results" / "near_contact_rolling.json"
RPM = math.pi / 30
C_BH = 4.0 / (8.0 / math.pi) ** 1.5  # Biboulet-Houpert Part 1, Eq. 42 in classical units


def bh_force_per_length(w: float, eta: float, u_m: float, R: float, E: float) -> float:
    """Biboulet-Houpert's rolling force per unit length [N/m] (kegel's law, Eq. 40-42)."""
    U = 2.0 * eta * u_m / (E * R)
    W = w / (E * R)
    M = W / math.sqrt(U)
    return E * R * (1.4 / C_BH) * math.sqrt(U * W) / (1.0 + ((1.4 / 1.45) * math.sqrt(M)) ** 10) ** 0.1


def contact_estimate(g, b, m, lub, fr, *, speed_rpm: float, load_N: float, contact: str, slices: int = 30,
                     floor_factor: float = 1.0) -> dict:
    res = evaluate_raceway_contact(g, b, m, lub, fr, temperature_K=323.15, load_N=load_N,
                                   shaft_speed_rad_s=speed_rpm * RPM, contact=contact, slices=slices)
    mid = res.slices[slices // 2]
    R, u_m, h = mid["reduced_radius_m"], 0.5 * (mid["u_roller_m_s"] + mid["u_ring_m_s"]), mid["film_m"]
    E = _core.reduced_modulus_Pa(m.core, m.core)
    eta = kegel.lubricant_state(lub, 323.15).dynamic_viscosity_Pas
    L = g.roller_length_m  # the slice model slices the whole roller (edge radii in the profile)
    C = _core.contact
    prof = C.RollerProfile(b.roller_mean_diameter_m, b.roller_length_m, b.profile_a_p, b.profile_c_p_m,
                           b.profile_d_p_m, b.profile_k_p_m, b.edge_radius_m)
    xs = (np.arange(slices) + 0.5) / slices * L - 0.5 * L
    drop = np.array([prof.drop_m(float(x)) for x in xs])
    model = C.LineContactModel(slices, L, [R] * slices, E, C.SliceMethod.alternative_slicing)
    data = C.LineContactData(model)
    approach = C.solve_line_contact_load(model, data, list(drop), load_N)
    w = np.array(data.line_load_N_m)
    dx = L / slices
    loaded = sum(bh_force_per_length(wi, eta, u_m, R, E) * dx for wi in w if wi > 0)
    gap = np.maximum(drop - approach, 0.0) + floor_factor * h
    near = sum(bh_force_per_length(4.9 * eta * u_m * R / gi, eta, u_m, R, E) * dx
               for gi, wi in zip(gap, w) if wi <= 0)
    return {"contact": contact, "loaded_length_fraction": float(np.mean(w > 0)), "film_m": h,
            "rolling_force_loaded_N": loaded, "rolling_force_near_contact_N": near,
            "near_over_loaded": near / loaded if loaded else None}


def main() -> None:
    b = kegel.load_bearing("32216")
    m = kegel.load_material("bearing_steel")
    g = kegel.derive_geometry(b, m)
    lub = kegel.load_lubricant("FVA3")
    fr = load_friction("steel_mineral_oil")
    rows = []
    for speed in (500.0, 2000.0, 4000.0):
        for Fa in (6000.0,):
            Q = axial_roller_loads(g, Fa)
            for contact in ("inner", "outer"):
                for floor in (1.0, 2.0):
                    r = contact_estimate(g, b, m, lub, fr, speed_rpm=speed, load_N=Q[f"{contact}_N"],
                                         contact=contact, floor_factor=floor)
                    rows.append({"speed_rpm": speed, "axial_load_N": Fa, "gap_floor_over_film": floor, **r})
                    print(f"n {speed:5.0f} rpm, Fa {Fa / 1e3:.0f} kN, {contact:5s}, gap floor {floor:.0f} h: "
                          f"loaded {100 * r['loaded_length_fraction']:3.0f} % of the length, "
                          f"near-contact / loaded rolling force {100 * r['near_over_loaded']:5.1f} %")
    atomic_write_json(OUT, {"command": "python benchmarks/near_contact_rolling.py",
                            "scene": "32216, FVA 3 at 50 degC, pure axial load (Table 1), per roller contact",
                            "what": __doc__.split("\n\n")[0], "provenance": provenance(), "rows": rows})
    print(f"written: {OUT}")


if __name__ == "__main__":
    main()
