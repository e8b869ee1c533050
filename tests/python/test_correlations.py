"""Liebrecht's drag and churning correlation (seed paper Eq. 38-40) and `kegel losses`."""

from __future__ import annotations

import json
import math

import pytest

import kegel
from conftest import run_kegel
from kegel.correlations import (
    LiebrechtInput,
    cylinder_drag_coefficient,
    free_disc_moment_coefficient,
    hydraulic_torques,
    immersed_fraction,
    implied_coefficients,
    liebrecht_torques,
)

RPM = math.pi / 30


def base_input(**kw) -> LiebrechtInput:
    x = dict(density_kg_m3=866.6, kinematic_viscosity_m2_s=60.6e-6, roller_length_m=0.017,
             roller_diameter_m=0.010, pitch_diameter_m=0.060, outer_raceway_diameter_m=0.0698,
             inner_raceway_diameter_m=0.0502, inner_ring_speed_rev_s=2000 / 60, cage_speed_rev_s=2000 / 60 * 0.418)
    x.update(kw)
    return LiebrechtInput(**x)


def test_hand_calculation_two_points():
    # Eq. 38-40 take the speeds in 1/min (issue 19, see correlations/liebrecht.py); before, this
    # test built its expectation with the speeds in rev/s, the superseded reading, which gave
    # torques 60^(2-a) = 117-194 times smaller. Hand values (SI, speeds in 1/min, torques N m):
    # 1000 rpm, n_C = 0.418 * 1000 = 418 1/min:
    #   drag = 0.86*866.6*0.017 * 0.010^0.164 * (60.6e-6)^0.836 * 0.060^2.164 * 418^1.164
    #        = 12.6697 * 0.469894 * 2.97953e-4 * 2.26944e-3 * 1124.73            = 4.52774e-3
    #   OR   = 0.32*866.6*pi*0.0698*0.017 * 0.0698^0.287 * (60.6e-6)^0.713 * (0.060*418)^1.287
    #        = 1.03377 * 0.465786 * 9.83791e-4 * 25.08^1.287 (63.2317)        = 2.99535e-2
    #   IR   = 0.52*866.6*pi*0.0502*0.017 * 0.0502^0.265 * (60.6e-6)^0.735 * (0.0502*1000 - 25.08)^1.265
    #        = 1.20816 * 0.452571 * 7.94543e-4 * 25.12^1.265 (59.0235)        = 2.56421e-2
    # 3000 rpm, n_C = 1254 1/min: the same prefactors with 1254^1.164 = 4040.34, 75.24^1.287 =
    #   260.010, 75.36^1.265 = 236.910: drag 1.62649e-2, OR 1.23169e-1, IR 1.02923e-1
    hand = {1000.0: (4.52774e-3, 2.99535e-2, 2.56421e-2), 3000.0: (1.62649e-2, 1.23169e-1, 1.02923e-1)}
    for n_rpm, (drag, cor, cir) in hand.items():
        n_i = n_rpm / 60
        n_c = 0.418 * n_i
        t = liebrecht_torques(base_input(inner_ring_speed_rev_s=n_i, cage_speed_rev_s=n_c))
        assert t.components["drag_rollers_Nm"] == pytest.approx(drag, rel=2e-5)
        assert t.components["churning_outer_ring_Nm"] == pytest.approx(cor, rel=2e-5)
        assert t.components["churning_inner_ring_Nm"] == pytest.approx(cir, rel=2e-5)
        assert t.total_Nm == pytest.approx(drag + cor + cir, rel=2e-5)
        # the superseded rev/s reading differs by 60^(2-a) per equation
        old = liebrecht_torques(base_input(inner_ring_speed_rev_s=n_i, cage_speed_rev_s=n_c), speed_reading="rev/s")
        for k, p in (("drag_rollers_Nm", 1.164), ("churning_outer_ring_Nm", 1.287), ("churning_inner_ring_Nm", 1.265)):
            assert t.components[k] == pytest.approx(old.components[k] * 60**p, rel=1e-12)


def _log_slope(f, x0, rel=1e-4):
    return (math.log(f(x0 * (1 + rel))) - math.log(f(x0 * (1 - rel)))) / (math.log1p(rel) - math.log1p(-rel))


@pytest.mark.parametrize("component, exponent", [
    ("drag_rollers_Nm", 0.836), ("churning_outer_ring_Nm", 0.713), ("churning_inner_ring_Nm", 0.735)])
