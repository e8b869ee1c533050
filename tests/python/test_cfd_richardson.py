"""Richardson extrapolation and GCI (kegel.cfd_cases.richardson) against hand calculations."""

from __future__ import annotations

import math

import pytest

from kegel.cfd_cases.richardson import richardson_three_levels


def _levels(phi_exact, C, p, cells):
    return [phi_exact + C * n ** (-p / 3.0) for n in cells]


@pytest.mark.parametrize("cells", [(8000, 1000, 125), (952_963, 234_055, 71_317)])
def test_exact_power_law_recovers_order_and_limit(cells):
    """phi = phi_ext + C h^p with h = N^(-1/3): the procedure returns p and phi_ext exactly, for a
    constant refinement ratio (2) and for the uneven ratios of kegel's tiny/small/fine meshes."""
    phi = _levels(0.07, -0.4, 1.7, cells)
    r = richardson_three_levels(phi, cells)
    assert r.apparent_order == pytest.approx(1.7, rel=1e-9)
    assert r.phi_extrapolated == pytest.approx(0.07, rel=1e-9)
    assert r.convergence == "monotonic" and r.safety_factor == 1.25 and not r.notes


def test_hand_calculation_constant_ratio():
    """r = 2, phi = 1.00, 1.04, 1.20 (finest first): e32 / e21 = 4, p = ln 4 / ln 2 = 2,
    phi_ext = (4 * 1.00 - 1.04) / 3 = 0.98667, e_a = 0.04, GCI = 1.25 * 0.04 / 3 = 1.6667 %."""
    r = richardson_three_levels([1.00, 1.04, 1.20], [8000, 1000, 125])
    assert r.r21 == pytest.approx(2.0) and r.r32 == pytest.approx(2.0)
    assert r.apparent_order == pytest.approx(2.0, rel=1e-10)
    assert r.phi_extrapolated == pytest.approx(2.96 / 3.0, rel=1e-12)
    assert r.relative_change_fine == pytest.approx(0.04)
    assert r.gci_fine == pytest.approx(1.25 * 0.04 / 3.0)
    assert r.uncertainty == pytest.approx(r.gci_fine * 1.00)
    assert r.relative_error_extrapolated == pytest.approx(abs(2.96 / 3 - 1) / (2.96 / 3))


def test_oscillatory_convergence_is_flagged_and_uses_the_formal_order():
    r = richardson_three_levels([1.00, 1.04, 0.98], [8000, 1000, 125])
    assert r.convergence == "oscillatory"
    assert r.order_used == 2.0 and r.safety_factor == 3.0
    assert r.gci_fine == pytest.approx(3.0 * 0.04 / 3.0)
    assert any("oscillatory" in n for n in r.notes)


def test_order_outside_the_asymptotic_range_is_flagged():
    # e32 / e21 = 64 with r = 2: p = 6
    r = richardson_three_levels([1.00, 1.01, 1.65], [8000, 1000, 125])
    assert r.apparent_order == pytest.approx(6.0, rel=1e-9)
    assert r.order_used == 2.0 and r.safety_factor == 3.0 and r.notes


@pytest.mark.parametrize("phi, cells, words", [
    ([1.0, 1.1], [8000, 1000, 125], "three values"),
    ([1.0, 1.1, 1.2], [1000, 8000, 125], "decreasing"),
    ([1.0, math.nan, 1.2], [8000, 1000, 125], "finite"),
    ([1.0, 1.0, 1.2], [8000, 1000, 125], "equal"),
])
def test_bad_input_is_named(phi, cells, words):
    with pytest.raises(ValueError, match=words):
        richardson_three_levels(phi, cells)
