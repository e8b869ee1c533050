"""A contact temperature per ring (issue 27, item 6): ``operating.inner_ring_temperature`` and
``outer_ring_temperature`` in scenes, ``inner_ring_temperature=`` / ``outer_ring_temperature=`` in
:meth:`kegel.Bearing.friction`, ``inner_ring_temperature_K`` / ``outer_ring_temperature_K`` in
:func:`kegel.quasi_static.bearing_friction` and :func:`kegel.simulate`."""

from __future__ import annotations

import math

import pytest

import kegel
from kegel.errors import KegelInputError
from kegel.quasi_static import bearing_friction
from kegel.scene import scene_from_dict
from kegel.tribology import load_friction

RPM = math.pi / 30
T50, T60 = 323.15, 333.15


@pytest.fixture(scope="module")
def b32216():
    b = kegel.load_bearing("32216")
    m = kegel.load_material("bearing_steel")
    return kegel.derive_geometry(b, m), b, m, kegel.load_lubricant("FVA3"), load_friction()


def table1(b32216, **kw):
    """The 32216 of the seed paper's Table 1 at 2000 rpm, Fa = 6 kN, FVA 3 at 50 degC."""
    g, b, m, lub, fr = b32216
    return bearing_friction(g, b, m, lub, fr, temperature_K=T50, inner_speed_rad_s=2000.0 * RPM, axial_N=6000.0,
                            slices=15, **kw)[1]


def test_defaults_are_bit_identical_to_one_state_for_every_contact(b32216):
    base = table1(b32216)
    same = table1(b32216, inner_ring_temperature_K=T50, outer_ring_temperature_K=T50)
    assert base.converged and same.converged
    assert same.drive_torque_Nm == base.drive_torque_Nm
    assert same.power_W == base.power_W
    assert same.Lambda_min == base.Lambda_min
    assert same.cage_speed_rad_s == base.cage_speed_rad_s


def test_a_warmer_inner_ring_thins_its_film_and_lowers_its_rolling_torque(b32216):
    base = table1(b32216)
    warm = table1(b32216, inner_ring_temperature_K=T60)
    assert warm.converged
    # hand check of the viscosity ratio: Vogel (seed paper Eq. 8) with FVA 3's Table A1 constants,
    # B = 1021.7 K, C = 101.5517 degC: eta(60) / eta(50) = exp(B / 161.5517 - B / 151.5517) = 0.6588
    ratio = math.exp(1021.7 / (60.0 + 101.5517) - 1021.7 / (50.0 + 101.5517))
    assert ratio == pytest.approx(0.6588, abs=1e-4)
    s50, s60 = kegel.lubricant_state("FVA3", T50), kegel.lubricant_state("FVA3", T60)
    assert s60.dynamic_viscosity_Pas / s50.dynamic_viscosity_Pas == pytest.approx(ratio, rel=1e-12)
    alpha = s60.pressure_viscosity_coefficient_1_Pa / s50.pressure_viscosity_coefficient_1_Pa
    # the film of the inner raceway: Lambda = h / sigma, and the EHL film goes as (eta0 u)^0.7
    # alpha^0.5 roughly (Moes / Dowson-Higginson); the thermal factor recovers a little of it (a
    # thinner oil shears less heat in the inlet)
    film = warm.Lambda_min["inner_raceway"] / base.Lambda_min["inner_raceway"]
    isothermal = ratio ** 0.7 * alpha ** 0.5
    assert film < 0.9
    assert film == pytest.approx(isothermal, rel=0.1)
    # the outer ring's film: unchanged but for the slightly different kinematics
    assert warm.Lambda_min["outer_raceway"] == pytest.approx(base.Lambda_min["outer_raceway"], rel=0.01)
    # the rib belongs to the inner ring: its film thins too
    assert warm.Lambda_min["rib"] < base.Lambda_min["rib"]
    w = 2000.0 * RPM
    assert warm.power_W["inner_raceway"]["ehl_rolling"] < 0.9 * base.power_W["inner_raceway"]["ehl_rolling"]
    assert warm.torque_by_contact_Nm(w)["inner_raceway"] < base.torque_by_contact_Nm(w)["inner_raceway"]
    assert warm.drive_torque_Nm < base.drive_torque_Nm


def test_both_rings_at_T_give_the_contact_friction_of_the_oil_at_T(b32216):
    rings = table1(b32216, inner_ring_temperature_K=T60, outer_ring_temperature_K=T60)
    g, b, m, lub, fr = b32216
    oil60 = bearing_friction(g, b, m, lub, fr, temperature_K=T60, inner_speed_rad_s=2000.0 * RPM, axial_N=6000.0,
                             slices=15)[1]
    assert rings.drive_torque_Nm == oil60.drive_torque_Nm
    assert rings.power_W == oil60.power_W


