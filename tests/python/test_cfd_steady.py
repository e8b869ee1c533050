"""Statistically steady torque of a transient run: window means and the drift estimate."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kegel.cfd_cases.steady import steady_drift, window_means


def _uneven_times(t_end: float, n: int = 4000, seed: int = 1) -> np.ndarray:
    """Time steps that vary by a factor of 3, as with an adjustable time step."""
    dt = np.random.default_rng(seed).uniform(1.0, 3.0, n)
    t = np.concatenate(([0.0], np.cumsum(dt)))
    return t * t_end / t[-1]


def test_window_means_are_time_means_not_sample_means():
    # y = t on uneven samples: each window's time mean is its mid-point, whatever the sampling
    t = _uneven_times(3.0)
    m = window_means(t, t, 1.0)
    assert m == pytest.approx([0.5, 1.5, 2.5], abs=1e-12)
    assert window_means(t, t, 1.01) is None  # shorter than three windows


def test_geometric_approach_is_extrapolated_to_its_limit():
    # y = 5 + 2 exp(-t / tau): window means approach 5 geometrically with q = exp(-W / tau)
    tau, w = 0.7, 0.5
    t = _uneven_times(2.0)
    d = steady_drift(t, 5.0 + 2.0 * np.exp(-t / tau), w)
    assert d.estimate == pytest.approx(5.0, abs=1e-6)  # trapezoidal window means
    # the remaining change is the tail of the geometric series of window changes
    m3 = 5.0 + 2.0 * tau / w * (np.exp(-(2.0 - w) / tau) - np.exp(-2.0 / tau))
    assert d.remaining == pytest.approx(5.0 - m3, rel=1e-5)
    assert not d.steady(0.02, 5.0)  # still 7 % away after 2 s
    t = _uneven_times(8.0)
    d = steady_drift(t, 5.0 + 2.0 * np.exp(-t / tau), w)
    assert d.steady(0.02, 5.0)


def test_linear_creep_is_never_steady():
    # the window-to-window change (0.5 % of the level) passes a 2 % test; the creep does not stop
    t = _uneven_times(30.0)
    d = steady_drift(t, 100.0 + 0.5 * t, 1.0)
    assert abs(d.means[2] - d.means[1]) < 0.02 * 100
    assert math.isinf(d.remaining) and not d.steady(0.02, 100.0)


def test_a_trend_that_just_stopped_is_not_steady_yet():
    # a drop from 30 to 19 over the first window, then a slight rise (the tiny 32208 oil bath at
    # 0.11 s: window means 29.7, 19.07, 19.09 mN m, and 23.4 after 0.25 s): the last two window
    # means agree, but the drop may be the first phase of a longer transient
    t = _uneven_times(3.0)
    y = np.where(t < 1.0, 30.0 - 11.0 * t, 19.0 + 0.01 * (t - 1.0))
    d = steady_drift(t, y, 1.0)
    assert abs(d.means[2] - d.means[1]) < 0.02 * 19 and d.means[0] - d.means[1] > 5
    assert not d.steady(0.02, 19.0)
    assert d.estimate == pytest.approx(d.means[2])


def test_fluctuations_about_a_level_are_steady_when_small():
    t = _uneven_times(3.0, n=30000)
    y = -20.0 + 0.1 * np.sin(2 * np.pi * t / 0.013) + 0.05 * np.random.default_rng(2).standard_normal(len(t))
    d = steady_drift(t, y, 1.0)
    assert d.estimate == pytest.approx(-20.0, abs=0.02)
    assert d.steady(0.02, 20.0)
    # the same signal with a large slow oscillation (period of two windows) is not
    d = steady_drift(t, y + 3.0 * np.sin(np.pi * t + 0.5), 1.0)
    assert not d.steady(0.02, 20.0)


def _write_forces(folder, times, value):
    folder.mkdir(parents=True)
    rows = "".join(f"{t:.10g} ({value} 0 {value}) (0 0 0) ({value} 0 {value})\n" for t in times)
    for name in ("force.dat", "moment.dat"):
        (folder / name).write_text("# Time total pressure viscous\n" + rows)


def test_force_series_of_a_resumed_run_replace_what_followed_the_restart_time(tmp_path):
    from kegel.cfd_cases.forces import read_forces

    root = tmp_path / "postProcessing" / "forces_x"
    # the first run wrote its fields at 0.5 but went on to 0.77 before it was stopped
    _write_forces(root / "0", np.arange(0.01, 0.775, 0.01), 1.0)
    _write_forces(root / "0.5", np.arange(0.5, 1.0, 0.013), 2.0)
    f = read_forces(tmp_path, "forces_x")
    assert np.all(np.diff(f.time) > 0)
    assert np.all(f.moment_total[f.time <= 0.49, 2] == 1.0)
    assert np.all(f.moment_total[f.time >= 0.5, 2] == 2.0)
    assert f.time[-1] == pytest.approx(0.994)
