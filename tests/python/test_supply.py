"""Lubricant supply of the raceway contacts (kegel.supply) and the contact / hydraulic boundary g:
Biboulet-Houpert Part 1 Eq. 44 and SKF's kinematic replenishment factor against hand
calculations, the mapping between them, the immersion geometry, and what a run reports."""

from __future__ import annotations

import math

import pytest

from kegel import load_bearing
from kegel.errors import KegelInputError
from kegel.supply import (K_RS, STARVATION_FACTOR_AT_S2, immersed_fraction, inlet_gap_ratio_for_factor,
                          lubricant_supply, skf_replenishment_factor, starvation_factor)


def eq44(S: float) -> float:
    """Biboulet-Houpert Part 1, Eq. 44 as printed."""
    return (S * S + 162.8 * S) / (S * S + 193.1 * S + 1257.0)


# Eq. 44 evaluated by hand (docs/sources/biboulet_houpert.md, section 3.2)
@pytest.mark.parametrize("S, factor", [(2, 0.2001), (3, 0.2695), (5, 0.3733), (10, 0.5255), (20, 0.6624),
                                       (50, 0.7933), (100, 0.8598), (1000, 0.9736)])
def test_starvation_factor_is_eq44(S, factor):
    assert starvation_factor(S) == pytest.approx(factor, abs=5e-5)
    assert starvation_factor(S) == pytest.approx(eq44(S), rel=1e-14)


def test_starvation_factor_limits():
    assert starvation_factor(0.0) == 1.0          # fully flooded
    assert starvation_factor(1.0) == starvation_factor(2.0)  # below the computed range: S = 2
    assert STARVATION_FACTOR_AT_S2 == pytest.approx(329.6 / 1647.2, rel=1e-12)


@pytest.mark.parametrize("S", [2.0, 3.7, 10.0, 76.2, 500.0, 1e5])
def test_inlet_ratio_inverts_eq44(S):
    got, clamped = inlet_gap_ratio_for_factor(eq44(S))
    assert not clamped
    assert got == pytest.approx(S, rel=1e-9)


def test_inlet_ratio_edges():
    assert inlet_gap_ratio_for_factor(1.0) == (0.0, False)
    assert inlet_gap_ratio_for_factor(0.1) == (2.0, True)        # below Eq. 44's range: clamped
    # the printed rounding of the hand table: a factor of 0.5255 is an inlet of about 10 film thicknesses
    assert inlet_gap_ratio_for_factor(0.5255)[0] == pytest.approx(10.0, abs=0.01)
    with pytest.raises(KegelInputError, match="factor"):
        inlet_gap_ratio_for_factor(0.0)


def test_skf_replenishment_by_hand_and_against_the_skf_column():
    """32216 (d = 80, D = 140 mm), FVA 3 at 50 degC (nu = 60.59 mm^2/s), 2000 rpm, K_Z = 6:
    3e-8 * 60.59 * 2000 * 220 * sqrt(6 / 120) = 0.178838 -> phi_rs = 0.836241 (low-level oil bath);
    twice the exponent for oil-air (K_rs = 6e-8): 0.699300."""
    kw = dict(kinematic_viscosity_m2_s=60.59e-6, speed_rpm=2000.0, bore_m=0.080, outer_diameter_m=0.140)
    assert skf_replenishment_factor(K_rs=3e-8, **kw) == pytest.approx(math.exp(-0.178838), rel=1e-5)
    assert skf_replenishment_factor(K_rs=3e-8, **kw) == pytest.approx(0.836241, abs=1e-6)
    assert skf_replenishment_factor(K_rs=6e-8, **kw) == pytest.approx(0.699300, abs=1e-6)
    # the same factor as kegel's SKF column (correlations/skf.py, an independent implementation)
    from kegel.correlations.skf import skf_bearing, skf_friction

    f = skf_friction(skf_bearing(load_bearing("32216")), speed_rad_s=2000 * math.pi / 30,
                     kinematic_viscosity_m2_s=60.59e-6, axial_load_N=6000.0, radial_load_N=0.0, oil_level_m=None,
                     lubrication="oil_bath")
    assert skf_replenishment_factor(K_rs=K_RS["oil_bath"], **kw) == pytest.approx(f.phi_rs, rel=1e-12)
    with pytest.raises(KegelInputError, match="outer_diameter_m"):
        skf_replenishment_factor(K_rs=3e-8, kinematic_viscosity_m2_s=6e-5, speed_rpm=1.0, bore_m=0.1,
                                 outer_diameter_m=0.05)


