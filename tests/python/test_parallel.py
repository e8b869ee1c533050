"""Operating points in parallel (kegel.parallel): local processes and a Dask cluster give the
serial run's figures, to the last digit, in the serial order; an interrupted parallel run keeps
its finished points and resumes from them; the CFD sweep sends one task per case to Dask."""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import pytest

import kegel.parallel as P
from kegel.run import run_scene
from kegel.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]
STUDY = ROOT / "examples" / "32208_study.toml"


def _study():
    # the study's CFD results as an absolute path: the workers need not share the test's folder
    return load_scene(STUDY, [f'study.cfd_results="{ROOT / "benchmarks" / "results" / "cfd"}"'])


def _close(a, b, where: str, rel: float = 1e-10) -> None:
    """Equal records: the same keys, lists, texts and flags; numbers equal to the solver's
    rounding (see _same)."""
    if isinstance(a, dict):
        assert isinstance(b, dict) and set(a) == set(b), where
        for k in a:
            if k != "runtime_s":
                _close(a[k], b[k], f"{where}.{k}", rel)
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            _close(x, y, f"{where}[{i}]", rel)
    elif isinstance(a, float) and not isinstance(b, bool) and isinstance(b, (int, float)):
        assert math.isclose(a, b, rel_tol=rel, abs_tol=1e-12), (where, a, b)
    else:
        assert a == b, (where, a, b)


def _number(text: str):
    try:
        return float(text)
    except ValueError:
        return text


def _same(a: list[dict], b: list[dict], rel: float = 1e-10) -> None:
    """The same points in the same order with the same figures (the wall time aside). The chains
    are the same whatever the processes (kegel.parallel), so the figures would be identical, but
    the C++ core's quasi-static friction solve is not bit-reproducible between processes: the
    same point in two fresh processes differs by up to about 2e-13 relative (found with this
    test: 0.29647395194622156 or ...27385 N m at the study's first point, depending on the
    process's history). Numbers are therefore compared to 1e-10 relative."""
    assert [p["index"] for p in a] == [p["index"] for p in b] == list(range(len(a)))
    for p, q in zip(a, b):
        _close(p, q, f"point {p['index']}", rel)


@pytest.fixture(scope="module")
def serial():
    """The study solved in this process alone, in chains of two points."""
    chain = P.QUASI_STATIC_CHAIN
    P.QUASI_STATIC_CHAIN = 2
    try:
        return run_scene(_study(), write=False, progress=False, jobs=1).points
    finally:
        P.QUASI_STATIC_CHAIN = chain


@pytest.fixture()
def chain_of_two(monkeypatch):
    # the chains are cut in the parent (the workers solve what they are given)
    monkeypatch.setattr(P, "QUASI_STATIC_CHAIN", 2)


def test_chains_are_fixed_by_the_scene_not_the_jobs():
    scene = _study()
    assert P.point_blocks(scene) == [[0, 1, 2, 3, 4]]  # 16 points a chain
    dyn = load_scene(ROOT / "examples" / "32216_table1_dynamic.toml")
    assert P.point_blocks(dyn) == [[i] for i in range(len(dyn.operating_points))]
    assert P.effective_jobs(8, 3) == 3 and P.effective_jobs(1, 3) == 1 and P.effective_jobs(None, 1) == 1
    from kegel.errors import KegelInputError

    with pytest.raises(KegelInputError, match="jobs"):
        P.effective_jobs(0, 3)


def test_a_chain_start_is_a_fresh_solution(serial, chain_of_two):
    # the serial run of the study in chains of two: every point converged, and its figures
    # differ from one unbroken chain only within the solver's tolerance (a warm start changes
    # the last digits, not the answer)
    one = run_scene(_study(), write=False, progress=False, jobs=1)
    assert all(p["converged"] for p in serial)
    P.QUASI_STATIC_CHAIN = 16
    unbroken = run_scene(_study(), write=False, progress=False, jobs=1).points
    for p, q in zip(serial, unbroken):
        assert math.isclose(p["friction_torque_Nm"], q["friction_torque_Nm"], rel_tol=1e-8)
    _same(one.points, serial)


def test_parallel_study_equals_the_serial_run(serial, chain_of_two, tmp_path):
    seen: list[int] = []
    res = run_scene(_study(), tmp_path / "par", progress=False, jobs=2, on_point=lambda p: seen.append(p["index"]))
    _same(res.points, serial)
    assert seen == list(range(5))  # on_point in the scene's order
    ser = run_scene(_study(), tmp_path / "ser", progress=False, jobs=1)
    for name in ("results.csv", "study.csv"):  # the same table (numbers as in _same)
        par, ser = (list(csv.reader((tmp_path / d / name).open())) for d in ("par", "ser"))
        assert par[0] == ser[0] and len(par) == len(ser) > 5
        for i, (r, q) in enumerate(zip(par, ser)):
            _close([_number(x) for x in r], [_number(x) for x in q], f"{name} row {i}")


