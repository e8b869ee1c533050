"""A disc dipped in an oil bath: Changenet & Velex's churning correlation, and the CFD against it."""

from __future__ import annotations

import math

import pytest

from kegel.cfd_cases.validation import (
    IMMERSED_DISC_TOLERANCE,
    changenet_velex_churning_torque,
    changenet_velex_moment_coefficient,
    disc_wetted_area,
)


def test_disc_wetted_area_hand_values():
    r, b = 0.02, 0.008
    # half immersed: one face's half disc on each side, half the rim: pi R^2 + pi R b
    assert disc_wetted_area(r, b, r) == pytest.approx(math.pi * r * r + math.pi * r * b, rel=1e-12)
    # fully immersed: 2 pi R^2 + 2 pi R b = 2.51327e-3 + 1.00531e-3
    assert disc_wetted_area(r, b, 2 * r) == pytest.approx(3.51858e-3, rel=1e-5)
    # h = R/2: half-angle pi/3, segment R^2 (pi/3 - sqrt(3)/4) = 2.45674e-4 per face, rim 2 R (pi/3) b = 3.35103e-4
    assert disc_wetted_area(r, b, 0.5 * r) == pytest.approx(2 * 2.45674e-4 + 3.35103e-4, rel=1e-5)
    with pytest.raises(ValueError, match="0 < h <= 2R"):
        disc_wetted_area(r, b, 2.5 * r)


def test_changenet_velex_low_speed_hand_value():
    # 1.366 * 0.5^0.45 * 10^0.1 * 10^-0.6 * 1000^-0.21
    # = 1.366 * 0.73204 * 1.25893 * 0.25119 * 0.23442 = 0.074121
    cm = changenet_velex_moment_coefficient(immersion_ratio=0.5, oil_volume_ratio=10.0, froude=10.0, reynolds=1000.0,
                                            face_width_ratio=0.2, critical_reynolds=400.0)
    assert cm == pytest.approx(0.074121, rel=2e-4)


def test_changenet_velex_high_speed_hand_value():
    # 3.644 * 0.5^0.1 * 10^-0.35 * 10^-0.88 * 0.2^0.85 = 3.644 * 0.93303 * 0.44668 * 0.13183 * 0.25463 = 0.050980
    cm = changenet_velex_moment_coefficient(immersion_ratio=0.5, oil_volume_ratio=10.0, froude=10.0, reynolds=1000.0,
                                            face_width_ratio=0.2, critical_reynolds=1.0e4)
    assert cm == pytest.approx(0.050980, rel=5e-4)


def test_changenet_velex_rejects_the_gap_between_regimes_and_bad_input():
    kw = dict(immersion_ratio=0.5, oil_volume_ratio=10.0, froude=10.0, reynolds=1000.0, face_width_ratio=0.2)
    with pytest.raises(ValueError, match="between the two regimes"):
        changenet_velex_moment_coefficient(**kw, critical_reynolds=7000.0)
    with pytest.raises(ValueError, match="positive finite"):
        changenet_velex_moment_coefficient(**{**kw, "froude": -1.0}, critical_reynolds=400.0)


def test_changenet_velex_torque_of_the_default_case():
    # R 20 mm, b 8 mm, h = R, Omega 50 rad/s, nu 2e-5, rho 870; V0 = 0.12 * 0.06 * 0.08 - (pi R^2 / 2) b
    v0 = 0.12 * 0.06 * 0.08 - 0.5 * math.pi * 0.02**2 * 0.008
    t = changenet_velex_churning_torque(radius_m=0.02, face_width_m=0.008, immersion_depth_m=0.02, oil_volume_m3=v0,
                                        omega_rad_s=50.0, kinematic_viscosity_m2_s=2e-5, density_kg_m3=870.0)
    # C_m = 0.109812 (V0/D^3 = 8.9215, Fr = 5.0968, Re = 1000); S_m = 1.75929e-3 m2;
    # T = 0.5 * 870 * 2500 * 1.75929e-3 * 8e-6 * 0.109812 = 1.68077e-3 N m
    assert t == pytest.approx(1.68077e-3, rel=1e-4)
    # the correlation's speed exponent in the low-speed regime: T ~ Omega^(2 - 1.2 - 0.21) = Omega^0.59
    t2 = changenet_velex_churning_torque(radius_m=0.02, face_width_m=0.008, immersion_depth_m=0.02, oil_volume_m3=v0,
                                         omega_rad_s=100.0, kinematic_viscosity_m2_s=2e-5, density_kg_m3=870.0)
    assert t2 / t == pytest.approx(2.0**0.59, rel=1e-9)
