"""Mixed friction against its sources (issue 27, item 2).

Sources: Zhou and Hoeprich, "Torque of Tapered Roller Bearings", ASME J. Tribol. 113 (1991)
590-597 (the seed's ref. [73]): Eq. 29 (asperity load share N_a/N = exp(-B Lambda^C)), Eq. 30
(Lambda = phi_T h_iso / sigma_c), Eq. 32-34 (mu_a = phi_c S0/P0, S0/P0 about 0.2, phi_c = 1 for a
base oil; F_a = mu_a N exp(-B Lambda^C)); the seed's Table 4 (B, C, sigma of the 32216);
Biboulet and Houpert Part 1 Eq. 44 (starved rolling force); the SKF catalogue model's phi_bl.
"""

from __future__ import annotations

import dataclasses
import math

import pytest

import kegel
import kegel.run
from kegel.tribology import evaluate_raceway_contact, load_friction

RPM = math.pi / 30


@pytest.fixture(scope="module")
def setup32216():
    b = kegel.load_bearing("32216")
    m = kegel.load_material("bearing_steel")
    return b, m, kegel.derive_geometry(b, m), kegel.load_lubricant("FVA3"), load_friction()


def _contact(setup, friction=None, **kw):
    """A thin-film inner raceway contact of the 32216 (140 degC, 100 rpm: Lambda about 0.1-0.2)
    with sliding beyond the Coulomb regularisation (slide-to-roll 0.2)."""
    b, m, g, lub, fr = setup
    args = dict(temperature_K=413.15, load_N=1400.0, shaft_speed_rad_s=100 * RPM, slide_to_roll=0.2)
    args.update(kw)
    return evaluate_raceway_contact(g, b, m, lub, friction or fr, **args)


def test_boundary_coefficient_is_zhou_hoeprich_eq33_for_a_base_oil():
    # Eq. 33: mu_a = phi_c S0 / P0 with S0/P0 "about 0.2" and phi_c = 1.0 "for base oil";
    # FVA 3 is a mineral oil without additives (its data file)
    phi_c, S0_over_P0 = 1.0, 0.2
    fr = load_friction()
    assert fr.mu_d == pytest.approx(phi_c * S0_over_P0) and fr.mu_s == fr.mu_d
    assert "without additives" in kegel.load_lubricant("FVA3").description


def test_seed_table4_surface_data_of_the_32216():
    b = kegel.load_bearing("32216")
    assert (b.sigma_raceway_m, b.zhou_hoeprich_raceway_B, b.zhou_hoeprich_raceway_C) == (0.16e-6, 2.32, 0.97)
    assert (b.sigma_rib_m, b.zhou_hoeprich_rib_B, b.zhou_hoeprich_rib_C) == (0.24e-6, 1.90, 0.99)


def test_lambda_is_the_thermal_central_film_over_sigma_eq30(setup32216):
    b = setup32216[0]
    res = _contact(setup32216)
    for s in res.slices:
        # Zhou-Hoeprich Eq. 30 (the seed's Eq. 30 with Eq. 11-14): Lambda = phi_T h_iso / sigma
        assert s["film_m"] == pytest.approx(s["thermal_factor"] * s["film_isothermal_m"], rel=1e-12)
        assert s["Lambda"] == pytest.approx(s["film_m"] / b.sigma_raceway_m, rel=1e-12)
    assert 0.05 < res.totals["Lambda_min"] < 0.5  # a thin film: the share below is far from 0 and 1


def test_asperity_share_and_solid_friction_are_eq29_and_eq34(setup32216):
    b = setup32216[0]
    res = _contact(setup32216)
    for s in res.slices:
        phi = math.exp(-b.zhou_hoeprich_raceway_B * s["Lambda"] ** b.zhou_hoeprich_raceway_C)  # Eq. 29
        assert s["phi"] == pytest.approx(phi, rel=1e-12)
        assert s["sliding_speed_m_s"] > 2e-3  # beyond v_d: the Coulomb coefficient itself
        # Eq. 34: F_a = mu_a N exp(-B Lambda^C) with mu_a = 0.2
        assert abs(s["F_solid_sliding_x_N"]) == pytest.approx(0.2 * s["load_N"] * phi, rel=1e-9)


