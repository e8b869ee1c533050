"""Statistically steady torque of a transient run: window means and the drift estimate."""

from __future__ import annotations

import json
import math
import re
import shutil
import time
from pathlib import Path

import numpy as np
import pytest

from kegel.cfd_cases.steady import first_steady_time, steady_drift, window_means


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


def test_replayed_steady_test_stops_where_the_monitor_would():
    # y = 5 + 2 exp(-t / tau): the first sample time at which the three-window test passes
    tau, w = 0.7, 0.5
    t = _uneven_times(8.0)
    y = 5.0 + 2.0 * np.exp(-t / tau)
    ts = first_steady_time(t, y, w, 0.02)
    assert ts is not None and 1.5 < ts < 8.0
    k = np.searchsorted(t, ts)
    assert steady_drift(t[:k + 1], y[:k + 1], w).steady(0.02, abs(steady_drift(t[:k + 1], y[:k + 1], w).estimate))
    assert not steady_drift(t[:k], y[:k], w).steady(0.02, abs(steady_drift(t[:k], y[:k], w).estimate))
    # no verdict before the minimum time, and only at the times checked
    assert first_steady_time(t, y, w, 0.02, min_time=6.0) >= 6.0
    checks = np.arange(0.0, 8.0, 1.0)
    assert first_steady_time(t, y, w, 0.02, check_times=checks) == pytest.approx(
        t[np.searchsorted(t, math.ceil(ts), side="right") - 1])
    # hold: the test must pass at every check point over a span; a pass that ends does not count
    ts_hold = first_steady_time(t, y, w, 0.02, check_times=checks, hold=2.0)
    assert ts_hold == pytest.approx(t[np.searchsorted(t, math.ceil(ts) + 2.0, side="right") - 1])
    assert math.ceil(ts) == 3  # passes at the check points 3 and 4 s; a step at 4.5 s breaks it
    jump = np.where(t < 4.5, y, y + 3.0)
    assert first_steady_time(t, jump, w, 0.02, check_times=checks, hold=1.0) == pytest.approx(
        t[np.searchsorted(t, 4.0, side="right") - 1])
    assert first_steady_time(t, jump, w, 0.02, check_times=checks, hold=1.5) is None
    # a tolerance of 0 never stops (a reference run); a creep never does either
    assert first_steady_time(t, y, w, 0.0) is None
    assert first_steady_time(t, 100.0 + 0.5 * t, w, 0.02) is None


def _write_forces(folder, times, value):
    folder.mkdir(parents=True)
    rows = "".join(f"{t:.10g} ({value} 0 {value}) (0 0 0) ({value} 0 {value})\n" for t in times)
    for name in ("force.dat", "moment.dat"):
        (folder / name).write_text("# Time total pressure viscous\n" + rows)


def test_force_series_of_a_resumed_run_replace_what_followed_the_restart_time(tmp_path):
    from kegel.cfd_cases.forces import read_forces

    root = Path(tmp_path) / "postProcessing" / "forces_x"
    # the first run wrote its fields at 0.5 but went on to 0.77 before it was stopped
    _write_forces(root / "0", np.arange(0.01, 0.775, 0.01), 1.0)
    _write_forces(root / "0.5", np.arange(0.5, 1.0, 0.013), 2.0)
    f = read_forces(tmp_path, "forces_x")
    assert np.all(np.diff(f.time) > 0)
    assert np.all(f.moment_total[f.time <= 0.49, 2] == 1.0)
    assert np.all(f.moment_total[f.time >= 0.5, 2] == 2.0)
    assert f.time[-1] == pytest.approx(0.994)


def test_a_run_restarted_from_the_same_time_replaces_the_earlier_file_beside_it(tmp_path):
    """A run stopped before it wrote any time restarts from 0; OpenFOAM then writes
    moment_0.dat beside the stopped run's moment.dat in postProcessing/<name>/0. The reader
    read moment.dat alone: the 23 iterations of the stopped run instead of the new run's 620
    (the 0.04 D_w, 6-cell gap case, 2026-11-26)."""
    import os

    from kegel.cfd_cases.forces import read_forces

    root = Path(tmp_path) / "postProcessing" / "forces_x"
    _write_forces(root / "0", np.arange(1, 24), 1.0)        # the stopped run: iterations 1-23
    rows = "".join(f"{t:.10g} (2 0 2) (0 0 0) (2 0 2)\n" for t in np.arange(1, 621))
    for name in ("force_0.dat", "moment_0.dat"):
        (root / "0" / name).write_text("# Time total pressure viscous\n" + rows)
        os.utime(root / "0" / name, ns=(2_000_000_000_000_000_000, 2_000_000_000_000_000_000))
    f = read_forces(tmp_path, "forces_x")
    assert len(f.time) == 620 and f.time[-1] == 620
    assert np.all(f.moment_total[:, 2] == 2.0)
    # and a later restart from a written time still replaces what followed it
    _write_forces(root / "600", np.arange(601, 700), 3.0)
    f = read_forces(tmp_path, "forces_x")
    assert f.time[-1] == 699 and np.all(f.moment_total[f.time > 600, 2] == 3.0)
    assert np.all(f.moment_total[f.time <= 600, 2] == 2.0)


