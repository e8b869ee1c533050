"""Order-of-magnitude estimate of the rolling resistance that kegel's slice model leaves out: the
hydrodynamic (isoviscous-rigid) rolling of the unloaded, nearly touching crowned stretch of each
raceway line, fully flooded (docs/cfd.md, "Open"). Not a kegel model; an estimate for the record.

Each roller's line contact is solved alone at the roller's loads from kegel's load distribution
(32208, Fa = 1 kN), without the roller's tilt, twice:

- rigid: kegel's slice model; an unloaded slice's gap is its crown drop less the approach;
- elastic: a finite crowned line contact on a 3-D elastic half-space (both bodies), slices of
  uniform pressure over their Hertz width (Love's rectangle, checked against quadrature below);
  an unloaded slice's gap is its crown drop less the approach plus the surface's elastic lift.

Gaps are floored at the film h_floor (where the EHL film takes over). The rolling force per unit
length is Martin's 4.601 eta0 u sqrt(R / h0) (Reynolds outlet, inlet at infinity, fully flooded;
near_contact_rolling/README.md, 1e), its dissipation 2 f u.

    .venv/bin/python docs/sources/near_contact_rolling/unloaded_stretch.py

It ends with the same fully flooded estimate for the 32216 of the seed's Figure 5, beside kegel's
total there and the supply model's inlet ratio S.
"""
import math

import numpy as np
from scipy.integrate import dblquad

import kegel._core.contact as C
import kegel.physics.contact as pc
from kegel.model.data import load_bearing, load_material
from kegel.model.geometry import derive_geometry
from kegel.model.lubricant import lubricant_state
from kegel.physics.tribology import cage_speed_rad_s, raceway_line_point
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


def rigid_unloaded_stretch_Nm(g, b, dist, w, floor):
    """Martin's dissipation over the unloaded slices of one roller per raceway (rigid gaps: the
    crown's drop less the approach, at least ``floor``), fully flooded, times the roller count,
    as a torque at the shaft turning at ``w``."""
    wc, prof = cage_speed_rad_s(g, w), pc.roller_profile(b)
    total = 0.0
    for name, Q in (("inner", dist.inner_N[0]), ("outer", dist.outer_N[0])):
        R, r_ring = raceway_line_point(g, 0.0, name)
        u = (w - wc) * r_ring if name == "inner" else wc * r_ring
        model = C.LineContactModel(n, b.roller_length_m, [R] * n, E, C.SliceMethod.alternative_slicing)
        data = C.LineContactData(model)
        drop = np.array([prof.drop_m(v) for v in model.positions_m])
        a = C.solve_line_contact_load(model, data, list(drop), Q)
        gap = np.maximum(drop[np.array(data.line_load_N_m) <= 0] - a, floor)
        f = 4.601 * eta * u * np.sqrt(R / gap)          # N/m per surface
        total += g.roller_count * float(np.sum(2 * f * u * model.width_m)) / w
    return total


for floor in (0.5e-6, 1e-6, 2e-6):
    total = rigid_unloaded_stretch_Nm(g, b, dist, w, floor)
    print(f"h_floor {floor * 1e6:.1f} um: unloaded stretch, flooded, inlet at infinity: {1e3 * total:.0f} mN m")


# --- the elastic version ---------------------------------------------------------------------

def _f(X, Y):
    r = np.sqrt(X * X + Y * Y)
    with np.errstate(divide="ignore", invalid="ignore"):
        return (np.where(np.abs(X) > 0, X * np.log(np.abs(Y + r) + 1e-300), 0.0)
                + np.where(np.abs(Y) > 0, Y * np.log(np.abs(X + r) + 1e-300), 0.0))


def love(x, y, a, c):
    """int int 1 / r over the rectangle [-a, a] x [-c, c] seen from the surface point (x, y)
    (Love 1929; the displacement of a uniformly loaded rectangle is (1 - nu^2) p / (pi E) times it)."""
    return _f(x + a, y + c) - _f(x + a, y - c) - _f(x - a, y + c) + _f(x - a, y - c)


