"""Outputs that never mislead (issue 20, items 1, 2, 4 and 5): studies as one command, warnings
printed once and recorded per point, a complete CSV, labels from the resolved scene, checks before
anything runs, failed points kept beside finished ones, file modes from the umask, no silent
overwrite of another run's results."""

from __future__ import annotations

import csv
import io
import json
import math
import os
import stat
from pathlib import Path

import pytest

from conftest import EXAMPLES, run_kegel

import kegel
from kegel.coupling import cfd_loss_at
from kegel.point_warnings import COMPARED_RANGE
from kegel.run import run_scene
from kegel.scene import load_scene, scene_from_dict

STUDY = """
[scene]
name = "study test"
[bearing]
designation = "32208"
[lubricant]
name = "FVA3"
[operating]
axial_load = "1 kN"
speed = ["500 rpm", "1000 rpm", "2000 rpm", "3000 rpm"]
temperature = "50 degC"
[study]
lubrication = ["flooded", "shaft_center", "minimum_quantity"]
hydraulic = ["liebrecht", "skf", "cfd"]
cfd_results = "cfd"
[model]
fidelity = "fast"
"""


def _fake_cfd(folder: Path, rpm: float, loss_Nm: float, *, level_m: float | None = None, cells: int = 1000,
              steady: bool = True) -> None:
    """A minimal ``kegel cfd run`` results.json (the keys the study reads)."""
    d = folder / f"case_{rpm:.0f}_{'flooded' if level_m is None else level_m}_{cells}"
    d.mkdir(parents=True)
    (d / "results.json").write_text(json.dumps({
        "point": {"bearing": "32208", "lubricant": "FVA3", "speed_rad_s": rpm * math.pi / 30,
                  "temperature_K": 323.15, "oil_level_m": level_m},
        "kinematics": {}, "loss_torque_at_shaft_Nm": loss_Nm, "steady": steady, "runtime_s": 100.0,
        "fidelity": {"mesh": "tiny", "cells": cells}}))


def test_a_study_gives_every_lubrication_and_method_in_one_run(tmp_path, monkeypatch):
    """Finding 1: flooded vs minimum quantity, Liebrecht vs SKF vs CFD were separate runs and a
    manual merge; a CFD result had to exist for every speed. Now one scene gives them side by
    side; CFD between computed speeds is interpolated with a stated error, outside them it is
    missing and names the command that computes it."""
    monkeypatch.chdir(tmp_path)
    # flooded CFD: a power law T = 0.06 (n / 2000)^1.2 at 1000, 2000 (coarse and finer mesh), 3000
    for rpm in (1000.0, 2000.0, 3000.0):
        _fake_cfd(tmp_path / "cfd", rpm, 0.06 * (rpm / 2000) ** 1.2)
    _fake_cfd(tmp_path / "cfd", 2000.0, 0.07, cells=5000)  # the finer mesh wins
    (tmp_path / "s.toml").write_text(STUDY)
    res = run_kegel("run", "s.toml", "--output", "out", cwd=tmp_path)
    assert res.returncode == 0, res.stderr
    data = json.loads((tmp_path / "out" / "results.json").read_text())
    assert data["study"]["hydraulic"] == ["liebrecht", "skf", "cfd"]
    by = {}
    for p in data["points"]:
        rows = p["study"]
        assert len(rows) == 2 * 3 + 1  # two oil levels x three methods, minimum quantity once
        for r in rows:
            by[(p["speed_rpm"], r["lubrication"], r["method"])] = r
            if r["total_torque_Nm"] is not None:
                # each lubrication's own contact friction (its oil supply: kegel.supply)
                assert r["total_torque_Nm"] == pytest.approx(r["friction_torque_Nm"] + r["hydraulic_torque_Nm"])
                if r["lubrication"] == "flooded":
                    assert r["friction_torque_Nm"] == pytest.approx(p["friction_torque_Nm"])
                else:
                    assert r["friction_torque_Nm"] < p["friction_torque_Nm"]
    assert by[(500.0, "minimum_quantity", "none")]["hydraulic_torque_Nm"] == 0.0
    assert by[(2000.0, "flooded", "cfd")]["hydraulic_torque_Nm"] == pytest.approx(0.07)  # finest mesh
    assert by[(2000.0, "flooded", "cfd")]["status"] == "computed"
    missing = by[(500.0, "flooded", "cfd")]
    assert missing["status"] == "missing" and missing["total_torque_Nm"] is None
    assert "kegel cfd run --bearing 32208" in missing["command"] and "'500 rpm'" in missing["command"]
    assert by[(1000.0, "shaft_center", "cfd")]["status"] == "missing"  # no oil-bath result at all
    text = (tmp_path / "out" / "study.csv").read_text()
    rows = list(csv.DictReader(io.StringIO(text)))
    assert len(rows) == 4 * 7
    assert {r["method"] for r in rows} == {"liebrecht", "skf", "cfd", "none"}
    assert (tmp_path / "out" / "study.png").is_file()
    assert "Study: total torque" in res.stdout and "missing" in res.stdout
    assert res.stderr.count("[cfd_missing]") == 1  # printed once per run


