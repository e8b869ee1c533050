"""Flow-force coupling: laws fitted to a correlation or a CFD result reproduce it at the fitted
point through the C++ force element, and oil-bath scenes run dynamically with the oil acting on
the rollers."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import kegel
from conftest import scene_text
from kegel.correlations import hydraulic_torques
from kegel.coupling import flow_forces_from_correlation
from kegel.coupling.flow_forces import orbit_radius_m
from kegel.dynamics import D, dynamic_model
from kegel.scene import scene_from_dict
from kegel.tribology import load_friction

RPM = math.pi / 30


@pytest.fixture(scope="module")
def b32216():
    b = kegel.load_bearing("32216")
    m = kegel.load_material("bearing_steel")
    return kegel.derive_geometry(b, m), b, m, kegel.load_lubricant("FVA3")


def _orbiting_state(model, g, wc, spin):
    qs = kegel._core.quasi_static.BearingData(model[1])
    return np.asarray(D.initial_state(model[0], qs, wc, [spin] * g.roller_count))


def _external(model, y, elements):
    d = D.RingDrive()
    d.time_s, d.speed_rad_s, d.axial_N = [0.0], [0.0], 0.0
    st, f, out = D.rhs(model, d, 0.0, y, elements)
    assert st == 0
    return out["external_power_W"]


def test_the_correlation_law_reproduces_the_roller_set_drag(b32216):
    g, b, m, lub = b32216
    state = kegel.lubricant_state(lub, 323.15)
    w = 2000 * RPM
    wc = kegel.tribology.cage_speed_rad_s(g, w)
    hyd = hydraulic_torques("liebrecht", g, state, shaft_speed_rad_s=w, oil_level_m=g.outer_diameter_m,
                            cage_speed_rad_s=wc)
    law = flow_forces_from_correlation(hyd, g, density_kg_m3=state.density_kg_m3, cage_speed_rad_s=wc)
    # by hand: Z rollers at the pitch radius, each with the fitted drag
    r = orbit_radius_m(g)
    assert -g.roller_count * r * law.roller_orbit_force_N(wc * r) == pytest.approx(hyd.cage_Nm, rel=1e-12)
    # through the C++ element: the power it takes from rollers orbiting at wc
    fr = load_friction()
    model = dynamic_model(g, b, m, lub, fr, temperature_K=323.15, slices=8)
    y = _orbiting_state(model, g, wc, 0.0)
    P = _external(model[0], y, [law.element()])
    # the rollers sit at their quasi-static places, um from the nominal ones
    assert P == pytest.approx(hyd.cage_Nm * wc, rel=1e-3)
    # quadratic in the speed off the fitted point
    assert law.roller_orbit_force_N(2 * wc * r) == pytest.approx(4 * law.roller_orbit_force_N(wc * r))
    with pytest.raises(kegel.KegelInputError, match="cage_speed_rad_s"):
        flow_forces_from_correlation(hyd, g, density_kg_m3=state.density_kg_m3, cage_speed_rad_s=0.0)


def _bath_scene(speed: str, model: str) -> str:
    return scene_text(speed=speed, lubrication='mode = "oil_bath"\noil_level = "flooded"', model=model)


_DYNAMIC = 'solution = "dynamic"\n[dynamic]\nduration = "2 ms"\noutput_interval = "0.2 ms"'


def test_an_oil_bath_scene_runs_dynamically_with_the_oil_on_the_rollers(tmp_path):
    from conftest import run_kegel

    scene = _bath_scene('"2000 rpm"', _DYNAMIC)
    (tmp_path / "bath.toml").write_text(scene)
    res = run_kegel("run", "bath.toml", cwd=tmp_path, timeout=300)
    assert res.returncode == 0, res.stderr
    p = json.loads((tmp_path / "out" / "results.json").read_text())["points"][0]
    h = p["hydraulic"]
    assert h["flow_force_law"]["roller_drag_coefficient"] > 0
    assert h["roller_drag_on_the_bodies_Nm"] > 0
    churn = h["components"]["churning_inner_ring_Nm"] + h["components"]["churning_outer_ring_Nm"]
    assert p["hydraulic_torque_Nm"] == pytest.approx(h["roller_drag_on_the_bodies_Nm"] + churn, rel=1e-12)
    assert p["total_torque_Nm"] == pytest.approx(p["friction_torque_Nm"] + p["hydraulic_torque_Nm"], rel=1e-12)
    # the element's drag equals the correlation's roller-set drag within the cage slip
    assert h["roller_drag_on_the_bodies_Nm"] == pytest.approx(
        h["components"]["drag_rollers_Nm"] * p["cage_speed_rpm"] / p["speed_rpm"], rel=0.05)


def _cfd_result_file(path, g, speed_rpm, *, flooded=True, temperature_K=323.15, scale=1.0):
    """A results.json as `kegel cfd run` writes it, with round numbers: orbit drag 1 mN m per roller,
    spin torque 0.2 mN m, cage -1 mN m (the bodies' drags times ``scale``), inner ring -20 mN m,
    shaft -5 mN m, loss torque 40 mN m."""
    from kegel.cfd_cases.run import kinematics

    kin = kinematics(g, speed_rpm * RPM)
    Z = g.roller_count
    rollers = [{"name": f"roller_{k:02d}", "force_N": [0.0, 0.0, 0.0], "moment_about_centre_Nm": [0.0, 0.0, 0.0],
                "spin_torque_Nm": {"total": 2e-4 * scale}, "moment_about_bearing_axis_Nm": -1e-3 * scale}
               for k in range(Z)]
    total = {"inner_ring": -20e-3, "shaft": -5e-3, "outer_ring": 10e-3, "housing": 8e-3, "cage": -1e-3 * scale,
             "rollers_about_bearing_axis": -1e-3 * scale * Z, "rollers_spin_sum": 2e-4 * scale * Z}
    res = {"point": {"bearing": g.designation, "lubricant": "FVA3", "speed_rad_s": speed_rpm * RPM,
                     "temperature_K": temperature_K, "oil_level_m": None if flooded else 0.05},
           "kinematics": kin, "rollers": rollers, "cage": {"force_N": [0, 0, 0], "moment_Nm": [0.0, 0.0, -1e-3 * scale]},
           "torques_Nm": {k: {"total": v} for k, v in total.items()}, "loss_torque_at_shaft_Nm": 40e-3,
           "steady": True}
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(res))
    return res




_CFD = 'hydraulic = "cfd"\ncfd_results = "cfd"'


def test_a_scene_takes_each_points_cfd_result(b32216, tmp_path):
    from conftest import run_kegel

    g = b32216[0]
    _cfd_result_file(tmp_path / "cfd" / "a" / "results.json", g, 1000.0)
    _cfd_result_file(tmp_path / "cfd" / "b" / "results.json", g, 2000.0)
    _cfd_result_file(tmp_path / "cfd" / "c" / "results.json", g, 2000.0, flooded=False)  # another oil level
    (tmp_path / "s.toml").write_text(_bath_scene('["1000 rpm", "2000 rpm"]', _CFD))
    res = run_kegel("run", "s.toml", cwd=tmp_path, timeout=300)
    assert res.returncode == 0, res.stderr
    pts = json.loads((tmp_path / "out" / "results.json").read_text())["points"]
    for p, sub in zip(pts, ("a", "b")):
        assert p["hydraulic_torque_Nm"] == pytest.approx(40e-3)
        assert p["total_torque_Nm"] == pytest.approx(p["friction_torque_Nm"] + 40e-3)
        assert p["hydraulic"]["source"] == "cfd" and p["hydraulic"]["file"].endswith(f"{sub}/results.json")
    # a point without its CFD result: the error names the key and lists what there is
    (tmp_path / "t.toml").write_text(_bath_scene('"3000 rpm"', _CFD))
    res = run_kegel("run", "t.toml", cwd=tmp_path, timeout=300)
    assert res.returncode != 0
    assert "model.cfd_results" in res.stderr and "3000 rpm" in res.stderr and "1000 rpm" in res.stderr


def test_cfd_results_scene_keys_are_checked(b32216, tmp_path):
    base = {"bearing": {"designation": "32216"}, "lubricant": {"name": "FVA3"},
            "operating": {"axial_load": "6 kN", "speed": "2000 rpm", "temperature": "50 degC"},
            "lubrication": {"mode": "oil_bath", "oil_level": "flooded"}}
    with pytest.raises(kegel.KegelInputError, match="model.cfd_results.*needed by hydraulic"):
        scene_from_dict({**base, "model": {"hydraulic": "cfd"}})
    with pytest.raises(kegel.KegelInputError, match="model.cfd_results.*existing"):
        scene_from_dict({**base, "model": {"hydraulic": "cfd", "cfd_results": str(tmp_path / "nothing")}})
    with pytest.raises(kegel.KegelInputError, match="model.cfd_results.*unless"):
        scene_from_dict({**base, "model": {"hydraulic": "correlation", "cfd_results": str(tmp_path)}})


def test_a_dynamic_scene_puts_the_cfd_forces_on_the_bodies(b32216, tmp_path):
    from conftest import run_kegel

    g = b32216[0]
    _cfd_result_file(tmp_path / "cfd" / "results.json", g, 2000.0)
    # the sweep the speed exponents come from: the bodies' drags at half the speed, a quarter
    _cfd_result_file(tmp_path / "cfd" / "1000" / "results.json", g, 1000.0, scale=0.25)
    (tmp_path / "d.toml").write_text(_bath_scene('"2000 rpm"', _CFD + "\n" + _DYNAMIC))
    res = run_kegel("run", "d.toml", cwd=tmp_path, timeout=300)
    assert res.returncode == 0, res.stderr
    p = json.loads((tmp_path / "out" / "results.json").read_text())["points"][0]
    h = p["hydraulic"]
    assert h["source"] == "cfd" and h["inner_ring_and_shaft_Nm"] == pytest.approx(25e-3)
    assert h["flow_force_law"]["source"].endswith("cfd/results.json")  # the law names its file
    # the exponents from the two speeds: a quarter of the drag at half the speed
    assert h["flow_force_law"]["provenance"]["exponents"] == pytest.approx({"orbit": 2.0, "spin": 2.0, "cage": 2.0})
    # rollers and cage through the force law: at the CFD's kinematics their power is
    # Z (1 mN m) w_c + Z (0.2 mN m) |spin| + (1 mN m) w_c, about the CFD's 15 mN m loss share
    assert h["roller_drag_on_the_bodies_Nm"] > 0
    assert p["hydraulic_torque_Nm"] == pytest.approx(h["roller_drag_on_the_bodies_Nm"] + 25e-3, rel=1e-12)
