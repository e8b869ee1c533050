"""The SKF catalogue friction model of tapered roller bearings (correlations/skf.py).

Hand values were computed independently in the catalogue's own units (N mm, mm, r/min, mm^2/s,
N) in a Python shell from the equations of shared/reference/skf_friction_model.toml; the comments
show the arithmetic. FVA 3 at 50 degC: nu = 52.5084 mPa s / 866.6 kg/m^3 = 60.5913 mm^2/s
(kegel's lubricant data). Catalogue d_m = 0.5 (d + D): 32208 60 mm, 32216 110 mm; B (cone
width) 23 / 33 mm, Y 1.6 / 1.4.
"""

from __future__ import annotations

import math

import pytest

import kegel
from kegel.correlations import skf
from kegel.correlations.skf import (
    SkfBearing,
    drag_loss_variable,
    skf_bearing,
    skf_drag_moment,
    skf_friction,
    skf_oil_level_H_m,
    skf_rolling_moment,
    skf_sliding_moment,
)

RPM = math.pi / 30


@pytest.fixture(scope="module")
def nu50():
    nu = kegel.lubricant_state(kegel.load_lubricant("FVA3"), 323.15).kinematic_viscosity_m2_s
    assert nu * 1e6 == pytest.approx(60.5913, rel=1e-6)
    return nu


@pytest.fixture(scope="module")
def b08():
    return skf_bearing(kegel.load_bearing("32208"))


@pytest.fixture(scope="module")
def b16():
    return skf_bearing(kegel.load_bearing("32216"))


def test_bearing_data_from_kegel(b08, b16):
    assert (b08.bore_diameter_m, b08.outer_diameter_m) == (0.040, 0.080)
    assert (b08.width_m, b08.axial_load_factor_Y) == (0.023, 1.6)
    assert b08.mean_diameter_m == pytest.approx(0.060)
    assert b16.mean_diameter_m == pytest.approx(0.110)  # not the roller pitch diameter 108.5 mm
    assert (b16.R1, b16.R2, b16.S1, b16.S2) == (2.27e-6, 10.9, 0.018, 2.0)
    with pytest.raises(kegel.KegelInputError, match="series.*'302'"):
        skf_bearing(kegel.load_bearing("32208"), series="302")


# --- rolling: two points --------------------------------------------------------------------------

def test_rolling_32216_500rpm_oil_bath(b16, nu50):
    # G_rr = 2.27e-6 * 110^2.38 * (0 + 10.9*1.4*6000)^0.31 = 2.27e-6 * 72196.24 * 34.52461 = 5.658082
    # phi_ish = 1/(1 + 1.84e-9 (500*110)^1.28 nu^0.64) = 1/(1 + 1.84e-9*1168595.6*13.82746) = 0.9711264
    # phi_rs = exp(-3e-8 * nu * 500 * 220 * sqrt(6/(2*60))) = exp(-0.04471044) = 0.9562743
    # M_rr = 0.9711264 * 0.9562743 * 5.658082 * (nu*500)^0.6 (488.4589) = 2566.584 N mm
    M, ish, rs = skf_rolling_moment(b16, speed_rad_s=500 * RPM, kinematic_viscosity_m2_s=nu50, axial_load_N=6000)
    assert ish == pytest.approx(0.9711264, rel=1e-6)
    assert rs == pytest.approx(0.9562743, rel=1e-6)
    assert M == pytest.approx(2566.584e-3, rel=1e-6)


def test_rolling_32208_3000rpm_combined_load_oil_air(b08, nu50):
    # G_rr = 2.27e-6 * 60^2.38 * (2000 + 10.9*1.6*1000)^0.31 = 2.27e-6 * 17060.82 * 21.35482 = 0.8270308
    # phi_ish = 1/(1 + 1.84e-9 (3000*60)^1.28 nu^0.64) = 1/(1 + 0.1356154) = 0.8805798
    # phi_rs (oil-air, K_rs 6e-8) = exp(-6e-8 * nu * 3000 * 120 * sqrt(6/80)) = exp(-0.3584218) = 0.6987783
    # M_rr = 0.8805798 * 0.6987783 * 0.8270308 * (nu*3000)^0.6 (1431.261) = 728.3641 N mm
    M, ish, rs = skf_rolling_moment(b08, speed_rad_s=3000 * RPM, kinematic_viscosity_m2_s=nu50, axial_load_N=1000,
                                    radial_load_N=2000, lubrication="oil_air")
    assert (ish, rs) == (pytest.approx(0.8805798, rel=1e-6), pytest.approx(0.6987783, rel=1e-6))
    assert M == pytest.approx(728.3641e-3, rel=1e-6)