def _fake_oil_bath(tmp_path, t_end: float):
    """A case folder with force series whose loss torque falls to a false plateau of 1.0 N m,
    holds it, then rises to 1.3 N m as in the 32208 start-up (inner ring 10 rad/s, cage 4 rad/s:
    windows of half a cage revolution, 0.785 s, and the minimum of 5 cage revolutions, 7.85 s, from
    rest)."""
    t = np.arange(0.005, t_end, 0.005)
    loss = 1.0 + 2.0 * np.exp(-t / 0.05) + 0.3 * np.clip((t - 3.2) / 0.8, 0.0, 1.0)
    root = Path(tmp_path) / "postProcessing"
    for name, moment in (("inner_ring", -loss), ("shaft", 0 * loss), ("cage", 0 * loss)):
        folder = root / f"forces_{name}" / "0"
        folder.mkdir(parents=True)
        rows = "".join(f"{a:.10g} (0 0 0) (0 0 0) (0 0 0)\n" for a in t)
        (folder / "force.dat").write_text("# Time total pressure viscous\n" + rows)
        rows = "".join(f"{a:.10g} (0 0 {m:.10g}) (0 0 0) (0 0 {m:.10g})\n" for a, m in zip(t, moment))
        (folder / "moment.dat").write_text("# Time total pressure viscous\n" + rows)
    return {"kinematics": {"inner_ring_rad_s": 10.0, "cage_rad_s": 4.0, "roller_spin_rad_s": 0.0}, "rollers": []}


@pytest.mark.parametrize("t_end, min_time, steady", [(2.6, 0.0, True), (2.6, "rest", False), (7.5, "rest", False),
                                                     (9.0, "rest", True)])
def test_a_false_plateau_early_in_the_start_up_does_not_stop_the_run(tmp_path, t_end, min_time, steady):
    from kegel.cfd_cases.run import _SteadyMonitor, steady_min_time_s, steady_window_s

    meta = _fake_oil_bath(tmp_path, t_end)
    window = steady_window_s(4.0)
    assert window == pytest.approx(math.pi / 4.0) and steady_min_time_s(4.0) == pytest.approx(10 * math.pi / 4.0)
    m = _SteadyMonitor(tmp_path, False, window, 0.02, meta,
                       min_time_s=steady_min_time_s(4.0) if min_time == "rest" else min_time)
    m.every_s = 0.0
    assert m(None) is steady
    if steady:  # the first check point that passes, and the mean of the window before it: the
        # plateau (no minimum time), or the level after the rise
        lo, hi = m.window  # hi: the last sample (every 5 ms) up to the passing check point
        assert hi - lo == pytest.approx(window)
        assert m.min_time_s - 0.005 <= hi <= t_end and hi == pytest.approx(round(hi / (window / 20)) * window / 20, abs=0.006)
        tt = np.linspace(lo, hi, 2001)
        mean = float(np.mean(1.0 + 2.0 * np.exp(-tt / 0.05) + 0.3 * np.clip((tt - 3.2) / 0.8, 0.0, 1.0)))
        assert mean == pytest.approx(1.0 if min_time == 0.0 else 1.3, rel=0.02)
        # the next call looks only at check points after the ones already tested
        assert m.checked_until == pytest.approx(t_end, abs=0.006)


def test_where_a_run_stops_does_not_depend_on_when_the_forces_are_read(tmp_path):
    # A monitor that reads the series now and then (a busy or a quiet machine) stops at the same
    # check point, with the same window, as one that reads it once at the end.
    from kegel.cfd_cases.run import _SteadyMonitor, steady_min_time_s, steady_window_s

    window, t_min = steady_window_s(4.0), steady_min_time_s(4.0)
    once = _SteadyMonitor(tmp_path / "once", False, window, 0.02, _fake_oil_bath(tmp_path / "once", 9.0),
                          min_time_s=t_min)
    once.every_s = 0.0
    assert once(None)
    for reads in ([8.0, 9.0], [4.8, 7.9, 8.1, 8.3, 9.0], [2.0, 8.2, 9.0]):
        m = _SteadyMonitor(tmp_path, False, window, 0.02, None, min_time_s=t_min)
        m.every_s = 0.0
        for k, t_read in enumerate(reads):
            m.case = tmp_path / f"{len(reads)}_{k}"
            m.meta = _fake_oil_bath(m.case, t_read)
            if m(None):
                break
        assert m.window == pytest.approx(once.window, abs=1e-12)


