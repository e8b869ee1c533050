"""Issue 21, case by case: the cases of the issue that had no test of their own (an audit of the
issue's "Done when"). Each test states the case; a test marked ``xfail(strict=True)`` is a case
kegel still gets wrong (the reason says how), so it turns into a failure once fixed and unmarked."""

from __future__ import annotations

import io
import json
import math
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import kegel
from conftest import EXAMPLES, call_kegel as _call, run_kegel, scene_text

TABLE1 = str(EXAMPLES / "32216_table1.toml")
TABLE3 = str(EXAMPLES / "32216_table3.toml")
ONE_POINT = ("--set", 'operating.speed="2000 rpm"', "--set", 'operating.temperature="50 degC"',
             "--set", 'model.fidelity="fast"')
BEARING_FILE = Path(kegel.__file__).parent / "data" / "bearings" / "32216.toml"
RPM = math.pi / 30


def _one_line_error(code: int, err: str, *words: str) -> None:
    assert code == 2, err
    lines = [line for line in err.strip().splitlines() if not line.startswith("kegel: warning")]
    assert len(lines) == 1 and lines[0].startswith("kegel: error:"), err
    for w in words:
        assert w in lines[0], (w, lines[0])


def _plausible_or_failed(p: dict) -> None:
    """The property of every point: converged with a finite torque opposing the rotation and a
    closed power balance, or marked as failed (converged false, a failure message)."""
    if p["converged"]:
        t = p["friction_torque_Nm"]
        assert t is not None and math.isfinite(t), p["failure"]
        assert t * p["speed_rad_s"] > 0, t
        assert abs(p["power_balance_error"]) < 1e-3, p["power_balance_error"]
    else:
        assert p["failure"], p
        assert any(w["code"] == "not_converged" for w in p["warnings"])


def _scene_with(tmp_path: Path, text: str, name: str = "scene.toml") -> str:
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def _offset_scene(tmp_path: Path, offset: str) -> str:
    body = Path(TABLE1).read_text().replace('axial_load = "6 kN"', f'axial_offset = "{offset}"')
    return _scene_with(tmp_path, body, "offset.toml")


def _bearing_file(tmp_path: Path, name: str, **replace: str) -> Path:
    text = BEARING_FILE.read_text()
    for old, new in replace.items():
        assert old in text, old
        text = text.replace(old, new)
    path = tmp_path / f"{name}.toml"
    path.write_text(text)
    return path


# --- silently wrong answers ------------------------------------------------------------------

def test_hz_counts_revolutions_in_run_tribology_losses_and_the_api(tmp_path):
    """'33.3333 Hz' ran at 318 rpm (2 pi too slow) in kegel run and kegel tribology; every entry
    point now takes it as 2000 rpm (test_units.py checks only the unit parser)."""
    code, out, err = _call("run", TABLE1, *ONE_POINT, "--set", 'operating.speed="33.3333 Hz"',
                           "--output", str(tmp_path / "r"), "--format", "json")
    assert code == 0, err
    assert json.loads(out)["points"][0]["speed_rpm"] == pytest.approx(2000.0, rel=1e-5)
    code, out, err = _call("tribology", "--speed", "33.3333 Hz", "--format", "json")
    assert code == 0, err
    assert json.loads(out)["shaft_speed_rad_s"] == pytest.approx(2000 * RPM, rel=1e-5)
    code, out, err = _call("losses", "--bearing", "32208", "--speed", "33.3333 Hz", "--format", "json")
    assert code == 0, err
    assert json.loads(out)["points"][0]["speed_rpm"] == pytest.approx(2000.0, rel=1e-5)
    res = kegel.Bearing("32216", fidelity="fast").friction("33.3333 Hz", "6 kN")
    assert res.speed_rpm == pytest.approx(2000.0, rel=1e-5)