def test_interrupted_parallel_run_keeps_its_points_and_resumes(serial, chain_of_two, tmp_path, capfd):
    out = tmp_path / "run"

    def stop(point):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_scene(_study(), out, progress=False, jobs=2, on_point=stop)
    err = capfd.readouterr().err
    assert "interrupted" in err and "rerun the same command to resume" in err
    assert not out.exists()  # nothing written to the output folder yet
    stream = tmp_path / ".run.kegel-staging" / "points.jsonl"
    records = {r["point"]["index"]: r["point"] for r in map(json.loads, stream.read_text().splitlines()[1:])}
    kept = sorted(records)
    assert 0 in kept and len(stream.read_text().splitlines()) == 1 + len(kept)
    res = run_scene(_study(), out, progress=False, jobs=2)
    assert f"{len(kept)} of 5 point(s) already solved" in capfd.readouterr().err
    # the kept points as they were; a point whose chain predecessor was kept starts from a
    # fresh state instead of the predecessor's: equal to the solver's tolerance, not its rounding
    keys = ("index", "converged", "friction_torque_Nm", "total_torque_Nm", "cage_slip", "study")
    _same([{k: p[k] for k in keys} for p in res.points], [{k: p[k] for k in keys} for p in serial], rel=1e-8)
    assert [p for p in res.points if p["index"] in records] == [records[i] for i in kept]  # kept as they were
    assert not stream.exists() and (out / "results.json").is_file()


def test_dask_local_cluster_study_equals_the_serial_run(serial, chain_of_two):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None,
                                  silence_logs=40) as cluster, distributed.Client(cluster) as client:
        res = run_scene(_study(), write=False, progress=False, client=client)
        assert len({w for w in client.scheduler_info()["workers"]}) == 2
    _same(res.points, serial)


CALLS: list[tuple[float, str]] = []


def _stub_case(point, case: Path, args) -> dict:
    """The case runner of ``kegel cfd sweep`` without OpenFOAM: a loss torque from the speed."""
    rpm = point.speed_rad_s * 30 / math.pi
    CALLS.append((rpm, case.name))
    t = {"total": -1e-5 * rpm, "pressure": 0.0, "viscous": -1e-5 * rpm}
    return {"loss_torque_at_shaft_Nm": 2e-5 * rpm, "torques_Nm": {"inner_ring": t, "outer_ring": t},
            "liebrecht_Nm": {"total_Nm": 4e-5 * rpm}, "runtime_s": 1.0, "fidelity": {"cells": 1000}}


def test_cfd_sweep_runs_one_dask_task_per_case(monkeypatch, tmp_path, capsys):
    distributed = pytest.importorskip("distributed")
    from kegel.cfd_cases import cli as cfd_cli
    from kegel.cli import main

    monkeypatch.setattr(cfd_cli, "_run_one", _stub_case)
    CALLS.clear()
    # workers that declare their cores: a case on --np 2 is annotated with 2 of them
    with distributed.LocalCluster(n_workers=1, processes=False, threads_per_worker=2, resources={"cores": 2},
                                  dashboard_address=None, silence_logs=40) as cluster:
        with distributed.Client(cluster) as client:
            assert P.task_resources(client, 2) == {"cores": 2}
        code = main(["cfd", "sweep", "--speed", "500 rpm", "--speed", "1000 rpm", "--speed", "2000 rpm",
                     "--np", "2", "--scheduler", cluster.scheduler_address, "--output", str(tmp_path / "sweep"),
                     "--quiet"])
    assert code == 0
    assert sorted(round(rpm) for rpm, _ in CALLS) == [500, 1000, 2000]  # each case once
    rows = json.loads((tmp_path / "sweep" / "sweep.json").read_text())["rows"]
    assert [round(r["speed_rpm"]) for r in rows] == [500, 1000, 2000]  # the command line's order
    assert [r["cfd_loss_torque_Nm"] for r in rows] == pytest.approx([0.01, 0.02, 0.04])
    assert {Path(r["case"]).parent for r in rows} == {tmp_path / "sweep"}


def test_cfd_sweep_refuses_a_case_bigger_than_every_worker():
    distributed = pytest.importorskip("distributed")
    from kegel.errors import KegelInputError

    with distributed.LocalCluster(n_workers=1, processes=False, threads_per_worker=1, resources={"cores": 2},
                                  dashboard_address=None, silence_logs=40) as cluster, \
            distributed.Client(cluster) as client:
        with pytest.raises(KegelInputError, match="at least 4 cores"):
            P.task_resources(client, 4)