def test_time_from_rest_counts_the_runs_a_case_was_started_from():
    from kegel.cfd_cases.run import time_from_rest_at_start_s

    assert time_from_rest_at_start_s({"initial_state": None}) == 0.0
    assert time_from_rest_at_start_s({}) == 0.0
    # a case made before time_from_rest_s was recorded: its source's time
    assert time_from_rest_at_start_s({"initial_state": {"source_time_s": 0.21}}) == 0.21
    assert time_from_rest_at_start_s({"initial_state": {"source_time_s": 0.11, "time_from_rest_s": 0.32}}) == 0.32


def _written_times(case: Path, names: list[str], where: str = "") -> None:
    for name in names:
        d = case / where / name
        d.mkdir(parents=True)
        for f in ("U", "alpha.oil"):  # a whole OpenFOAM file ends with its divider
            (d / f).write_text("fake\n// " + "*" * 73 + " //\n")


def test_a_finer_run_maps_the_write_before_the_steady_stop_not_the_last_state(tmp_path):
    # The solver runs on past the passing check point until the runner reads the forces again
    # (how far depends on the machine); the regular write before the point does not.
    import json

    from kegel.cfd_cases.run import _restart_state, last_write_at_or_before, mapping_source_time

    case = tmp_path / "start"
    _written_times(case, ["0.24", "0.27", "0.3", "0.31012345"])
    assert last_write_at_or_before(sorted(case.iterdir(), key=lambda d: float(d.name)), 0.30647164).name == "0.3"
    assert last_write_at_or_before([case / "0.24"], 0.2) is None
    # where the machine stopped the solver changes nothing
    assert _restart_state(case, 1, 0.30647164) == 0.3
    _written_times(case, ["0.3171"])
    assert _restart_state(case, 1, 0.30647164) == 0.3
    # a write exactly at the stop point counts (written to 8 digits)
    assert _restart_state(case, 1, 0.27000000001) == 0.27
    # without results (a run stopped by its budget or end time) the latest time is mapped
    assert mapping_source_time(case) == ("0.3171", "its latest time")
    # a reconstructed time cut by a killed reconstructPar is passed over, and the reason says so
    _written_times(case, ["0.32"])
    (case / "0.32" / "U").write_text("fake\n(1 2")
    name, why = mapping_source_time(case)
    assert name == "0.3171" and "latest whole time" in why and "0.32/U is cut short" in why
    (case / "0.33").mkdir()  # a time without the fields (post-processing only) is passed over silently
    assert mapping_source_time(case)[0] == "0.3171"
    for d in ("0.32", "0.33"):
        shutil.rmtree(case / d)
    (case / "results.json").write_text(json.dumps({"restart_state_time_s": 0.3}))
    assert mapping_source_time(case) == ("0.3", "its last regular write before the steady stop")
    (case / "results.json").write_text(json.dumps({"restart_state_time_s": 0.33}))
    name, why = mapping_source_time(case)  # purged: the latest time, and the reason says so
    assert name == "0.3171" and "0.33 s" in why and "gone" in why
    from kegel.cfd_cases.foam import FoamError

    (case / "results.json").write_text(json.dumps({"restart_state_time_s": "0.3"}))
    with pytest.raises(FoamError, match=r"results\.json: restart_state_time_s = '0\.3'; expected a finite time"):
        mapping_source_time(case)
    # a parallel run's writes are in processor0 (reconstructed there when missing: needs OpenFOAM)
    par = tmp_path / "par"
    _written_times(par, ["0.27", "0.3", "0.31"], "processor0")
    _written_times(par, ["0.3"])  # already reconstructed: nothing to run
    assert _restart_state(par, 2, 0.305) == 0.3
    assert _restart_state(par, 2, 0.2) is None


def _stand_in_solver(tmp_path, monkeypatch, body: str) -> Path:
    bindir = tmp_path / "bin"
    bindir.mkdir()
    exe = bindir / "interFoam"
    exe.write_text("#!/bin/sh\n" + body)
    exe.chmod(0o755)
    monkeypatch.setenv("KEGEL_OPENFOAM_BIN", str(bindir))
    case = tmp_path / "case"
    (case / "system").mkdir(parents=True)
    (case / "system" / "controlDict").write_text("stopAt          endTime;\nendTime         100;\n")
    return case


#: Steps forever; writes "written" and stops once controlDict says writeNow (as runTimeModifiable does).
_OBEDIENT = ("i=0\nwhile true; do\n  i=$((i+1))\n  echo \"Time = $i\"\n"
             "  if grep -q writeNow \"$2/system/controlDict\"; then touch \"$2/written\"; echo End; exit 0; fi\n"
             "  sleep 0.05\ndone\n")