def test_immersed_fraction_by_hand():
    D = 0.14
    assert immersed_fraction(0.0, D, 0.05) == 0.0                   # no oil
    assert immersed_fraction(D, D, 0.05) == 1.0                     # flooded
    assert immersed_fraction(0.5 * D, D, 0.05) == pytest.approx(0.5)   # oil to the shaft centre
    # a contact at r = 0.06 m, oil 20 mm above the lowest point: acos((0.07 - 0.02) / 0.06) / pi
    assert immersed_fraction(0.02, D, 0.06) == pytest.approx(math.acos(0.05 / 0.06) / math.pi, rel=1e-12)
    assert immersed_fraction(0.005, D, 0.06) == 0.0                 # the contacts never reach the oil


@pytest.fixture(scope="module")
def bearing_32216():
    from kegel.scene import load_scene

    sc = load_scene("examples/32216_table1.toml")
    return sc.geometry, sc.bearing


def _supply(gb, mode, level, rpm=2000.0, nu=60.59e-6, **kw):
    g, b = gb
    return lubricant_supply(g, b, mode=mode, oil_level_m=level, speed_rad_s=rpm * math.pi / 30,
                            kinematic_viscosity_m2_s=nu, **kw)


def test_supply_by_lubrication(bearing_32216):
    g, b = bearing_32216
    D = b.outer_diameter_m
    phi_bath, phi_air = 0.836241, 0.699300
    flooded = _supply(bearing_32216, "oil_bath", D)
    assert flooded.flooded and flooded.rolling_force_factor_inner == flooded.rolling_force_factor_outer == 1.0
    assert _supply(bearing_32216, "oil_bath", 0.07, model="flooded").flooded
    mql = _supply(bearing_32216, "minimum_quantity", 0.0)
    assert mql.K_rs == 6e-8 and mql.immersed_fraction_inner == mql.immersed_fraction_outer == 0.0
    assert mql.rolling_force_factor_inner == pytest.approx(phi_air, abs=1e-6)
    assert eq44(mql.inlet_gap_ratio_outer) == pytest.approx(phi_air, abs=1e-6)
    # oil to the shaft centre: every contact spends half its orbit in the oil
    centre = _supply(bearing_32216, "oil_bath", 0.5 * D)
    assert centre.immersed_fraction_inner == pytest.approx(0.5) and centre.immersed_fraction_outer == pytest.approx(0.5)
    assert centre.rolling_force_factor_inner == pytest.approx(0.5 + 0.5 * phi_bath, abs=1e-6)
    # half roller height (the lowest roller's centre): the cone's contacts stay above the oil, the
    # cup's dip in near the bottom
    half = _supply(bearing_32216, "oil_bath", 0.5 * (D - b.pitch_diameter_m))
    assert half.immersed_fraction_inner == 0.0
    x = math.acos(0.5 * b.pitch_diameter_m / (0.5 * g.outer_raceway_diameter_mid_m)) / math.pi
    assert half.immersed_fraction_outer == pytest.approx(x, rel=1e-12)
    assert half.rolling_force_factor_inner == pytest.approx(phi_bath, abs=1e-6)
    assert half.rolling_force_factor_outer == pytest.approx(x + (1 - x) * phi_bath, abs=1e-6)
    # more oil, more supply; more speed or viscosity, less
    assert 1.0 > centre.rolling_force_factor_inner > half.rolling_force_factor_inner > mql.rolling_force_factor_inner
    assert _supply(bearing_32216, "minimum_quantity", 0.0, rpm=4000).rolling_force_factor_inner < \
        mql.rolling_force_factor_inner
    assert _supply(bearing_32216, "minimum_quantity", 0.0, nu=90e-6).rolling_force_factor_inner < \
        mql.rolling_force_factor_inner
    assert _supply(bearing_32216, "oil_jet", 0.0).K_rs == 3e-8
    with pytest.raises(KegelInputError, match="oil_level_m"):
        _supply(bearing_32216, "minimum_quantity", 0.01)


