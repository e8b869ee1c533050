"""Oils from their viscosities (kegel.estimate, issue 28 item 3).

What the method achieves against the one measured oil kegel ships, FVA 3 (seed paper Table A1),
estimated from its nu40 = 96.88 and nu100 = 11.79 mm^2/s (from its own Vogel law) and density:

==============  ============  =====================================================
temperature     viscosity     pressure-viscosity coefficient (So-Klaus vs Dicke)
==============  ============  =====================================================
0 degC          +0.25 %       +38.6 %  (42.3 vs 30.5 1/GPa; 1/alpha linear in theta from 40/100)
20 degC         +0.07 %       +25.3 %
50 degC         -0.01 %       +14.0 %  (23.9 vs 21.0 1/GPa)
100 degC        +0.00 %       +4.3 %   (16.7 vs 16.0 1/GPa)
150 degC        +0.06 %       -0.9 %
==============  ============  =====================================================

The friction torque of the 32216 at Table 1 (6 kN, 50 degC) moves by +0.2 % at 500-4000 rpm with
the estimated oil: the pressure-viscosity coefficient hardly enters kegel's friction there.
The tolerances below are these figures rounded up.
"""

from __future__ import annotations

import json
import math

import pytest

import kegel
from kegel import data as D
from kegel.estimate import (EstimateError, astm_d341_line, astm_d341_viscosity_mm2_s, so_klaus_alpha_per_Pa,
                            vogel_through_points)
from kegel.geometry import derive_geometry
from kegel.lubricant import lubricant_state
from kegel.quasi_static import bearing_friction
from kegel.tribology import load_friction

from conftest import call_kegel


def fva3_estimated() -> tuple[D.LubricantData, D.LubricantData]:
    fva3 = D.load_lubricant("FVA3")
    nu40 = lubricant_state(fva3, 313.15).kinematic_viscosity_m2_s * 1e6
    nu100 = lubricant_state(fva3, 373.15).kinematic_viscosity_m2_s * 1e6
    est = D.lubricant_from_viscosities("FVA3 estimated", nu40_mm2_s=nu40, nu100_mm2_s=nu100,
                                       density_15C_kg_m3=fva3.parameters.density_ref_kg_m3)
    return fva3, est


def test_astm_d341_slope_by_hand():
    """nu40 = 96.9, nu100 = 11.8 mm^2/s: log10 log10(97.6) = 0.298734, log10 log10(12.5) = 0.040171;
    log10(313.15) = 2.495752, log10(373.15) = 2.571884; B = 0.258563 / 0.076132 = 3.3962."""
    A, B = astm_d341_line(96.9, 40.0, 11.8, 100.0)
    assert B == pytest.approx(3.3962, rel=2e-4)
    assert astm_d341_viscosity_mm2_s(A, B, 40.0) == pytest.approx(96.9, rel=1e-9)
    assert astm_d341_viscosity_mm2_s(A, B, 100.0) == pytest.approx(11.8, rel=1e-9)
    with pytest.raises(EstimateError, match=">= 2 mm"):
        astm_d341_line(1.5, 40.0, 1.0, 100.0)


def test_so_klaus_by_hand():
    """FVA 3 at 50 degC: nu = 60.6 mm^2/s, rho = 0.8666 g/cm^3, b = 3.396; X = log10(60.6) = 1.78247:
    1.216 + 4.143 X^3.0627 (24.33) + 2.848e-4 b^5.1903 X^1.5976 (0.409) - 3.999 X^3.0975 rho^0.1162 (23.57)
    = 2.385 (x 1e-8 m^2/N), the hand sums rounded to 4 digits."""
    assert so_klaus_alpha_per_Pa(60.6, 0.8666, 3.396) == pytest.approx(2.385e-8, rel=3e-3)


def test_vogel_through_three_points_recovers_a_vogel_law():
    K, B, C = 0.062, 1021.7, 101.5517   # FVA 3, Table A1
    pts = [(t, K * math.exp(B / (t + C))) for t in (40.0, 70.0, 100.0)]
    k, b, c = vogel_through_points(pts)
    assert (k, b, c) == pytest.approx((K, B, C), rel=1e-8)
    with pytest.raises(EstimateError):
        vogel_through_points([(40.0, 84.5), (70.0, 30.0), (100.0, 9.9)])  # no Vogel law through these


# temperature [degC]: (tolerance viscosity, tolerance alpha), relative deviation from FVA 3
TOLERANCES = {20.0: (0.002, 0.27), 50.0: (0.001, 0.15), 100.0: (0.001, 0.05), 150.0: (0.002, 0.02)}


