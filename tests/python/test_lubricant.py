"""Lubricant data and `kegel lubricant` against ../shared/reference/lubricants.toml (0.5 %)."""

from __future__ import annotations

import math

import pytest

import kegel
from kegel import _core

# theta [degC], eta0 [mPa s], density [kg/m3], nu [mm2/s], alpha_p0 [1/GPa]
# (../shared/reference/lubricants.toml, computed independently of kegel)
REFERENCE = [
    (40, 84.5, 872.6, 96.9, 22.4),
    (50, 52.5, 866.6, 60.6, 21.0),
    (100, 9.9, 836.6, 11.8, 16.0),
]


@pytest.mark.parametrize("theta, eta, rho, nu, alpha", REFERENCE)
def test_cli_matches_reference(kegel_json, theta, eta, rho, nu, alpha):
    data = kegel_json("lubricant", "FVA3", "--temperature", f"{theta} degC")
    (s,) = data["states"]
    assert s["temperature_degC"] == pytest.approx(theta)
    assert s["dynamic_viscosity_Pas"] * 1e3 == pytest.approx(eta, rel=5e-3)
    assert s["density_kg_m3"] == pytest.approx(rho, rel=5e-3)
    assert s["kinematic_viscosity_m2_s"] * 1e6 == pytest.approx(nu, rel=5e-3)
    assert s["pressure_viscosity_coefficient_1_Pa"] * 1e9 == pytest.approx(alpha, rel=5e-3)


def test_cli_table_output():
    from conftest import run_kegel

    res = run_kegel("lubricant", "FVA3", "--temperature", "50 degC", "--temperature", "323.15 K")
    assert res.returncode == 0, res.stderr
    assert res.stdout.count("52.51") == 2  # degC and K give the same state (four figures)


def test_cli_rejects_bad_temperature():
    from conftest import run_kegel

    res = run_kegel("lubricant", "FVA3", "--temperature", "50 bar")
    assert res.returncode == 2
    assert "--temperature" in res.stderr and "'50 bar'" in res.stderr and "a temperature" in res.stderr
    res = run_kegel("lubricant", "FVA3", "--temperature", "-150 degC")  # below the Vogel pole: kegel's range first
    assert res.returncode == 2 and "[-20, 150] degC" in res.stderr
    res = run_kegel("lubricant", "FVA3", "--temperature", "-15 degC")  # in range, outside Eq. 7's domain
    assert res.returncode == 2 and "domain" in res.stderr and "Eq. 7" in res.stderr


def test_unknown_lubricant_lists_known_ones():
    from conftest import run_kegel

    res = run_kegel("lubricant", "FVA99")
    assert res.returncode == 2
    assert "'FVA99'" in res.stderr and "FVA3" in res.stderr


def test_data_file_values_loaded_in_si():
    lub = kegel.load_lubricant("FVA3")
    p = lub.parameters
    assert p.vogel_K_Pas == pytest.approx(0.062e-3)
    assert p.density_slope_kg_m3_K == pytest.approx(-0.6)
    assert p.density_ref_temperature_K == pytest.approx(288.15)
    assert lub.limiting_shear_stress_gamma > 0
    # literature values carry their citation in the data file
    text = open(lub.source_file).read()
    assert "Hoeglund" in text and "Cragoe" in text


def test_core_value_type_rejects_invalid_parameters():
    p = kegel.load_lubricant("FVA3").parameters
    bad = _core.LubricantParameters()
    for name in dir(p):
        if not name.startswith("_"):
            setattr(bad, name, getattr(p, name))
    bad.dicke_a1_bar = -5.0
    with pytest.raises(ValueError, match=r"dicke_a1_bar = -5: expected a finite value > 0"):
        _core.Lubricant(bad)


def test_state_is_consistent():
    s = kegel.lubricant_state(kegel.load_lubricant("FVA3"), 323.15)
    assert s.kinematic_viscosity_m2_s == pytest.approx(s.dynamic_viscosity_Pas / s.density_kg_m3, rel=1e-14)
    assert math.isfinite(s.specific_heat_J_kgK) and 1800 < s.specific_heat_J_kgK < 2100