def test_cfd_interpolation_states_its_error():
    """Between computed speeds: a power law (exact for power-law data), its error from leaving out
    a computed neighbour; with two speeds no estimate; never an extrapolation."""
    def results(pairs):
        return [(Path(f"r{i}.json"), {"point": {"bearing": "32208", "lubricant": "FVA3",
                                                "speed_rad_s": n * math.pi / 30, "temperature_K": 323.15,
                                                "oil_level_m": None},
                                      "loss_torque_at_shaft_Nm": t, "fidelity": {"cells": 1}, "steady": True})
                for i, (n, t) in enumerate(pairs)]

    kw = dict(bearing="32208", lubricant="FVA3", temperature_K=323.15, oil_level_m=0.08, flooded=True)
    law = results([(n, 1e-4 * n ** 1.3) for n in (500, 1000, 2000, 4000)])
    c = cfd_loss_at(law, speed_rad_s=1500 * math.pi / 30, **kw)
    assert c["status"] == "interpolated"
    assert c["loss_torque_at_shaft_Nm"] == pytest.approx(1e-4 * 1500 ** 1.3, rel=1e-12)
    assert c["error_rel"] == pytest.approx(0.0, abs=1e-12)
    bent = results([(500, 0.010), (1000, 0.025), (2000, 0.065), (4000, 0.169)])
    c = cfd_loss_at(bent, speed_rad_s=3000 * math.pi / 30, **kw)
    # leave 2000 out: predicted from 1000 and 4000 as 0.025 * 2^(log(0.169/0.025)/log 4)
    pred = 0.025 * 2 ** (math.log(0.169 / 0.025) / math.log(4))
    assert c["error_rel"] == pytest.approx(abs(pred / 0.065 - 1), rel=1e-9)
    two = results([(1000, 0.025), (2000, 0.065)])
    c = cfd_loss_at(two, speed_rad_s=1500 * math.pi / 30, **kw)
    assert c["error_rel"] is None and "no estimate" in c["note"]
    assert cfd_loss_at(two, speed_rad_s=3000 * math.pi / 30, **kw)["status"] == "missing"


def test_an_unsettled_cfd_result_is_flagged(tmp_path, monkeypatch):
    """A CFD result whose wall torques do not sum to zero (the oil still gaining or losing angular
    momentum) is not a settled loss: the study warns (cfd_unbalanced) and marks its cell with '!';
    within the limit, as every flooded mesh level is, no warning."""
    from kegel.coupling.cfd_results import BALANCE_LIMIT

    monkeypatch.chdir(tmp_path)
    for rpm, bal in ((1000.0, 0.81), (2000.0, -0.8 * BALANCE_LIMIT)):
        _fake_cfd(tmp_path / "cfd", rpm, 0.03 * rpm / 1000)
        f = next((tmp_path / "cfd").glob(f"case_{rpm:.0f}_*")) / "results.json"
        data = json.loads(f.read_text())
        data["angular_momentum_balance"] = {"relative_to_drive_torque": bal}
        f.write_text(json.dumps(data))
    kw = dict(bearing="32208", lubricant="FVA3", temperature_K=323.15, oil_level_m=0.08, flooded=True)
    from kegel.coupling.cfd_results import read_cfd_results
    runs = read_cfd_results(str(tmp_path / "cfd"))
    assert cfd_loss_at(runs, speed_rad_s=1000 * math.pi / 30, **kw)["balance"] == pytest.approx(0.81)
    assert cfd_loss_at(runs, speed_rad_s=1500 * math.pi / 30, **kw)["balance"] == pytest.approx(0.81)
    (tmp_path / "s.toml").write_text(STUDY.replace('"500 rpm", ', ""))
    res = run_kegel("run", "s.toml", "--output", "out", cwd=tmp_path)
    assert res.returncode == 0, res.stderr
    assert res.stderr.count("[cfd_unbalanced]") == 1 and "+81 %" in res.stderr
    # the shared reading (coupling.cfd_results.unbalanced_reason), not a message of its own
    assert "frozen rotor's MRF term" in res.stderr.replace("\n", " ")
    data = json.loads((tmp_path / "out" / "results.json").read_text())
    flagged = {(p["speed_rpm"], r["lubrication"]) for p in data["points"] for r in p["study"]
               if any(w["code"] == "cfd_unbalanced" for w in r["warnings"])}
    assert (1000.0, "flooded") in flagged and (2000.0, "flooded") not in flagged
    line = next(x for x in res.stdout.splitlines() if " 1000 " in x and "flooded" in x)
    assert line.rstrip().endswith("!")


