"""Thin-film terms of the CFD (kegel.cfd_cases.thin_films) against hand calculations."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kegel.cfd_cases.geometry import cfd_geometry
from kegel.cfd_cases.run import kinematics
from kegel.cfd_cases.thin_films import (annulus_couette_power_W, annulus_couette_shear_stress_Pa, couette_power_W,
                                        film_dissipation_W, pocket_film_loss, rib_film_gap_m, rib_film_loss,
                                        thin_film_losses)
from kegel.contact import RibContact
from kegel.data import load_bearing, load_material
from kegel.geometry import derive_geometry

W_2000 = 2000.0 * math.pi / 30.0


@pytest.fixture(scope="module")
def bg():
    b = load_bearing("32208")
    return b, derive_geometry(b, load_material("bearing_steel"))


def test_parallel_plate_couette_by_hand():
    # eta u^2 A / h = 0.05 * 2^2 * 1e-4 / 1e-4 = 0.2 W
    assert couette_power_W(0.05, 2.0, 1e-4, 1e-4) == pytest.approx(0.2, rel=1e-12)
    # a film of equal cells gives the same
    u2 = np.full((4, 5), 4.0)
    h = np.full((4, 5), 1e-4)
    assert film_dissipation_W(0.05, u2, h, 1e-4 / 20) == pytest.approx(0.2, rel=1e-12)


def test_concentric_cylinder_couette_by_hand():
    # Landau-Lifshitz Sec. 18: torque per length 4 pi eta w R1^2 R2^2 / (R2^2 - R1^2)
    eta, w, R1, c, L = 0.05, 600.0, 5e-3, 1e-3, 0.017
    R2 = R1 + c
    torque = 4 * math.pi * eta * w * R1**2 * R2**2 / (R2**2 - R1**2) * L
    tau = annulus_couette_shear_stress_Pa(eta, w, R1, c)
    assert tau * R1 * (2 * math.pi * R1 * L) == pytest.approx(torque, rel=1e-12)
    assert annulus_couette_power_W(eta, w, R1, c, 2 * math.pi * R1 * L) == pytest.approx(torque * w, rel=1e-12)
    # thin gap: Petroff's eta w R1 / c times (1 + e)^2 / (1 + e/2) = 1 + 3e/2 + O(e^2), e = c / R1
    e = 1e-6 / R1
    thin = annulus_couette_shear_stress_Pa(eta, w, R1, 1e-6)
    assert thin == pytest.approx(eta * w * R1 / 1e-6 * (1 + 1.5 * e), rel=1e-7)
    assert thin != pytest.approx(eta * w * R1 / 1e-6, rel=1e-4)
    # R2^2 / ((R2 - R1)(R2 + R1)) at c = R1 / 5: 1.44 / (0.2 * 2.2) = 3.2727 -> tau = 2 eta w * 3.2727
    assert annulus_couette_shear_stress_Pa(eta, w, R1, c) == pytest.approx(2 * eta * w * 1.44 / (0.2 * 2.2), rel=1e-12)


def test_paraboloid_film_integral_matches_the_closed_form():
    # h = h0 + x^2/(2 Rx) + y^2/(2 Ry) over the ellipse where h <= h0 + H:
    # int dA / h = 2 pi sqrt(Rx Ry) ln((h0 + H) / h0)
    Rx, Ry, h0, H = 0.14, 1.25, 2e-6, 20e-6
    n = 1201
    x = np.linspace(-1.05, 1.05, n) * math.sqrt(2 * Rx * H)
    y = np.linspace(-1.05, 1.05, n) * math.sqrt(2 * Ry * H)
    X, Y = np.meshgrid(x, y, indexing="ij")
    gap = h0 + X**2 / (2 * Rx) + Y**2 / (2 * Ry)
    mask = gap <= h0 + H
    dA = (x[1] - x[0]) * (y[1] - y[0])
    got = film_dissipation_W(1.0, np.ones_like(gap), gap, dA, mask)
    assert got == pytest.approx(2 * math.pi * math.sqrt(Rx * Ry) * math.log((h0 + H) / h0), rel=5e-3)


def test_rib_gap_in_the_axial_plane_is_the_circle_against_its_tangent(bg):
    b, g = bg
    grid = rib_film_gap_m(g, 0.0008, cells=201)
    j = 100                                         # eta = 0 (the axial plane)
    assert abs(grid.eta_m[0, j]) < 1e-12
    R = g.roller_end_radius_m
    sel = grid.on_film[:, j]
    xi = grid.xi_m[sel, j]
    assert sel.sum() > 50
    np.testing.assert_allclose(grid.gap_rigid_m[sel, j], R - np.sqrt(R * R - xi * xi), rtol=1e-6, atol=1e-11)


def test_rib_gap_near_the_contact_is_the_paraboloid_of_the_contact_model(bg):
    # the contact model's principal relative radii (mbs_core rib_gap, a separate implementation)
    b, g = bg
    rc = RibContact(g, b, load_material("bearing_steel"))
    grid = rib_film_gap_m(g, 0.0008, cells=201)
    # near the generator through the contact point: the circumferential conformity changes with
    # the radius along the generator (a xi eta^2 term: 15 % of 1/Ry at xi = 0.5 mm), so close to it
    near = grid.on_film & (np.abs(grid.xi_m) < 6e-5) & (np.abs(grid.eta_m) > 3e-4) & (np.abs(grid.eta_m) < 2e-3)
    para = grid.xi_m**2 / (2 * rc.Rx_m) + grid.eta_m**2 / (2 * rc.Ry_m)
    assert near.sum() >= 40
    np.testing.assert_allclose(grid.gap_rigid_m[near], para[near], rtol=0.03)


def test_cfd_rib_gap_is_the_clearance_in_the_axial_plane(bg):
    b, g = bg
    c = cfd_geometry(g).clearance_m
    grid = rib_film_gap_m(g, c, cells=201)
    sel = grid.on_film[:, 100]
    # the flat end and the set-back rib face are parallel in the axial plane; the ray along the
    # rib normal (1.3 deg off the roller axis) crosses the gap at that angle
    tilt = g.rib_face_angle_to_roller_end_plane_rad
    np.testing.assert_allclose(grid.gap_cfd_m[sel, 100], c / math.cos(tilt), rtol=1e-6)


def test_sliding_speed_at_the_rib_contact_by_hand(bg):
    b, g = bg
    r = rib_film_loss(g, b, "FVA3", 323.15, W_2000, 0.0008)
    kin = kinematics(g, W_2000)
    # relative to the cage the rib moves at (w_i - w_c) r_P circumferentially; the roller end at
    # w_s (a x (P - M)), also circumferential (a and P - M lie in the axial plane)
    (x, r_p), (xm, rm) = g.rib_contact_point_m, g.roller_mid_point()
    a = g.roller_axis_unit()
    lever = a[0] * (r_p - rm) - a[1] * (x - xm)
    u_rib = (kin["inner_ring_rad_s"] - kin["cage_rad_s"]) * r_p
    u_roller = kin["roller_spin_rad_s"] * lever
    # tangential parts in the rib plane: both are circumferential, normal to the rib normal
    assert r["sliding_speed_m_s"] == pytest.approx(abs(u_roller - u_rib), rel=1e-9)
    assert r["entrainment_speed_m_s"] == pytest.approx(0.5 * abs(u_roller + u_rib), rel=1e-9)


def test_rib_term_is_real_minus_cfd_and_positive(bg):
    b, g = bg
    r = rib_film_loss(g, b, "FVA3", 323.15, W_2000, 0.0008)
    assert r["loss_W"] == pytest.approx(r["real_film_W"] - r["cfd_film_W"], rel=1e-12)
    assert r["real_film_W"] > 10 * r["cfd_film_W"] > 0.0
    assert r["loss_torque_Nm"] == pytest.approx(r["loss_W"] / W_2000)
    # the real film lies between the central film and the cap's edge gap; thinner than c
    lo, hi = r["gap_range_m"]
    assert r["film_thickness_m"] <= lo < hi < 0.0008
    # a thicker film at the contact: less loss (roughly logarithmic)
    thick = rib_film_loss(g, b, "FVA3", 323.15, W_2000, 0.0008, film_thickness_m=2 * r["film_thickness_m"])
    assert 0.5 * r["loss_W"] < thick["loss_W"] < r["loss_W"]


def test_rib_term_is_bounded_by_the_thinnest_film_and_the_fastest_sliding(bg):
    # the relative motion is nearly a rotation about the roller axis (spin minus the ring's turn),
    # so the sliding speed grows with the distance from that axis: at most the cap edge's
    # r_L / (r_L - h_c) times the contact point's (with 20 % for the ring's share); the film is
    # nowhere thinner than its minimum: Z eta u_max^2 A / h_min bounds the real film's loss,
    # and the area mean of 1/h is well above 1/h_max
    b, g = bg
    r = rib_film_loss(g, b, "FVA3", 323.15, W_2000, 0.0008)
    area = r["area_m2"]
    r_L = 0.5 * g.roller_large_end_diameter_m
    u_max = 1.2 * r["sliding_speed_m_s"] * r_L / (r_L - g.rib_contact_height_m)
    upper = g.roller_count * r["viscosity_Pas"] * u_max**2 * area / r["gap_range_m"][0]
    lower = g.roller_count * r["viscosity_Pas"] * (0.2 * r["sliding_speed_m_s"]) ** 2 * area / r["gap_range_m"][1]
    assert lower < r["real_film_W"] < upper


def test_pocket_term_is_the_annulus_over_the_cage_walls(bg):
    b, g = bg
    eta = 0.05
    p = pocket_film_loss(g, eta, W_2000, 0.0008)
    w_s = abs(kinematics(g, W_2000)["roller_spin_rad_s"])
    sides = p["sides"]
    c_real = 0.5 * g.cage_pocket_clearance_circumferential_m
    assert sides["real_clearance_m"] == pytest.approx(1e-4)
    # thin-gap hand estimate with the mean radius: Z eta (w R)^2 A / h, within the radius spread
    R = 0.5 * g.roller_mean_diameter_m
    hand = g.roller_count * eta * (w_s * R) ** 2 * sides["wall_area_m2"] / c_real
    assert sides["real_film_W"] == pytest.approx(hand, rel=0.06)
    # the walls are two bands of the cage sheet: about 2 x L x (sheet thickness / sin(angle))
    assert 1.5e-5 < sides["wall_area_m2"] < 6e-5
    assert p["loss_W"] == pytest.approx(sides["loss_W"] + p["ends"]["loss_W"])
    # the CFD's film at c: the same power at about (c_real / c) of the real
    assert sides["cfd_film_W"] == pytest.approx(sides["real_film_W"] * c_real / 0.0008, rel=0.25)


def test_no_pocket_term_when_the_cfd_has_the_real_clearance(bg):
    b, g = bg
    p = pocket_film_loss(g, 0.05, W_2000, 0.5 * g.cage_pocket_clearance_circumferential_m)
    assert p["sides"]["loss_W"] == 0.0 and p["ends"]["loss_W"] == 0.0 and p["loss_torque_Nm"] == 0.0


def test_losses_scale_with_speed_and_viscosity(bg):
    b, g = bg
    p1 = pocket_film_loss(g, 0.05, W_2000, 0.0008)
    p2 = pocket_film_loss(g, 0.10, 2 * W_2000, 0.0008)
    # Couette: power ~ eta w^2, torque ~ eta w
    assert p2["loss_W"] == pytest.approx(8 * p1["loss_W"], rel=1e-9)
    assert p2["loss_torque_Nm"] == pytest.approx(4 * p1["loss_torque_Nm"], rel=1e-9)


def test_thin_film_losses_sum_their_parts(bg):
    b, g = bg
    out = thin_film_losses(g, b, lubricant="FVA3", temperature_K=323.15, inner_speed_rad_s=W_2000,
                           clearance_m=0.0008)
    assert out["loss_torque_Nm"] == pytest.approx(sum(out["parts_Nm"].values()), rel=1e-12)
    assert set(out["parts_Nm"]) == {"rib", "pocket_sides", "pocket_ends"}
    assert out["rib_load_N"] == pytest.approx(16.85, rel=1e-3)   # axial_roller_loads at 1 kN


@pytest.mark.parametrize("kwargs, word", [
    ({"viscosity_Pas": -1.0}, "viscosity_Pas"),
    ({"viscosity_Pas": float("nan")}, "viscosity_Pas"),
    ({"gap_m": 0.0}, "gap_m"),
    ({"area_m2": -1e-6}, "area_m2"),
])
def test_couette_inputs_are_checked(kwargs, word):
    args = {"viscosity_Pas": 0.05, "sliding_speed_m_s": 1.0, "gap_m": 1e-4, "area_m2": 1e-6, **kwargs}
    with pytest.raises(ValueError, match=word):
        couette_power_W(**args)


def test_rib_and_pocket_inputs_are_checked(bg):
    b, g = bg
    with pytest.raises(ValueError, match="clearance_m"):
        rib_film_gap_m(g, -1e-3)
    with pytest.raises(ValueError, match="cells"):
        rib_film_gap_m(g, 1e-3, cells=5)
    with pytest.raises(ValueError, match="rib_load_N"):
        rib_film_loss(g, b, "FVA3", 323.15, W_2000, 0.0008, rib_load_N=0.0)
    with pytest.raises(ValueError, match="inner_speed_rad_s"):
        pocket_film_loss(g, 0.05, float("inf"), 0.0008)
    with pytest.raises(ValueError, match="gap_m"):
        film_dissipation_W(0.05, np.ones(3), np.array([1e-5, 0.0, 1e-5]), 1e-8)


def test_results_json_terms_of_a_cfd_point(bg):
    """What run_case writes into results.json (thin_film_loss_Nm, thin_films), without a CFD run."""
    import json

    from kegel.cfd_cases.run import CfdPoint, thin_film_json

    b, g = bg
    point = CfdPoint(bearing="32208", speed_rad_s=W_2000, temperature_K=323.15, oil_level_m=None)
    meta = {"geometry": {"clearance_m": 0.0008}}
    thin = thin_film_json(point, meta)
    direct = thin_film_losses(g, b, lubricant="FVA3", temperature_K=323.15, inner_speed_rad_s=W_2000,
                              clearance_m=0.0008)
    assert thin["loss_torque_Nm"] == pytest.approx(direct["loss_torque_Nm"], rel=1e-12)
    json.loads(json.dumps(thin, allow_nan=False))          # strict JSON
    # without the clearance in the case's metadata: the point's geometry (c = 0.08 D_w = 0.8 mm)
    assert thin_film_json(point, {})["loss_torque_Nm"] == pytest.approx(thin["loss_torque_Nm"], rel=1e-12)
    # an oil bath: each film's term times its supply factor (test_oil_bath_film_factors_by_hand)
    bath = CfdPoint(bearing="32208", speed_rad_s=W_2000, temperature_K=323.15, oil_level_m=0.04)
    out = thin_film_json(bath, meta)
    sup = out["supply"]
    assert thin["supply"] is None and 0.9 < sup["rib"] < 1.0
    assert out["parts_Nm"]["rib"] == pytest.approx(sup["rib"] * thin["parts_Nm"]["rib"], rel=1e-12)
    assert out["parts_Nm"]["pocket_sides"] == pytest.approx(sup["pockets"] * thin["parts_Nm"]["pocket_sides"], rel=1e-12)
    assert out["loss_torque_Nm"] == pytest.approx(sum(out["parts_Nm"].values()), rel=1e-12)
    json.loads(json.dumps(out, allow_nan=False))


def test_oil_bath_film_factors_by_hand(bg):
    """The thin films' supply in an oil bath: full under the oil surface, SKF's kinematic
    replenishment factor above it (the raceway contacts' model). By hand for the 32208 (d = 40,
    D = 80 mm), FVA 3 at 50 degC (nu from the lubricant data), 2000 rpm: phi_rs = exp(-3e-8 nu n
    (d + D) sqrt(6 / (2 (D - d)))); oil to the shaft centre immerses half of every orbit."""
    from kegel.cfd_cases.thin_films import oil_bath_film_factors
    from kegel.model.lubricant import lubricant_state

    b, g = bg
    nu = lubricant_state("FVA3", 323.15).kinematic_viscosity_m2_s
    phi = math.exp(-3e-8 * (nu * 1e6) * 2000.0 * (40.0 + 80.0) * math.sqrt(6.0 / (2.0 * 40.0)))
    f = oil_bath_film_factors(g, b, oil_level_m=0.5 * b.outer_diameter_m, inner_speed_rad_s=W_2000,
                              kinematic_viscosity_m2_s=nu)
    assert f["phi_rs"] == pytest.approx(phi, rel=1e-12)
    assert f["immersed_rib"] == pytest.approx(0.5, abs=1e-12) and f["immersed_pockets"] == pytest.approx(0.5, abs=1e-12)
    assert f["rib"] == pytest.approx(0.5 + 0.5 * phi, rel=1e-12)
    # submerged: full films; no bath: phi_rs alone; faster: less oil above the surface
    full = oil_bath_film_factors(g, b, oil_level_m=b.outer_diameter_m, inner_speed_rad_s=W_2000,
                                 kinematic_viscosity_m2_s=nu)
    assert full["rib"] == 1.0 and full["pockets"] == 1.0
    dry = oil_bath_film_factors(g, b, oil_level_m=0.0, inner_speed_rad_s=W_2000, kinematic_viscosity_m2_s=nu)
    assert dry["rib"] == pytest.approx(phi, rel=1e-12)
    fast = oil_bath_film_factors(g, b, oil_level_m=0.04, inner_speed_rad_s=2 * W_2000, kinematic_viscosity_m2_s=nu)
    assert fast["rib"] < f["rib"]


def test_thin_films_of_a_finished_case_are_evaluated_again(tmp_path, bg):
    """``kegel cfd thin-films CASE`` rewrites a finished case's thin films (an oil-bath case run
    before they were evaluated) and leaves the CFD's figures alone; a folder that is not a
    finished case is refused."""
    import json
    import subprocess
    import sys
    from pathlib import Path

    from kegel.cfd_cases.run import CfdPoint, thin_film_json

    b, g = bg
    point = CfdPoint(bearing="32208", speed_rad_s=W_2000, temperature_K=323.15, oil_level_m=0.04, gap_ratio=0.08)
    from dataclasses import asdict

    case = tmp_path / "case"
    case.mkdir()
    (case / "kegel-case.json").write_text(json.dumps({"point": asdict(point), "geometry": {"clearance_m": 0.0008}}))
    old = {"point": asdict(point), "loss_torque_at_shaft_Nm": 0.0273, "thin_film_loss_Nm": None,
           "thin_films": {"loss_torque_Nm": None}, "loss_torque_at_shaft_with_thin_films_Nm": None}
    (case / "results.json").write_text(json.dumps(old))
    exe = Path(sys.executable).with_name("kegel")
    res = subprocess.run([str(exe), "cfd", "thin-films", str(case)], capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    new = json.loads((case / "results.json").read_text())
    want = thin_film_json(point, {"geometry": {"clearance_m": 0.0008}})["loss_torque_Nm"]
    assert new["thin_film_loss_Nm"] == pytest.approx(want, rel=1e-12)
    assert new["loss_torque_at_shaft_Nm"] == 0.0273
    assert new["loss_torque_at_shaft_with_thin_films_Nm"] == pytest.approx(0.0273 + want, rel=1e-12)
    assert "oil bath" in res.stdout
    res = subprocess.run([str(exe), "cfd", "thin-films", str(tmp_path)], capture_output=True, text=True)
    assert res.returncode != 0 and "kegel-case.json" in res.stderr


def test_reynolds_solver_against_the_inclined_slider_by_hand():
    """Fixed-incline slider (one wall sliding at u_b, gap falling linearly from h_i to h_o over l):
    dp/dx = 6 eta u_b (h - h*)/h^3 with h* = 2 h_i h_o / (h_i + h_o) (p = 0 at both ends); the
    solver's pressure on the middle row of a strip 40 l wide matches it."""
    from kegel.cfd_cases.thin_films import _reynolds_pressure_Pa

    eta, u_b, l, h_i, h_o = 0.05, 2.0, 2e-3, 20e-6, 10e-6
    nx, ny = 40, 400
    dx, dy = l / nx, 40 * l / ny
    x = (np.arange(nx) + 0.5) * dx
    h1 = h_i + (h_o - h_i) * x / l
    h = np.repeat(h1[:, None], ny, axis=1)
    film = np.ones_like(h, bool)
    p = _reynolds_pressure_Pa(h, np.full_like(h, 0.5 * u_b), np.zeros_like(h), film, dx, dy, eta)
    # hand: fine quadrature of the closed-form gradient
    xf = np.linspace(0.0, l, 200001)
    hf = h_i + (h_o - h_i) * xf / l
    hstar = 2 * h_i * h_o / (h_i + h_o)
    dp = 6 * eta * u_b * (hf - hstar) / hf**3
    pf = np.concatenate([[0.0], np.cumsum(0.5 * (dp[1:] + dp[:-1]) * np.diff(xf))])
    assert abs(pf[-1]) < 1e-6 * pf.max()
    mid = p[:, ny // 2]
    assert mid.max() == pytest.approx(pf.max(), rel=0.01)
    np.testing.assert_allclose(mid, np.interp(x, xf, pf), atol=0.01 * pf.max())


def test_reynolds_rib_film_carries_the_rib_load_at_the_contact_models_film(bg):
    """The rigid isoviscous Reynolds film of the real rib gap carries the 1 kN rib load (17 N) at
    a film within 20 % of the contact model's (Hamrock-Dowson with the Zhu-Cheng factor), and its
    pressure flow adds under 10 % to the Couette dissipation: the Couette term with that film
    is the film's loss."""
    from kegel.cfd_cases.thin_films import rib_film_reynolds

    b, g = bg
    rey = rib_film_reynolds(g, b, "FVA3", 323.15, W_2000, cells=80)
    rib = rib_film_loss(g, b, "FVA3", 323.15, W_2000, 0.0008)
    assert rey["film_thickness_m"] == pytest.approx(rib["film_thickness_m"], rel=0.2)
    assert 0.0 < rey["pressure_flow_W"] < 0.1 * rey["couette_W"]
    assert rey["pressure_flow_W"] * g.roller_count <= rib["pressure_flow_bound_W"]