# --- sliding: two points --------------------------------------------------------------------------

def test_sliding_32216_100rpm(b16, nu50):
    # G_sl = 0.018 * 110^0.82 * (0 + 2*1.4*6000) = 0.018 * 47.20000 * 16800 = 14273.28
    # phi_bl = exp(-2.6e-8 (100 nu)^1.4 * 110) = exp(-0.5645989) = 0.5685882
    # mu_sl = 0.5685882*0.15 + (1 - 0.5685882)*0.002 = 0.08615105; M_sl = 1229.658 N mm
    M, bl, mu = skf_sliding_moment(b16, speed_rad_s=100 * RPM, kinematic_viscosity_m2_s=nu50, axial_load_N=6000)
    assert bl == pytest.approx(0.5685882, rel=1e-6)
    assert mu == pytest.approx(0.08615105, rel=1e-6)
    assert M == pytest.approx(1229.658e-3, rel=1e-6)


def test_sliding_32208_200rpm_combined_load(b08, nu50):
    # G_sl = 0.018 * 60^0.82 * (2000 + 2*1.6*1000) = 0.018 * 28.71336 * 5200 = 2687.571
    # phi_bl = exp(-2.6e-8 (200 nu)^1.4 * 60) = exp(-0.8127193) = 0.4436500
    # mu_sl = 0.44365*0.15 + 0.55635*0.002 = 0.06766020; M_sl = 181.8416 N mm
    M, bl, mu = skf_sliding_moment(b08, speed_rad_s=200 * RPM, kinematic_viscosity_m2_s=nu50, axial_load_N=1000,
                                   radial_load_N=2000)
    assert bl == pytest.approx(0.4436500, rel=1e-6)
    assert mu == pytest.approx(0.06766020, rel=1e-6)
    assert M == pytest.approx(181.8416e-3, rel=1e-6)


# --- drag: three oil levels (32208, 2000 rpm) -------------------------------------------------------
# K_roll = 0.7*6*(40+80)/(80-40)*1e-12 = 1.26e-11; l_D = 5*0.7*23/60 = 1.341667;
# C_w = 2.789e-10 l_D^3 - 2.786e-4 l_D^2 + 0.0195 l_D + 0.6439 = 0.6695610; f_A = 0.05*6*120/40 = 0.9;
# n d_m^2 / nu = 2000*3600/60.5913 = 118829.0

def test_drag_low_level_half_roller(b08, nu50):
    # kegel half_roller 10 mm -> H = 10 - 40 + 36 = 6 mm = 0.1 d_m: V_M = 1.169e-4 (table node)
    # first = 4 * 1.169e-4 * 1.26e-11 * 0.6695610 * 23 * 60^4 * 2000^2 = 4.703574 N mm
    # t = 2 acos((36 - 6)/36) = 1.171371; f_t = sin(t/2) = 0.5527708; R_s = 0.36*3600*(t - sin t)*0.9 = 291.7008
    # second = 1.093e-7 * 2000^2 * 60^3 * (118829.0*0.5527708)^-1.379 * 291.7008 = 6.263019 N mm
    d = skf_drag_moment(b08, speed_rad_s=2000 * RPM, kinematic_viscosity_m2_s=nu50, oil_level_m=0.010)
    assert d.oil_level_H_m == pytest.approx(0.006) and not d.flooded
    assert d.V_M == pytest.approx(1.169e-4, rel=1e-12)
    assert d.C_w == pytest.approx(0.6695610, rel=1e-6)
    assert d.first_term_Nm == pytest.approx(4.703574e-3, rel=1e-6)
    assert d.second_term_Nm == pytest.approx(6.263019e-3, rel=1e-6)
    assert d.drag_Nm == pytest.approx(10.96659e-3, rel=1e-6)