def test_an_unbalanced_result_is_flagged_on_either_side_with_one_reading():
    """Beyond BALANCE_LIMIT on either side a result is unbalanced; the reading every place
    prints states the figure with its sign and the limit."""
    from kegel.coupling.cfd_results import BALANCE_LIMIT, is_unbalanced, unbalanced_reason

    assert is_unbalanced(-1.01 * BALANCE_LIMIT) and is_unbalanced(1.01 * BALANCE_LIMIT)
    assert not is_unbalanced(BALANCE_LIMIT) and not is_unbalanced(-0.99 * BALANCE_LIMIT)
    assert not is_unbalanced(None)
    r = unbalanced_reason(-0.3)
    assert "-30 %" in r and f"within {100 * BALANCE_LIMIT:.0f} %" in r and "unconfirmed" in r


def test_the_angular_momentum_balance_counts_the_weight_of_an_oil_bath():
    """In an oil bath the walls' torques sum to the moment of the oil's weight, not to zero (the
    flow holds the oil up on one side): the balance subtracts it; an oil-bath result that does not
    state it has no balance (never a false alarm), a flooded one needs none."""
    from kegel.cfd_cases.run import angular_momentum_balance as _balance
    from kegel.coupling.cfd_results import balance_of

    t = {k: {"total": v} for k, v in (("inner_ring", -1.5e-3), ("shaft", -0.5e-3), ("outer_ring", 2.5e-3),
                                        ("housing", 2.7e-3), ("cage", -1.0e-3), ("rollers_about_bearing_axis", -0.3e-3))}
    b = _balance(t, {"torque_Nm": 1.8e-3, "states_s": [0.24]})
    assert b["sum_of_wall_torques_Nm"] == pytest.approx(1.9e-3)
    assert b["relative_to_drive_torque"] == pytest.approx((1.9e-3 - 1.8e-3) / 2.0e-3)
    assert _balance(t)["relative_to_drive_torque"] == pytest.approx(1.9e-3 / 2.0e-3)
    bath = {"point": {"oil_level_m": 0.04}, "angular_momentum_balance": b}
    assert balance_of(bath) == pytest.approx(0.05)
    old = {"point": {"oil_level_m": 0.04}, "angular_momentum_balance": _balance(t)}
    assert balance_of(old) is None
    assert balance_of({"point": {"oil_level_m": None}, "angular_momentum_balance": _balance(t)}) == pytest.approx(0.95)


@pytest.mark.parametrize("extra, key", [
    ('[lubrication]\nmode = "oil_bath"\noil_level = "flooded"\n', "lubrication"),
    ('[study]\nlubrication = ["flooded", "flooded"]\n', "study.lubrication[1]"),
    ('[study]\nlubrication = ["flooded"]\nhydraulic = ["petrov"]\n', "study.hydraulic[0]"),
    ('[study]\nlubrication = ["flooded"]\nhydraulic = ["cfd"]\n', "study.cfd_results"),
    ('[study]\nlubrication = ["flooded"]\ncfd_results = "x"\n', "study.cfd_results"),
    ('[study]\nlubrication = ["2 m"]\n', "study.lubrication[0]"),
])
def test_study_errors_name_the_key(tmp_path, extra, key):
    base = STUDY.split("[study]")[0] + "[model]\nfidelity = \"fast\"\n"
    if extra.startswith("[lubrication]"):
        text = STUDY + extra
    else:
        text = base + extra
    f = tmp_path / "s.toml"
    f.write_text(text)
    with pytest.raises(kegel.KegelInputError) as e:
        load_scene(f)
    assert key in str(e.value)


