"""CFD validation through the bearing pipeline (gmsh -> msh 2.2 -> gmshToFoam -> solver -> forces)."""

from __future__ import annotations

import math

import pytest

from kegel.cfd_cases.validation import couette_torque_analytic, taylor_couette

pytestmark = pytest.mark.openfoam


def test_couette_analytic_torque_hand_value():
    # R1 = 20 mm, R2 = 25 mm, mu = 0.087 Pa s, omega = 10 rad/s, h = 2 mm:
    # 4 pi * 0.087 * 10 * 4e-4 * 6.25e-4 / 2.25e-4 * 2e-3 = 2.4295e-5 N m
    assert couette_torque_analytic(0.02, 0.025, 10.0, 0.087, 0.002) == pytest.approx(-2.42950e-5, rel=1e-5)
    # narrow gap limit: tau = mu omega R / gap on the area 2 pi R h at arm R
    r, g = 1.0, 1e-4
    narrow = 2 * math.pi * r * 1.0 * (1.0 * 1.0 * r / g) * r
    assert -couette_torque_analytic(r, r + g, 1.0, 1.0, 1.0) == pytest.approx(narrow, rel=2e-4)


def test_taylor_couette_torque_within_2_percent(tmp_path):
    res = taylor_couette(work_dir=tmp_path)
    assert res.reynolds == pytest.approx(10.0)
    assert res.torque_simulated_Nm < 0  # the fluid brakes the turning cylinder
    assert abs(res.relative_error) < 0.02, res


def test_taylor_couette_error_falls_with_refinement(tmp_path):
    coarse = taylor_couette(work_dir=tmp_path / "c", n_radial=4, n_theta=40)
    fine = taylor_couette(work_dir=tmp_path / "f", n_radial=8, n_theta=80)
    assert abs(fine.relative_error) < abs(coarse.relative_error)


def test_rotating_tank_surface_hand_values():
    from kegel.cfd_cases.validation import rotating_tank_surface

    # omega^2 R^2 / (4 g): the surface drops by this at the axis and rises by it at the wall
    h = rotating_tank_surface([0.0, 0.05], 0.05, 0.04, 12.0)
    d = 144 * 0.0025 / (4 * 9.81)
    assert h[0] == pytest.approx(0.04 - d) and h[1] == pytest.approx(0.04 + d)


def test_rotating_tank_free_surface_and_volume(tmp_path):
    """VOF with a known answer: the paraboloid of solid-body rotation, and the oil volume."""
    from kegel.cfd_cases.validation import rotating_tank

    res = rotating_tank(work_dir=tmp_path)
    # within a quarter of the cell height (2 mm) everywhere; measured 0.16 mm
    assert res.max_height_error_m < 0.25 * res.cell_height_m, res
    # the rise from axis to wall (9.2 mm analytic) is reproduced within 5 %
    rise_sim = res.height_sim_m[-1] - res.height_sim_m[0]
    rise_ref = res.height_analytic_m[-1] - res.height_analytic_m[0]
    assert rise_sim == pytest.approx(rise_ref, rel=0.05)
    assert abs(res.volume_change) < 1e-4