def test_film_limit_per_slice():
    """The contact / hydraulic boundary g: every slice's inlet ratio is g / h (its isothermal film),
    its rolling force the uncut one less the far field beyond g over its width (by hand:
    6 eta0 u_m I(g / R)); a supply below it wins."""
    import dataclasses

    from kegel import load_lubricant, load_material
    from kegel.geometry import derive_geometry
    from kegel.tribology import evaluate_raceway_contact, load_friction

    b, m, lub = load_bearing("32208"), load_material("bearing_steel"), load_lubricant("FVA3")
    g = derive_geometry(b, m)
    base = dataclasses.replace(load_friction(), rolling_thermal="off")
    kw = dict(temperature_K=323.15, load_N=1000.0, shaft_speed_rad_s=2000 * math.pi / 30, slices=10)
    from kegel.model.lubricant import lubricant_state

    eta0 = lubricant_state(lub, 323.15).dynamic_viscosity_Pas
    for contact in ("inner", "outer"):
        ref = evaluate_raceway_contact(g, b, m, lub, base, contact=contact, **kw)
        gap = 0.2e-3
        cut = evaluate_raceway_contact(g, b, m, lub, dataclasses.replace(base, contact_film_limit_m=gap),
                                       contact=contact, **kw)
        for r0, r1 in zip(ref.slices, cut.slices):
            S = gap / r0["film_isothermal_m"]
            assert r1["inlet_gap_ratio"] == pytest.approx(S, rel=1e-12)
            G = gap / r0["reduced_radius_m"]
            I = math.sqrt(2 / G - 1) + 2 * math.asin(math.sqrt(G / 2)) - 1 - math.pi / 2
            u = r0["entrainment_speed_m_s"]
            far = r0["F_ehl_rolling_N"] - r1["F_ehl_rolling_N"]
            assert far == pytest.approx(6 * eta0 * u * I * r0["width_m"], rel=1e-9)
            # an absolute amount, not a share of the force like Eq. 44 (at these 100 N slices it
            # takes 3.5 % where Eq. 44 at the same S would take 6.9 %); a positive force is left
            assert 0.0 < r1["F_ehl_rolling_N"] < r0["F_ehl_rolling_N"]
        # a supply more restrictive than the cut: the supply's ratio, on its own raceway only
        both = dataclasses.replace(base, contact_film_limit_m=gap, inlet_gap_ratio_inner=20.0,
                                   inlet_gap_ratio_outer=30.0)
        r = evaluate_raceway_contact(g, b, m, lub, both, contact=contact, **kw)
        assert all(s["inlet_gap_ratio"] == (20.0 if contact == "inner" else 30.0) for s in r.slices)


