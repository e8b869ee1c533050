"""Order-of-magnitude estimate of the rolling resistance that kegel's slice model leaves out: the
hydrodynamic (isoviscous-rigid) rolling of the unloaded, nearly touching crowned stretch of each
raceway line, fully flooded (docs/cfd.md, "Open"). Not a kegel model; an estimate for the record.

Each roller's line contact is solved alone with kegel's slice model at the roller's loads from
kegel's load distribution (32208, Fa = 1 kN), without the roller's tilt. An unloaded slice's gap
is its crown drop less the approach (rigid: the elastic lift of the surface beside the loaded
zone is ignored, so the gaps are too small and the estimate is an upper one), floored at the film
h_floor. Its rolling force per unit length is Martin's 4.601 eta0 u sqrt(R / h0) (Reynolds
outlet, inlet at infinity; near_contact_rolling/README.md, 1e), its dissipation 2 f u.

    .venv/bin/python docs/sources/near_contact_rolling/unloaded_stretch.py
"""
import math

import numpy as np

import kegel._core.contact as C
import kegel.physics.contact as pc
from kegel.model.data import load_bearing, load_material
from kegel.model.geometry import derive_geometry
from kegel.model.lubricant import lubricant_state
from kegel.physics.tribology import cage_speed_rad_s
from kegel.solutions.quasi_static import load_distribution

b, m = load_bearing("32208"), load_material("bearing_steel")
g = derive_geometry(b, m)
eta = lubricant_state("FVA3", "50 degC").dynamic_viscosity_Pas
E = 210e9 / (1 - 0.3 ** 2)
w = 2000 * math.pi / 30
wc = cage_speed_rad_s(g, w)
dist = load_distribution(g, b, m, axial_N=1000.0)
prof = pc.roller_profile(b)
L, n = b.roller_length_m, 60
ri, ro = 0.5 * g.inner_raceway_diameter_mid_m, 0.5 * g.outer_raceway_diameter_mid_m
rw = 0.5 * g.roller_mean_diameter_m / math.cos(g.roller_half_angle_rad)
Rr_i, Rr_o = ri / math.cos(g.cone_angle_rad), ro / math.cos(g.cup_angle_rad)
contacts = {"inner": (dist.inner_N[0], rw * Rr_i / (Rr_i + rw), (w - wc) * ri),
            "outer": (dist.outer_N[0], rw * Rr_o / (Rr_o - rw), wc * ro)}
for floor in (0.5e-6, 1e-6, 2e-6):
    total = 0.0
    for name, (Q, R, u) in contacts.items():
        model = C.LineContactModel(n, L, [R] * n, E, C.SliceMethod.alternative_slicing)
        data = C.LineContactData(model)
        y = np.array(model.positions_m)
        drop = np.array([prof.drop_m(v) for v in y])
        a = C.solve_line_contact_load(model, data, list(drop), Q)
        q = np.array(data.line_load_N_m)
        gap = np.maximum(drop[q <= 0] - a, floor)
        f = 4.601 * eta * u * np.sqrt(R / gap)          # N/m per surface
        total += g.roller_count * float(np.sum(2 * f * u * model.width_m)) / w
    print(f"h_floor {floor * 1e6:.1f} um: unloaded stretch, flooded, inlet at infinity: {1e3 * total:.0f} mN m")