@pytest.mark.parametrize("change", [
    ("speed", "1e-6 rpm"),        # gave a negative friction torque and -760 % as converged
    ("offset", "1 m"),            # gave -2.1e6 N m and -100 % as converged
    ("offset", "1e-12 m"),        # gave +7 % as converged
])
def test_implausible_points_are_never_called_converged(tmp_path, change):
    kind, value = change
    if kind == "speed":
        scene, sets = TABLE1, ("--set", f'operating.speed="{value}"')
    else:
        scene, sets = _offset_scene(tmp_path, value), ()
    code, out, err = _call("run", scene, *ONE_POINT, *sets, "--output", str(tmp_path / "r"), "--format", "json")
    if code == 2:
        _one_line_error(code, err)
        return
    assert code in (0, 1), err
    assert "Traceback" not in err
    for p in json.loads(out)["points"]:
        _plausible_or_failed(p)


def test_an_axial_offset_beyond_c0r_is_refused_or_flagged(tmp_path):
    """axial_offset = "800 um" on a 32216: Fa = 441 kN, P0 = 347 kN > C0r = 260 kN (an axial_load of
    340 kN is refused by check); the point must be refused, failed, or warned about C0r."""
    code, out, err = _call("run", _offset_scene(tmp_path, "800 um"), *ONE_POINT, "--output", str(tmp_path / "r"),
                           "--format", "json")
    if code == 2:
        _one_line_error(code, err, "C0r")
        return
    assert code == 0, err
    p = json.loads(out)["points"][0]
    b = kegel.load_bearing("32216")
    g = kegel.derive_geometry(b, kegel.load_material("bearing_steel"))
    from kegel.scene import static_equivalent_load_N

    assert static_equivalent_load_N(g, p["axial_force_N"], p["radial_load_N"]) > b.C0r_N  # the case is real
    assert not p["converged"] or any("C0r" in w["message"] for w in p["warnings"]), p["warnings"]


def test_a_tilt_moment_is_refused_by_check_and_run_alike(tmp_path):
    """A quasi-static scene ignored tilt_moment = "1e12 N m" and echoed it: check and run refuse it."""
    for cmd in ("check", "run"):
        code, _, err = _call(cmd, TABLE1, *ONE_POINT, "--set", 'operating.tilt_moment="1e12 N m"',
                             *(("--output", str(tmp_path / "r")) if cmd == "run" else ()))
        _one_line_error(code, err, "operating.tilt_moment", "1e12 N m", "tips over")
    assert not (tmp_path / "r" / "results.json").exists()


@pytest.mark.parametrize("name, replace, words", [
    ("crowded", {"roller_count = 16": "roller_count = 200"}, "overlap"),
    ("fat", {"roller_diameter_mm = 17.0 ": "roller_diameter_mm = 40.0 "}, "outside (d/2, D/2)"),
    ("steep", {"calculation_factor_e = 0.42 ": "calculation_factor_e = 5 "}, "outside the width"),
])
def test_custom_bearings_outside_their_envelope_are_refused_everywhere(tmp_path, name, replace, words):
    """Overlapping rollers (Z = 200), rollers outside the rings and e = 5 ran to a torque in check
    and run while kegel bearing listed the violations; now kegel bearing lists them and check, run,
    tribology, losses and the Python API refuse the file with one line naming it."""
    bad = _bearing_file(tmp_path, name, **replace)
    code, out, err = _call("bearing", "--bearing", str(bad))
    assert code == 0 and words in out, err
    scene = _scene_with(tmp_path, Path(TABLE1).read_text().replace('designation = "32216"', f'designation = "{bad}"'))
    for argv in (("check", scene, *ONE_POINT), ("run", scene, *ONE_POINT, "--output", str(tmp_path / "r")),
                 ("tribology", "--bearing", str(bad)), ("losses", "--bearing", str(bad))):
        code, _, err = _call(*argv)
        _one_line_error(code, err, str(bad.name), words)
    assert not (tmp_path / "r" / "results.json").exists()
    with pytest.raises(kegel.KegelInputError, match="boundary dimensions"):
        kegel.Bearing(str(bad), fidelity="fast").friction("2000 rpm", "6 kN")


