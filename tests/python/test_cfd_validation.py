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