def test_viscosity_exponents(component, exponent):
    s = _log_slope(lambda nu: liebrecht_torques(base_input(kinematic_viscosity_m2_s=nu)).components[component], 60e-6)
    assert s == pytest.approx(exponent, abs=1e-6)


def test_speed_exponents():
    # scaling both speeds together keeps the relative speed in Eq. 40 proportional
    def comp(name):
        return lambda k: liebrecht_torques(base_input(inner_ring_speed_rev_s=30 * k, cage_speed_rev_s=12 * k)).components[name]
    assert _log_slope(comp("drag_rollers_Nm"), 1.0) == pytest.approx(1.164, abs=1e-6)
    assert _log_slope(comp("churning_outer_ring_Nm"), 1.0) == pytest.approx(1.287, abs=1e-6)
    assert _log_slope(comp("churning_inner_ring_Nm"), 1.0) == pytest.approx(1.265, abs=1e-6)


def test_dimensional_homogeneity():
    # the restored exponents make every equation homogeneous in mass and length (the speeds
    # enter in 1/min, a fixed unit of time carried by the coefficients): lengths in mm (x1e3),
    # density in kg/mm^3 (x1e-9), nu in mm^2/s (x1e6): the torque comes out in kg mm^2/s^2 = 1e-6 N m
    si = liebrecht_torques(base_input())
    mm = liebrecht_torques(base_input(density_kg_m3=866.6e-9, kinematic_viscosity_m2_s=60.6,
                                      roller_length_m=17.0, roller_diameter_m=10.0, pitch_diameter_m=60.0,
                                      outer_raceway_diameter_m=69.8, inner_raceway_diameter_m=50.2))
    for k in si.components:
        assert mm.components[k] == pytest.approx(si.components[k] * 1e6, rel=1e-10), k


def test_immersed_fraction():
    assert immersed_fraction(-1.0, 0.5) == 0.0
    assert immersed_fraction(1.0, 0.5) == 1.0
    assert immersed_fraction(0.0, 0.5) == pytest.approx(0.5)
    assert immersed_fraction(-0.25, 0.5) == pytest.approx(1 / 3)  # arccos(1/2)/pi


@pytest.fixture(scope="module")
def g32208():
    return kegel.derive_geometry(kegel.load_bearing("32208"), kegel.load_material("bearing_steel"))


def test_zero_oil_gives_zero_loss_and_monotonic_in_level_and_speed(g32208):
    state = kegel.lubricant_state(kegel.load_lubricant("FVA3"), 323.15)
    zero = hydraulic_torques("liebrecht", g32208, state, shaft_speed_rad_s=2000 * RPM, oil_level_m=0.0)
    assert zero.total_Nm == 0.0
    levels = [i / 20 * g32208.outer_diameter_m for i in range(21)]
    totals = [hydraulic_torques("liebrecht", g32208, state, shaft_speed_rad_s=2000 * RPM, oil_level_m=h).total_Nm
              for h in levels]
    assert all(b >= a for a, b in zip(totals, totals[1:]))
    assert totals[-1] > totals[10] > 0
    speeds = [hydraulic_torques("liebrecht", g32208, state, shaft_speed_rad_s=n * RPM, oil_level_m=0.08).total_Nm
              for n in (500, 1000, 2000, 4000)]
    assert all(b > a for a, b in zip(speeds, speeds[1:]))


def test_rejects_bad_input(g32208):
    state = kegel.lubricant_state(kegel.load_lubricant("FVA3"), 323.15)
    # "skf" is a correlation now (correlations/skf.py); an unknown name still fails
    with pytest.raises(ValueError, match="expected one of liebrecht, skf"):
        hydraulic_torques("palmgren", g32208, state, shaft_speed_rad_s=100.0, oil_level_m=0.01)
    with pytest.raises(ValueError, match="oil_level_m"):
        hydraulic_torques("liebrecht", g32208, state, shaft_speed_rad_s=100.0, oil_level_m=0.2)