def _run(tmp_path: Path, *args: str, scene: str = "examples/32216_table3.toml") -> tuple:
    res = run_kegel("run", str(EXAMPLES.parent / scene), "--set", 'model.fidelity="fast"', *args,
                    "--output", str(tmp_path / "out"))
    return res, tmp_path / "out"


def test_warnings_are_printed_once_and_recorded_per_point(tmp_path):
    """Finding 2: no warning anywhere (Liebrecht outside its fitted regime, parameters marked
    verify, ...); results.csv lacked cage_model, Lambda_min, converged and the hydraulic parts."""
    res, out = _run(tmp_path)
    assert res.returncode == 0, res.stderr
    for code in ("liebrecht_extrapolated", "parameters_to_verify", "skf_constants_to_verify"):
        assert res.stderr.count(f"[{code}]") == 1, res.stderr
    data = json.loads((out / "results.json").read_text())
    assert data["warnings"]["points_per_code"]["liebrecht_extrapolated"] == 15
    assert all({"code", "message"} <= set(w) for p in data["points"] for w in p["warnings"])
    rows = list(csv.DictReader(io.StringIO((out / "results.csv").read_text())))
    assert len(rows) == 15
    for col in ("cage_model", "Lambda_min", "converged", "hydraulic_source", "hydraulic_inner_ring_Nm",
                "hydraulic_cage_Nm", "skf_total_Nm", "warnings", "failure", "pocket_fraction"):
        assert col in rows[0], col
    assert rows[0]["hydraulic_source"] == "liebrecht"
    assert "liebrecht_extrapolated" in rows[0]["warnings"]
    assert float(rows[0]["Lambda_min"]) > 0 and rows[0]["converged"] == "True"


def test_mixed_lubrication_and_range_warnings(tmp_path):
    """Lambda < 1 and a point outside the conditions kegel has been compared at are warned."""
    s = scene_from_dict({"bearing": {"designation": "32216"}, "lubricant": {"name": "FVA3"},
                         "operating": {"axial_load": "6 kN", "speed": ["20 rpm", "2000 rpm"],
                                       "temperature": "100 degC"},
                         "lubrication": {"mode": "minimum_quantity"}, "model": {"fidelity": "fast"}})
    pts = run_scene(s, write=False, progress=False).points
    codes = [{w["code"] for w in p["warnings"]} for p in pts]
    assert "mixed_lubrication" in codes[0] and "outside_compared_range" in codes[0]
    assert "mixed_lubrication" not in codes[1]


def test_rib_edge_loading_is_recorded_and_warned():
    """A point records how many rollers' rib contacts an edge cuts (rib_edge_rollers, the rib
    cell model: kegel._core.quasi_static.RibPressure); a count above zero is warned."""
    from kegel.point_warnings import point_warnings

    s = scene_from_dict({"bearing": {"designation": "32216"}, "lubricant": {"name": "FVA3"},
                         "operating": {"axial_load": "6 kN", "radial_load": "6.5 kN", "speed": "2000 rpm",
                                       "temperature": "50 degC"},
                         "lubrication": {"mode": "oil_bath", "oil_level": "half_roller"}})
    (p,) = run_scene(s, write=False, progress=False).points
    assert p["rib_edge_rollers"] == 0
    assert "rib_edge_loading" not in {w["code"] for w in p["warnings"]}
    edged = point_warnings(s, {**p, "rib_edge_rollers": 3})
    (w,) = [w for w in edged if w.code == "rib_edge_loading"]
    assert w.message.startswith("3 roller(s)")


