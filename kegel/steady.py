"""When is a transient torque statistically steady, and how far is it from its steady value?

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
from dataclasses import dataclass

import numpy as np

__all__ = ["SteadyDrift", "SteadyTest", "window_means", "steady_drift", "first_steady_time"]


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


def steady_drift(t: np.ndarray, y: np.ndarray, window: float) -> SteadyDrift | None:
    """The steady-value estimate of a transient series from its last three windows (see the
    module text), or None when the series is shorter than three windows."""
    m = window_means(t, y, window, 3)
    if m is None:
        return None
    d1, d2 = m[1] - m[0], m[2] - m[1]
    q = d2 / d1 if d1 * d2 > 0.0 else None
    if q is not None and q < 1.0:  # geometric approach: the tail of the series of changes
        remaining = d2 * q / (1.0 - q)
        estimate = float(m[2] + remaining)
    else:  # no trend to extrapolate: the estimate is the last mean
        remaining = math.copysign(math.inf, d2) if q is not None else max(abs(d1), abs(d2))
        estimate = float(m[2])
    t_end = float(t[-1])
    return SteadyDrift(means=(float(m[0]), float(m[1]), float(m[2])), estimate=estimate,
                       remaining=float(remaining), window=(t_end - 3 * window, t_end))


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
