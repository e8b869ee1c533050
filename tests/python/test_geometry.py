"""Derived internal geometry: apex condition, pitch diameter, catalogue envelope, hand checks."""

from __future__ import annotations

import math

import pytest

import kegel
from kegel.geometry import roller_half_angle_rad

BEARINGS = ["32216", "32208"]


@pytest.fixture(params=BEARINGS)
def geom(request):
    b = kegel.load_bearing(request.param)
    return b, kegel.derive_geometry(b, kegel.load_material("bearing_steel"))


def test_apex_condition_within_1e9(geom):
    _, g = geom
    assert kegel.apex_residual(g) < 1e-9


def test_apex_residual_detects_a_wrong_roller_angle(geom):
    # The check must be able to fail: a geometry with the roller half-angle off by 1 % does
    # not meet in one apex.
    import dataclasses

    _, g = geom
    bad = dataclasses.replace(g, cone_angle_rad=g.cone_angle_rad * 1.01)
    assert kegel.apex_residual(bad) > 1e-4


def test_pitch_diameter_equals_paper(geom):
    b, g = geom
    paper_mm = {"32216": 108.5, "32208": 60.0}[b.designation]
    assert g.pitch_diameter_m == pytest.approx(paper_mm * 1e-3, rel=1e-12)
    assert g.roller_mid_point()[1] * 2 == pytest.approx(paper_mm * 1e-3, rel=1e-12)


def test_catalogue_dimensions_respected(geom):
    b, g = geom
    assert kegel.envelope_violations(g) == []
    cat = {"32216": (80, 140, 35.25, 33, 28), "32208": (40, 80, 24.75, 23, 19)}[b.designation]
    got = tuple(round(v * 1e3, 6) for v in (g.bore_diameter_m, g.outer_diameter_m, g.total_width_m,
                                             g.cone_width_m, g.cup_width_m))
    assert got == cat


def test_envelope_check_can_fail(geom):
    import dataclasses

    _, g = geom
    narrow = dataclasses.replace(g, total_width_m=0.5 * g.total_width_m)
    assert any("outside the width" in m for m in kegel.envelope_violations(narrow))


def test_cup_angle_from_calculation_factor(geom):
    b, g = geom
    assert math.tan(g.cup_angle_rad) * 1.5 == pytest.approx(b.calculation_factor_e, rel=1e-12)
    # ISO 281: e*Y = 0.6 for single-row tapered roller bearings (catalogue values are rounded)
    assert b.calculation_factor_e * b.axial_load_factor_Y == pytest.approx(0.6, rel=0.03)


def test_angles_and_hand_values_32216():
    g = kegel.derive_geometry(kegel.load_bearing("32216"), kegel.load_material("bearing_steel"))
    # alpha_o = atan(0.42/1.5) = 15.642 deg; gamma from tan g = (17/108.5) sin(alpha_o - g): 2.101 deg
    assert math.degrees(g.cup_angle_rad) == pytest.approx(15.6422, abs=1e-4)
    assert math.degrees(g.roller_half_angle_rad) == pytest.approx(2.1010, abs=1e-3)
    assert g.cone_angle_rad == pytest.approx(g.cup_angle_rad - 2 * g.roller_half_angle_rad, rel=1e-14)
    # raceway diameters at the roller mid-length: d_m +/- D_w cos(beta)
    c = math.cos(g.roller_axis_angle_rad)
    assert g.outer_raceway_diameter_mid_m == pytest.approx(0.1085 + 0.017 * c, rel=1e-14)
    assert g.inner_raceway_diameter_mid_m == pytest.approx(0.1085 - 0.017 * c, rel=1e-14)
    # the mid-length raceway diameters lie between the end diameters
    assert 2 * g.outer_raceway_small_end_m[1] < g.outer_raceway_diameter_mid_m < 2 * g.outer_raceway_large_end_m[1]


def test_roller_half_angle_solves_apex_equation():
    for alpha_deg, k in [(15.64, 17 / 108.5), (13.86, 10 / 60), (28.0, 0.2)]:
        a = math.radians(alpha_deg)
        g = roller_half_angle_rad(a, k)
        assert math.tan(g) == pytest.approx(k * math.sin(a - g), rel=1e-13)
        assert 0 < g < a / 2


@pytest.mark.parametrize("alpha, k", [(0.0, 0.1), (2.0, 0.1), (0.3, 0.0), (0.3, 1.5)])
def test_roller_half_angle_rejects_bad_input(alpha, k):
    with pytest.raises(ValueError, match="expected"):
        roller_half_angle_rad(alpha, k)


def test_roller_mass_matches_frustum_formula(geom):
    b, g = geom
    R, r, L = 0.5 * g.roller_large_end_diameter_m, 0.5 * g.roller_small_end_diameter_m, g.roller_length_m
    volume = math.pi * L / 3.0 * (R * R + R * r + r * r)
    assert g.roller_mass_kg == pytest.approx(7850.0 * volume, rel=1e-12)
    # axial inertia of a frustum: (3 m / 10) (R^5 - r^5) / (R^3 - r^3)
    i_ax = 0.3 * g.roller_mass_kg * (R**5 - r**5) / (R**3 - r**3)
    assert g.roller_inertia_axial_kgm2 == pytest.approx(i_ax, rel=1e-10)
    # a cylinder of the mean diameter is a close bound for the transverse inertia
    m, rm = g.roller_mass_kg, 0.5 * g.roller_mean_diameter_m
    assert g.roller_inertia_transverse_kgm2 == pytest.approx(m * (3 * rm * rm + L * L) / 12, rel=0.01)


def test_rib_contact_lies_on_end_sphere_and_inside_rib(geom):
    _, g = geom
    a = g.roller_axis_unit()
    centre = g.roller_mid_point() + (0.5 * g.roller_length_m - g.roller_end_radius_m) * a
    p = g.rib_contact_point_m
    assert math.dist(p, centre) == pytest.approx(g.roller_end_radius_m, rel=1e-12)
    assert 0 < g.rib_contact_height_m < g.rib_height_m
    assert 0 < g.rib_face_angle_to_roller_end_plane_rad < math.radians(5)
    # end-sphere radius ratio from the data file (0.90 of the apex distance of the crown)
    crown = g.roller_apex_distance_m + 0.5 * g.roller_length_m
    assert g.roller_end_radius_m == pytest.approx(0.90 * crown, rel=1e-12)


def test_cage_pocket_clearances(geom):
    b, g = geom
    assert g.cage_pitch_diameter_m == pytest.approx(b.pitch_diameter_m)
    assert g.cage_pocket_clearance_circumferential_m == pytest.approx(0.02 * b.roller_mean_diameter_m)


def test_bearing_cli_table_and_json(kegel_json):
    from conftest import run_kegel

    res = run_kegel("bearing", "--bearing", "32216")
    assert res.returncode == 0, res.stderr
    assert "cup angle alpha_o" in res.stdout and "catalogue envelope: respected" in res.stdout
    data = kegel_json("bearing", "--bearing", "32208")
    assert data["bearing"]["designation"] == "32208"
    assert data["apex_residual"] < 1e-9
    assert data["envelope_violations"] == []
    assert data["bearing"]["pitch_diameter_m"] == pytest.approx(0.060)
