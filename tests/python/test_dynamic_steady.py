"""Steady state of a dynamic run detected, not assumed (issue 30, item 2).

The detector (kegel.steady.settled_window, the CFD's drift-and-spread test on window means) on
synthetic signals, then dynamic runs: a run that is still ramping is not converged, a start from
rest settles on the quasi-static torque, and the answer does not depend on the output interval.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import kegel
from conftest import scene_text
from kegel.steady import drift_of_means, settled_window, steady_drift

RPM = math.pi / 30


def _integral(t: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Time integral from t[0] (trapezoidal), as the dynamic run's quadratures give it."""
    return np.concatenate(([0.0], np.cumsum(0.5 * (y[1:] + y[:-1]) * np.diff(t))))


# ------------------------------------------------------------------------------------------
# The detector on synthetic signals
# ------------------------------------------------------------------------------------------

W = 2.2e-3      # window: one roller pass of the 32216 at 4000 rpm
TOL = 5e-3


def _ramp_then_settling(t: np.ndarray, noise: float, seed: int = 1) -> np.ndarray:
    """A start from rest: a torque rising along a 50 ms ramp (inertia and speed), a drop to
    4.6 N m at its end that settles exponentially (tau 1 ms), white noise on every sample."""
    rng = np.random.default_rng(seed)
    y = np.where(t < 0.05, 4.6 + 4.6 * t / 0.05, 4.6 + 4.6 * np.exp(-(t - 0.05) / 1e-3))
    return y + noise * rng.standard_normal(len(t))


def test_the_window_starts_after_the_transient():
    t = np.arange(0.0, 0.08 + 1e-12, 1e-4)
    y = _ramp_then_settling(t, noise=0.01)
    s = settled_window(t, {"torque": _integral(t, y)}, W, TOL)
    assert s.settled, s.reason
    # the transient is 4.6 exp(-(t - 50 ms) / 1 ms): 0.5 % of 4.6 N m at 55.3 ms; the test sees a
    # geometric approach that is over within the tolerance before that, but never the ramp
    assert 0.050 < s.start < 0.0565 and s.end == pytest.approx(0.08)
    mean = (_integral(t, y)[-1] - np.interp(s.start, t, _integral(t, y))) / (s.end - s.start)
    assert mean == pytest.approx(4.6, rel=2e-3)
    # every figure it reports: remaining drift within the tolerance
    rem, last = s.relative("torque")
    assert rem <= TOL and last <= TOL and s.as_dict()["drift_relative"] <= TOL


def test_a_pure_ramp_is_not_steady():
    t = np.arange(0.0, 0.08 + 1e-12, 1e-4)
    for y in (4.6 + 50.0 * t, 4.6 + 50.0 * t + 0.01 * np.random.default_rng(2).standard_normal(len(t))):
        s = settled_window(t, {"torque": _integral(t, y)}, W, TOL)
        assert not s.settled
        assert "torque has not settled" in s.reason or "creeps" in s.reason, s.reason


def test_a_slow_creep_is_not_steady_even_when_three_windows_do_not_see_it():
    """0.05 % per window (below the scatter resolution of the three-window test) but 1.8 % over
    the 80 ms run: the trend across the averaging window limits it to the last part, where the
    creep stays within the tolerance (22 ms). A creep of 0.1 % per ms moves the torque by more
    than the tolerance over the shortest settled part (three windows, 6.6 ms): never settled."""
    t = np.arange(0.0, 0.08 + 1e-12, 1e-4)
    y = 4.6 * (1.0 + 0.225 * t)  # 0.0225 % per ms
    s = settled_window(t, {"torque": _integral(t, y)}, W, TOL)
    creep = (y[-1] - np.interp(s.start, t, y)) / y[-1]
    assert s.settled and s.trends["torque"] <= TOL and creep <= 1.01 * TOL
    assert 0.015 < s.end - s.start < 0.025
    y = 4.6 * (1.0 + 1.0 * t)  # 0.1 % per ms: 0.22 % per window, within the scatter resolution
    s = settled_window(t, {"torque": _integral(t, y)}, W, TOL)
    assert not s.settled and "creeps" in s.reason, s.reason


def test_a_settling_that_is_still_going_on_is_not_steady():
    """tau = 20 ms: at the end of a 30 ms run the torque is still 22 % above its level."""
    t = np.arange(0.0, 0.03 + 1e-12, 1e-4)
    y = 4.6 * (1.0 + np.exp(-t / 0.02))
    s = settled_window(t, {"torque": _integral(t, y)}, W, TOL)
    assert not s.settled
    # Aitken's extrapolation of the last three windows finds the level (hand calculation: the
    # window means of an exponential form a geometric series with q = exp(-W / tau))
    d = s.drifts["torque"]
    assert d.estimate == pytest.approx(4.6, rel=1e-3)
    m3 = d.means[2]
    assert d.remaining == pytest.approx(4.6 - m3, rel=1e-3)


