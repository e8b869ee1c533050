"""Liebrecht's drag and churning correlation (seed paper Eq. 38-40) and `kegel losses`."""

from __future__ import annotations

import json
import math

import pytest

import kegel
from conftest import run_kegel
from kegel.correlations import LiebrechtInput, hydraulic_torques, immersed_fraction, liebrecht_torques

RPM = math.pi / 30


def base_input(**kw) -> LiebrechtInput:
    x = dict(density_kg_m3=866.6, kinematic_viscosity_m2_s=60.6e-6, roller_length_m=0.017,
             roller_diameter_m=0.010, pitch_diameter_m=0.060, outer_raceway_diameter_m=0.0698,
             inner_raceway_diameter_m=0.0502, inner_ring_speed_rev_s=2000 / 60, cage_speed_rev_s=2000 / 60 * 0.418)
    x.update(kw)
    return LiebrechtInput(**x)


def test_hand_calculation_two_points():
    for n_rpm in (1000.0, 3000.0):
        n_i = n_rpm / 60
        n_c = 0.418 * n_i
        x = base_input(inner_ring_speed_rev_s=n_i, cage_speed_rev_s=n_c)
        t = liebrecht_torques(x)
        rho, nu, l, d, dm, do, di = 866.6, 60.6e-6, 0.017, 0.010, 0.060, 0.0698, 0.0502
        drag = 0.86 * rho * l * d**0.164 * nu**0.836 * dm**2.164 * n_c**1.164
        cor = 0.32 * rho * (math.pi * do * l) * do**0.287 * nu**0.713 * (dm * n_c) ** 1.287
        cir = 0.52 * rho * (math.pi * di * l) * di**0.265 * nu**0.735 * (di * n_i - dm * n_c) ** 1.265
        assert t.components["drag_rollers_Nm"] == pytest.approx(drag, rel=1e-12)
        assert t.components["churning_outer_ring_Nm"] == pytest.approx(cor, rel=1e-12)
        assert t.components["churning_inner_ring_Nm"] == pytest.approx(cir, rel=1e-12)
        assert t.total_Nm == pytest.approx(drag + cor + cir, rel=1e-12)


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
    # the restored exponents make every equation a torque in any consistent unit system:
    # lengths in mm (x1e3), density in kg/mm^3 (x1e-9), nu in mm^2/s (x1e6): the torque comes
    # out in kg mm^2/s^2 = 1e-6 N m
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
    with pytest.raises(ValueError, match="expected one of liebrecht"):
        hydraulic_torques("skf", g32208, state, shaft_speed_rad_s=100.0, oil_level_m=0.01)
    with pytest.raises(ValueError, match="oil_level_m"):
        hydraulic_torques("liebrecht", g32208, state, shaft_speed_rad_s=100.0, oil_level_m=0.2)


def test_cli_losses_table_json_and_plot(tmp_path):
    png = tmp_path / "losses.png"
    res = run_kegel("losses", "32208", "--temperature", "50 degC", "--speed", "500 rpm", "--speed", "4000 rpm",
                    "--points", "4", "--oil-level", "half_roller", "--oil-level", "flooded", "--plot", str(png))
    assert res.returncode == 0, res.stderr
    assert "drag" in res.stdout and "flooded" in res.stdout
    assert png.stat().st_size > 1000
    res = run_kegel("losses", "32208", "--oil-level", "flooded", "--format", "json")
    data = json.loads(res.stdout)
    rows = data["points"]
    assert rows and all(r["correlation"] == "liebrecht" for r in rows)
    assert all(r["total_Nm"] > 0 for r in rows)
    bad = run_kegel("losses", "32208", "--oil-level", "200 mm")
    assert bad.returncode == 2 and "--oil-level" in bad.stderr and "[0, D] = [0, 80 mm]" in bad.stderr