def _cfd_point(monkeypatch, bearing: str, out: Path):
    """The point `kegel cfd run --bearing FILE` would run (its runner replaced: no gmsh, no OpenFOAM)."""
    import kegel.cfd_cases.cli as cc  # the module kegel.cli dispatches to (not a top-level cfd_cases)
    import kegel.cfd_cases.run as cr

    seen = []

    def no_openfoam(point, case, args):
        seen.append(point)
        raise KeyboardInterrupt  # stop before anything is run

    def never(*a, **k):
        raise AssertionError("a CFD case was built or run")

    monkeypatch.setattr(cc, "_run_one", no_openfoam)
    for name in ("run_case", "build_mesh", "gmsh_to_foam", "run_solver", "run_utility"):
        monkeypatch.setattr(cr, name, never)
    code, _, err = _call("cfd", "run", "--bearing", bearing, "--speed", "2000 rpm", "--output", str(out))
    return code, err, seen


def test_cfd_run_refuses_a_custom_bearing_outside_its_envelope(tmp_path, monkeypatch):
    bad = _bearing_file(tmp_path, "crowded", **{"roller_count = 16": "roller_count = 200"})
    code, err, seen = _cfd_point(monkeypatch, str(bad), tmp_path / "case")
    assert not seen, "the CFD case was started"
    _one_line_error(code, err, "overlap")


def test_cfd_run_uses_the_custom_bearing_file_it_was_given(tmp_path, monkeypatch):
    custom = _bearing_file(tmp_path, "seventeen", **{"roller_count = 16": "roller_count = 17"})
    assert kegel.envelope_violations(kegel.derive_geometry(kegel.load_bearing(str(custom)),
                                                           kegel.load_material("bearing_steel"))) == []
    _, err, seen = _cfd_point(monkeypatch, str(custom), tmp_path / "case")
    assert seen, err
    assert kegel.load_bearing(seen[0].bearing_file or seen[0].bearing).roller_count == 17


# --- the Python API's ranges -----------------------------------------------------------------

@pytest.fixture(scope="module")
def parts():
    from kegel.tribology import load_friction

    b = kegel.load_bearing("32216")
    m = kegel.load_material("bearing_steel")
    lub = kegel.load_lubricant("FVA3")
    return kegel.derive_geometry(b, m), b, m, lub, load_friction("steel_mineral_oil")


def test_the_api_checks_the_ranges_of_the_command_line():
    """FVA 3 at 1000 degC, Fa = 5 MN, 1e7 rpm, -15 degC through kegel.Bearing and lubricant_state."""
    with pytest.raises(kegel.KegelInputError, match=r"\[-20, 150\] degC"):
        kegel.lubricant_state("FVA3", "1000 degC")
    bearing = kegel.Bearing("32216", fidelity="fast")
    for kwargs, key in ((dict(speed="2000 rpm", axial_load="5 MN"), "axial_load"),
                        (dict(speed="1e7 rpm", axial_load="6 kN"), "speed"),
                        (dict(speed="2000 rpm", axial_load="6 kN", temperature="-15 degC"), "temperature")):
        with pytest.raises(kegel.KegelInputError) as info:
            bearing.friction(**kwargs)
        assert info.value.key == key


@pytest.mark.parametrize("load_N, T_K, n_rpm", [(1e9, 323.15, 2000.0), (1000.0, 1273.15, 2000.0),
                                                (1000.0, 323.15, 1e7)])
def test_the_api_contact_checks_its_ranges(parts, load_N, T_K, n_rpm):
    g, b, m, lub, fr = parts
    with pytest.raises(kegel.KegelInputError):
        kegel.evaluate_raceway_contact(g, b, m, lub, fr, temperature_K=T_K, load_N=load_N,
                                       shaft_speed_rad_s=n_rpm * RPM)


@pytest.mark.parametrize("kwargs", [
    dict(speed_profile=[(0.0, 0.0), (0.01, 1e9 * RPM)]),
    dict(duration_s=1e9, output_interval_s=1e-3),
    dict(output_interval_s=1e-9),
    dict(temperature_K=1273.15),
])
def test_the_api_simulation_checks_its_inputs_before_it_runs(parts, monkeypatch, kwargs):
    import kegel.dynamics as dyn

    def never(*a, **k):
        raise AssertionError("the simulation was built from inputs a scene refuses")

    monkeypatch.setattr(dyn.D, "DynamicSimulation", never)
    g, b, m, lub, fr = parts
    base = dict(temperature_K=323.15, speed_profile=[(0.0, 2000 * RPM)], duration_s=1e-3, axial_N=6000.0,
                slices=8, output_interval_s=2e-4)
    with pytest.raises(kegel.KegelInputError):
        dyn.simulate(g, b, m, lub, fr, **{**base, **kwargs})