def test_scene_options():
    from kegel.scene import scene_from_dict

    raw = {"bearing": {"designation": "32208"}, "lubricant": {"name": "FVA3"},
           "operating": {"axial_load": "1 kN", "speed": "2000 rpm", "temperature": "50 degC"},
           "lubrication": {"mode": "minimum_quantity"}}
    sc = scene_from_dict({**raw, "model": {"contact_film_limit": "0.2 mm", "lubricant_supply": "flooded"}})
    assert sc.fidelity.contact_film_limit_m == pytest.approx(2e-4)
    assert sc.fidelity.lubricant_supply == "flooded"
    assert scene_from_dict(raw).fidelity.lubricant_supply == "kinematic_replenishment"
    with pytest.raises(KegelInputError, match="model.lubricant_supply"):
        scene_from_dict({**raw, "model": {"lubricant_supply": "wet"}})
    for bad in ("-0.1 mm", "2 cm", "0.2"):
        with pytest.raises(KegelInputError, match="model.contact_film_limit"):
            scene_from_dict({**raw, "model": {"contact_film_limit": bad}})


def test_run_reports_supply_and_starves_minimum_quantity():
    """A minimum-quantity point: its record carries the supply, its EHL rolling torque is SKF's
    phi_rs (oil-air) times the flooded one within the kinematics' shift (< 2 %), and it no
    longer says its contacts are fully flooded (unless the supply model is switched off)."""
    from kegel.run import _csv, run_scene
    from kegel.scene import scene_from_dict

    def run(**model):
        raw = {"bearing": {"designation": "32216"}, "lubricant": {"name": "FVA3"},
               "operating": {"axial_load": "6 kN", "speed": "2000 rpm", "temperature": "50 degC"},
               "lubrication": {"mode": "minimum_quantity"}, "model": {"fidelity": "fast", **model}}
        (p,) = run_scene(scene_from_dict(raw), write=False, progress=False).points
        return p

    starved, flooded = run(), run(lubricant_supply="flooded")
    sup = starved["lubricant_supply"]
    assert sup["rolling_force_factor_inner"] == pytest.approx(0.6993, abs=1e-4)  # nu at 50 degC: 60.59 mm^2/s
    ratio = starved["torque_by_mechanism_Nm"]["ehl_rolling"] / flooded["torque_by_mechanism_Nm"]["ehl_rolling"]
    assert ratio == pytest.approx(sup["rolling_force_factor_inner"], rel=0.02)
    assert starved["friction_torque_Nm"] < flooded["friction_torque_Nm"]
    codes = lambda p: {w["code"] for w in p["warnings"]}  # noqa: E731
    assert "contacts_fully_flooded" not in codes(starved)
    assert "contacts_fully_flooded" in codes(flooded)
    header, row = _csv([starved]).splitlines()[:2]
    cols = dict(zip(header.split(","), row.split(",")))
    assert float(cols["supply_rolling_force_factor_inner"]) == pytest.approx(sup["rolling_force_factor_inner"])


def test_study_gives_each_lubrication_its_contact_friction():
    from kegel.run import run_scene
    from kegel.scene import scene_from_dict

    raw = {"bearing": {"designation": "32208"}, "lubricant": {"name": "FVA3"},
           "operating": {"axial_load": "1 kN", "speed": "3000 rpm", "temperature": "50 degC"},
           "study": {"lubrication": ["flooded", "shaft_center", "minimum_quantity"], "hydraulic": ["liebrecht"]},
           "model": {"fidelity": "fast"}}
    (p,) = run_scene(scene_from_dict(raw), write=False, progress=False).points
    fr = {r["lubrication"]: r["friction_torque_Nm"] for r in p["study"]}
    assert fr["flooded"] == pytest.approx(p["friction_torque_Nm"])   # the point's own: flooded contacts
    assert fr["flooded"] > fr["shaft_center"] > fr["minimum_quantity"]
    sup = {r["lubrication"]: r["supply_rolling_force_factor_inner"] for r in p["study"]}
    assert sup["flooded"] == 1.0 and 1.0 > sup["shaft_center"] > sup["minimum_quantity"]
    for r in p["study"]:
        if r["method"] != "none":
            assert r["total_torque_Nm"] == pytest.approx(r["friction_torque_Nm"] + r["hydraulic_torque_Nm"])
    assert "contacts_fully_flooded" not in {w["code"] for w in p["warnings"]}
