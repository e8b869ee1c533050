"""One roller/raceway contact evaluated slice by slice, and `kegel tribology`."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import kegel
from conftest import run_kegel
from kegel.tribology import (
    axial_roller_loads,
    cage_speed_rad_s,
    evaluate_raceway_contact,
    load_friction,
)

RPM = math.pi / 30


@pytest.fixture(scope="module")
def setup32216():
    b = kegel.load_bearing("32216")
    m = kegel.load_material("bearing_steel")
    return b, m, kegel.derive_geometry(b, m), kegel.load_lubricant("FVA3"), load_friction()


def contact(setup, **kw):
    b, m, g, lub, fr = setup
    args = dict(temperature_K=323.15, load_N=1400.0, shaft_speed_rad_s=2000 * RPM)
    args.update(kw)
    return evaluate_raceway_contact(g, b, m, lub, fr, **args)


def test_axial_roller_loads_balance_cup_and_roller(setup32216):
    g = setup32216[2]
    q = axial_roller_loads(g, 6000.0)
    assert g.roller_count * q["outer_N"] * math.sin(g.cup_angle_rad) == pytest.approx(6000.0, rel=1e-12)
    a_o, a_i, phi = g.cup_angle_rad, g.cone_angle_rad, g.rib_face_angle_to_radial_plane_rad
    force = (q["outer_N"] * np.array([math.sin(a_o), -math.cos(a_o)])
             + q["inner_N"] * np.array([-math.sin(a_i), math.cos(a_i)])
             + q["rib_N"] * np.array([-math.cos(phi), -math.sin(phi)]))
    assert np.linalg.norm(force) < 1e-9 * q["outer_N"]
    assert 0 < q["rib_N"] < 0.1 * q["inner_N"]


def test_cage_speed_of_pure_rolling(setup32216):
    g = setup32216[2]
    w = 2000 * RPM
    wc = cage_speed_rad_s(g, w)
    # rolling condition at the roller mid-length: (w - wc) r_i = wc r_o
    assert (w - wc) * g.inner_raceway_diameter_mid_m == pytest.approx(wc * g.outer_raceway_diameter_mid_m, rel=1e-12)


def test_pure_rolling_has_only_rolling_losses(setup32216):
    r = contact(setup32216)
    t = r.totals
    assert t["P_ehl_sliding_W"] == 0 and t["P_solid_sliding_W"] == 0
    assert t["P_ehl_rolling_W"] > 0 and t["P_hysteresis_W"] > 0
    assert t["P_total_W"] == pytest.approx(sum(v for k, v in t.items() if k.startswith("P_") and k != "P_total_W"))


def test_totals_are_slice_sums(setup32216):
    r = contact(setup32216, slide_to_roll=0.01, slices=12)
    assert len(r.slices) == 12
    assert sum(s["load_N"] for s in r.slices) == pytest.approx(1400.0)
    for key in ("F_ehl_sliding_x_N", "P_hysteresis_W", "F_ehl_rolling_N"):
        assert r.totals[key] == pytest.approx(sum(s[key] for s in r.slices), rel=1e-12)


def test_slip_direction_and_oddness(setup32216):
    lag = contact(setup32216, slide_to_roll=0.01)    # roller slower than the ring
    lead = contact(setup32216, slide_to_roll=-0.01)
    assert lag.totals["F_ehl_sliding_x_N"] > 0           # the ring drags the roller forward
    assert lead.totals["F_ehl_sliding_x_N"] < 0
    assert lag.totals["P_ehl_sliding_W"] > 0 and lead.totals["P_ehl_sliding_W"] > 0


def test_converges_with_slice_count(setup32216):
    ref = contact(setup32216, slide_to_roll=0.01, slices=400).totals["P_total_W"]
    errs = [abs(contact(setup32216, slide_to_roll=0.01, slices=n).totals["P_total_W"] / ref - 1) for n in (5, 10, 20, 40)]
    assert errs[-1] < 1e-4
    assert all(e2 < e1 for e1, e2 in zip(errs, errs[1:]))  # monotone convergence
    # midpoint rule: second order, error ratio ~4 per halving
    assert errs[1] / errs[2] > 3.0


def test_regularisation_velocity_does_not_matter(setup32216):
    # kegel/data/friction/steel_mineral_oil.toml claims < 1 % change when v_s and v_d are halved
    b, m, g, lub, fr = setup32216
    half = dataclasses.replace(fr, v_s_m_s=fr.v_s_m_s / 2, v_d_m_s=fr.v_d_m_s / 2)
    for T in (323.15, 373.15):  # full film and mixed friction
        for srr in (0.001, 0.02):
            kw = dict(temperature_K=T, load_N=1400.0, shaft_speed_rad_s=500 * RPM, slide_to_roll=srr)
            a = evaluate_raceway_contact(g, b, m, lub, fr, **kw).totals["P_total_W"]
            c = evaluate_raceway_contact(g, b, m, lub, half, **kw).totals["P_total_W"]
            assert c == pytest.approx(a, rel=1e-2)


def test_mixed_friction_at_high_temperature_and_low_speed(setup32216):
    hot = contact(setup32216, temperature_K=373.15, shaft_speed_rad_s=500 * RPM).totals
    cold = contact(setup32216, temperature_K=313.15, shaft_speed_rad_s=4000 * RPM).totals
    assert hot["Lambda_max"] < 1.5 < cold["Lambda_min"]
    assert hot["phi_min"] > 0.05 > cold["phi_max"]
    assert hot["P_solid_rolling_W"] > cold["P_solid_rolling_W"]


def test_sliding_loss_grows_with_viscosity_in_full_film(setup32216):
    warm = contact(setup32216, temperature_K=323.15, slide_to_roll=0.001).totals["P_ehl_sliding_W"]
    cool = contact(setup32216, temperature_K=313.15, slide_to_roll=0.001).totals["P_ehl_sliding_W"]
    assert cool > warm > 0


def test_invalid_contact_arguments(setup32216):
    with pytest.raises(kegel.KegelInputError, match="'inner' or 'outer'"):
        contact(setup32216, contact="rib")
    with pytest.raises(kegel.KegelInputError, match="positive contact load"):
        contact(setup32216, load_N=-5.0)


def test_cli_tribology_table_and_json(kegel_json):
    res = run_kegel("tribology", "--speed", "2000 rpm", "--axial-load", "6 kN", "--temperature", "50 degC",
                    "--slide-to-roll", "0.01", "--per-slice")
    assert res.returncode == 0, res.stderr
    for text in ("film h =", "Lambda =", "phi =", "EHL sliding", "hysteresis", "total", "xi [mm]"):
        assert text in res.stdout
    data = kegel_json("tribology", "--contact", "outer", "--contact-load", "1.5 kN", "--slices", "10")
    assert data["contact"] == "outer" and data["load_N"] == pytest.approx(1500.0)
    assert len(data["slices"]) == 10 and data["totals"]["P_total_W"] > 0


def test_cli_tribology_errors():
    res = run_kegel("tribology", "--temperature", "-150 degC")
    assert res.returncode == 2 and "[-20, 150] degC" in res.stderr
    res = run_kegel("tribology", "--axial-load", "-1 kN")
    assert res.returncode == 2 and "--axial-load" in res.stderr
    res = run_kegel("tribology", "--friction", "teflon")
    assert res.returncode == 2 and "steel_mineral_oil" in res.stderr


def test_friction_data_file_errors(tmp_path):
    src = (kegel.data.DATA_DIR / "friction" / "steel_mineral_oil.toml").read_text()
    bad = tmp_path / "bad.toml"
    bad.write_text(src.replace("v_d_mm_s = 2.0", "v_d_mm_s = 0.5"))
    with pytest.raises(kegel.KegelInputError) as info:
        load_friction(str(bad))
    assert str(bad) in str(info.value) and "solid_sliding.v_d_mm_s" in str(info.value)


def test_compression_heating_switch_from_data_file(tmp_path, setup32216):
    b, m, g, lub, fr = setup32216
    src = (kegel.data.DATA_DIR / "friction" / "steel_mineral_oil.toml").read_text()
    on = tmp_path / "gold.toml"
    on.write_text(src + "\n[compression_heating]\nC1_Pa_K2 = 2.0e3\nC2_Pa_K = 7.0e6\n")
    hot = load_friction(str(on))
    assert hot.core(lub).compression_heating and not fr.core(lub).compression_heating
    kw = dict(temperature_K=323.15, load_N=1400.0, shaft_speed_rad_s=2000 * RPM, slide_to_roll=0.001)
    a = evaluate_raceway_contact(g, b, m, lub, fr, **kw)
    c = evaluate_raceway_contact(g, b, m, lub, hot, **kw)
    assert a.slices[0]["contact_temperature_K"] == pytest.approx(323.15)
    assert c.slices[0]["contact_temperature_K"] > 323.15 + 1.0
    assert c.totals["P_ehl_sliding_W"] < a.totals["P_ehl_sliding_W"]