# --- documented-valid inputs that crashed in run -----------------------------------------------

def test_every_temperature_from_minus_20_to_minus_11_degc_is_refused_or_solved(tmp_path):
    """-20 ... -11 degC passed check and crashed in run (Eq. 7's domain): each is now refused by
    check and run alike with one line, or solved (converged or marked failed), never a traceback."""
    for T in range(-20, -10):
        sets = (*ONE_POINT, "--set", f'operating.temperature="{T} degC"')
        c_check, _, err_check = _call("check", TABLE1, *sets)
        code, out, err = _call("run", TABLE1, *sets, "--output", str(tmp_path / f"t{T}"), "--format", "json")
        assert "Traceback" not in err, (T, err)
        if c_check == 2:
            _one_line_error(c_check, err_check, "operating.temperature")
            _one_line_error(code, err, "operating.temperature")
            continue
        assert c_check == 0 and code == 0, (T, err)
        for p in json.loads(out)["points"]:
            _plausible_or_failed(p)


@pytest.mark.parametrize("mis", ["1 mrad", "3 mrad", "10 mrad", "-10 mrad"])
def test_a_misalignment_up_to_10_mrad_runs_at_fidelity_fast(tmp_path, mis):
    """Misalignment 1-10 mrad at fidelity fast passed check and crashed in run."""
    code, out, err = _call("run", TABLE1, *ONE_POINT, "--set", f'operating.misalignment="{mis}"',
                           "--output", str(tmp_path / "r"), "--format", "json")
    assert code == 0, err
    p = json.loads(out)["points"][0]
    assert p["misalignment_rad"] == pytest.approx(float(mis.split()[0]) * 1e-3)
    _plausible_or_failed(p)


def test_a_misalignment_beyond_10_mrad_is_refused():
    code, _, err = _call("check", TABLE1, *ONE_POINT, "--set", 'operating.misalignment="11 mrad"')
    _one_line_error(code, err, "operating.misalignment", "10 mrad")


@pytest.mark.parametrize("override, key", [
    ('dynamic.speed_profile=[["0 ms", "0 rpm"], ["10 ms", "1e9 rpm"]]', "dynamic.speed_profile[1][1]"),
    ('dynamic.load_profile=[["0 ms", "0 kN", "0 kN"]]', "dynamic.load_profile[0][1]"),
    ('dynamic.duration="1e9 s"', "dynamic.duration"),
    ('dynamic.output_interval="1 ns"', "dynamic.output_interval"),
])
def test_dynamic_profiles_and_times_are_refused_by_the_run_command(tmp_path, override, key):
    """The same cases as test_scene_errors.py, through kegel run: one line, nothing computed."""
    t0 = time.monotonic()
    code, _, err = _call("run", TABLE1, *ONE_POINT, "--set", 'model.solution="dynamic"', "--set", override,
                         "--output", str(tmp_path / "r"))
    _one_line_error(code, err, key)
    assert time.monotonic() - t0 < 20 and not (tmp_path / "r").exists()


# --- inputs that are no regular files ----------------------------------------------------------

@pytest.mark.parametrize("where", ["scene_run", "bearing_cmd", "lubricant_cmd", "tribology_bearing",
                                   "losses_bearing", "losses_cfd", "scene_bearing", "scene_lubricant"])
