"""When is a transient torque statistically steady, and how far is it from its steady value?

Shared by the CFD runner (``kegel.cfd_cases.run``: when an OpenFOAM run may stop) and the dynamic
solution (:mod:`kegel.dynamics`: where its speed ramps and the cage's free flight have died out,
:func:`settled_window`).

A transient run (the oil bath) starts with the oil at rest and spins it up. The torque then creeps
towards its steady value over a time set by the slowest viscous and free-surface motions, and it
may carry fluctuations on top. Two consecutive window means that agree are not enough: a slow
creep passes that test long before it is over. :func:`steady_drift` therefore looks at three
consecutive window means m1, m2, m3 (differences d1 = m2 - m1, d2 = m3 - m2):

- d1 and d2 of one sign with ``q = d2 / d1 < 1``: a geometric approach. The remaining change is
  the rest of the geometric series, ``d2 q / (1 - q)`` (Aitken's delta-squared extrapolation), and
  ``m3`` plus it estimates the steady value.
- d1 and d2 of one sign with ``q >= 1``: the drift does not slow down; the remaining change is
  unknown (infinite).
- opposite signs: the window means scatter about a level, or a trend has just stopped; the
  larger of ``|d1|`` and ``|d2|`` is the uncertainty and ``m3`` the estimate. (A drop that ends
  in the second window gives a large d1 and a small d2 of the other sign: not steady yet.)

Window means are time averages (trapezoidal rule), so a variable time step does not weight them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Sequence

import numpy as np

__all__ = ["SettledWindow", "SteadyDrift", "SteadyTest", "cumulative_window_means", "drift_of_means",
           "first_steady_time", "settled_window", "steady_drift", "window_means"]


@dataclass(frozen=True)
class SteadyDrift:
    """Three window means and what they say about the steady value (units of the series)."""

    means: tuple[float, float, float]
    estimate: float          # estimated steady value
    remaining: float         # estimated change still to come (signed; the scatter when the
                             # window means scatter; inf when unknown)
    window: tuple[float, float]  # the time span of the three windows

    def steady(self, tol: float, scale: float) -> bool:
        """Whether the remaining change and the last window-to-window change are both within
        ``tol * scale``; never for ``tol`` = 0 (a run that is not to stop on it)."""
        d2 = self.means[2] - self.means[1]
        return tol > 0.0 and abs(self.remaining) <= tol * scale and abs(d2) <= tol * scale


def window_means(t: np.ndarray, y: np.ndarray, window: float, n: int = 3) -> np.ndarray | None:
    """Time means of ``y(t)`` over the last ``n`` windows of length ``window`` (oldest first),
    or None when the series is shorter than ``n`` windows."""
    t = np.asarray(t, dtype=float)
    y = np.asarray(y, dtype=float)
    if window <= 0 or len(t) < 2 or t[-1] - t[0] < n * window:
        return None
    edges = t[-1] - window * np.arange(n, -1, -1)
    means = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        inside = (t > lo) & (t < hi)
        ts = np.concatenate(([lo], t[inside], [hi]))
        ys = np.interp(ts, t, y)
        means.append(float(np.sum(0.5 * (ys[1:] + ys[:-1]) * np.diff(ts)) / (hi - lo)))
    return np.array(means)


def drift_of_means(means: Sequence[float], span: tuple[float, float], resolution: float = 0.0) -> SteadyDrift:
    """What three consecutive window means ``m1, m2, m3`` (oldest first) covering the time
    ``span`` say about the steady value (see the module text: a geometric approach is
    extrapolated, a drift that does not slow down has an unknown remaining change, scattering
    means count their larger change as the uncertainty).

    Changes of one sign that are both within ``resolution`` count as scatter, not as a trend: the
    window means of a settled signal with a little noise change by chance in one direction twice
    in a row, and ``q >= 1`` would call that a drift without end. (0, the CFD's use: every
    same-sign pair is a trend.)"""
    m = [float(x) for x in means]
    if len(m) != 3:
        raise ValueError(f"drift_of_means: {len(m)} window means: expected 3")
    d1, d2 = m[1] - m[0], m[2] - m[1]
    trend = d1 * d2 > 0.0 and max(abs(d1), abs(d2)) > resolution
    q = d2 / d1 if trend else None
    if q is not None and q < 1.0:  # geometric approach: the tail of the series of changes
        remaining = d2 * q / (1.0 - q)
        estimate = m[2] + remaining
    else:  # no trend to extrapolate: the estimate is the last mean
        remaining = math.copysign(math.inf, d2) if q is not None else max(abs(d1), abs(d2))
        estimate = m[2]
    return SteadyDrift(means=(m[0], m[1], m[2]), estimate=float(estimate), remaining=float(remaining),
                       window=(float(span[0]), float(span[1])))


def steady_drift(t: np.ndarray, y: np.ndarray, window: float) -> SteadyDrift | None:
    """The steady-value estimate of a transient series from its last three windows (see the
    module text), or None when the series is shorter than three windows."""
    m = window_means(t, y, window, 3)
    if m is None:
        return None
    t_end = float(t[-1])
    return drift_of_means(m, (t_end - 3 * window, t_end))


@dataclass
class SteadyTest:
    """The steady test applied at check points, in pieces as a series grows.

    At each check point from ``min_time`` on the series up to then must pass
    :meth:`SteadyDrift.steady` (``tol`` relative to the estimate); the test is passed when it has
    passed at every check point over the last ``hold`` of time. ``hold`` = 0 takes the first pass.
    A test that must hold over a span does not stop on a brief pass, which a slow swing of the
    series can give (window means that happen to look like a geometric approach).
    """

    window: float
    tol: float
    min_time: float = 0.0
    hold: float = 0.0
    since: float | None = None  # first check point of the current run of passes

    def update(self, t: np.ndarray, y: np.ndarray, check_times: np.ndarray) -> float | None:
        """Apply the test at ``check_times`` (increasing, after those of earlier calls) to the
        series ``t, y`` up to each; return the last sample time up to the check point at which
        the test is passed, or None."""
        t = np.asarray(t, dtype=float)
        y = np.asarray(y, dtype=float)
        checks = np.asarray(check_times, dtype=float)
        for tc in checks[checks >= self.min_time]:
            k = int(np.searchsorted(t, tc, side="right"))
            d = steady_drift(t[:k], y[:k], self.window)
            if d is None or not d.steady(self.tol, abs(d.estimate)):
                self.since = None
                continue
            self.since = tc if self.since is None else self.since
            if tc - self.since >= self.hold * (1 - 1e-9):
                return float(t[k - 1])
        return None


def first_steady_time(t: np.ndarray, y: np.ndarray, window: float, tol: float, *,
                      min_time: float = 0.0, check_times: np.ndarray | None = None,
                      hold: float = 0.0) -> float | None:
    """Replay :class:`SteadyTest` on a recorded series at ``check_times`` (default: every sample
    time): the last sample time up to the check point at which it is passed, or None."""
    test = SteadyTest(window, tol, min_time=min_time, hold=hold)
    return test.update(t, y, np.asarray(t, dtype=float) if check_times is None else check_times)


def cumulative_window_means(t: np.ndarray, integral: np.ndarray, edges: np.ndarray) -> np.ndarray:
    """Means between consecutive ``edges`` of a quantity whose time integral from the start is
    ``integral`` at the times ``t`` (the dynamic solution's CVODES quadratures: exact time means
    at output times; the integral is linear in between, so a window edge between two outputs
    gets the mean of that output interval for its part of it)."""
    edges = np.asarray(edges, dtype=float)
    values = np.interp(edges, np.asarray(t, dtype=float), np.asarray(integral, dtype=float))
    return np.diff(values) / np.diff(edges)


@dataclass(frozen=True)
class SettledWindow:
    """Where a set of signals has settled (:func:`settled_window`); times in the units of ``t``.

    ``start``-``end`` is the settled part (the averaging window) when ``settled``; otherwise it
    is the longest passing tail found (possibly empty: ``start`` = ``end``). ``drifts`` are the
    three-window tests at the run's end, per signal, with the ``scales`` their tolerance is
    relative to; ``reason`` says in words why the signals are or are not settled.
    """

    settled: bool
    start: float
    end: float
    window: float
    tol: float
    hold: float
    drifts: dict[str, SteadyDrift | None] = field(default_factory=dict)
    scales: dict[str, float] = field(default_factory=dict)
    reason: str = ""
    trends: dict[str, float] = field(default_factory=dict)  # change across start-end, relative

    def relative(self, name: str) -> tuple[float, float]:
        """(remaining change, last window-to-window change) of signal ``name`` at the run's end,
        relative to its scale (nan when the run is shorter than three windows)."""
        d, s = self.drifts.get(name), self.scales.get(name, 0.0)
        if d is None or not s > 0.0:
            return math.nan, math.nan
        return abs(d.remaining) / s, abs(d.means[2] - d.means[1]) / s

    def as_dict(self) -> dict[str, object]:
        """Plain dictionary (JSON): the window, the test's settings, and per signal the three
        window means at the end, the estimate, the remaining change and the relative figures
        (None where not known: a run shorter than three windows, a drift without end)."""
        def num(x: float | None) -> float | None:
            return float(x) if x is not None and math.isfinite(x) else None

        sig: dict[str, object] = {}
        for name, d in self.drifts.items():
            rem, last = self.relative(name)
            sig[name] = None if d is None else {
                "window_means": list(d.means), "estimate": num(d.estimate), "remaining": num(d.remaining),
                "scale": num(self.scales.get(name)), "remaining_relative": num(rem), "last_change_relative": num(last),
                "trend_relative": num(self.trends.get(name))}
        drift = [self.relative(n)[0] for n in self.drifts] + list(self.trends.values())
        known = [x for x in drift if not math.isnan(x)]
        return {"settled": self.settled, "start": self.start, "end": self.end, "window": self.window,
                "tolerance": self.tol, "hold": self.hold,
                # the largest remaining drift; inf (a drift without end) is given as None with the reason
                "drift_relative": num(max(known)) if known else None, "signals": sig, "reason": self.reason}


def window_trend(t: np.ndarray, integral: np.ndarray, start: float, end: float, window: float) -> float:
    """The change of a signal across ``start``-``end`` that a straight line through its window
    means says (least squares; whole windows back from ``end``; 0 with fewer than two)."""
    n = int(math.floor((end - start) / window * (1 + 1e-9)))
    if n < 2:
        return 0.0
    edges = end - window * np.arange(n, -1, -1)
    means = cumulative_window_means(t, integral, edges)
    centres = 0.5 * (edges[1:] + edges[:-1])
    slope = float(np.polyfit(centres - centres.mean(), means, 1)[0])
    return slope * (end - start)


def settled_window(t: np.ndarray, integrals: dict[str, np.ndarray], window: float, tol: float, *,
                   floors: dict[str, float] | None = None, hold: float | None = None,
                   step: float | None = None, trend_span: float | None = None,
                   time_unit: tuple[str, float] = ("", 1.0)) -> SettledWindow:
    """The part at the end of a run over which every signal has settled.

    Drift and spread on consecutive window means:

    1. The steady test of :class:`SteadyTest` (three consecutive window means,
       :func:`drift_of_means`: the remaining change and the last window-to-window change both
       within ``tol`` of the signal's scale ``max(|estimate|, floor)``; changes of one sign within
       half of that count as scatter) is applied at check points every ``step`` (default: a
       quarter window) back from the run's end; a check point passes when every signal passes.
       The candidate part is the final run of passing check points, from two windows before
       its first one to the end: the first check point's last two window means agree with each
       other and with the extrapolated level, its first window may still hold the end of a
       transient (a step in the signal passes the test once it lies in that window).
    2. Over that part, the straight line through every signal's window means must change by at
       most ``tol`` of its scale over the part or over ``trend_span``, whichever is longer
       (:func:`window_trend`: a creep too slow for three windows to see, such as a slow speed
       ramp, is still a drift); where it does not, the part starts later, a step at a time.

    The signals are settled when the check at the end passes and the run of passes lasts at
    least ``hold`` (default: one window): a settled part is at least two windows and ``hold``
    long, and the run at least three windows and ``hold``. A transient that dies out (a speed ramp's inertia torque, a cage's free flight) ends
    before it; a drift that does not slow down never passes.

    Parameters
    ----------
    t
        Increasing times.
    integrals
        Per signal, its time integral from ``t[0]`` at the times ``t`` (window means are exact
        differences of it: :func:`cumulative_window_means`).
    window
        Window length (> 0): long enough that a periodic part of the signal (a roller pass)
        averages out in one window.
    tol
        Relative tolerance (> 0).
    floors
        Per signal, the smallest scale (a signal settling at zero is judged against it).
    trend_span
        The time over which a trend may change a signal by at most ``tol`` (default: the
        shortest settled part, two windows and ``hold``).
    time_unit
        (name, factor) of the times in ``reason``: ("ms", 1e3) for times in seconds shown in ms.
    """
    t = np.asarray(t, dtype=float)
    if not window > 0.0 or not tol > 0.0:
        raise ValueError(f"settled_window: window = {window!r}, tol = {tol!r}: expected both > 0")
    hold = window if hold is None else float(hold)
    step = 0.25 * window if step is None else float(step)
    floors = floors or {}
    t0, t_end = (float(t[0]), float(t[-1])) if len(t) else (0.0, 0.0)
    eps = 1e-9 * window
    unit, factor = time_unit

    def ft(x: float) -> str:
        return f"{x * factor:.4g}{' ' + unit if unit else ''}"
    need = max(3 * window, 2 * window + hold)
    trend_span = need if trend_span is None else float(trend_span)

    def test_at(tc: float) -> tuple[bool, dict[str, SteadyDrift], dict[str, float]]:
        edges = tc - window * np.arange(3, -1, -1)
        ok, drifts, scales = True, {}, {}
        for name, integral in integrals.items():
            m = cumulative_window_means(t, integral, edges)
            floor = floors.get(name, 0.0)
            d = drift_of_means(m, (edges[0], edges[-1]), resolution=0.5 * tol * max(abs(m[2]), floor))
            scale = max(abs(d.estimate), floor)
            drifts[name], scales[name] = d, scale
            ok = ok and d.steady(tol, scale)
        return ok, drifts, scales

    def result(settled: bool, start: float, reason: str, drifts: dict, scales: dict,
               trends: dict | None = None) -> SettledWindow:
        return SettledWindow(settled, start, t_end, window, tol, hold, drifts, scales, reason, trends or {})

    if len(t) < 2 or t_end - t0 < 3 * window - eps:
        return result(False, t_end, f"the run ({ft(t_end - t0)}) is shorter than the steady test needs (three "
                      f"windows of {ft(window)}; a settled part is at least {ft(need)})",
                      {n: None for n in integrals}, {n: 0.0 for n in integrals})
    ok_end, drifts, scales = test_at(t_end)
    since = None
    k = 0
    while True:
        tc = t_end - k * step
        if tc - 3 * window < t0 - eps or not (ok_end if k == 0 else test_at(tc)[0]):
            break
        since = tc
        k += 1
    if since is None:
        worst = max(drifts, key=lambda n: abs(drifts[n].remaining) / scales[n] if scales[n] > 0 else math.inf)
        d, sc = drifts[worst], scales[worst]
        rem = "does not slow down" if math.isinf(d.remaining) else f"{abs(d.remaining) / sc:.2%} still to come"
        return result(False, t_end, f"{worst} has not settled at the end: its means over the last three windows "
                      f"of {ft(window)} are {d.means[0]:.5g}, {d.means[1]:.5g}, {d.means[2]:.5g}: "
                      f"{abs(d.means[2] - d.means[1]) / sc:.2%} change in the last window, {rem} "
                      f"(tolerance {tol:.2%} of {sc:.4g})", drifts, scales)
    start = max(t0, since - 2 * window)
    while True:  # the creep across the part, a step later at a time
        span = max(t_end - start, trend_span)
        trends = {n: abs(window_trend(t, I, start, t_end, window)) / (t_end - start) * span / scales[n]
                  for n, I in integrals.items()}
        worst = max(trends, key=trends.get)
        if trends[worst] <= tol or t_end - start - step < need - eps:
            break
        start += step
    if trends[worst] > tol:
        return result(False, start, f"{worst} creeps by {trends[worst]:.2%} over {ft(span)} (its trend across "
                      f"{ft(start)}-{ft(t_end)}; tolerance {tol:.2%}): not settled", drifts, scales, trends)
    if t_end - start < need - eps:
        return result(False, start, f"steady only from {ft(start)} to {ft(t_end)} ({ft(t_end - start)}); the "
                      f"test needs {ft(need)} (two windows of {ft(window)} and a hold of {ft(hold)})",
                      drifts, scales, trends)
    return result(True, start, f"every signal within {tol:.2%} over three windows of {ft(window)} at every check "
                  f"point from {ft(start + 2 * window)} to {ft(t_end)}, and its trend across "
                  f"{ft(start)}-{ft(t_end)} within it over {ft(span)}", drifts, scales, trends)