def test_a_roller_pass_fluctuation_averages_out_in_one_window():
    """A torque with a large fluctuation at the roller pass (the window): settled from the first
    window on (the settled part starts two windows before the first passing check point, which
    is three windows after the start)."""
    t = np.arange(0.0, 0.03 + 1e-12, 2e-5)
    y = 0.126 * (1.0 + 0.3 * np.sin(2 * np.pi * t / W))
    s = settled_window(t, {"torque": _integral(t, y)}, W, TOL)
    assert s.settled and W - 1e-12 <= s.start <= W + W / 4 + 1e-12
    # the same with windows of half a pass: the means scatter by 19 %, never steady
    assert not settled_window(t, {"torque": _integral(t, y)}, W / 2, TOL).settled


def test_every_signal_must_settle():
    t = np.arange(0.0, 0.03 + 1e-12, 1e-4)
    flat, ramp = np.full_like(t, 4.6), 100.0 + 5000.0 * t
    s = settled_window(t, {"torque": _integral(t, flat), "cage_speed": _integral(t, ramp)}, W, TOL)
    assert not s.settled and "cage_speed" in s.reason


def test_a_run_shorter_than_the_test_is_not_settled():
    t = np.arange(0.0, 0.005 + 1e-12, 1e-4)
    s = settled_window(t, {"torque": _integral(t, np.full_like(t, 4.6))}, W, TOL, time_unit=("ms", 1e3))
    assert not s.settled and "shorter than the steady test needs" in s.reason and "6.6 ms" in s.reason


def test_the_result_does_not_depend_on_the_sampling():
    """The check points are anchored at the run's end, the window edges are not output times:
    the same signal sampled every 0.1 ms and every 0.25 ms gives the same window and mean."""
    out = []
    for dt in (1e-4, 2.5e-4):
        t = np.arange(0.0, 0.08 + 1e-12, dt)
        y = 4.6 + 4.6 * np.where(t < 0.05, t / 0.05, np.exp(-(t - 0.05) / 1e-3)) + 0.05 * np.sin(2 * np.pi * t / W)
        ti = np.linspace(0.0, 0.08, 80001)  # the integral of the signal, exact at the samples
        yi = 4.6 + 4.6 * np.where(ti < 0.05, ti / 0.05, np.exp(-(ti - 0.05) / 1e-3)) + 0.05 * np.sin(2 * np.pi * ti / W)
        I = np.interp(t, ti, _integral(ti, yi))
        s = settled_window(t, {"torque": I}, W, TOL)
        assert s.settled, s.reason
        out.append((s.start, (I[-1] - np.interp(s.start, t, I)) / (s.end - s.start)))
    assert out[0][0] == pytest.approx(out[1][0], abs=1e-12)
    assert out[0][1] == pytest.approx(out[1][1], rel=2e-4)


def test_drift_of_means_by_hand_and_the_cfd_names_unchanged():
    # geometric approach 1, 0.5, 0.25 (q = 0.5): the rest of the series is -0.25, the level 0
    d = drift_of_means([1.0, 0.5, 0.25], (0.0, 3.0))
    assert d.remaining == pytest.approx(-0.25) and d.estimate == pytest.approx(0.0)
    # a drift that does not slow down: unknown remaining change ...
    assert math.isinf(drift_of_means([1.0, 1.001, 1.002], (0.0, 3.0)).remaining)
    # ... unless both changes are within the resolution: scatter, the larger change the uncertainty
    d = drift_of_means([1.0, 1.001, 1.002], (0.0, 3.0), resolution=0.002)
    assert d.remaining == pytest.approx(0.001) and d.estimate == 1.002
    # the CFD imports the same objects from its old place
    from kegel.cfd_cases import steady as cfd_steady
    import kegel.steady as shared

    assert cfd_steady.steady_drift is steady_drift is shared.steady_drift
    assert cfd_steady.SteadyTest is shared.SteadyTest


# ------------------------------------------------------------------------------------------
# Dynamic runs
# ------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def setup():
    b = kegel.load_bearing("32216")
    m = kegel.load_material("bearing_steel")
    lub = kegel.load_lubricant("FVA3")
    g = kegel.derive_geometry(b, m)
    return g, b, m, lub, kegel.tribology.load_friction("steel_mineral_oil")