def test_a_named_pipe_never_hangs_any_entry_point(tmp_path, where):
    """A named pipe as the scene file hung kegel check for good; every other file input is
    refused without reading it as well (one line, exit 2, within seconds)."""
    fifo = tmp_path / "pipe.toml"
    os.mkfifo(fifo)
    base = Path(TABLE1).read_text()
    args = {
        "scene_run": ("run", str(fifo), "--output", str(tmp_path / "r")),
        "bearing_cmd": ("bearing", "--bearing", str(fifo)),
        "lubricant_cmd": ("lubricant", str(fifo)),
        "tribology_bearing": ("tribology", "--bearing", str(fifo)),
        "losses_bearing": ("losses", "--bearing", str(fifo)),
        "losses_cfd": ("losses", "--bearing", "32208", "--cfd", str(fifo)),
        "scene_bearing": ("check", _scene_with(tmp_path, base.replace('designation = "32216"', f'designation = "{fifo}"'))),
        "scene_lubricant": ("check", _scene_with(tmp_path, base.replace('name = "FVA3"', f'name = "{fifo}"'))),
    }[where]
    res = run_kegel(*args, timeout=30)
    assert res.returncode == 2 and "Traceback" not in res.stderr, res.stderr
    assert len(res.stderr.strip().splitlines()) == 1 and str(fifo.name) in res.stderr, res.stderr


# --- progress, output folders, interrupted runs ------------------------------------------------

def test_progress_in_a_log_is_throttled(monkeypatch):
    """A 10^6-point run wrote 96 MB of progress text into a log: without a terminal, a line at
    most every 10 s (and the last one)."""
    import types

    import kegel.run as kr

    clock = [0.0]
    err = io.StringIO()  # not a terminal
    monkeypatch.setattr(kr, "time", types.SimpleNamespace(perf_counter=lambda: clock[0]))
    monkeypatch.setattr(kr, "sys", types.SimpleNamespace(stderr=err))
    n = 100_000
    bar = kr._Progress(n, True)
    for i in range(1, n + 1):
        clock[0] = i * 1e-3  # a point per millisecond: 100 s in all
        bar.update(i, "n = 2000 rpm")
    bar.close()
    lines = err.getvalue().splitlines()
    assert 5 <= len(lines) <= 12, len(lines)
    assert lines[-1].split("]")[1].strip().startswith(f"{n}/{n}")


def _stream_points(folder: Path) -> int:
    from kegel.io import staging_path

    f = staging_path(folder) / "points.jsonl"  # a run computes in its staging folder (issue 28)
    return max(0, len(f.read_text().splitlines()) - 1) if f.is_file() else 0