def test_cli_losses_table_json_and_plot(tmp_path):
    png = tmp_path / "losses.png"
    res = run_kegel("losses", "--bearing", "32208", "--temperature", "50 degC", "--speed-range", "500 rpm", "4000 rpm",
                    "--points", "4", "--oil-level", "half_roller", "--oil-level", "flooded", "--plot", str(png))
    assert res.returncode == 0, res.stderr
    assert "drag" in res.stdout and "flooded" in res.stdout
    assert png.stat().st_size > 1000
    res = run_kegel("losses", "--bearing", "32208", "--oil-level", "flooded", "--format", "json")
    data = json.loads(res.stdout)
    rows = data["points"]
    # Liebrecht's rows as before, followed by the SKF drag rows (issue 19)
    assert rows and {r["correlation"] for r in rows} == {"liebrecht", "skf"}
    assert all(r["total_Nm"] > 0 for r in rows)
    bad = run_kegel("losses", "--bearing", "32208", "--oil-level", "200 mm")
    assert bad.returncode == 2 and "--oil-level" in bad.stderr and "[0, D] = [0, 80 mm]" in bad.stderr


# --- issue 19: the speed unit of Eq. 38-40, checked against physical drag data -------------------

FLOODED_RPM = (500.0, 1000.0, 2000.0, 3000.0, 4000.0)


def _flooded_input(g, state, rpm: float) -> LiebrechtInput:
    from kegel.tribology import cage_speed_rad_s

    w = rpm * RPM
    return LiebrechtInput(
        density_kg_m3=state.density_kg_m3, kinematic_viscosity_m2_s=state.kinematic_viscosity_m2_s,
        roller_length_m=g.roller_length_m, roller_diameter_m=g.roller_mean_diameter_m,
        pitch_diameter_m=g.pitch_diameter_m, outer_raceway_diameter_m=g.outer_raceway_diameter_mid_m,
        inner_raceway_diameter_m=g.inner_raceway_diameter_mid_m, inner_ring_speed_rev_s=w / (2 * math.pi),
        cage_speed_rev_s=cage_speed_rad_s(g, w) / (2 * math.pi))


@pytest.fixture(scope="module")
def fva3_50():
    return kegel.lubricant_state(kegel.load_lubricant("FVA3"), 323.15)


def test_hand_values_32208_flooded_in_1_per_min(g32208, fva3_50):
    # 32208 flooded, FVA 3 at 50 degC (rho 866.6, nu 60.5913e-6), 2000 rpm, cage 0.418454 * 2000
    # = 836.909 1/min; d_m 0.060, D_w 0.010, l 0.017, d_ORL 0.0697855, d_IRL 0.0502145 (kegel.geometry):
    #   drag = 0.86*866.6*0.017*0.010^0.164*(60.5913e-6)^0.836*0.060^2.164*836.909^1.164 = 10.157 N mm
    #   OR = 0.32*866.6*pi*0.0697855*0.017*0.0697855^0.287*(60.5913e-6)^0.713*(0.060*836.909)^1.287 = 73.168 N mm
    #   IR = 0.52*866.6*pi*0.0502145*0.017*0.0502145^0.265*(60.5913e-6)^0.735
    #        *(0.0502145*2000-50.2145)^1.265 = 61.601 N mm
    t = hydraulic_torques("liebrecht", g32208, fva3_50, shaft_speed_rad_s=2000 * RPM,
                          oil_level_m=g32208.outer_diameter_m)
    assert t.components["drag_rollers_Nm"] == pytest.approx(10.157e-3, rel=1e-4)
    assert t.components["churning_outer_ring_Nm"] == pytest.approx(73.168e-3, rel=1e-4)
    assert t.components["churning_inner_ring_Nm"] == pytest.approx(61.601e-3, rel=1e-4)
    assert t.total_Nm == pytest.approx(144.93e-3, rel=1e-4)  # rev/s reading: 0.81 N mm


@pytest.mark.parametrize("rpm", FLOODED_RPM)
def test_implied_roller_drag_coefficient_in_physical_range(g32208, fva3_50, rpm):
    # Eq. 38 -> force per roller at the pitch radius -> C_D = F / (0.5 rho v^2 D_w l), v the
    # orbital speed against oil at rest (Re = v D_w / nu = 108-868). Upper bound: an isolated
    # cylinder at that Re (C_D = 1 + 10 Re^-2/3, 1.1-1.4): the relative speed in a housing at rest
    # cannot exceed the orbital speed, and oil carried with the roller set lowers the implied
    # value. Lower bound 0.004: half of what kegel's flooded CFD implies for rollers and cage at
    # 2000 rpm (2.1 mN m on the small mesh -> 0.008). 1/min gives 0.022-0.125, the superseded
    # rev/s reading 1.9e-4-1.1e-3.
    x = _flooded_input(g32208, fva3_50, rpm)
    c = implied_coefficients(x, g32208.roller_count)
    re = c["roller_reynolds_number"]
    assert 100 < re < 900
    assert 0.004 < c["roller_drag_coefficient"] < cylinder_drag_coefficient(re)
    old = implied_coefficients(x, g32208.roller_count, speed_reading="rev/s")
    assert old["roller_drag_coefficient"] < 0.002