def test_drag_half_bearing_H_0_6_dm(b08, nu50):
    # H = 0.6 d_m = 36 mm (kegel shaft_center, 40 mm): V_M = 7.86e-4; first = 31.62540 N mm;
    # t = pi, f_t = 1, R_s = 0.36*3600*pi*0.9 = 3664.354; second = 1.093e-7*4e6*216000*118829.0^-1.379
    # * 3664.354 = 34.73867 N mm; total 66.36407 N mm (the issue's "about 66 N mm")
    for kw in ({"oil_level_m": 0.040}, {"oil_level_H_m": 0.036}):
        d = skf_drag_moment(b08, speed_rad_s=2000 * RPM, kinematic_viscosity_m2_s=nu50, **kw)
        assert d.first_term_Nm == pytest.approx(31.62540e-3, rel=1e-6)
        assert d.second_term_Nm == pytest.approx(34.73867e-3, rel=1e-6)
        assert d.drag_Nm == pytest.approx(66.36407e-3, rel=1e-6)


def test_drag_flooded_both_editions(b08, nu50):
    # kegel flooded (80 mm) -> H = 76 mm = 1.267 d_m >= 1.2 d_m: V_M = 1.442e-3, t = 2 pi, f_t = 1,
    # R_s = 0.36*3600*2 pi*0.9 = 7328.707. 2013: first = 58.02014, second = 69.47733, total 127.4975 N mm
    # (the issue's "about 128 N mm"). 2005: 10 * 1.442e-3 * 1.26e-11 * 23 * 60^4 * 2000^2 = 216.6350 N mm
    d = skf_drag_moment(b08, speed_rad_s=2000 * RPM, kinematic_viscosity_m2_s=nu50, oil_level_m=0.080)
    assert d.flooded and d.V_M == 1.442e-3
    assert d.first_term_Nm == pytest.approx(58.02014e-3, rel=1e-6)
    assert d.second_term_Nm == pytest.approx(69.47733e-3, rel=1e-6)
    assert d.drag_Nm == pytest.approx(127.4975e-3, rel=1e-6)
    old = skf_drag_moment(b08, speed_rad_s=2000 * RPM, kinematic_viscosity_m2_s=nu50, oil_level_m=0.080, edition="2005")
    assert old.drag_Nm == pytest.approx(216.6350e-3, rel=1e-6) and old.second_term_Nm == 0.0
    # any H above 1.2 d_m is the flooded value
    higher = skf_drag_moment(b08, speed_rad_s=2000 * RPM, kinematic_viscosity_m2_s=nu50, oil_level_H_m=0.2)
    assert higher.drag_Nm == pytest.approx(d.drag_Nm, rel=1e-12)


def test_drag_no_oil_and_standstill(b08, nu50):
    assert skf_drag_moment(b08, speed_rad_s=2000 * RPM, kinematic_viscosity_m2_s=nu50, oil_level_m=0.0).drag_Nm == 0.0
    assert skf_drag_moment(b08, speed_rad_s=2000 * RPM, kinematic_viscosity_m2_s=nu50, oil_level_m=0.004).drag_Nm == 0.0
    assert skf_drag_moment(b08, speed_rad_s=0.0, kinematic_viscosity_m2_s=nu50, oil_level_m=0.08).drag_Nm == 0.0
    levels = [i * 0.004 for i in range(21)]
    drags = [skf_drag_moment(b08, speed_rad_s=2000 * RPM, kinematic_viscosity_m2_s=nu50, oil_level_m=h).drag_Nm
             for h in levels]
    assert all(b >= a for a, b in zip(drags, drags[1:])) and drags[2] > 0


# --- oil level convention and V_M -----------------------------------------------------------------