@pytest.mark.parametrize("obedient", [True, False])
def test_ctrl_c_stops_the_solver_and_says_how_to_resume(tmp_path, monkeypatch, obedient):
    """Ctrl-C reaches only kegel (the solver has its own session): kegel asks the solver to write
    and stop, and kills it when it does not within the grace time."""
    import kegel.cfd_cases.foam as foam

    body = _OBEDIENT if obedient else _OBEDIENT.replace("grep -q writeNow", "false")
    case = _stand_in_solver(tmp_path, monkeypatch, body)
    monkeypatch.setattr(foam, "STOP_GRACE_S", 1.0)

    def ctrl_c(st, eta):
        if st.steps >= 3:
            raise KeyboardInterrupt

    t0 = time.monotonic()
    with pytest.raises(foam.FoamInterrupted, match="resumes the run") as err:
        foam.run_solver(case, "interFoam", n_procs=1, end_time=100.0, progress=ctrl_c)
    assert time.monotonic() - t0 < 10.0
    assert "stopAt          writeNow;" in (case / "system" / "controlDict").read_text()
    assert (case / "written").exists() is obedient
    assert ("wrote its state" in str(err.value)) is obedient


def test_a_slow_solver_gets_time_to_write_before_it_is_killed(tmp_path, monkeypatch):
    """The grace after Ctrl-C grows with the solver's slowest step: a solver whose steps take
    0.6 s and whose write takes 1 s is not killed after a grace of 0.3 s (a 4.6 M-cell sector,
    50 s a step, was killed while writing after 60 s: its latest write cut short)."""
    import kegel.cfd_cases.foam as foam

    slow = ("i=0\nwhile true; do\n  i=$((i+1))\n  echo \"Time = $i\"\n"
            "  if grep -q writeNow \"$2/system/controlDict\"; then sleep 1; touch \"$2/written\"; echo End; exit 0; fi\n"
            "  sleep 0.6\ndone\n")
    case = _stand_in_solver(tmp_path, monkeypatch, slow)
    monkeypatch.setattr(foam, "STOP_GRACE_S", 0.3)

    def ctrl_c(st, eta):
        if st.steps >= 3:
            raise KeyboardInterrupt

    with pytest.raises(foam.FoamInterrupted, match="wrote its state"):
        foam.run_solver(case, "interFoam", n_procs=1, end_time=100.0, progress=ctrl_c)
    assert (case / "written").exists()


def test_sigterm_stops_the_solver_as_ctrl_c_does(tmp_path, monkeypatch):
    """``kill`` (SIGTERM) on kegel while a solver runs: the solver, in its own session, ran on
    orphaned after its parent died (a 4.6 M-cell run kept both cores). It is now stopped as on
    Ctrl-C (asked to write its state), and kegel's own SIGTERM handler is given back after."""
    import os
    import signal

    import kegel.cfd_cases.foam as foam

    case = _stand_in_solver(tmp_path, monkeypatch, _OBEDIENT)
    before = signal.getsignal(signal.SIGTERM)

    def term(st, eta):
        if st.steps == 3:
            os.kill(os.getpid(), signal.SIGTERM)

    with pytest.raises(foam.FoamInterrupted, match="wrote its state"):
        foam.run_solver(case, "interFoam", n_procs=1, end_time=100.0, progress=term)
    assert (case / "written").exists()
    assert signal.getsignal(signal.SIGTERM) is before


def test_eta_of_a_resumed_run_counts_from_where_it_resumed(tmp_path, monkeypatch):
    """A run resumed at t = 10 that advances 0.1 per step, 20 steps per second, to an end time
    of 11: 0.2 s to go at t = 10.6. (Counting from t = 0, the ETA was a hundredth of that.)"""
    from kegel.cfd_cases.foam import run_solver

    case = _stand_in_solver(tmp_path, monkeypatch,
                            "for i in $(seq 1 6); do\n  echo \"Time = 10.$i\"\n  sleep 0.05\ndone\necho End\n")
    seen: list[tuple[float, float]] = []
    run_solver(case, "interFoam", n_procs=1, end_time=11.0, progress=lambda st, eta: seen.append((st.time, eta)))
    assert [t for t, _ in seen] == pytest.approx([10.2, 10.3, 10.4, 10.5, 10.6])
    t, eta = seen[-1]
    assert eta == pytest.approx((11.0 - t) / 2.0, rel=0.5)  # 0.1 per 0.05 s: 2 per second


def test_progress_line_says_what_its_eta_is_to():
    # The ETA runs to the end time; a steady torque stops the run sooner.
    import io

    from kegel.cfd_cases.foam import LogState
    from kegel.cfd_cases.run import _Progress

    out = io.StringIO()
    st = LogState(time=0.25, delta_t=1e-4, courant_max=3.0, residuals={"Ux": 2e-3}, steps=100)
    _Progress(stream=out, end="t = 0.6 s")(st, 1800.0)
    line = out.getvalue()
    assert "t = 0.25 s  step 100" in line and "Ux 2.0e-03" in line and line.rstrip().endswith("ETA to t = 0.6 s 30.0 min")
    out = io.StringIO()
    _Progress(stream=out)(st, math.nan)
    assert out.getvalue().rstrip().endswith("ETA ?")