@pytest.mark.parametrize("theta", sorted(TOLERANCES))
def test_estimated_fva3_against_its_measured_laws(theta):
    fva3, est = fva3_estimated()
    a, b = lubricant_state(fva3, theta + 273.15), lubricant_state(est, theta + 273.15)
    tol_nu, tol_alpha = TOLERANCES[theta]
    dev_nu = b.kinematic_viscosity_m2_s / a.kinematic_viscosity_m2_s - 1
    dev_alpha = b.pressure_viscosity_coefficient_1_Pa / a.pressure_viscosity_coefficient_1_Pa - 1
    assert abs(dev_nu) <= tol_nu, f"{theta} degC: nu {100 * dev_nu:+.2f} %"
    assert abs(dev_alpha) <= tol_alpha, f"{theta} degC: alpha {100 * dev_alpha:+.1f} %"
    if theta == 50.0:  # the reference's figures: 21.0 1/GPa (Dicke) against So-Klaus
        assert a.pressure_viscosity_coefficient_1_Pa * 1e9 == pytest.approx(20.96, abs=0.01)
        assert b.pressure_viscosity_coefficient_1_Pa * 1e9 == pytest.approx(23.90, abs=0.02)
    assert est.estimated and not fva3.estimated


def test_torque_with_the_estimated_oil():
    fva3, est = fva3_estimated()
    m, b = D.load_material("bearing_steel"), D.load_bearing("32216")
    g, fr = derive_geometry(b, m), load_friction("steel_mineral_oil")
    t = [bearing_friction(g, b, m, lub, fr, temperature_K=323.15, inner_speed_rad_s=2000 * math.pi / 30,
                          axial_N=6000.0)[1].drive_torque_Nm for lub in (fva3, est)]
    assert t[1] / t[0] - 1 == pytest.approx(0.0015, abs=0.002)


def test_iso_vg_is_the_nu40_midpoint_and_unknown_grades_are_refused(tmp_path):
    p = tmp_path / "oil.toml"
    p.write_text('name = "VG 220"\n[viscosity]\niso_vg = 220\nnu100_mm2_s = 19.0\ndensity_15C_kg_m3 = 895\n')
    lub = D.load_lubricant(str(p))
    assert lubricant_state(lub, 313.15).kinematic_viscosity_m2_s * 1e6 == pytest.approx(220.0, rel=1e-9)
    assert lubricant_state(lub, 373.15).kinematic_viscosity_m2_s * 1e6 == pytest.approx(19.0, rel=1e-9)
    p = tmp_path / "oil_221.toml"  # (a new path: loaded files are cached by path)
    p.write_text('name = "VG 221"\n[viscosity]\niso_vg = 221\nnu100_mm2_s = 19.0\ndensity_15C_kg_m3 = 895\n')
    with pytest.raises(kegel.KegelInputError, match="ISO 3448"):
        D.load_lubricant(str(p))


def scene(tmp_path, lubricant: str) -> str:
    p = tmp_path / "scene.toml"
    p.write_text(f"""
[bearing]
designation = "32208"
[lubricant]
{lubricant}
[operating]
axial_load = "1 kN"
speed = ["1000 rpm", "3000 rpm"]
temperature = "60 degC"
[lubrication]
mode = "oil_bath"
oil_level = "flooded"
[model]
fidelity = "fast"
[output]
directory = "{tmp_path / 'out'}"
""")
    return str(p)


def test_kegel_run_flags_every_point_of_an_estimated_oil(tmp_path):
    code, out, err = call_kegel("run", scene(tmp_path, 'name = "PAO 68"\nnu40_mm2_s = 68\nnu100_mm2_s = 10.3\n'
                                                       'density_15C_kg_m3 = 835'))
    assert code == 0, err
    data = json.loads((tmp_path / "out" / "results.json").read_text())
    for p in data["points"]:
        assert p["converged"]
        assert "lubricant_estimated" in [w["code"] for w in p["warnings"]]
        assert "geometry_estimated" not in [w["code"] for w in p["warnings"]]


@pytest.mark.parametrize("lubricant, key, fragment", [
    ("nu40_mm2_s = 68\nnu100_mm2_s = 10.3", "lubricant.density_15C_kg_m3", "density_15C_kg_m3"),
    ("nu40_mm2_s = 10\nnu100_mm2_s = 68\ndensity_15C_kg_m3 = 850", "lubricant", "nu40 > nu100"),
    ("nu40_mm2_s = 68\niso_vg = 68\nnu100_mm2_s = 10\ndensity_15C_kg_m3 = 850", "lubricant.nu40_mm2_s",
     "exactly one of"),
    ("nu40_mm2_s = 68\nnu100_mm2_s = 10\ndensity_15C_kg_m3 = 85", "lubricant", "600-1300"),
    ('nu40_mm2_s = "68 cSt"\nnu100_mm2_s = 10\ndensity_15C_kg_m3 = 850', "lubricant.nu40_mm2_s", "number"),
])
def test_bad_viscosities_are_refused_naming_the_key(tmp_path, lubricant, key, fragment):
    with pytest.raises(kegel.KegelInputError) as info:
        kegel.load_scene(scene(tmp_path, lubricant))
    assert info.value.key == key
    assert fragment in str(info.value)
