"""Contact models built from the bearing data: consistency with the derived geometry,
Palmgren, edge loading, tilt, rib cell model vs Hertz and grid convergence."""

from __future__ import annotations

import numpy as np
import pytest

import kegel
from kegel.contact import RacewayContact, RibContact, nominal_roller_pose, palmgren_approach_m
from kegel.errors import KegelInputError


@pytest.fixture(scope="module", params=["32216", "32208"])
def bearing(request):
    b = kegel.load_bearing(request.param)
    m = kegel.load_material("bearing_steel")
    return kegel.derive_geometry(b, m), b, m


@pytest.mark.parametrize("side", ["inner", "outer"])
def test_nominal_roller_touches_both_raceways(bearing, side):
    g, b, m = bearing
    rc = RacewayContact(g, b, m, side=side, slices=31)  # odd: one slice at the middle
    geo = rc.slice_geometry(*nominal_roller_pose(g))
    e = geo["interference_m"]
    assert abs(e[15]) < 1e-12  # the crown is zero at the middle: touching
    assert e.max() <= 1e-12    # nowhere overlapping
    normals = geo["n_R"]
    assert np.allclose(np.linalg.norm(normals, axis=1), 1.0)


def test_nominal_roller_touches_the_rib(bearing):
    g, b, m = bearing
    rib = RibContact(g, b, m, cells=16)
    gmin, h0, p, n = rib._gap(*rib.nominal_end(), 16, 16, rib.dx_m, rib.dy_m)
    assert abs(gmin) < 1e-12
    assert p[2] == pytest.approx(g.rib_contact_point_m[0], abs=1e-12)
    assert p[0] == pytest.approx(g.rib_contact_point_m[1], abs=1e-12)
    assert min(h0) >= -1e-15
    # the rib's relative radius along its generator is the end sphere's radius
    assert rib.Rx_m == pytest.approx(g.roller_end_radius_m, rel=1e-3)


@pytest.mark.parametrize("q_N_mm", [200.0, 1000.0, 2000.0])
def test_independent_slices_reproduce_palmgren_on_the_real_contact(bearing, q_N_mm):
    g, b, m = bearing
    rc = RacewayContact(g, b, m, side="inner", slices=40, method="independent", crowned=False, edge=False)
    Q = q_N_mm * g.roller_length_m * 1e3
    res = rc.solve_load(Q)
    # the unprofiled roller against the tapered raceway: uniform interference
    assert res["approach_m"] == pytest.approx(palmgren_approach_m(Q, g.roller_length_m), rel=0.05)


@pytest.mark.parametrize("q_N_mm", [200.0, 1000.0, 2000.0])
def test_alternative_slicing_reproduces_palmgren_on_the_real_contact(bearing, q_N_mm):
    # known_values.md: an unprofiled slice model within 5 % of Palmgren over 200 ... 2000 N/mm.
    # The AST's finite-body reference depth is set at 1000 N/mm on a flat line of the slice
    # model's length; here the roller carries its edge radius (a shorter loaded line).
    g, b, m = bearing
    rc = RacewayContact(g, b, m, side="inner", slices=40, crowned=False, edge=True)
    l_eff = g.roller_effective_length_m
    Q = q_N_mm * l_eff * 1e3
    ratio = rc.solve_load(Q)["approach_m"] / palmgren_approach_m(Q, l_eff)
    assert ratio == pytest.approx(1.0, abs=0.05)
    # the pure half-space sits above Palmgren
    hs = RacewayContact(g, b, m, side="inner", slices=40, crowned=False, edge=True, reference="half_space")
    assert hs.solve_load(Q)["approach_m"] / palmgren_approach_m(Q, l_eff) > ratio + 0.03


def test_raceway_contact_rejects_an_unknown_reference(bearing):
    g, b, m = bearing
    with pytest.raises(KegelInputError, match="reference"):
        RacewayContact(g, b, m, reference="infinity")


def test_edge_peaks_without_crown_and_none_with_crown(bearing):
    g, b, m = bearing
    Q = 500.0 * g.roller_effective_length_m * 1e3
    flat = RacewayContact(g, b, m, slices=40, crowned=False, edge=False).solve_load(Q)
    q = flat["line_load_N_m"]
    assert q[0] > 1.3 * q[20] and q[-1] > 1.3 * q[20]
    crowned = RacewayContact(g, b, m, slices=40).solve_load(Q)
    q = crowned["line_load_N_m"]
    assert q.argmax() in range(17, 23)
    assert np.all(np.diff(q[:20]) >= -1e-9 * q.max()) and np.all(np.diff(q[20:]) <= 1e-9 * q.max())