for (x0, y0, a0, c0) in [(1.3e-6, 2.1e-6, 1e-4, 3e-4), (0.0, 2e-3, 1e-4, 3e-4)]:
    num = dblquad(lambda yy, xx: 1 / math.hypot(x0 - xx, y0 - yy), -a0, a0, -c0, c0, epsabs=1e-12, epsrel=1e-8)[0]
    assert abs(love(x0, y0, a0, c0) / num - 1) < 1e-6

Ep = E  # Biboulet-Houpert's E': 2 / E' = sum of (1 - nu^2) / E
ne = 120
we = L / ne
ye = (np.arange(ne) + 0.5) * we - 0.5 * L
drop_e = np.array([prof.drop_m(v) for v in ye])


def elastic_contact(Q, R):
    """Line loads, approach and gaps of a crowned roller of length L on a half-space (active set)."""
    q = np.full(ne, Q / L)
    act = drop_e < np.sort(drop_e)[ne // 2]
    for _ in range(200):
        bh = np.sqrt(8 * np.maximum(q, Q / L * 1e-3) * R / (math.pi * Ep))
        C = np.array([[2 / (math.pi * Ep) * love(0.0, ye[j] - ye[i], bh[i], 0.5 * we) / (2 * bh[i])
                       for i in range(ne)] for j in range(ne)])
        A = np.nonzero(act)[0]
        M = np.zeros((len(A) + 1, len(A) + 1))
        M[:len(A), :len(A)] = C[np.ix_(A, A)]
        M[:len(A), -1] = -1.0
        M[-1, :len(A)] = we
        sol = np.linalg.solve(M, np.concatenate([-drop_e[A], [Q]]))
        qn = np.zeros(ne)
        qn[A] = sol[:-1]
        gap = drop_e - sol[-1] + C @ qn
        new = ((qn > 0) | ((~act) & (gap < 0))) & (qn >= 0)
        if np.array_equal(new, act) and np.allclose(qn, q, rtol=1e-6, atol=1e-9):
            return qn, sol[-1], gap
        act, q = new, np.maximum(qn, 0.0)
    raise RuntimeError("the elastic line contact did not settle")


for floor in (0.5e-6, 1e-6, 2e-6):
    total = 0.0
    for name, Q in (("inner", dist.inner_N[0]), ("outer", dist.outer_N[0])):
        R, r_ring = raceway_line_point(g, 0.0, name)
        u = (w - wc) * r_ring if name == "inner" else wc * r_ring
        q, delta, gap = elastic_contact(Q, R)
        h = np.maximum(gap[q <= 0], floor)
        total += g.roller_count * float(np.sum(2 * 4.601 * eta * u * np.sqrt(R / h) * u * we)) / w
    print(f"h_floor {floor * 1e6:.1f} um: elastic gaps: {1e3 * total:.0f} mN m")


# --- the 32216 of the seed's Figure 5 (6 kN, 50 degC, oil bath at half roller height): the same
# fully flooded estimate (rigid gaps, floor 1 um) beside kegel's total and the supply's inlet ratio

import kegel  # noqa: E402

b6 = load_bearing("32216")
g6 = derive_geometry(b6, m)
dist6 = load_distribution(g6, b6, m, axial_N=6000.0)
for rpm in (500, 2000, 4000):
    total = rigid_unloaded_stretch_Nm(g6, b6, dist6, rpm * math.pi / 30, 1e-6)
    r = kegel.Bearing("32216").friction(speed=f"{rpm} rpm", axial_load="6 kN", temperature="50 degC")
    sup = r.points[0]["lubricant_supply"]
    print(f"32216, 6 kN, {rpm} rpm: unloaded stretch (fully flooded, floor 1 um) {total:.2f} N m; kegel total "
          f"{r.total_torque_Nm:.2f} N m (oil bath, half roller height); supply S = "
          f"{sup['inlet_gap_ratio_inner']:.0f} / {sup['inlet_gap_ratio_outer']:.0f} (inner / outer)")