def test_the_api_reports_the_temperatures_and_matches_the_uniform_scene():
    bearing = kegel.Bearing("32216", fidelity="fast")
    kw = dict(speed="2000 rpm", axial_load="6 kN", lubrication="flooded", hydraulic="none")
    base = bearing.friction(temperature="50 degC", **kw)
    p = base.points[0]
    assert p["inner_ring_temperature_degC"] == pytest.approx(50.0)
    assert p["outer_ring_temperature_K"] == p["temperature_K"]
    same = bearing.friction(temperature="50 degC", inner_ring_temperature="50 degC",
                            outer_ring_temperature="50 degC", **kw)
    assert same.friction_torque_Nm == base.friction_torque_Nm
    rings = bearing.friction(temperature="50 degC", inner_ring_temperature="60 degC",
                             outer_ring_temperature="60 degC", **kw)
    oil60 = bearing.friction(temperature="60 degC", **kw)
    # flooded contacts: the contact friction depends on the contacts' temperature only
    assert rings.friction_torque_Nm == oil60.friction_torque_Nm
    q = rings.points[0]
    assert q["temperature_degC"] == pytest.approx(50.0)
    assert q["inner_ring_temperature_degC"] == pytest.approx(60.0)
    assert q["outer_ring_temperature_degC"] == pytest.approx(60.0)
    warm = bearing.friction(temperature="50 degC", inner_ring_temperature="60 degC", **kw)
    assert warm.friction_torque_Nm < base.friction_torque_Nm
    assert warm.points[0]["outer_ring_temperature_degC"] == pytest.approx(50.0)


def _scene(**operating):
    return {"bearing": {"designation": "32216"}, "lubricant": {"name": "FVA3"},
            "operating": {"axial_load": "6 kN", "speed": "2000 rpm", "temperature": "50 degC", **operating},
            "lubrication": {"mode": "minimum_quantity"}, "model": {"fidelity": "fast"}}


def test_the_scene_keys_reach_the_points():
    sc = scene_from_dict(_scene(inner_ring_temperature="60 degC"))
    op = sc.operating_points[0]
    assert op.inner_ring_temperature_K == pytest.approx(T60) and op.outer_ring_temperature_K is None
    assert op.as_dict()["outer_ring_temperature_degC"] == pytest.approx(50.0)
    plain = scene_from_dict(_scene()).operating_points[0]
    assert plain.inner_ring_temperature_K is None
    assert plain.as_dict()["inner_ring_temperature_K"] == plain.temperature_K


@pytest.mark.parametrize("key, value, words", [
    ("inner_ring_temperature", "200 degC", "[-20, 150] degC"),
    ("outer_ring_temperature", "-18 degC", "domain"),
    ("inner_ring_temperature", ["50 degC", "60 degC"], "not swept"),
    ("outer_ring_temperature", "6 kN", "temperature"),
])
def test_scene_errors_name_the_key(key, value, words):
    with pytest.raises(KegelInputError) as e:
        scene_from_dict(_scene(**{key: value}))
    assert e.value.key == f"operating.{key}"
    assert words in str(e.value)


@pytest.mark.parametrize("key, value, words", [
    ("inner_ring_temperature", "200 degC", "[-20, 150] degC"),
    ("outer_ring_temperature", 60, "with its unit"),
    ("inner_ring_temperature", ["50 degC", "60 degC"], "not swept"),
])
def test_api_errors_name_the_argument(key, value, words):
    with pytest.raises(KegelInputError) as e:
        kegel.Bearing("32216", fidelity="fast").friction(speed="2000 rpm", axial_load="6 kN", **{key: value})
    assert e.value.key == key
    assert words in str(e.value)


def test_bearing_friction_errors_name_the_argument(b32216):
    with pytest.raises(KegelInputError) as e:
        table1(b32216, outer_ring_temperature_K=500.0)
    assert e.value.key == "outer_ring_temperature_K"
    with pytest.raises(KegelInputError) as e:
        table1(b32216, inner_ring_temperature_K="60 degC")
    assert e.value.key == "inner_ring_temperature_K"


def test_the_dynamic_model_takes_a_state_per_ring(b32216):
    from kegel.dynamics import dynamic_model

    g, b, m, lub, fr = b32216
    model, _ = dynamic_model(g, b, m, lub, fr, temperature_K=T50, inner_ring_temperature_K=T60)
    assert model.state_size == 12 * g.roller_count + 23
    with pytest.raises(KegelInputError) as e:
        dynamic_model(g, b, m, lub, fr, temperature_K=T50, outer_ring_temperature_K=math.nan)
    assert e.value.key == "outer_ring_temperature_K"