def test_tilt_moves_load_to_one_end_and_builds_an_edge_peak(bearing):
    g, b, m = bearing
    Q = 500.0 * g.roller_effective_length_m * 1e3
    rc = RacewayContact(g, b, m, slices=40)
    straight = rc.solve_load(Q)
    tilted = rc.solve_load(Q, tilt_rad=1e-3)
    # the tapered roller's reduced radius grows towards its large end: a slight asymmetry only
    assert abs(straight["moment_Nm"]) < 0.01 * Q * g.roller_length_m / 2
    assert abs(tilted["moment_Nm"] - straight["moment_Nm"]) > 0.05 * Q * g.roller_length_m / 2
    strong = rc.solve_load(Q, tilt_rad=4e-3)
    p0 = strong["max_pressure_Pa"]
    assert p0.argmax() in (*range(0, 8), *range(32, 40))  # at one end
    assert min(p0[0], p0[-1]) == 0.0                     # the other end is unloaded


def test_slice_convergence_order(bearing):
    g, b, m = bearing
    Q = 1000.0 * g.roller_effective_length_m * 1e3
    ns = [10, 20, 40, 80, 160]
    d = [RacewayContact(g, b, m, slices=n).solve_load(Q)["approach_m"] for n in ns]
    err = [abs(x / d[-1] - 1) for x in d[:-1]]
    assert err[-1] < 0.005
    assert all(e2 < e1 for e1, e2 in zip(err, err[1:]))


def test_rib_cell_model_matches_closed_form_and_converges(bearing):
    g, b, m = bearing
    load = 100.0
    approaches = {}
    for n in (16, 32, 64):
        rib = RibContact(g, b, m, cells=n, reference_load_N=load)
        approaches[n] = rib.solve_load(load)["approach_m"]
    hz = RibContact(g, b, m, cells=16, reference_load_N=load).solve_load(load, "hertz")
    assert approaches[64] == pytest.approx(hz["approach_m"], rel=0.01)
    assert abs(approaches[32] / approaches[64] - 1) < abs(approaches[16] / approaches[64] - 1)


def test_invalid_arguments(bearing):
    g, b, m = bearing
    with pytest.raises(kegel.KegelInputError, match="'inner' or 'outer'"):
        RacewayContact(g, b, m, side="rib")
    with pytest.raises(kegel.KegelInputError, match="integer in \\[1, 400\\]"):
        RacewayContact(g, b, m, slices=0)
    rc = RacewayContact(g, b, m, slices=10)
    with pytest.raises(ValueError, match="force_N"):
        rc.solve_load(-5.0)
    with pytest.raises(ValueError, match="interference_m: 3 values: expected 10"):
        kegel._core.contact.solve_line_contact(rc.model, rc.data, [0.0, 1e-6, 0.0])


@pytest.mark.parametrize("q_N_mm", [200.0, 1000.0])
def test_alternative_slicing_matches_the_full_half_space(q_N_mm):
    # The same unprofiled finite line contact solved by the cell model (Boussinesq on a 2D grid,
    # FFT + CG): the AST's slice coupling must reproduce its approach.
    C = kegel._core.contact
    E, R, l = 210e9 / 0.91, 7.5e-3, 20e-3
    Q = q_N_mm * l * 1e3
    n = 60
    line = C.LineContactModel(n, l, [R] * n, E, C.SliceMethod.alternative_slicing, C.ApproachReference.half_space)
    ast = C.solve_line_contact_load(line, C.LineContactData(line), [0.0] * n, Q)
    b = np.sqrt(8 * q_N_mm * 1e3 * R / (np.pi * E))
    nx, ny = 256, 48
    wx, wy = 1.2 * l, 6 * b
    x = (np.arange(nx) + 0.5) * wx / nx - wx / 2
    y = (np.arange(ny) + 0.5) * wy / ny - wy / 2
    X, Y = np.meshgrid(x, y, indexing="ij")
    h0 = np.where(np.abs(X) <= l / 2, Y**2 / (2 * R), 1.0)
    cells = C.CellContactModel(nx, ny, wx / nx, wy / ny, E)
    data = C.CellContactData(cells)
    assert C.solve_cell_contact(cells, data, list(h0.ravel()), Q, 1e-9, 5000) == 0
    assert ast == pytest.approx(data.approach_m, rel=0.015)