def test_a_run_whose_torque_still_drifts_is_not_converged(tmp_path):
    """A scene ramping 3000 -> 4000 rpm over its whole 8 ms: the cage speed (and the inertia
    torque) still change at the end. The point keeps its figures, is converged false with the
    reason, and its not_converged warning says it has not settled."""
    from kegel.run import run_scene
    from kegel.scene import load_scene

    text = scene_text(speed='"4000 rpm"', model='solution = "dynamic"\nslices = 4\n[dynamic]\nduration = "8 ms"\n'
                      'output_interval = "0.2 ms"\nthreads = 1\n'
                      'speed_profile = [["0 ms", "3000 rpm"], ["8 ms", "4000 rpm"]]')
    (tmp_path / "ramp.toml").write_text(text)
    res = run_scene(load_scene(tmp_path / "ramp.toml"), tmp_path / "out", progress=False)
    p = res.points[0]
    assert p["converged"] is False
    assert "has not settled" in p["failure"] and "lengthen dynamic.duration" in p["failure"]
    assert any(why in p["failure"] for why in ("does not slow down", "still to come", "creeps"))
    assert any(w["code"] == "not_converged" and "has not settled" in w["message"] for w in p["warnings"])
    # the figures are there, over the last half of the run, with the drift that disqualifies them
    assert math.isfinite(p["friction_torque_Nm"]) and p["friction_torque_Nm"] > 0
    assert p["steady_window_s"] == pytest.approx([4e-3, 8e-3])
    assert p["steady_drift"] is None or p["steady_drift"] > 5e-3  # None: a drift without end
    st = p["dynamic"]["steady"]
    assert st["settled"] is False and st["settling"]["window_s"] == pytest.approx(2.2e-3, rel=0.02)


@pytest.fixture(scope="module")
def start_from_rest(setup):
    """The start from rest shortened for the tests: the example ramps 0 -> 4000 rpm in 50 ms and
    runs 20 ms at speed (70 ms, 1-2 min on two free cores; its first milliseconds near standstill
    take the smallest steps). Here the ramp's second half, faster: 2000 -> 4000 rpm in 3 ms from
    the quasi-static state at 2000 rpm, then 5 ms at speed; 6 independent slices."""
    from kegel.dynamics import simulate

    g, b, m, lub, fr = setup
    return simulate(g, b, m, lub, fr, temperature_K=323.15,
                    speed_profile=[(0.0, 2000 * RPM), (3e-3, 4000 * RPM)], duration_s=8e-3, axial_N=6000.0,
                    slices=6, method="independent", threads=1, output_interval_s=1e-4)


def test_a_start_from_rest_settles_on_the_quasi_static_torque(setup, start_from_rest):
    from kegel.quasi_static import bearing_friction

    g, b, m, lub, fr = setup
    r = start_from_rest
    st = r.steady
    assert st["settled"], st["settling"]["reason"]
    # the window starts after the ramp (3 ms) and its inertia torque, and is at least three
    # windows long
    assert 3e-3 <= st["window_start_s"] <= 8e-3 - 3 * st["settling"]["window_s"]
    assert st["window_end_s"] == pytest.approx(8e-3)
    assert st["drift_relative"] <= 5e-3
    _, q = bearing_friction(g, b, m, lub, fr, temperature_K=323.15, inner_speed_rad_s=4000 * RPM, axial_N=6000.0,
                            slices=6, method="independent")
    assert st["outer_ring_torque_Nm"] == pytest.approx(q.outer_ring_torque_Nm, rel=0.02)
    assert st["drive_torque_Nm"] == pytest.approx(q.drive_torque_Nm, rel=0.02)
    assert st["cage_speed_rad_s"] == pytest.approx(q.cage_speed_rad_s, rel=0.02)
    # over the ramp, the drive torque holds the inertia torque of the rollers and the cage
    ramp = r.series["mean_drive_torque_Nm"][(r.time_s > 0.5e-3) & (r.time_s < 3e-3)]
    assert ramp.min() > 1.05 * st["drive_torque_Nm"]


