"""Aihara's running-torque formula (J. Tribol. 109 (1987) 471-477), the second independent
engineering model beside the SKF catalogue model: each equation against a hand calculation and
against the numbers the paper prints (FORMULAS.md, section 4.1)."""

from __future__ import annotations

import math

import pytest

import kegel
from kegel import _core
from kegel.correlations.aihara import (
    CONSTANT,
    MU_0,
    aihara_moment_per_roller_Nm,
    aihara_running_torque,
    aihara_thermal_factor,
    hamrock_dowson_min_film_m,
    vogel_viscosity_temperature_coefficient_1_K,
)
from kegel.errors import KegelInputError


def test_the_constant_merges_the_equations_it_comes_from():
    # 2 (Eq. 22) x 4.318 (Eq. 19) x 20.4 (Eq. 25) = 176.2, printed 1.76e2
    assert 2 * 4.318 * 20.4 == pytest.approx(CONSTANT, rel=2e-3)
    assert MU_0 == 0.2


def test_eq_27_by_hand():
    # U 1e-10, G 5000, W 5e-5, L 1, alpha0 2e-8 1/Pa, R_e 5 mm, l 20 mm:
    # 176 / 1.29 = 136.434; / 2e-8 = 6.8217e9; x (5e-7)^0.658 = 7.1437e-5 -> 4.8732e5;
    # x (5e-5)^0.31 = 0.046417 -> 2.2620e4; x R_e^2 = 2.5e-5 -> 0.56551; x l -> 0.011310 N m
    M = aihara_moment_per_roller_Nm(U=1e-10, G=5000.0, W=5e-5, L=1.0, alpha0_1_Pa=2e-8, Re_m=5e-3, length_m=0.02)
    assert M == pytest.approx(0.011310, rel=1e-4)


def test_eq_27_is_eq_22_x_21_x_19_x_l_x_f_w():
    """Eq. 27 reproduces 2 R_e t_r (Eq. 22) with Crook's t_r (Eq. 19), the thermal factor (Eq. 21),
    l and the load correction f(W) = 20.4 W^0.3 (Eq. 25), up to its rounding (176 for 176.2,
    W^0.31 for W^0.3126: 2.6 % at W = 5e-5)."""
    U, G, W, L, a0, Re, l = 1e-10, 5000.0, 5e-5, 1.0, 2e-8, 5e-3, 0.02
    t_r = 4.318 / a0 * (G * U) ** 0.658 * W ** 0.0126 * Re
    merged = 2 * Re * t_r / (1 + 0.29 * L ** 0.78) * l * 20.4 * W ** 0.3
    M = aihara_moment_per_roller_Nm(U=U, G=G, W=W, L=L, alpha0_1_Pa=a0, Re_m=Re, length_m=l)
    assert M == pytest.approx(merged, rel=0.03)


def test_thermal_factor_and_asperity_share():
    assert aihara_thermal_factor(0.0) == 1.0
    assert aihara_thermal_factor(1.0) == pytest.approx(1 / 1.29)
    # the core's factor (kegel's rolling_thermal = "aihara") is the same law
    assert _core.tribology.aihara_thermal_factor(3.0) == pytest.approx(aihara_thermal_factor(3.0))
    # Eq. 13 at Lambda = 2: 0.016 ("almost all the load is supported by the fluid film for Lambda over 2")
    assert math.exp(-1.8 * 2 ** 1.2) == pytest.approx(0.016, abs=5e-4)
    with pytest.raises(KegelInputError):
        aihara_thermal_factor(-1.0)


def test_hamrock_dowson_by_hand():
    # U 1e-11, G 5000, W 1e-6, k 1.03, R_x 0.2 m: 3.63 x 3.3113e-8 x 64.937 x 2.7416 x 0.50361 x 0.2
    h = hamrock_dowson_min_film_m(U=1e-11, G=5000.0, W=1e-6, k=1.03, Rx_m=0.2)
    by_hand = 3.63 * (1e-11) ** 0.68 * 5000 ** 0.49 * (1e-6) ** -0.073 * (1 - math.exp(-0.68 * 1.03)) * 0.2
    assert h == pytest.approx(by_hand, rel=1e-12)
    assert h == pytest.approx(3.63 * 3.3113e-8 * 64.937 * 2.7416 * 0.50361 * 0.2, rel=1e-3)


def test_vogel_beta():
    # FVA 3: B 1021.7 K, C 101.55 degC; at 50 degC beta = 1021.7 / 151.55^2 = 0.04448 1/K
    assert vogel_viscosity_temperature_coefficient_1_K(1021.7, 101.5517, 323.15) == pytest.approx(0.04448, rel=1e-3)


@pytest.fixture(scope="module")
def table1():
    b = kegel.load_bearing("32216")
    m = kegel.load_material("bearing_steel")
    lub = kegel.load_lubricant("FVA3")
    g = kegel.derive_geometry(b, m)
    E = _core.reduced_modulus_Pa(m.core, m.core)
    P = lub.parameters

    def at(n_rpm: float, T_degC: float, Fa: float = 6000.0, Fr: float = 0.0):
        T = T_degC + 273.15
        return aihara_running_torque(g, kegel.lubricant_state(lub, T), speed_rad_s=n_rpm * math.pi / 30,
                                     axial_load_N=Fa, radial_load_N=Fr, E_reduced_Pa=E, sigma_rib_m=b.sigma_rib_m,
                                     viscosity_temperature_coefficient_1_K=vogel_viscosity_temperature_coefficient_1_K(
                                         P.vogel_B_K, P.vogel_C_degC, T))
    return at


def test_32216_at_table_1_conditions(table1):
    """Regression (1e-3) of the figures in docs/validation.md, and what they must look like: N m,
    rising with speed and flattening (thermal factor 0.98 at 500 rpm, 0.66 at 4000 rpm), full film
    at the rib (its term negligible), the load effect F_a^0.31."""
    a500, a2000, a4000 = table1(500, 50), table1(2000, 50), table1(4000, 50)
    assert a500.total_Nm == pytest.approx(1.844, rel=1e-3)
    assert a2000.total_Nm == pytest.approx(3.975, rel=1e-3)
    assert a4000.total_Nm == pytest.approx(4.843, rel=1e-3)
    assert a500.thermal_factor_inner == pytest.approx(0.980, abs=2e-3)
    assert a4000.thermal_factor_inner == pytest.approx(0.655, abs=2e-3)
    assert a500.Lambda_rib > 2 and a500.rib_Nm < 1e-3 * a500.total_Nm
    assert table1(2000, 50, Fa=12000.0).rolling_Nm / a2000.rolling_Nm == pytest.approx(2 ** 0.31, rel=1e-9)


def test_a_radial_load_is_refused(table1):
    with pytest.raises(KegelInputError, match="pure axial load"):
        table1(2000, 50, Fr=1000.0)
    with pytest.raises(KegelInputError, match="axial_load_N"):
        table1(2000, 50, Fa=0.0)
