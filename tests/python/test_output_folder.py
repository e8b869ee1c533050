"""An output folder that never loses or deletes what kegel did not write (issue 28, item 2).

Each test names the finding it covers; every one failed on the code before the staging folder and
the manifest (the previous results were removed when a new run started, a folder's foreign files
were deleted or overwritten, SIGTERM left temporary files and said nothing, a bad record of the
stream was accepted on resume)."""

from __future__ import annotations

import hashlib
import json
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from conftest import EXAMPLES, call_kegel, run_kegel, scene_text

TABLE1 = str(EXAMPLES / "32216_table1.toml")
TABLE3 = str(EXAMPLES / "32216_table3.toml")  # 15 points, about 0.5 s each
ONE = ("--set", 'operating.speed="2000 rpm"', "--set", 'operating.temperature="50 degC"',
       "--set", 'model.fidelity="fast"')
TWO = ("--set", 'operating.speed=["2000 rpm", "3000 rpm"]', "--set", 'operating.temperature="50 degC"',
       "--set", 'model.fidelity="fast"')


def _snapshot(folder: Path) -> dict[str, str]:
    """Every file under ``folder`` (hidden ones too) with the hash of its bytes."""
    return {p.relative_to(folder).as_posix(): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(folder.rglob("*")) if p.is_file()}


def _stream(root: Path) -> Path | None:
    """The points.jsonl of the run under ``root``, wherever kegel keeps it."""
    return next(iter(sorted(root.rglob("points.jsonl"))), None)


def _stream_points(root: Path) -> int:
    f = _stream(root)
    return max(0, len(f.read_text().splitlines()) - 1) if f is not None else 0


def _temporary_files(root: Path) -> list[str]:
    """Temporary files (kegel's atomic writes go through hidden ``.<name>.*.tmp*`` files)."""
    return sorted(p.relative_to(root).as_posix() for p in root.rglob("*")
                  if p.is_file() and ".tmp" in p.name)


# -- the previous results survive ---------------------------------------------------------------

def test_the_previous_results_survive_a_run_that_fails_before_it_has_finished(tmp_path, monkeypatch):
    """Finding: a new run removed the previous run's results when it started, so a run that failed
    (here: an interrupt while its plots are written) left neither set. Now the previous set is
    untouched, byte for byte, until the new run has finished."""
    import kegel.run as kr
    from kegel.scene import load_scene

    out = tmp_path / "out"
    code, _, err = call_kegel("run", TABLE1, *ONE, "--output", str(out))
    assert code == 0, err
    before = _snapshot(out)
    assert {"results.json", "results.csv", "torque.png"} <= set(before)

    def plots(*a, **k):
        raise KeyboardInterrupt

    monkeypatch.setattr(kr, "_plots", plots)
    other = load_scene(TABLE1, ['operating.speed="3000 rpm"', 'operating.temperature="50 degC"',
                                'model.fidelity="fast"'])
    with pytest.raises(KeyboardInterrupt):
        kr.run_scene(other, out, progress=False)
    assert _snapshot(out) == before
    monkeypatch.undo()
    res = kr.run_scene(other, out, progress=False)  # resumes: the point is not solved again
    assert json.loads((out / "results.json").read_text())["points"][0]["speed_rpm"] == pytest.approx(3000.0)
    assert res.files["json"] == str(out / "results.json")