def test_the_settled_answer_does_not_depend_on_the_output_interval(setup, start_from_rest):
    """The same trajectory recorded every 0.1 ms and every 0.4 ms (every fourth output: CVODE's
    steps do not depend on the output times, tests/python/test_dynamics.py): the settled means
    agree within 0.1 %. The window start may move by up to a window: the windows are at least two
    output intervals, so coarse outputs can make them longer."""
    from kegel.dynamics import _steady, settling

    g = setup[0]
    r = start_from_rest
    a = r.steady
    t, Q = r.time_s[::4], r.quadratures[::4]
    series = {k: v[::4] for k, v in r.series.items()}
    from kegel.dynamics import _interval_means

    series.update(_interval_means(t, Q))
    s = settling(t, Q, g, 4000 * RPM, output_interval_s=4e-4)
    assert s.settled, s.reason
    b = _steady(t, series, Q, s.start)
    assert abs(s.start - a["window_start_s"]) <= max(s.window, a["settling"]["window_s"]) + 1e-12
    for k in ("outer_ring_torque_Nm", "drive_torque_Nm", "cage_speed_rad_s", "power_input_W"):
        assert b[k] == pytest.approx(a[k], rel=1e-3), k


def test_automatic_duration_runs_until_the_signals_settle(setup):
    """max_duration_s: the ramp 2000 -> 4000 rpm in 3 ms asked for 4 ms only (its transient still
    going on) goes on until the torques and the cage speed settle, on the same output grid; with
    a cap too short to settle, it stops at the cap and says it has not settled."""
    from kegel.dynamics import simulate
    from kegel.quasi_static import bearing_friction

    g, b, m, lub, fr = setup
    kw = dict(temperature_K=323.15, speed_profile=[(0.0, 2000 * RPM), (3e-3, 4000 * RPM)], axial_N=6000.0,
              slices=6, method="independent", output_interval_s=1e-4)
    short = simulate(g, b, m, lub, fr, duration_s=4e-3, **kw)
    assert not short.steady["settled"] and not short.stats["extended"]
    auto = simulate(g, b, m, lub, fr, duration_s=4e-3, max_duration_s=20e-3, **kw)
    assert auto.steady["settled"], auto.steady["settling"]["reason"]
    assert auto.stats["extended"] and 4e-3 < auto.stats["duration_s"] < 20e-3
    assert auto.stats["duration_s"] == pytest.approx(auto.time_s[-1])
    dt = np.diff(auto.time_s)
    assert dt.min() > 0.5e-4 and dt.max() < 1e-4 + 1e-12  # the output grid goes on unchanged
    _, q = bearing_friction(g, b, m, lub, fr, temperature_K=323.15, inner_speed_rad_s=4000 * RPM, axial_N=6000.0,
                            slices=6, method="independent")
    assert auto.steady["outer_ring_torque_Nm"] == pytest.approx(q.outer_ring_torque_Nm, rel=0.02)
    capped = simulate(g, b, m, lub, fr, duration_s=4e-3, max_duration_s=4.5e-3, **kw)
    assert capped.stats["duration_s"] == pytest.approx(4.5e-3)
    assert not capped.steady["settled"]
    with pytest.raises(kegel.KegelInputError, match="max_duration_s"):
        simulate(g, b, m, lub, fr, duration_s=4e-3, max_duration_s=3e-3, **kw)


def test_a_scene_max_duration_lets_a_drifting_point_run_on(tmp_path):
    """The same ramp with ``dynamic.max_duration``: the point runs past its 8 ms until the cage
    speed has settled (or says it reached the cap), and the scene checks the key's range."""
    from kegel.errors import KegelInputError
    from kegel.run import run_scene
    from kegel.scene import load_scene

    base = ('solution = "dynamic"\nslices = 4\n[dynamic]\nduration = "8 ms"\noutput_interval = "0.2 ms"\n'
            'threads = 1\nspeed_profile = [["0 ms", "3000 rpm"], ["8 ms", "4000 rpm"]]\n')
    (tmp_path / "bad.toml").write_text(scene_text(speed='"4000 rpm"', model=base + 'max_duration = "5 ms"'))
    with pytest.raises(KegelInputError, match=r"dynamic\.max_duration.*from dynamic\.duration"):
        load_scene(tmp_path / "bad.toml")
    (tmp_path / "on.toml").write_text(scene_text(speed='"4000 rpm"', model=base + 'max_duration = "40 ms"'))
    p = run_scene(load_scene(tmp_path / "on.toml"), tmp_path / "out", progress=False).points[0]
    stats = p["dynamic"]["stats"]
    assert stats["extended"] is True and 8e-3 < stats["duration_s"] <= 40e-3 + 1e-12
    if p["converged"]:
        assert p["steady_window_s"][0] >= 8e-3  # averaged only after the ramp
    else:
        assert stats["duration_s"] == pytest.approx(40e-3) and "dynamic.max_duration (40 ms)" in p["failure"]
