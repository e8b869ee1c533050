"""Python entry points of the friction laws: reference values and argument checks."""

from __future__ import annotations

import math

import pytest

from kegel._core import tribology as t

E_STEEL = 230.8e9


@pytest.mark.parametrize("u_m, h_um", [(1.5, 0.537), (5.9, 1.371), (11.8, 2.194)])
def test_moes_known_values(u_m, h_um):
    h = t.moes_line_film_thickness_m(0.0525, 2 * u_m, 7.5e-3, 68e3, 21e-9, E_STEEL)
    assert h * 1e6 == pytest.approx(h_um, rel=5e-3)


def test_bair_winer_saturates_and_is_odd():
    assert t.bair_winer_shear_stress_Pa(100.0, 5.0, 1e-7, 3e7) == pytest.approx(3e7)
    assert t.bair_winer_shear_stress_Pa(100.0, -0.01, 1e-6, 3e7) == -t.bair_winer_shear_stress_Pa(100.0, 0.01, 1e-6, 3e7)


def test_cubic_law_and_damping():
    assert t.cubic_friction_coefficient(0.0, 0.12, 0.08, 0.01, 0.05) == 0.0
    assert t.cubic_friction_coefficient(0.01, 0.12, 0.08, 0.01, 0.05) == pytest.approx(0.12)
    assert t.damping_coefficient(0.5e-6, 500.0, 1e-6) == pytest.approx(250.0)
    assert 0 < t.asperity_load_ratio(1.0, 2.32, 0.97) == pytest.approx(math.exp(-2.32))


@pytest.mark.parametrize(
    "call, fragment",
    [
        (lambda: t.moes_line_film_thickness_m(0.05, 3.0, -7.5e-3, 68e3, 21e-9, E_STEEL), "R_m = -0.0075"),
        (lambda: t.bair_winer_shear_stress_Pa(100.0, float("nan"), 1e-6, 3e7), "u_rel_m_s = nan"),
        (lambda: t.cubic_friction_coefficient(0.1, 0.12, 0.08, 0.05, 0.01), "v_d_m_s = 0.01"),
        (lambda: t.asperity_load_ratio(-1.0, 2.32, 0.97), "Lambda = -1"),
    ],
)
def test_bad_arguments_raise_value_error_naming_them(call, fragment):
    with pytest.raises(ValueError, match="expected") as info:
        call()
    assert fragment in str(info.value)