def test_progress_line_of_a_steady_run_tells_how_far_the_steady_test_is():
    """issue 20: "ETA to iteration 2000 30.8 min" on a run that stopped at 262. With a steady
    test, the line says where the test stands and gives the end time only as the latest end."""
    import io
    from types import SimpleNamespace

    from kegel.cfd_cases.foam import LogState
    from kegel.cfd_cases.run import _Progress

    out = io.StringIO()
    st = LogState(time=150.0, delta_t=math.nan, courant_max=math.nan, residuals={"Ux": 2e-3}, steps=150)
    monitor = SimpleNamespace(tol=0.02, status="inner ring -40.7 mN m, torque spread 3.2 x the steady limit")
    _Progress(stream=out, end="iteration 2000", monitor=monitor)(st, 1800.0)
    line = out.getvalue().rstrip()
    assert "torque spread 3.2 x the steady limit" in line
    assert line.endswith("at the latest to iteration 2000, ETA 30.0 min") and "  ETA to" not in line


def _flooded_monitor(monkeypatch, tmp_path, inner, outer, n=800, roller_tangential_N=None, housing=None):
    """A flooded monitor over synthetic force files of ``n`` iterations: the oil takes ``inner(it)`` N m
    from the inner ring, the outer ring takes ``outer(it)``, the housing ``housing(it)`` (default
    nothing), shaft, cage and the one roller take nothing; the shaft turns at 100 rad/s, cage and
    roller stand (cage frame)."""
    import numpy as np
    from types import SimpleNamespace

    import kegel.cfd_cases.run as run

    it = np.arange(1, n + 1, dtype=float)

    def body(mz):
        s = SimpleNamespace(time=it, moment_total=np.zeros((n, 3)), force_total=np.zeros((n, 3)))
        s.moment_total[:, 2] = mz
        return s

    zero = np.zeros(n)
    bodies = {"forces_inner_ring": body(inner(it)), "forces_shaft": body(zero), "forces_outer_ring": body(outer(it)),
              "forces_housing": body(zero if housing is None else housing(it)), "forces_cage": body(zero),
              "forces_roller_0": body(zero)}
    if roller_tangential_N is not None:  # a force along +y on the roller at x = 0.03 m
        bodies["forces_roller_0"].force_total[:, 1] = roller_tangential_N(it)
    monkeypatch.setattr(run, "read_forces", lambda case, name: bodies[name])
    meta = {"rollers": [{"name": "roller_0", "centre_m": [0.03, 0.0, 0.0], "axis": [0.0, 0.0, 1.0]}],
            "kinematics": {"inner_ring_rad_s": 100.0, "cage_rad_s": 0.0, "roller_spin_rad_s": 0.0}}
    mon = run._SteadyMonitor(tmp_path, True, 1.0, 0.02, meta)
    mon.last_check = -1e9
    return mon


def test_the_progress_line_reports_the_balance_of_the_wall_torques(tmp_path, monkeypatch):
    """The balance is a discretisation error (-14 % on the whole bearing's tiny mesh), reported,
    not a stop criterion: steady torques that leave -22.5 % of the drive unbalanced are steady."""
    mon = _flooded_monitor(monkeypatch, tmp_path, lambda n: -0.04 + 0 * n, lambda n: 0.031 + 0 * n)
    assert mon(None) is True
    assert "balance -22.5 %" in mon.status


def test_rollers_still_spinning_the_oil_up_are_not_steady(tmp_path, monkeypatch):
    """Flat ring and cage torques passed the g = 0.02 D_w gap-study case at iteration 264 while
    the rollers' orbit drag still changed (balance -23 % -> -7 %): the rollers' moment about the
    axis is tested too."""
    import numpy as np

    mon = _flooded_monitor(monkeypatch, tmp_path, lambda n: -0.04 + 0 * n, lambda n: 0.04 + 0 * n,
                           roller_tangential_N=lambda n: 0.3 * np.exp(-n / 400.0))
    assert mon(None) is False


def test_side_chambers_still_spinning_up_are_not_steady(tmp_path, monkeypatch):
    """The housing's torque (the side chambers' spin-up) is the slowest part of a flooded run: from
    oil at rest the 6-cell sectors' housing still moved by 5 % of the drive per 100 iterations at
    iteration 1000 while the loss and the rings held (benchmarks/cfd_flooded_convergence.py). A
    resting wall's torque still moving is not steady; once it settles, the same run is."""
    import numpy as np

    inner, outer = (lambda n: -0.04 + 0 * n), (lambda n: 0.02 + 0 * n)
    creeping = _flooded_monitor(monkeypatch, tmp_path, inner, outer, n=1000,
                                housing=lambda n: 0.02 * (1 - np.exp(-n / 600.0)))
    assert creeping(None) is False
    settled = _flooded_monitor(monkeypatch, tmp_path, inner, outer, n=1000,
                               housing=lambda n: 0.02 * (1 - np.exp(-n / 60.0)))
    assert settled(None) is True


