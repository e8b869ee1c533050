"""The typed scene model (kegel.scene_model), the range checks of the public functions that take
SI floats (kegel.limits), and the power loss beside the torque in results.json / results.csv."""

from __future__ import annotations

import csv
import json
import math

import pytest

from conftest import call_kegel, scene_text
from kegel.errors import KegelInputError


# --- public functions taking SI floats -----------------------------------------------------------

@pytest.fixture(scope="module")
def g32216():
    from kegel.data import load_bearing, load_material
    from kegel.geometry import derive_geometry

    return derive_geometry(load_bearing("32216"), load_material("bearing_steel"))


@pytest.fixture(scope="module")
def skf32216():
    from kegel.correlations.skf import skf_bearing
    from kegel.data import load_bearing

    return skf_bearing(load_bearing("32216"))


@pytest.mark.parametrize("kw, key", [
    ({"speed_rad_s": 1e6}, "speed_rad_s"),                     # 9.5e6 rpm
    ({"speed_rad_s": math.inf}, "speed_rad_s"),
    ({"kinematic_viscosity_m2_s": 220.0}, "kinematic_viscosity_m2_s"),   # mm^2/s given as m^2/s
    ({"kinematic_viscosity_m2_s": 1e-9}, "kinematic_viscosity_m2_s"),
])
def test_skf_friction_checks_its_ranges(skf32216, kw, key):
    from kegel.correlations.skf import skf_friction

    args = {"speed_rad_s": 200.0, "kinematic_viscosity_m2_s": 3e-5, "axial_load_N": 6000.0, **kw}
    with pytest.raises(KegelInputError) as exc:
        skf_friction(skf32216, **args)
    assert exc.value.key == key


def test_skf_speed_limit_is_the_scenes_speed_factor(skf32216):
    """n d_m <= 1e6 rpm mm with the catalogue's d_m = (d + D) / 2 = 110 mm: 9090.9 rpm."""
    from kegel.correlations.skf import skf_friction

    d_m_mm = 0.5 * (80 + 140)
    ok = 1e6 / d_m_mm * math.pi / 30 * 0.999
    skf_friction(skf32216, speed_rad_s=ok, kinematic_viscosity_m2_s=3e-5, axial_load_N=6000.0)
    with pytest.raises(KegelInputError, match="9091 rpm"):
        skf_friction(skf32216, speed_rad_s=ok / 0.999 * 1.01, kinematic_viscosity_m2_s=3e-5, axial_load_N=6000.0)


@pytest.mark.parametrize("w", [math.nan, math.inf, 1e9, "200", True])
def test_cage_speed_checks_its_range(g32216, w):
    from kegel.tribology import cage_speed_rad_s

    with pytest.raises(KegelInputError) as exc:
        cage_speed_rad_s(g32216, w)
    assert exc.value.key == "inner_speed_rad_s"


def test_cage_speed_accepts_rest_and_both_directions(g32216):
    from kegel.tribology import cage_speed_rad_s

    assert cage_speed_rad_s(g32216, 0.0) == 0.0
    w = cage_speed_rad_s(g32216, 100.0)
    assert cage_speed_rad_s(g32216, -100.0) == -w
    # omega_c = omega_i d_i / (2 d_m)
    assert w == pytest.approx(100.0 * g32216.inner_raceway_diameter_mid_m / (2 * g32216.pitch_diameter_m))


# --- power loss beside the torque --------------------------------------------------------------

def test_power_loss_is_in_results_json_and_csv_beside_the_torque(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "s.toml").write_text(scene_text(speed='["1000 rpm", "2000 rpm"]'))
    code, out, err = call_kegel("run", "s.toml", "--output", "out")
    assert code == 0, err
    points = json.loads((tmp_path / "out" / "results.json").read_text())["points"]
    with open(tmp_path / "out" / "results.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    header = list(rows[0])
    assert header.index("power_loss_W") == header.index("total_torque_Nm") + 1
    for p, row in zip(points, rows):
        expected = abs(p["total_torque_Nm"]) * p["speed_rpm"] * math.pi / 30
        assert p["power_loss_W"] == pytest.approx(expected, rel=1e-12)
        assert float(row["power_loss_W"]) == pytest.approx(expected, rel=1e-9)