def test_oil_level_conversion():
    # H = h - D/2 + 0.6 d_m: 32208 (D 80, d_m 60) -> H = h - 4 mm
    assert skf_oil_level_H_m(0.040, 0.080, 0.060) == pytest.approx(0.036)   # shaft centre: 0.6 d_m
    assert skf_oil_level_H_m(0.000, 0.080, 0.060) == pytest.approx(-0.004)  # below the 0.6 d_m circle
    assert skf_oil_level_H_m(0.080, 0.080, 0.060) == pytest.approx(0.076)
    # a thin section (D/2 < 0.6 d_m): kegel's flooded level D still counts as flooded
    assert skf_oil_level_H_m(0.050, 0.050, 0.045) == pytest.approx(1.2 * 0.045)


def test_V_M_nodes_between_and_clamp():
    table = dict(skf.V_M_TABLE)
    for x in (0.01, 0.1, 0.175, 0.6, 1.2):
        assert drag_loss_variable(x) == table[x]
    assert drag_loss_variable(0.55) == pytest.approx(0.5 * (6.87e-4 + 7.86e-4), rel=1e-12)
    assert drag_loss_variable(0.185) == pytest.approx(2.932e-4 + 0.4 * (3.17e-4 - 2.932e-4), rel=1e-12)
    assert drag_loss_variable(0.005) == pytest.approx(2.7e-6, rel=1e-12)  # linear from V_M(0) = 0
    assert drag_loss_variable(0.0) == 0.0 and drag_loss_variable(-0.3) == 0.0
    assert drag_loss_variable(1.5) == drag_loss_variable(1.2) == 1.442e-3
    assert drag_loss_variable(100.0) == 1.442e-3
    xs = [i / 200 for i in range(260)]
    vals = [drag_loss_variable(x) for x in xs]
    assert all(b >= a for a, b in zip(vals, vals[1:]))


# --- the issue's reference figures ----------------------------------------------------------------

@pytest.mark.parametrize("rpm, hand_Nm, issue_Nm", [
    # M_rr + M_sl in N mm (hand): 500: 2566.584 + 38.339; 2000: 4517.547 + 28.547; 4000: 4720.200 + 28.547
    (500.0, 2.604923, 2.6), (2000.0, 4.546094, 4.5), (4000.0, 4.748747, 4.7)])
def test_32216_reference_rolling_plus_sliding(b16, nu50, rpm, hand_Nm, issue_Nm):
    # 32216, Fa = 6 kN, Fr = 0, FVA 3 at 50 degC, oil bath: reproduces 2.6 / 4.5 / 4.7 N m
    f = skf_friction(b16, speed_rad_s=rpm * RPM, kinematic_viscosity_m2_s=nu50, axial_load_N=6000)
    assert f.rolling_sliding_Nm == pytest.approx(hand_Nm, rel=1e-6)
    assert f.rolling_sliding_Nm == pytest.approx(issue_Nm, rel=0.015)
    assert f.drag_Nm == 0.0 and f.drag.oil_level_H_m is None
    assert f.total_Nm == pytest.approx(f.rolling_Nm + f.sliding_Nm)


def test_32208_reference_drag(b08, nu50):
    # 32208, 2000 rpm, 50 degC: about 128 N mm flooded and about 66 N mm at H = 0.6 d_m (issue 19)
    kw = dict(speed_rad_s=2000 * RPM, kinematic_viscosity_m2_s=nu50)
    assert skf_drag_moment(b08, oil_level_m=0.08, **kw).drag_Nm == pytest.approx(0.128, rel=0.01)
    assert skf_drag_moment(b08, oil_level_H_m=0.6 * 0.060, **kw).drag_Nm == pytest.approx(0.066, rel=0.01)
    # and the 32208's own contact friction at Fa = 6 kN (`kegel losses` default): 1284.107 + 19.847
    # = 1303.954 N mm (phi_ish 0.92532, phi_rs 0.88739, G_rr = 2.27e-6*60^2.38*(10.9*1.6*6000)^0.31)
    f = skf_friction(b08, axial_load_N=6000, oil_level_m=0.08, **kw)
    assert f.rolling_sliding_Nm == pytest.approx(1.303954, rel=1e-6)
    assert f.total_Nm == pytest.approx(1.303954 + 0.1274975, rel=1e-6)
    d = f.as_dict()
    assert d["total_Nm"] == f.total_Nm and d["verify"] is True and d["phi_rs"] == pytest.approx(0.8873871, rel=1e-6)