@pytest.mark.parametrize("rpm", FLOODED_RPM)
def test_ring_terms_against_rotating_disc(g32208, fva3_50, rpm):
    # Eq. 40 as the moment coefficient of a disc of the inner raceway radius at the speed relative
    # to the cage, against the laminar free disc (von Karman/Cochran, both faces, 3.87 Re^-1/2):
    # 1/min is 9-15 times above it (a ring in a narrow annulus), rev/s 12-19 times below.
    x = _flooded_input(g32208, fva3_50, rpm)
    c = implied_coefficients(x, g32208.roller_count)
    free = free_disc_moment_coefficient(c["inner_ring_reynolds_number"])
    assert c["inner_ring_moment_coefficient"] > free
    old = implied_coefficients(x, g32208.roller_count, speed_reading="rev/s")
    assert old["inner_ring_moment_coefficient"] < 0.1 * free
    # the flooded total must exceed what the two side faces of the cone dissipate as free discs:
    # one face M = 0.308 pi rho sqrt(nu w^3) (r_o^4 - r_i^4), bore radius to rib top and to the
    # small raceway end (2.2 N mm at 500 rpm ... 49 N mm at 4000 rpm)
    w = rpm * RPM
    rb = g32208.bore_diameter_m / 2
    faces = (g32208.rib_top_point_m[1] ** 4 - rb**4) + (g32208.inner_raceway_small_end_m[1] ** 4 - rb**4)
    floor = 0.308 * math.pi * fva3_50.density_kg_m3 * math.sqrt(fva3_50.kinematic_viscosity_m2_s * w**3) * faces
    assert liebrecht_torques(x).total_Nm > 5 * floor
    assert liebrecht_torques(x, speed_reading="rev/s").total_Nm < floor / 10


def test_liebrecht_agrees_with_skf_drag(g32208, fva3_50):
    # two independent empirical models: Liebrecht (1/min) / SKF drag = 0.75-1.22 over 500-4000 rpm
    # at the three default levels of `kegel losses`; the rev/s reading was 0.004-0.01 of SKF
    for h in (0.01, 0.04, g32208.outer_diameter_m):
        for rpm in FLOODED_RPM:
            kw = dict(shaft_speed_rad_s=rpm * RPM, oil_level_m=h)
            ratio = (hydraulic_torques("liebrecht", g32208, fva3_50, **kw).total_Nm
                     / hydraulic_torques("skf", g32208, fva3_50, **kw).total_Nm)
            assert 0.7 < ratio < 1.3, (h, rpm, ratio)


def test_speed_reading_rejected():
    with pytest.raises(ValueError, match="speed_reading"):
        liebrecht_torques(base_input(), speed_reading="rad/s")


# --- `kegel losses`: Liebrecht and SKF side by side ------------------------------------------------

def test_cli_losses_side_by_side_table():
    res = run_kegel("losses", "--bearing", "32208", "--speed", "2000 rpm",
                    "--oil-level", "flooded", "--oil-level", "shaft_center")
    assert res.returncode == 0, res.stderr
    out = res.stdout
    for column in ("Liebrecht drag (38)", "Liebrecht total", "SKF drag", "SKF rolling+sliding"):
        assert column in out
    assert "speeds in 1/min" in out and "Fa = 6 kN" in out
    flooded = next(line for line in out.splitlines() if line.startswith("flooded"))
    # Liebrecht total 144.926, SKF drag 127.497 (H = 1.2 d_m), SKF rolling+sliding at Fa = 6 kN
    # 1303.95 N mm (hand values in test_skf.py and above), printed with four figures
    cells = flooded.split()
    assert "144.9" in cells and "127.5" in cells and "1304" in cells
    centre = next(line for line in out.splitlines() if line.startswith("shaft_center"))
    assert "66.36" in centre.split()  # SKF drag at H = 0.6 d_m