def test_compared_range_is_the_example_scenes_range():
    """COMPARED_RANGE must cover exactly the conditions kegel validate compares at (the Table 1-3
    scenes): recomputed here, so a change of the scenes cannot leave it stale."""
    from kegel.lubricant import lubricant_state
    from kegel.validation import SKF_SCENES

    ndm, nun = [], []
    for name in SKF_SCENES:
        s = load_scene(EXAMPLES / name)
        for p in s.operating_points:
            n = p.speed_rpm
            nu = lubricant_state(s.lubricant, p.temperature_K).kinematic_viscosity_m2_s * 1e6
            ndm.append(n * s.geometry.pitch_diameter_m * 1e3)
            nun.append(nu * n)
    for key, vals in (("speed_factor_rpm_mm", ndm), ("nu_n_mm2_s_rpm", nun)):
        lo, hi = COMPARED_RANGE[key]
        assert lo <= min(vals) and max(vals) <= hi, key
        assert min(vals) / lo < 1.02 and hi / max(vals) < 1.02, key  # tight, not a loose blanket


def test_labels_come_from_the_resolved_scene(tmp_path):
    """Finding 2: "Fa = 6 kN" printed for a 6.5 kN run and "fully flooded" for a minimum-quantity
    run: the title carries the --set changes and the description is marked as the file's words."""
    res = run_kegel("run", str(EXAMPLES / "32208_flooded.toml"), "--set", "lubrication.mode=minimum_quantity",
                    "--set", "lubrication.oil_level=none", "--set", 'model.fidelity="fast"',
                    "--set", 'operating.speed="2000 rpm"', "--output", str(tmp_path / "out"))
    assert res.returncode == 0, res.stderr
    assert "--set lubrication.mode=minimum_quantity" in res.stdout.splitlines()[0]
    assert "as written in the scene file, before --set" in res.stdout
    assert "minimum quantity" in res.stdout.splitlines()[2]
    data = json.loads((tmp_path / "out" / "results.json").read_text())
    assert "lubrication.oil_level" in data["scene"]["overridden"]
    assert "minimum_quantity" in data["scene"]["title"]
    assert data["lubrication"]["label"] == "minimum quantity"


def test_check_rejects_what_run_would_reject_for_every_point(tmp_path):
    """Finding 4: `kegel check` passed a radial-load sweep whose second point lifts the inner ring
    off; `kegel run` then failed at that point with an internal name (axial_N) and saved nothing."""
    args = ("--set", 'operating.axial_load="1 kN"', "--set", 'operating.radial_load=["1 kN","5 kN","16 kN"]')
    for cmd in ("check", "run"):
        res = run_kegel(cmd, str(EXAMPLES / "32216_table3.toml"), *args, "--output" if cmd == "run" else "--format",
                        str(tmp_path / "o") if cmd == "run" else "table")
        assert res.returncode == 2, (cmd, res.stderr)
        assert "operating.radial_load" in res.stderr and "point 1" in res.stderr and "axial_N" not in res.stderr
        assert "Traceback" not in res.stderr
    assert not (tmp_path / "o").exists()


def test_a_point_whose_solver_raises_is_recorded_and_the_run_goes_on(tmp_path, monkeypatch):
    """Finding 4: one failure lost everything. Now the point is recorded as failed with its message
    and the other points finish and are written."""
    import kegel.run as R

    real = R._quasi_static_record

    def flaky(scene, fid, op, *a, **k):
        if op.index == 1:
            raise kegel.KegelSolverError("load distribution diverged (test)")
        return real(scene, fid, op, *a, **k)

    monkeypatch.setattr(R, "_quasi_static_record", flaky)
    s = load_scene(EXAMPLES / "32216_table3.toml", ['model.fidelity="fast"', 'operating.radial_load=["1 kN", '
                                                    '"2 kN", "3 kN"]'])
    res = run_scene(s, tmp_path / "out", progress=False)
    assert [p["converged"] for p in res.points] == [True, False, True]
    assert "diverged (test)" in res.points[1]["failure"]
    rows = list(csv.DictReader(io.StringIO((tmp_path / "out" / "results.csv").read_text())))
    assert rows[1]["friction_torque_Nm"] == "" and "not_converged" in rows[1]["warnings"]
    assert (tmp_path / "out" / "torque.png").is_file()


