"""Runs that survive (issue 21): an interrupted quasi-static sweep keeps its finished points and
resumes from them; an output folder belongs to one live run; no file of an older run stays beside
a new run's files."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conftest import run_kegel

SCENE = "examples/32216_table3.toml"  # 15 points
#: the same at the fine level, about 0.7 s a point: the interrupt tests need points that last
#: (at the default level a point took 0.5 s once and 0.13 s since the quasi-static speed-up of
#: issue 30, and a Ctrl-C after the third point found the run finished)
SLOW_SCENE = (SCENE, "--set", 'model.fidelity="fine"')


def _kegel(*args: str) -> subprocess.Popen:
    """A live `kegel run` in one process: its points reach the stream one by one (a parallel
    chain of 16 points reaches it whole, after the moment these tests interrupt)."""
    exe = Path(sys.executable).with_name("kegel")
    jobs = ["--jobs", "1"] if args and args[0] == "run" else []
    return subprocess.Popen([str(exe), *args, *jobs], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def _stream_points(folder: Path) -> int:
    from kegel.io import staging_path

    f = staging_path(folder) / "points.jsonl"  # a run computes in its staging folder (issue 28)
    return max(0, len(f.read_text().splitlines()) - 1) if f.is_file() else 0


@pytest.mark.slow
def test_an_interrupted_sweep_resumes_from_its_finished_points(tmp_path):
    """Ctrl-C after a few points: exit 130, the finished points kept in points.jsonl, the lock
    released, no summary file; the rerun solves only the rest, and its torques equal those of an
    uninterrupted run (before: Ctrl-C after 1138 of 3000 points kept nothing)."""
    out = tmp_path / "run"
    proc = _kegel("run", *SLOW_SCENE, "--output", str(out))
    t0 = time.monotonic()
    while _stream_points(out) < 3 and proc.poll() is None and time.monotonic() - t0 < 120:
        time.sleep(0.05)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, err
    kept = _stream_points(out)
    assert 3 <= kept < 15
    assert not (out / "results.json").exists() and not (out / ".kegel-run.lock").exists()
    res = run_kegel("run", *SLOW_SCENE, "--output", str(out), "--format", "json")
    assert res.returncode == 0, res.stderr
    assert f"resuming the run in {out}: {kept} of 15" in res.stderr
    assert not (out / "points.jsonl").exists()
    resumed = json.loads((out / "results.json").read_text())["points"]
    ref = run_kegel("run", *SLOW_SCENE, "--output", str(tmp_path / "ref"), "--format", "json")
    full = json.loads((tmp_path / "ref" / "results.json").read_text())["points"]
    assert [p["index"] for p in resumed] == list(range(15))
    for a, b in zip(resumed, full):
        assert a["friction_torque_Nm"] == pytest.approx(b["friction_torque_Nm"], rel=1e-6)


def test_a_live_run_owns_its_output_folder(tmp_path):
    """Two runs into one folder ended with one run's results.json beside the other's plots; now the
    second is refused while the first lives, and a lock left by a dead process is taken over."""
    out = tmp_path / "run"
    out.mkdir()
    lock = out / ".kegel-run.lock"
    lock.write_text(json.dumps({"pid": os.getpid(), "run_id": "x"}))  # this test process: alive
    res = run_kegel("run", "examples/32216_table1.toml", "--output", str(out))
    assert res.returncode == 2 and str(os.getpid()) in res.stderr and "another --output" in res.stderr
    assert not (out / "results.json").exists()
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    lock.write_text(json.dumps({"pid": dead.pid, "run_id": "x"}))
    res = run_kegel("run", "examples/32216_table1.toml", "--output", str(out))
    assert res.returncode == 0, res.stderr
    assert (out / "results.json").is_file() and not lock.exists()


def test_a_new_run_keeps_the_previous_runs_files_until_it_has_finished(tmp_path):
    """A run of another scene in the same folder computes in its staging folder: interrupted, it
    leaves the previous run's files as they were (issue 28: before, it removed them when it
    started, so the folder held neither set) and its finished points beside them for a resume."""
    from kegel.io import staging_path

    out = tmp_path / "run"
    assert run_kegel("run", "examples/32216_table1.toml", "--set", 'operating.speed="2000 rpm"', "--set",
                     'operating.temperature="50 degC"', "--output", str(out)).returncode == 0
    old = {p.name: p.read_bytes() for p in out.iterdir()}
    proc = _kegel("run", *SLOW_SCENE, "--output", str(out))
    t0 = time.monotonic()
    while _stream_points(out) < 1 and proc.poll() is None and time.monotonic() - t0 < 120:
        time.sleep(0.05)
    proc.send_signal(signal.SIGINT)
    proc.communicate(timeout=60)
    assert {p.name: p.read_bytes() for p in out.iterdir()} == old
    assert sorted(p.name for p in staging_path(out).iterdir()) == ["points.jsonl"]


def test_an_unwritable_output_is_found_before_computing(tmp_path):
    f = tmp_path / "a_file"
    f.write_text("")
    t0 = time.monotonic()
    res = run_kegel("run", SCENE, "--output", str(f))
    assert res.returncode == 2 and str(f) in res.stderr and "Traceback" not in res.stderr
    assert time.monotonic() - t0 < 30


def _mount_tmpfs(path: Path, size: str) -> bool:
    path.mkdir(parents=True, exist_ok=True)
    try:
        return subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(path)],
                              capture_output=True, timeout=10).returncode == 0
    except (OSError, subprocess.SubprocessError):
        return False


@pytest.mark.parametrize("size", ["40k", "100k"])
def test_a_full_disk_gives_one_line_and_the_run_resumes(tmp_path, size):
    """Fault injection: the output folder on a tiny tmpfs fills up while the points stream (40k)
    or while the summary files are written (100k). kegel exits 1 with one line naming the file,
    no traceback, no temporary file or lock left; once there is space the same command resumes
    from the streamed points."""
    disk = tmp_path / "disk"
    if os.geteuid() != 0 or not _mount_tmpfs(disk, size):
        pytest.skip("needs root to mount a small tmpfs")
    try:
        args = ("run", SCENE, "--set", 'model.fidelity="fast"', "--output", str(disk / "out"))
        res = run_kegel(*args)
        assert res.returncode == 1, res.stderr
        assert "Traceback" not in res.stderr
        assert "No space left on device" in res.stderr and str(disk / "out") in res.stderr
        from kegel.io import staging_path

        stage = staging_path(disk / "out")  # the run computes here; out is written when it has finished
        left = sorted(p.name for p in stage.iterdir())
        assert left == ["points.jsonl"], left
        assert not (disk / "out").exists()
        kept = 0  # whole lines only: the disk cut the last one
        for line in (stage / "points.jsonl").read_text().splitlines()[1:]:
            try:
                json.loads(line)
                kept += 1
            except json.JSONDecodeError:
                pass
        subprocess.run(["mount", "-o", "remount,size=4m", str(disk)], check=True, timeout=10)
        res = run_kegel(*args)
        assert res.returncode == 0, res.stderr
        if kept:
            assert f"resuming the run in {disk / 'out'}: {kept} of 15" in res.stderr
        assert len(json.loads((disk / "out" / "results.json").read_text())["points"]) == 15
    finally:
        subprocess.run(["umount", str(disk)], capture_output=True, timeout=10)


def test_a_resumed_stream_drops_the_cut_line_before_appending(tmp_path):
    """A line cut by an interrupt is dropped before the resumed run appends: the next point's line
    stays whole, so a second resume finds every point the first one added."""
    from kegel.io import RunFolder

    key = {"scene": "s"}
    out = tmp_path / "out"
    with RunFolder(out, key, ()) as folder:
        assert folder.open() == {}
        folder.add({"index": 0, "x": 1.0})
    with open(folder.stream_path, "a", encoding="utf-8") as fh:
        fh.write('{"point": {"index": 1, "x"')  # the interrupt cut this line
    with RunFolder(out, key, ()) as folder:
        assert sorted(folder.open()) == [0]
        folder.add({"index": 1, "x": 2.0})
    with RunFolder(out, key, ()) as folder:
        done = folder.open()
    assert sorted(done) == [0, 1] and done[1]["x"] == 2.0