def test_asperity_share_at_printed_parameters():
    # exp(-2.32 Lambda^0.97) by hand: Lambda 1 -> exp(-2.32) = 0.09827; Lambda 0.5 -> 0.5^0.97 = 0.51048,
    # exp(-2.32 x 0.51048) = exp(-1.18431) = 0.30594
    t = kegel._core.tribology
    assert t.asperity_load_ratio(1.0, 2.32, 0.97) == pytest.approx(0.098274, rel=1e-4)
    assert t.asperity_load_ratio(0.5, 2.32, 0.97) == pytest.approx(math.exp(-2.32 * 0.5 ** 0.97), rel=1e-12)
    assert t.asperity_load_ratio(0.5, 2.32, 0.97) == pytest.approx(0.30594, rel=1e-4)


def test_starved_supply_cuts_the_rolling_force_not_the_film(setup32216):
    # what the code does (docs/validation.md, Stribeck section): the supply's inlet ratio S scales
    # the EHL rolling force by Biboulet-Houpert Eq. 44; the film and Lambda stay the flooded ones
    fr = setup32216[4]
    flooded = _contact(setup32216, slide_to_roll=0.0, temperature_K=323.15, shaft_speed_rad_s=500 * RPM)
    starved = _contact(setup32216, friction=dataclasses.replace(fr, inlet_gap_ratio_inner=10.0), slide_to_roll=0.0,
                       temperature_K=323.15, shaft_speed_rad_s=500 * RPM)
    eq44 = (10.0 ** 2 + 162.8 * 10.0) / (10.0 ** 2 + 193.1 * 10.0 + 1257.0)  # = 1728 / 3288
    assert eq44 == pytest.approx(0.525547, rel=1e-5)
    for a, s in zip(flooded.slices, starved.slices):
        assert s["F_ehl_rolling_N"] == pytest.approx(eq44 * a["F_ehl_rolling_N"], rel=1e-9)
        assert s["Lambda"] == a["Lambda"] and s["film_m"] == a["film_m"]


def test_skf_phi_bl_at_the_issue_point():
    # SKF: phi_bl = exp(-2.6e-8 (n nu)^1.4 d_m), 32216 (d_m = (80 + 140)/2 = 110 mm), 500 rpm, FVA 3 at
    # 100 degC; by hand with nu = 11.7866 mm^2/s: n nu = 5893.3, (n nu)^1.4 = 1.8985e5, phi_bl = 0.5810
    from kegel.correlations.skf import skf_bearing, skf_sliding_moment

    nu = kegel.lubricant_state(kegel.load_lubricant("FVA3"), 373.15).kinematic_viscosity_m2_s
    assert nu * 1e6 == pytest.approx(11.7866, rel=1e-4)
    _, phi_bl, mu_sl = skf_sliding_moment(skf_bearing(kegel.load_bearing("32216")), speed_rad_s=500 * RPM,
                                          kinematic_viscosity_m2_s=nu, axial_load_N=6000.0)
    assert phi_bl == pytest.approx(math.exp(-2.6e-8 * (500 * 11.7866) ** 1.4 * 110.0), rel=1e-4)
    assert phi_bl == pytest.approx(0.5810, abs=5e-4)
    assert mu_sl == pytest.approx(phi_bl * 0.15 + (1 - phi_bl) * 0.002, rel=1e-12)


def test_rib_boundary_friction_is_linear_in_mu(monkeypatch):
    # Eq. 34 at the rib, near Lambda -> 0 (32216, 1 rpm, 140 degC: rib Lambda about 0.02): the rib's
    # solid-sliding torque doubles with mu_a (0.1 -> 0.2); the bearing's equilibrium keeps the loads
    orig = kegel.run.load_friction

    def rib_solid(mu: float) -> float:
        monkeypatch.setattr(kegel.run, "load_friction",
                            lambda *a, **k: dataclasses.replace(orig(*a, **k), mu_s=mu, mu_d=mu))
        r = kegel.Bearing("32216").friction(speed_rpm=1, axial_load_N=6000, temperature_degC=140)
        p = r.points[0]
        assert p["converged"] and p["phi_max"]["rib"] > 0.9
        return p["power_W"]["rib"]["solid_sliding"] / p["speed_rad_s"]

    assert rib_solid(0.2) / rib_solid(0.1) == pytest.approx(2.0, rel=0.03)