def test_two_live_runs_never_share_a_folder(tmp_path):
    """Two real runs into one folder (the existing test fakes the first one's lock): the second is
    refused while the first computes, and the first's results are whole."""
    out = tmp_path / "run"
    exe = Path(sys.executable).with_name("kegel")
    # one process: its points reach the stream one by one (a parallel chain of 16 reaches it whole)
    first = subprocess.Popen([str(exe), "run", TABLE3, "--set", 'model.fidelity="fine"', "--output", str(out), "--format", "json", "--jobs", "1"],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        t0 = time.monotonic()
        while _stream_points(out) < 1 and first.poll() is None and time.monotonic() - t0 < 120:
            time.sleep(0.05)
        assert first.poll() is None, "the first run ended before the second started"
        second = run_kegel("run", TABLE1, *ONE_POINT, "--output", str(out))
        assert second.returncode == 2 and "another --output" in second.stderr, second.stderr
        assert len(second.stderr.strip().splitlines()) == 1
        first.send_signal(signal.SIGINT)
        first.communicate(timeout=60)
    finally:
        if first.poll() is None:
            first.kill()
            first.wait()
    assert first.returncode == 130
    res = run_kegel("run", TABLE3, "--set", 'model.fidelity="fine"', "--output", str(out))
    assert res.returncode == 0 and "resuming the run" in res.stderr, res.stderr
    assert len(json.loads((out / "results.json").read_text())["points"]) == 15


def test_two_checkpoint_writes_into_one_file_do_not_collide(tmp_path, monkeypatch):
    """Two dynamic runs collided on the fixed checkpoint temp name (FileNotFoundError): a second
    write of the same checkpoint while the first is under way now uses its own temporary file."""
    import kegel.dynamics as dyn

    ck = tmp_path / "checkpoint.npz"
    real = np.savez
    nested = []

    def savez(file, **arrays):
        real(file, **arrays)
        if not nested:  # the other run writes and renames its checkpoint before this one renames
            nested.append(file)
            dyn._save_checkpoint(ck, 2.0, np.ones(3), [2.0], [np.ones(3)], [np.ones(2)], {}, "other run")

    monkeypatch.setattr(np, "savez", savez)
    dyn._save_checkpoint(ck, 1.0, np.zeros(3), [1.0], [np.zeros(3)], [np.zeros(2)], {}, "this run")
    with np.load(ck) as f:
        assert float(f["t"]) == 1.0 and str(f["key"]) == "this run"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["checkpoint.npz"]


def test_a_read_only_output_folder_is_found_before_computing(tmp_path):
    """Output folders that are read-only were found only after the whole computation."""
    ro = tmp_path / "ro"
    ro.mkdir()
    if os.geteuid() != 0 or subprocess.run(["mount", "-t", "tmpfs", "-o", "ro,size=64k", "tmpfs", str(ro)],
                                           capture_output=True, timeout=10).returncode != 0:
        pytest.skip("needs root to mount a read-only tmpfs")
    try:
        for out in (ro, ro / "sub"):
            t0 = time.monotonic()
            res = run_kegel("run", TABLE3, "--output", str(out))
            assert res.returncode == 2 and "Traceback" not in res.stderr, res.stderr
            assert str(out) in res.stderr and "Read-only" in res.stderr
            assert len([x for x in res.stderr.splitlines() if "warning" not in x]) == 1
            assert time.monotonic() - t0 < 15
    finally:
        subprocess.run(["umount", str(ro)], capture_output=True, timeout=10)


def test_an_interrupt_while_plotting_leaves_no_old_plots_or_temporary_files(tmp_path, monkeypatch):
    """An interrupt in the plot phase left new results beside old plots and hidden temporary PNGs
    that piled up: now the older run's files stay whole and alone (the new run computes in its
    staging folder, issue 28), no temporary file is left, and the rerun writes the summary without
    solving again."""
    from kegel.io import staging_path

    import matplotlib.figure

    import kegel.run as kr
    from kegel.scene import load_scene

    out = tmp_path / "run"
    kr.run_scene(load_scene(TABLE1, ['operating.speed="2000 rpm"', 'operating.temperature="50 degC"',
                                     'model.fidelity="fast"']), out, progress=False)
    old = {p.name: p.stat().st_mtime_ns for p in out.iterdir()}
    assert {"torque.png", "breakdown.png", "results.json"} <= set(old)
    other = load_scene(TABLE1, ['operating.speed="3000 rpm"', 'operating.temperature="50 degC"',
                                'model.fidelity="fast"'])
    real, calls = matplotlib.figure.Figure.savefig, []

    def savefig(self, *a, **k):
        calls.append(1)
        if len(calls) == 2:
            raise KeyboardInterrupt
        return real(self, *a, **k)

    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", savefig)
    with pytest.raises(KeyboardInterrupt):
        kr.run_scene(other, out, progress=False)
    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", real)
    left = {p.name: p.stat().st_mtime_ns for p in out.iterdir()}
    assert left == old, "the older run's files changed"
    stage = sorted(p.name for p in staging_path(out).iterdir())
    assert "points.jsonl" in stage and not [n for n in stage if n.startswith(".")], stage
    def solve(*a, **k):
        raise AssertionError("a finished point was solved again")

    monkeypatch.setattr(kr, "_quasi_static_record", solve)
    res = kr.run_scene(other, out, progress=False)
    assert res.points[0]["speed_rpm"] == pytest.approx(3000.0)
    assert {"results.json", "results.csv", "torque.png", "breakdown.png"} <= {p.name for p in out.iterdir()}
    assert not (out / "points.jsonl").exists()


DYN2 = scene_text(speed='["2000 rpm", "2500 rpm"]', model='solution = "dynamic"\n[dynamic]\nduration = "1 ms"\n'
                                                          'output_interval = "0.25 ms"\nthreads = 1')


def _interrupt_after_first_point(scene_path: Path, out: Path) -> None:
    import kegel.run as kr
    from kegel.scene import load_scene

    def stop(point):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        kr.run_scene(load_scene(scene_path), out, progress=False, on_point=stop)
    assert _stream_points(out) == 1


def _first_point_solved(scene_path: Path, out: Path, monkeypatch, overrides=()) -> int:
    """Rerun the scene and return the index of the first point it solves (stopped there)."""
    import kegel.run as kr
    from kegel.scene import load_scene

    seen = []

    def stop(scene, op, *a, **k):
        seen.append(op.index)
        raise KeyboardInterrupt

    monkeypatch.setattr(kr, "_dynamic_point", stop)
    with pytest.raises(KeyboardInterrupt):
        kr.run_scene(load_scene(scene_path, list(overrides)), out, progress=False)
    return seen[0]


def test_an_interrupted_dynamic_run_skips_its_finished_points(tmp_path, monkeypatch):
    """Dynamic runs resumed only the interrupted point and recomputed the finished ones."""
    scene = tmp_path / "dyn.toml"
    scene.write_text(DYN2)
    _interrupt_after_first_point(scene, tmp_path / "out")
    assert _first_point_solved(scene, tmp_path / "out", monkeypatch) == 1


def test_changing_threads_keeps_the_finished_dynamic_points(tmp_path, monkeypatch):
    scene = tmp_path / "dyn.toml"
    scene.write_text(DYN2)
    _interrupt_after_first_point(scene, tmp_path / "out")
    assert _first_point_solved(scene, tmp_path / "out", monkeypatch, ["dynamic.threads=2"]) == 1


def test_changing_threads_keeps_the_checkpoint_of_the_interrupted_point(tmp_path, monkeypatch):
    """'changing threads silently discards the checkpoint': the point resumes from its checkpoint."""
    import kegel.dynamics as dyn
    import kegel.run as kr
    from kegel.scene import load_scene

    scene = tmp_path / "dyn.toml"
    scene.write_text(scene_text(model='solution = "dynamic"\n[dynamic]\nduration = "1 ms"\n'
                                      'output_interval = "0.1 ms"\ncheckpoint_interval = "0.2 ms"\nthreads = 1'))
    out = tmp_path / "out"
    real, saved = dyn._save_checkpoint, []

    def save_then_stop(*a, **k):
        real(*a, **k)
        saved.append(a[1])
        if len(saved) == 2:
            raise KeyboardInterrupt

    monkeypatch.setattr(dyn, "_save_checkpoint", save_then_stop)
    with pytest.raises(KeyboardInterrupt):
        kr.run_scene(load_scene(scene), out, progress=False)
    monkeypatch.setattr(dyn, "_save_checkpoint", real)
    from kegel.io import staging_path  # an unfinished run's files are in its staging folder (issue 28)

    assert (staging_path(out) / "dynamic" / "point_000" / "checkpoint.npz").is_file()
    kr.run_scene(load_scene(scene, ["dynamic.threads=2"]), out, progress=False)
    meta = json.loads((out / "dynamic" / "point_000" / "dynamic.json").read_text())
    assert meta["stats"]["resumed_from_s"] == pytest.approx(saved[-1], abs=1e-9)


def test_a_new_run_leaves_no_dynamic_files_of_an_older_run(tmp_path):
    import kegel.run as kr
    from kegel.scene import load_scene

    scene = tmp_path / "dyn.toml"
    scene.write_text(DYN2)
    out = tmp_path / "out"
    kr.run_scene(load_scene(scene), out, progress=False)
    assert (out / "dynamic" / "point_001" / "series.csv").is_file()
    kr.run_scene(load_scene(TABLE1, ['operating.speed="2000 rpm"', 'operating.temperature="50 degC"',
                                     'model.fidelity="fast"']), out, progress=False)
    assert json.loads((out / "results.json").read_text())["fidelity"]["solution_used"] == "quasi_static"
    assert not (out / "dynamic").exists(), sorted(str(p.relative_to(out)) for p in (out / "dynamic").rglob("*"))