def test_cli_losses_side_by_side_json_options_and_errors(tmp_path):
    res = run_kegel("losses", "--bearing", "32208", "--speed", "2000 rpm",
                    "--oil-level", "flooded", "--axial-load", "1 kN", "--radial-load", "2 kN",
                    "--skf-edition", "2005", "--format", "json")
    assert res.returncode == 0, res.stderr
    data = json.loads(res.stdout)
    assert data["skf"]["edition"] == "2005" and data["skf"]["axial_load_N"] == 1000.0
    assert data["skf"]["radial_load_N"] == 2000.0 and data["skf"]["verify"] is True
    (side,) = data["side_by_side"]
    assert side["liebrecht_total_Nm"] == pytest.approx(0.144926, rel=1e-4)
    assert side["skf_drag_Nm"] == pytest.approx(0.216635, rel=1e-5)  # 10 V_M K_roll B d_m^4 n^2 (2005)
    skf_row = next(r for r in data["points"] if r["correlation"] == "skf")
    assert skf_row["flooded"] and skf_row["oil_level_H_m"] == pytest.approx(0.076)
    assert skf_row["drag_second_term_Nm"] == 0.0
    assert skf_row["rolling_sliding_Nm"] == pytest.approx(skf_row["rolling_Nm"] + skf_row["sliding_Nm"])
    bad = run_kegel("losses", "--bearing", "32208", "--axial-load", "-1 kN")
    assert bad.returncode == 2 and "--axial-load" in bad.stderr and "a force >= 0" in bad.stderr
    # a bearing without SKF series constants: drag only
    src = (kegel.data.DATA_DIR / "bearings" / "32208.toml").read_text()
    other = tmp_path / "30208x.toml"
    other.write_text(src.replace('designation = "32208"', 'designation = "30208x"'))
    res = run_kegel("losses", "--bearing", str(other), "--points", "2", "--oil-level", "flooded", "--format", "json")
    assert res.returncode == 0, res.stderr
    data = json.loads(res.stdout)
    assert data["skf"]["rolling_sliding"].startswith("no SKF series constants")
    assert all(s["skf_rolling_sliding_Nm"] is None and s["skf_drag_Nm"] > 0 for s in data["side_by_side"])


def test_losses_puts_cfd_results_beside_the_correlations(tmp_path):
    """kegel losses --cfd: a CFD result of the same bearing, oil and temperature joins the table
    with the correlations evaluated at its own speed and oil level and its wall time (run plus
    meshing); results of another temperature are left out."""
    import json
    import math

    from conftest import run_kegel

    def result(folder, T_K, level, loss):
        case = tmp_path / folder
        case.mkdir()
        (case / "results.json").write_text(json.dumps({
            "point": {"bearing": "32208", "lubricant": "FVA3", "speed_rad_s": 2000 * math.pi / 30,
                      "temperature_K": T_K, "oil_level_m": level},
            "kinematics": {}, "fidelity": {"mesh": "small", "cells": 234055}, "runtime_s": 300.0,
            "loss_torque_at_shaft_Nm": loss, "steady": True,
            "angular_momentum_balance": {"relative_to_drive_torque": -0.078}}))
        (case / "kegel-case.json").write_text(json.dumps({"mesh_time_s": 40.0}))

    result("a", 323.15, None, 0.0652)
    result("b", 323.15, 0.04, 0.026)
    result("c", 353.15, None, 0.03)  # another temperature
    res = run_kegel("losses", "--bearing", "32208", "--cfd", str(tmp_path), "--format", "json", "--plot", str(tmp_path / "l.png"))
    assert res.returncode == 0, res.stderr
    d = json.loads(res.stdout)
    rows = d["cfd"]
    assert [r["oil_level"] for r in rows] == ["flooded", "shaft_center"]
    flooded = rows[0]
    assert flooded["loss_torque_Nm"] == 0.0652 and flooded["wall_time_s"] == 340.0
    assert flooded["liebrecht_total_Nm"] == pytest.approx(0.145, rel=0.01)  # 145 N mm at 2000 rpm, 1/min reading
    assert flooded["skf_drag_Nm"] == pytest.approx(0.1275, rel=0.01)
    assert rows[1]["skf_drag_Nm"] == pytest.approx(0.066, rel=0.02)
    assert d["cost_per_point_s"]["liebrecht_s"] < 0.01 and (tmp_path / "l.png").is_file()