def test_the_previous_results_survive_ctrl_c(tmp_path):
    """The same through the command: Ctrl-C during a sweep into a folder holding a finished run's
    results leaves those results as they were and says what it kept."""
    out = tmp_path / "out"
    assert run_kegel("run", TABLE1, *ONE, "--output", str(out)).returncode == 0
    before = _snapshot(out)
    exe = Path(sys.executable).with_name("kegel")
    # one process: its points reach the stream one by one (parallel chains of 16 reach it whole)
    # the fine level, about 0.7 s a point: since the quasi-static speed-up a default point takes
    # 0.13 s, and a signal after the second point found the run finished
    proc = subprocess.Popen([str(exe), "run", TABLE3, "--set", 'model.fidelity="fine"', "--output", str(out),
                             "--jobs", "1"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    t0 = time.monotonic()
    while _stream_points(tmp_path) < 2 and proc.poll() is None and time.monotonic() - t0 < 120:
        time.sleep(0.05)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, err
    assert _snapshot(out) == before
    assert "are as they were" in err and "kept in" in err and "Traceback" not in err
    assert not _temporary_files(tmp_path)


def test_a_replacement_cut_by_a_kill_is_completed_by_the_next_run(tmp_path, monkeypatch):
    """A kill between the renames that move a finished run's results in: the next run into the
    folder completes the replacement first (the results are one run's, never a mixture)."""
    import kegel.io as kio
    import kegel.run as kr
    from kegel.scene import load_scene

    out = tmp_path / "out"
    first = load_scene(TABLE1, ['operating.speed="2000 rpm"', 'operating.temperature="50 degC"', 'model.fidelity="fast"'])
    second = load_scene(TABLE1, ['operating.speed="3000 rpm"', 'operating.temperature="50 degC"', 'model.fidelity="fast"'])
    kr.run_scene(first, out, progress=False)
    real, calls = os.replace, []

    def replace(src, dst):
        if Path(dst).parent == out:  # a staged result moved into the output folder
            calls.append(dst)
            if len(calls) == 2:  # the first has moved: "killed" before the second
                raise SystemExit("killed")
        return real(src, dst)

    monkeypatch.setattr(kio.os, "replace", replace)
    with pytest.raises(SystemExit):
        kr.run_scene(second, out, progress=False)
    monkeypatch.setattr(kio.os, "replace", real)
    code, _, err = call_kegel("run", TABLE1, *ONE, "--output", str(out))
    assert code == 0, err
    assert "completing the replacement" in err
    manifest = json.loads((out / ".kegel-manifest.json").read_text())
    assert set(manifest["files"]) == {p for p in _snapshot(out) if p != ".kegel-manifest.json"}


def test_an_output_folder_that_is_a_mount_point_stages_inside_it(tmp_path):
    """A container volume: the output folder is a mount point, so its parent is another
    filesystem and the staging folder is inside it (renames within one filesystem)."""
    out = tmp_path / "volume"
    out.mkdir()
    if os.geteuid() != 0 or subprocess.run(["mount", "-t", "tmpfs", "-o", "size=8m", "tmpfs", str(out)],
                                           capture_output=True, timeout=10).returncode != 0:
        pytest.skip("needs root to mount a tmpfs")
    try:
        for args in (ONE, TWO):
            code, _, err = call_kegel("run", TABLE1, *args, "--output", str(out))
            assert code == 0, err
        assert len(json.loads((out / "results.json").read_text())["points"]) == 2
        assert sorted(p.name for p in out.iterdir() if p.name.startswith(".")) == [".kegel-manifest.json"]
        assert not [p for p in tmp_path.iterdir() if "staging" in p.name]
    finally:
        subprocess.run(["umount", str(out)], capture_output=True, timeout=10)


# -- foreign files ------------------------------------------------------------------------------

def _users_folder(path: Path) -> Path:
    (path / "dynamic").mkdir(parents=True)
    (path / "dynamic" / "notes.txt").write_text("my measurements\n")
    (path / ".sketch.png").write_bytes(b"\x89PNG my sketch")
    (path / ".draft.tmp").write_text("my draft\n")
    (path / "results.csv").write_text("my,table\n1,2\n")
    (path / "torque.png").write_bytes(b"\x89PNG my plot")
    return path


def test_a_folder_with_the_users_files_is_refused_and_left_as_it_was(tmp_path):
    """Finding: --output into a folder of the user's files deleted their dynamic/ folder (even for
    a quasi-static run) and every hidden .*.png / .*.tmp, and overwrote results.csv and
    torque.png without a word (there was no results.json). Now it is refused, naming them."""
    user = _users_folder(tmp_path / "mine")
    before = _snapshot(user)
    res = run_kegel("run", TABLE1, *ONE, "--output", str(user))
    assert res.returncode == 2, res.stderr
    assert _snapshot(user) == before
    err = res.stderr.strip()
    assert len(err.splitlines()) == 1 and "Traceback" not in err
    for name in ("dynamic", ".sketch.png", "results.csv", "--force"):
        assert name in err, name
    assert not list(tmp_path.glob(".*kegel-staging*")), "a refused run left its staging folder"


def test_force_writes_beside_the_users_files_and_deletes_none(tmp_path):
    """--force: the run goes ahead; the user's files stay, and those with a name kegel writes are
    moved to kegel-replaced-<run id>/ with their contents, never deleted."""
    user = _users_folder(tmp_path / "mine")
    code, _, err = call_kegel("run", TABLE1, *ONE, "--output", str(user), "--force")
    assert code == 0, err
    assert (user / "dynamic" / "notes.txt").read_text() == "my measurements\n"
    assert (user / ".sketch.png").read_bytes() == b"\x89PNG my sketch"
    assert (user / ".draft.tmp").read_text() == "my draft\n"
    aside = list(user.glob("kegel-replaced-*"))
    assert len(aside) == 1 and str(aside[0]) in err
    assert (aside[0] / "results.csv").read_text() == "my,table\n1,2\n"
    assert (aside[0] / "torque.png").read_bytes() == b"\x89PNG my plot"
    assert (user / "results.json").is_file() and (user / "results.csv").read_text().startswith("index,")


def test_a_file_changed_since_kegel_wrote_it_is_not_kegels_any_more(tmp_path):
    """The manifest lists each file with its size and time: a results.csv the user edited after
    the run is theirs, so the next run is refused rather than replacing it."""
    out = tmp_path / "out"
    assert call_kegel("run", TABLE1, *ONE, "--output", str(out))[0] == 0
    (out / "results.csv").write_text("edited by hand\n")
    code, _, err = call_kegel("run", TABLE1, *TWO, "--output", str(out))
    assert code == 2 and "results.csv (changed since kegel wrote it)" in err, err
    assert (out / "results.csv").read_text() == "edited by hand\n"


def _cfd_case(path: Path) -> Path:
    """A stored CFD case: its results.json as `kegel cfd run` writes it, an OpenFOAM case."""
    (path / "system").mkdir(parents=True)
    (path / "system" / "controlDict").write_text("FoamFile {}\n")
    (path / "results.json").write_text(json.dumps({"point": {"bearing": "32208"}, "kinematics": {},
                                                   "loss_torque_at_shaft_Nm": 0.12}))
    return path


def test_a_symlink_to_a_cfd_case_is_refused(tmp_path):
    """Finding: --output through a symlink to a stored CFD case replaced the case's results.json
    (kegel described it as "scene '?', run id ?"). Now the symlink is refused, naming its target,
    and so is the case folder itself (a foreign results.json)."""
    case = _cfd_case(tmp_path / "cfd" / "case_2000")
    before = _snapshot(case)
    link = tmp_path / "latest"
    link.symlink_to(case)
    res = run_kegel("run", TABLE1, *ONE, "--output", str(link))
    assert res.returncode == 2 and "symlink" in res.stderr and "CFD case" in res.stderr, res.stderr
    res = run_kegel("run", TABLE1, *ONE, "--output", str(case))
    assert res.returncode == 2 and "results.json of a CFD case" in res.stderr, res.stderr
    assert _snapshot(case) == before and link.is_symlink()


def test_a_symlink_into_another_run_is_refused(tmp_path):
    out = tmp_path / "run_a"
    assert call_kegel("run", TABLE1, *ONE, "--output", str(out))[0] == 0
    before = _snapshot(out)
    (tmp_path / "b").symlink_to(out)
    code, _, err = call_kegel("run", TABLE1, *TWO, "--output", str(tmp_path / "b"))
    assert code == 2 and "symlink" in err and "kegel run output" in err, err
    assert _snapshot(out) == before


def test_kegels_own_older_files_are_replaced_and_only_those(tmp_path):
    """A run into a folder kegel wrote replaces the older run's files, removes those the new run
    does not write (a dynamic run's dynamic/ after a quasi-static one) and nothing else."""
    out = tmp_path / "out"
    (tmp_path / "s.toml").write_text(scene_text(model='solution = "dynamic"\n[dynamic]\nduration = "0.5 ms"\n'
                                                      'output_interval = "0.25 ms"\nthreads = 1'))
    code, _, err = call_kegel("run", str(tmp_path / "s.toml"), "--output", str(out))
    assert code == 0, err
    assert (out / "dynamic" / "point_000" / "dynamic.json").is_file()
    assert not list(out.rglob("checkpoint.npz")) and not _temporary_files(tmp_path)
    code, _, err = call_kegel("run", TABLE1, *ONE, "--output", str(out))
    assert code == 0, err
    assert not (out / "dynamic").exists()
    manifest = json.loads((out / ".kegel-manifest.json").read_text())
    assert set(manifest["files"]) == {p for p in _snapshot(out) if p != ".kegel-manifest.json"}


# -- signals ------------------------------------------------------------------------------------

DYNAMIC = scene_text(model='solution = "dynamic"\n[dynamic]\nduration = "1 ms"\noutput_interval = "0.25 ms"\n'
                           'checkpoint_interval = "0.25 ms"\nthreads = 1')


def test_sigterm_during_a_dynamic_run_leaves_no_temporary_file_and_says_what_it_kept(tmp_path):
    """Finding: SIGTERM during a dynamic run printed nothing and left a 1.9 MB
    .checkpoint.*.tmp.npz that ended in the finished results. The signal arrives here while a
    checkpoint is being written (deterministically: the write sends it to its own process)."""
    (tmp_path / "s.toml").write_text(DYNAMIC)
    script = textwrap.dedent("""
        import os, signal, sys, time
        import numpy as np
        real = np.savez
        def savez(file, **arrays):
            real(file, **arrays)
            if "checkpoint" in str(file):
                os.kill(os.getpid(), signal.SIGTERM)
                time.sleep(5)
        np.savez = savez
        from kegel.cli import main
        sys.exit(main(["run", "s.toml", "--output", "out"]))
    """)
    res = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert res.returncode == 128 + signal.SIGTERM, res.stderr
    assert "terminated (SIGTERM)" in res.stderr and "kept in" in res.stderr, res.stderr
    assert "Traceback" not in res.stderr
    assert not _temporary_files(tmp_path)
    res = run_kegel("run", "s.toml", "--output", "out", cwd=tmp_path, timeout=300)
    assert res.returncode == 0, res.stderr
    assert not _temporary_files(tmp_path) and not list(tmp_path.rglob("checkpoint.npz"))
    assert not [p for p in tmp_path.iterdir() if "staging" in p.name]


@pytest.mark.slow
def test_sigterm_during_a_sweep_exits_143_and_the_rerun_resumes(tmp_path):
    out = tmp_path / "out"
    exe = Path(sys.executable).with_name("kegel")
    # one process: its points reach the stream one by one (parallel chains of 16 reach it whole)
    # the fine level, about 0.7 s a point: since the quasi-static speed-up a default point takes
    # 0.13 s, and a signal after the second point found the run finished
    proc = subprocess.Popen([str(exe), "run", TABLE3, "--set", 'model.fidelity="fine"', "--output", str(out),
                             "--jobs", "1"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    t0 = time.monotonic()
    while _stream_points(tmp_path) < 2 and proc.poll() is None and time.monotonic() - t0 < 120:
        time.sleep(0.05)
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 143 and "kept in" in err, err
    kept = _stream_points(tmp_path)
    res = run_kegel("run", TABLE3, "--set", 'model.fidelity="fine"', "--output", str(out))
    assert res.returncode == 0 and f"{kept} of 15" in res.stderr, res.stderr


# -- resume validates every record ----------------------------------------------------------------

def _interrupted_run(tmp_path: Path) -> tuple[Path, Path]:
    """A two-point run interrupted after its first point: (output folder, its points.jsonl)."""
    import kegel.run as kr
    from kegel.scene import load_scene

    out = tmp_path / "out"
    scene = load_scene(TABLE1, [a for a in TWO if a != "--set"])

    def stop(point):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        kr.run_scene(scene, out, progress=False, on_point=stop)
    stream = _stream(tmp_path)
    assert stream is not None and len(stream.read_text().splitlines()) == 2
    return out, stream


def _edit(stream: Path, change) -> None:
    header, line = stream.read_text().splitlines()
    rec = json.loads(line)
    new = change(rec)
    stream.write_text(header + "\n" + (new if isinstance(new, str) else json.dumps(new)) + "\n")


OP_KEYS = ("index", "speed_rpm", "speed_rad_s", "temperature_degC", "temperature_K", "axial_load_N", "axial_offset_m",
           "radial_load_N", "tilt_moment_Nm", "misalignment_rad", "inner_ring_temperature_degC",
           "inner_ring_temperature_K", "outer_ring_temperature_degC", "outer_ring_temperature_K")


@pytest.mark.parametrize("change, key", [
    # the finding: a record with no figures (its operating point only) ended in a KeyError traceback
    (lambda r: {"point": {k: r["point"][k] for k in OP_KEYS}}, "converged"),
    (lambda r: {"point": {**{k: r["point"][k] for k in OP_KEYS}, "converged": True}}, "friction_torque_Nm"),
    (lambda r: {"point": {**r["point"], "friction_torque_Nm": "1.2"}}, "friction_torque_Nm"),
    (lambda r: {"point": {**r["point"], "speed_rpm": 2500.0}}, "speed_rpm"),
    (lambda r: {"point": {**r["point"], "index": 7}}, "index"),
    (lambda r: {"point": {**r["point"], "torque_by_contact_Nm": {}}}, "torque_by_contact_Nm"),
    (lambda r: {"point": {**r["point"], "roller_inner_N": [1.0]}}, "roller_inner_N"),
    (lambda r: {"point": {**r["point"], "warnings": [{"code": "x"}]}}, "warnings"),
    (lambda r: '{"point": {"index": 0, "friction', ""),  # a whole line (newline-ended) that is not JSON
])
def test_resume_refuses_a_bad_record_with_file_line_and_reason(tmp_path, change, key):
    out, stream = _interrupted_run(tmp_path)
    _edit(stream, change)
    res = run_kegel("run", TABLE1, *TWO, "--output", str(out))
    assert res.returncode == 2, res.stderr
    err = res.stderr.strip()
    assert "Traceback" not in err and len(err.splitlines()) == 1, err
    assert f"{stream}:2:" in err and (f"point.{key}" if key else "a JSON line") in err and "start afresh" in err, err


def test_resume_refuses_a_point_recorded_twice(tmp_path):
    out, stream = _interrupted_run(tmp_path)
    lines = stream.read_text().splitlines()
    stream.write_text("\n".join([*lines, lines[1]]) + "\n")
    res = run_kegel("run", TABLE1, *TWO, "--output", str(out))
    assert res.returncode == 2 and f"{stream}:3:" in res.stderr and "each point once" in res.stderr, res.stderr


def test_a_whole_record_resumes_and_a_cut_last_line_is_dropped(tmp_path):
    """The valid case: the finished point is not solved again; a last line cut by the interrupt
    (no newline) is dropped, as before."""
    out, stream = _interrupted_run(tmp_path)
    with open(stream, "a", encoding="utf-8") as fh:
        fh.write('{"point": {"index": 1, "fri')
    res = run_kegel("run", TABLE1, *TWO, "--output", str(out))
    assert res.returncode == 0, res.stderr
    assert "resuming the run" in res.stderr and "1 of 2" in res.stderr
    assert len(json.loads((out / "results.json").read_text())["points"]) == 2
    assert not _stream(tmp_path)