def test_result_files_respect_the_umask(tmp_path):
    """Finding 5: every result file was 0600 whatever the umask (mkstemp, no chmod)."""
    old = os.umask(0o022)
    try:
        s = load_scene(EXAMPLES / "32216_table3.toml", ['model.fidelity="fast"', 'operating.radial_load="1 kN"'])
        run_scene(s, tmp_path / "out", progress=False)
    finally:
        os.umask(old)
    files = [f for f in (tmp_path / "out").iterdir() if f.is_file()]
    assert {f.name for f in files} >= {"results.json", "results.csv", "torque.png"}
    for f in files:
        assert stat.S_IMODE(f.stat().st_mode) == 0o644, f


def test_another_runs_results_are_never_replaced_silently(tmp_path):
    s1 = load_scene(EXAMPLES / "32216_table3.toml", ['model.fidelity="fast"', 'operating.radial_load="1 kN"'])
    run_scene(s1, tmp_path / "out", progress=False)
    first = json.loads((tmp_path / "out" / "results.json").read_text())["run_id"]
    res = run_kegel("run", str(EXAMPLES / "32216_table3.toml"), "--set", 'model.fidelity="fast"',
                    "--set", 'operating.radial_load="2 kN"', "--output", str(tmp_path / "out"))
    assert res.returncode == 0, res.stderr
    assert f"run id {first}" in res.stderr and "replaced" in res.stderr
    assert json.loads((tmp_path / "out" / "results.json").read_text())["run_id"] != first


def test_cfd_sweep_checks_every_case_before_the_first_runs(tmp_path):
    """Finding 4: `cfd sweep` checked its second speed only after the first case had run (an
    hour of CFD). Now a bad second speed stops it before any case folder exists."""
    res = run_kegel("cfd", "sweep", "--speed", "2000 rpm", "--speed", "0 rpm", "--output", str(tmp_path / "sw"),
                    timeout=60)
    assert res.returncode == 2 and "'0 rpm'" in res.stderr, res.stderr
    assert not (tmp_path / "sw").exists()


def test_check_finds_a_missing_cfd_result_for_any_point(tmp_path, monkeypatch):
    """`kegel check` checks each point's CFD result (hydraulic = "cfd") as `kegel run` does
    before its first point."""
    monkeypatch.chdir(tmp_path)
    _fake_cfd(tmp_path / "cfd", 2000.0, 0.06)
    scene = STUDY.split("[study]")[0].replace('speed = ["500 rpm", "1000 rpm", "2000 rpm", "3000 rpm"]',
                                              'speed = ["2000 rpm", "3000 rpm"]')
    scene += '[lubrication]\nmode = "oil_bath"\noil_level = "flooded"\n[model]\nhydraulic = "cfd"\ncfd_results = "cfd"\n'
    (tmp_path / "s.toml").write_text(scene)
    res = run_kegel("check", "s.toml", cwd=tmp_path)
    assert res.returncode == 2 and "3000 rpm" in res.stderr and "model.cfd_results" in res.stderr, res.stderr
    (tmp_path / "s.toml").write_text(scene.replace('["2000 rpm", "3000 rpm"]', '"2000 rpm"'))
    assert run_kegel("check", "s.toml", cwd=tmp_path).returncode == 0


def test_results_json_is_written_record_by_record_with_the_same_text(tmp_path):
    """Bounded memory (issue 21): results.json is written one point at a time, never as one
    string of the whole sweep; the file is the same as the one-piece writer's, text for text."""
    from kegel.io import atomic_write_json, atomic_write_json_records

    header = {"scene": {"resolved": {"operating": {"speed": {"from": "1 rpm", "points": 8}}}}, "points": None,
              "after": [1, 2]}
    recs = [{"index": i, "x": [0.5, {"y": "a\nb"}], "points": []} for i in range(4)]
    atomic_write_json_records(tmp_path / "a.json", header, "points", iter(recs))
    atomic_write_json(tmp_path / "b.json", {**header, "points": recs})
    assert (tmp_path / "a.json").read_text() == (tmp_path / "b.json").read_text()
    atomic_write_json_records(tmp_path / "e.json", {"points": None}, "points", iter(()))
    assert json.loads((tmp_path / "e.json").read_text()) == {"points": []}
    with pytest.raises(ValueError):
        atomic_write_json_records(tmp_path / "n.json", {"points": None}, "points", iter([{"v": float("nan")}]))
    assert not (tmp_path / "n.json").exists() and not list(tmp_path.glob(".n*"))