def test_hydraulic_interface(nu50):
    g = kegel.derive_geometry(kegel.load_bearing("32208"), kegel.load_material("bearing_steel"))
    state = kegel.lubricant_state(kegel.load_lubricant("FVA3"), 323.15)
    from kegel.correlations import hydraulic_torques

    t = hydraulic_torques("skf", g, state, shaft_speed_rad_s=2000 * RPM, oil_level_m=g.outer_diameter_m)
    assert t.correlation == "skf" and t.total_Nm == pytest.approx(0.1274975, rel=1e-6)
    assert t.inner_ring_Nm == t.total_Nm and t.outer_ring_Nm == 0.0 and t.cage_Nm == 0.0
    rev = hydraulic_torques("skf", g, state, shaft_speed_rad_s=-2000 * RPM, oil_level_m=g.outer_diameter_m)
    assert rev.total_Nm == pytest.approx(-t.total_Nm)


# --- input validation -------------------------------------------------------------------------------

@pytest.mark.parametrize("kw, name", [
    ({"speed_rad_s": -1.0}, "speed_rad_s"),
    ({"speed_rad_s": math.nan}, "speed_rad_s"),
    ({"kinematic_viscosity_m2_s": 0.0}, "kinematic_viscosity_m2_s"),
    ({"kinematic_viscosity_m2_s": math.nan}, "kinematic_viscosity_m2_s"),
    ({"axial_load_N": -5.0}, "axial_load_N"),
    ({"radial_load_N": math.inf}, "radial_load_N"),
    ({"oil_level_m": -0.01}, "oil_level_m"),
    ({"oil_level_m": math.nan}, "oil_level_m"),
    ({"lubrication": "grease"}, "lubrication"),
    ({"edition": "2018"}, "edition"),
])
def test_rejects_bad_input(b08, nu50, kw, name):
    args = dict(speed_rad_s=100.0, kinematic_viscosity_m2_s=nu50, axial_load_N=1000.0, oil_level_m=0.04)
    args.update(kw)
    with pytest.raises(kegel.KegelInputError) as err:
        skf_friction(b08, **args)
    msg = str(err.value)
    assert f"'{name}'" in msg and "expected" in msg
    assert str(kw[name]) in msg or repr(kw[name]) in msg


def test_rejects_bad_bearing_and_missing_constants(nu50):
    with pytest.raises(kegel.KegelInputError, match="'width_m' = -0.02: expected a finite value > 0"):
        SkfBearing(designation="x", bore_diameter_m=0.04, outer_diameter_m=0.08, width_m=-0.02)
    with pytest.raises(kegel.KegelInputError, match="outer_diameter_m"):
        SkfBearing(designation="x", bore_diameter_m=0.08, outer_diameter_m=0.04, width_m=0.02)
    drag_only = SkfBearing(designation="x", bore_diameter_m=0.04, outer_diameter_m=0.08, width_m=0.023)
    assert skf_drag_moment(drag_only, speed_rad_s=2000 * RPM, kinematic_viscosity_m2_s=nu50,
                           oil_level_m=0.08).drag_Nm == pytest.approx(0.1274975, rel=1e-6)
    with pytest.raises(kegel.KegelInputError, match="axial_load_factor_Y"):
        skf_rolling_moment(drag_only, speed_rad_s=100.0, kinematic_viscosity_m2_s=nu50, axial_load_N=1.0)
    with pytest.raises(kegel.KegelInputError, match="exactly one of"):
        skf_drag_moment(drag_only, speed_rad_s=1.0, kinematic_viscosity_m2_s=nu50, oil_level_m=0.01, oil_level_H_m=0.01)
    with pytest.raises(kegel.KegelInputError, match="H_over_dm"):
        drag_loss_variable(math.nan)


def test_verify_flags_documented():
    assert skf.VERIFY["K_Z"] and skf.VERIFY["R1"] and skf.VERIFY["V_M_TABLE"]
    assert "verify" in skf.__doc__.lower()
    assert set(skf.DRAG_EDITIONS) == {"2013", "2005"}
    assert skf.K_RS["oil_bath"] == 3e-8 and skf.K_RS["oil_air"] == 6e-8