def test_an_oscillation_that_averages_out_is_steady_a_creep_is_not(tmp_path, monkeypatch):
    """SIMPLE on the sector makes the outer ring's torque oscillate from iteration to iteration
    (about ±5 %); its window means hold, so the run is steady, with its progress line saying
    how far the test is. A creep of the drive torque that does not slow down is not steady,
    however flat each window looks."""
    import numpy as np

    wobble = _flooded_monitor(monkeypatch, tmp_path, lambda n: -0.04 + 0 * n,
                              lambda n: 0.04 * (1 + 0.05 * np.sin(2.1 * n)))
    assert wobble(None) is True
    w0, w1 = wobble.window  # a window of 100 iterations, once the test has held for 100 more
    assert w1 - w0 == 100.0 and 400.0 <= w1 <= 500.0
    assert "loss 40 mN m" in wobble.status
    sector = _flooded_monitor(monkeypatch, tmp_path, lambda n: -0.04 + 0 * n, lambda n: 0.04 + 0 * n)
    sector.meta["geometry"] = {"copies": 17}  # a one-pitch sector: the progress line gives the bearing's loss
    assert sector(None) is True and "loss 680 mN m" in sector.status
    creep = _flooded_monitor(monkeypatch, tmp_path, lambda n: -0.04 * (1 + 2e-4 * n), lambda n: 0.04 * (1 + 2e-4 * n))
    assert creep(None) is False
    change = re.search(r"change (\S+) x the steady limit", creep.status).group(1)
    assert float(change) > 1.0  # a linear creep: its remaining change is unbounded


