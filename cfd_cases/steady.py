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

__all__ = ["SteadyDrift", "window_means", "steady_drift"]


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
        ``tol * scale``."""
        d2 = self.means[2] - self.means[1]
        return abs(self.remaining) <= tol * scale and abs(d2) <= tol * scale


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