def _foam_file(path: Path, body: str = "internalField uniform 0;", whole: bool = True) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    text = f"FoamFile {{ object {path.name}; }}\n{body}\n\n\n// {'*' * 73} //\n"
    path.write_text(text if whole else text[: len(text) // 2])


def test_writes_cut_by_a_kill_are_set_aside_and_nothing_is_deleted(tmp_path):
    """A resumed run goes on from the last whole write: a time cut on one processor (a file
    without OpenFOAM's closing line), lacking on one, or lacking a field of 0 is moved aside in
    every processor folder and the case; a reconstructed time cut in the case alone is moved
    aside there only (reconstructPar makes it again); whole writes stay."""
    from kegel.cfd_cases.foam import cut_write, set_aside_cut_writes, time_dirs

    case = Path(tmp_path)
    for root in (case, case / "processor0", case / "processor1"):
        for f in ("U", "p"):
            _foam_file(root / "0" / f)
        for t in ("100", "200", "300", "400"):
            for f in ("U", "p", "phi", "uniform/time"):
                _foam_file(root / t / f)
    _foam_file(case / "processor1" / "200" / "U", whole=False)         # killed while writing U
    (case / "processor0" / "300" / "p").unlink()                         # killed before p
    _foam_file(case / "400" / "p", whole=False)                          # reconstructPar killed
    (case / "processor1" / "500" / "U").parent.mkdir()                   # processor1 never reached 500
    for f in ("U", "p"):
        _foam_file(case / "processor0" / "500" / f)
    _foam_file(case / "processor0" / "200.cut" / "U")                    # an earlier kill's folder
    _foam_file(case / "0" / "V")                                         # a post-processing leftover
    _foam_file(case / "0" / "alpha.oil.orig")                            # setFields' original
    kept = (case / "processor1" / "200" / "U").read_bytes()
    said: list[str] = []
    moved = set_aside_cut_writes(case, log=said.append)
    assert [t.name for t in time_dirs(case / "processor0")] == ["100", "400"]
    assert [t.name for t in time_dirs(case / "processor1")] == ["100", "400"]
    assert [t.name for t in time_dirs(case)] == ["100"]
    assert (case / "processor1" / "200.cut" / "U").read_bytes() == kept  # moved, not deleted
    assert {p.relative_to(case).as_posix() for p in moved} == {
        "processor0/200.cut-2", "processor1/200.cut", "200.cut", "processor0/300.cut",
        "processor1/300.cut", "300.cut", "processor0/500.cut", "processor1/500.cut", "400.cut"}
    assert len(said) == 4 and "processor1/200/U is cut short" in said[0] and "lacks p" in said[1]
    assert cut_write(case / "processor0" / "100", ["U", "p"]) is None
    assert set_aside_cut_writes(case, log=said.append) == []  # nothing left to set aside


def test_a_force_line_cut_by_a_kill_is_dropped_and_a_bad_whole_line_is_an_error(tmp_path):
    from kegel.cfd_cases.foam import FoamError
    from kegel.cfd_cases.forces import read_forces

    root = Path(tmp_path) / "postProcessing" / "forces_x"
    _write_forces(root / "0", np.arange(1, 11), 1.0)
    for name in ("force.dat", "moment.dat"):
        f = root / "0" / name
        f.write_text(f.read_text() + "11 (1 0 1) (0 0")  # the solver was killed mid-line
    f = read_forces(tmp_path, "forces_x")
    assert f.time[-1] == 10 and len(f.time) == 10
    for name in ("force.dat", "moment.dat"):
        (root / "0" / name).write_text("# Time total\n1 (1 0 1) (0 0 0) (1 0 1)\n2 (1 0 1) (0 0\n")
    with pytest.raises(FoamError, match="expected 10 columns"):
        read_forces(tmp_path, "forces_x")


def _stop_on_recorded_run(stem: str, **rule):
    """Replay a steady rule (the runner's, or the settings given) on a recorded oil-bath loss
    series (benchmarks/cfd_oil_bath_stop_rule.py writes it: the run from rest to 10.5 cage
    revolutions without a stop). Returns the stop time in cage revolutions, the last window's
    mean there and the long-time mean (the last three cage revolutions), in N m."""
    from kegel.cfd_cases.run import replay_oil_bath_steady_test

    root = Path(__file__).resolve().parents[2] / "benchmarks" / "results"
    rev = json.loads((root / f"{stem}.json").read_text())["cage_revolution_s"]
    data = np.loadtxt(root / f"{stem}_series.csv", delimiter=",", skiprows=2)
    t, loss = data[:, 0], data[:, 1]
    reference = float(window_means(t, loss, 3 * rev, 1)[0])
    stop = replay_oil_bath_steady_test(t, loss, 2 * math.pi / rev, **rule)
    if stop is None:
        return None, None, reference
    return stop[0] / rev, stop[1], reference


def test_the_runners_oil_bath_rule_stops_near_the_long_time_mean_of_a_recorded_run():
    """The shaft-centre 32208 at 2000 rpm with the real rollers, run to 10.5 cage revolutions: the
    loss holds on a plateau from 2.0 to 3.5 revolutions, rises by 14 % up to 5 and then stays
    within 30.7-31.6 mN m (docs/cfd.md, "Oil bath: how steady"). The runner's rule must stop after
    the rise and within 2 % of the long-time mean (it gave +0.2 %); the rule it replaced stopped on
    the plateau, 11.8 % low. (This run chose the rule; the next test checks it at another speed.)"""
    stop_rev, last, reference = _stop_on_recorded_run("cfd_oil_bath_stop_rule")  # the runner's rule
    assert reference == pytest.approx(30.95e-3, rel=1e-3)
    assert stop_rev is not None and stop_rev >= 5.0
    assert last == pytest.approx(reference, rel=0.02)
    stop_old, last_old, _ = _stop_on_recorded_run("cfd_oil_bath_stop_rule", window_cage_revolutions=0.5, tol=0.02,
                                                  hold_windows=0.0, min_cage_revolutions=3.0)
    assert stop_old < 3.1 and last_old / reference - 1 == pytest.approx(-0.118, abs=0.005)


def test_the_runners_oil_bath_rule_on_a_run_it_was_not_chosen_on():
    """The check of the rule on another point: the shaft-centre 32208 at 4000 rpm with the real
    rollers, stopped by the runner's rule (the remade point) and run on to 10.5 cage revolutions
    (docs/cfd.md, "Oil bath: how steady"). The tolerance, 3 %, was set before the run: the 2 % of
    the chosen run plus 1 % for a point the rule was not chosen on."""
    stop_rev, last, reference = _stop_on_recorded_run("cfd_oil_bath_stop_rule_4000rpm")  # the runner's rule
    assert reference == pytest.approx(69.65e-3, rel=1e-3)
    assert stop_rev is not None and stop_rev >= 5.0
    assert last == pytest.approx(reference, rel=0.03)  # measured -1.8 %
    # the rule it replaced stops in the transient here too, 7.4 % low
    stop_old, last_old, _ = _stop_on_recorded_run("cfd_oil_bath_stop_rule_4000rpm", window_cage_revolutions=0.5,
                                                  tol=0.02, hold_windows=0.0, min_cage_revolutions=3.0)
    assert stop_old < 3.1 and last_old / reference - 1 == pytest.approx(-0.074, abs=0.005)


def _prose(name: str) -> str:
    """A Markdown file of the repository with its line breaks and runs of spaces folded to one
    space, so that a quoted figure is found wherever the text wraps."""
    return " ".join((Path(__file__).resolve().parents[2] / name).read_text().split())


#: The moving-mesh checks over the levelled stretch (docs/cfd.md, "Oil bath: frozen rotor or
#: moving mesh"; benchmarks/cfd_oil_bath_moving_mesh.py): speed -> the stored JSON.
MOVING_MESH_LEVELLED = {2000: "cfd_oil_bath_moving_mesh_levelled.json",
                        4000: "cfd_oil_bath_moving_mesh_levelled_4000rpm.json"}


@pytest.mark.parametrize("rpm", sorted(MOVING_MESH_LEVELLED))
def test_the_moving_mesh_figures_in_the_docs_are_the_stored_checks(rpm):
    """The moving mesh against the frozen rotor run on, released at five cage revolutions: the
    figures docs/cfd.md and the README quote (second-revolution losses and their difference, the
    quarter-revolution range, both balances, the rollers' orbit drag) are those of the stored
    JSON, and the physics they are quoted for holds: losses within 1 % over the second
    revolution, quarters within 3.5 %, the moving mesh's balance under half the frozen rotor's."""
    root = Path(__file__).resolve().parents[2]
    d = json.loads((root / "benchmarks" / "results" / MOVING_MESH_LEVELLED[rpm]).read_text())
    assert not d["partial"] and f", {rpm} rpm," in d["point"]
    b = d["last_revolution_by_body"]
    assert b["from_s"] == pytest.approx(d["cage_revolution_s"], rel=0.01)  # the second revolution
    moving, frozen = (1e3 * b[k]["loss_torque_at_shaft"]["mean_Nm"] for k in ("moving_mesh", "frozen_run_on"))
    diff = d["moving_vs_frozen_run_on_last_revolution"]
    quarters = [r["moving_vs_frozen_run_on"] for r in d["by_quarter_cage_revolution"]]
    bal = {k: b["balance"][k]["relative_to_drive_torque"] for k in ("moving_mesh", "frozen_run_on")}
    orbit = {k: 1e3 * b[k]["rollers_about_axis"]["mean_Nm"] for k in ("moving_mesh", "frozen_run_on")}
    assert abs(diff) < 0.01 and max(map(abs, quarters)) < 0.035
    assert abs(bal["moving_mesh"]) < 0.5 * abs(bal["frozen_run_on"])
    docs, readme = _prose("docs/cfd.md"), _prose("README.md")
    quoted = [f"{moving:.2f} against", f"{frozen:.2f}", f"{100 * diff:.1f} %",
              f"{100 * min(quarters):.1f}", f"{100 * max(quarters):+.1f} %",
              f"+{100 * bal['moving_mesh']:.1f} %", f"+{100 * bal['frozen_run_on']:.1f} %",
              f"{orbit['moving_mesh']:.2f} against {orbit['frozen_run_on']:.2f} mN m"]
    for s in quoted:
        assert s in docs, (rpm, s)
    for s in (f"+{100 * bal['moving_mesh']:.1f}", f"+{100 * bal['frozen_run_on']:.1f} %"):
        assert s in readme, (rpm, s)


@pytest.mark.parametrize("rpm", [2000, 4000])
def test_the_oil_bath_mesh_figures_are_the_stored_runs(rpm):
    """The oil bath on the small mesh against the shipped tiny run (shaft centre, real rollers;
    benchmarks/cfd_oil_bath_mesh.py): the JSON is what the two stored runs say, the small run is
    the finer mesh started from the tiny state and stopped by the same rule, and the figures
    docs/cfd.md and the README quote are the JSON's."""
    root = Path(__file__).resolve().parents[2]
    res = root / "benchmarks" / "results"
    row = next(r for r in json.loads((res / "cfd_oil_bath_mesh.json").read_text())["rows"] if r["speed_rpm"] == rpm)
    tiny, small = row["tiny"], row["small"]
    for k, folder in (("tiny", "cfd_oil_bath_runs"), ("small", "cfd_oil_bath_mesh")):
        d = json.loads((res / folder / row[k]["case"] / "results.json").read_text())
        assert row[k]["cfd_loss_Nm"] == d["loss_torque_at_shaft_Nm"] and d["steady"] is True
        assert d["fidelity"]["mesh"] == k
    assert small["cells"] > 3 * tiny["cells"]
    # started after five cage revolutions from rest (0.358 s at 2000 rpm, inversely with the speed)
    assert small["initial_state"]["source_mesh"] == "tiny"
    assert small["initial_state"]["time_from_rest_s"] >= 0.99 * 0.358 * 2000 / rpm
    assert row["small_over_tiny"] == pytest.approx(small["cfd_loss_Nm"] / tiny["cfd_loss_Nm"])
    assert row["total_small_Nm"] - row["total_tiny_Nm"] == pytest.approx(small["cfd_loss_Nm"] - tiny["cfd_loss_Nm"])
    docs, readme = _prose("docs/cfd.md"), _prose("README.md")
    up = f"+{100 * (row['small_over_tiny'] - 1):.1f} %"
    for s in (f"{1e3 * small['cfd_loss_Nm']:.2f} mN m ({up})", f"+{100 * small['balance']:.1f} %",
              f"+{100 * tiny['balance']:.1f} %", f"{1e3 * row['total_small_Nm']:.1f} mN m"):
        assert s in docs, s
    for s in (f"{1e3 * small['cfd_loss_Nm']:.2f} against {1e3 * tiny['cfd_loss_Nm']:.2f}", up,
              f"+{100 * small['balance']:.1f} against +{100 * tiny['balance']:.1f} %"):
        assert s in readme, s
