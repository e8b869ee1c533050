"""Scene loading, sweeps, overrides, fidelity presets and `kegel run` output files."""

from __future__ import annotations

import json
import math

import pytest

import kegel
from conftest import EXAMPLES, run_kegel

EXAMPLE_FILES = sorted(EXAMPLES.glob("*.toml"))


def test_the_paper_scenes_exist():
    names = {p.name for p in EXAMPLE_FILES}
    assert {"32216_table1.toml", "32216_table2.toml", "32216_table3.toml", "32208_flooded.toml"} <= names


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.name)
def test_every_example_is_valid(path):
    res = run_kegel("check", str(path))
    assert res.returncode == 0, res.stderr
    assert "valid scene" in res.stdout


def test_table1_sweep_matches_reference_conditions():
    s = kegel.load_scene(EXAMPLES / "32216_table1.toml")
    assert s.bearing.designation == "32216" and s.lubricant.name == "FVA3"
    assert s.swept == ("temperature", "speed")
    assert len(s.operating_points) == 16
    speeds = sorted({round(p.speed_rpm, 9) for p in s.operating_points})
    assert speeds[0] == pytest.approx(500) and speeds[-1] == pytest.approx(4000) and len(speeds) == 8
    assert {round(p.temperature_degC, 9) for p in s.operating_points} == {42.0, 50.0}
    assert all(p.axial_load_N == pytest.approx(6000) and p.radial_load_N == 0 for p in s.operating_points)
    # speed varies fastest
    assert s.operating_points[1].speed_rpm > s.operating_points[0].speed_rpm
    assert s.lubrication.mode == "oil_bath"
    assert s.lubrication.oil_level_m == pytest.approx(0.5 * (0.140 - 0.1085))


def test_table3_radial_sweep():
    s = kegel.load_scene(EXAMPLES / "32216_table3.toml")
    assert s.swept == ("radial_load",)
    loads = [p.radial_load_N for p in s.operating_points]
    assert loads[0] == pytest.approx(1000) and loads[-1] == pytest.approx(15000) and len(loads) == 15
    assert all(p.speed_rpm == pytest.approx(2000) for p in s.operating_points)


def test_flooded_32208():
    s = kegel.load_scene(EXAMPLES / "32208_flooded.toml")
    assert s.lubrication.oil_level_m == pytest.approx(0.080)
    assert s.fidelity.hydraulic == "correlation"
    mql = kegel.load_scene(EXAMPLES / "32208_flooded.toml",
                           ["lubrication.mode=minimum_quantity", "lubrication.oil_level=none"])
    assert mql.lubrication.oil_level_m == 0.0 and mql.fidelity.hydraulic == "none"


def test_overrides_set_values_of_any_type():
    s = kegel.load_scene(
        EXAMPLES / "32216_table1.toml",
        ["operating.axial_load=6.5 kN", 'operating.temperature=["60 degC"]', "model.slices=12",
         'operating.speed={from = "1000 rpm", to = "2000 rpm", points = 3}', "model.cage=false"],
    )
    assert all(p.axial_load_N == pytest.approx(6500) for p in s.operating_points)
    assert {round(p.temperature_degC, 9) for p in s.operating_points} == {60.0}
    assert len(s.operating_points) == 3
    assert s.fidelity.slices == 12 and s.fidelity.cage is False and s.fidelity.name == "default+custom"


def test_displacement_controlled_preload():
    from kegel._toml import read_toml

    raw = read_toml(EXAMPLES / "32216_table3.toml")
    del raw["operating"]["axial_load"]
    raw["operating"]["axial_offset"] = "25 um"
    s = kegel.scene.scene_from_dict(raw)
    assert all(p.axial_load_N is None and p.axial_offset_m == pytest.approx(25e-6) for p in s.operating_points)


@pytest.mark.parametrize("preset", ["fast", "default", "fine"])
def test_fidelity_presets(preset):
    s = kegel.load_scene(EXAMPLES / "32216_table1.toml", [f"model.fidelity={preset}"])
    assert s.fidelity.name == preset
    assert s.fidelity.slices == kegel.scene.FIDELITY_PRESETS[preset]["slices"]


def test_oil_level_keywords_and_lengths():
    base = EXAMPLES / "32216_table1.toml"
    assert kegel.load_scene(base, ["lubrication.oil_level=flooded"]).lubrication.oil_level_m == pytest.approx(0.14)
    assert kegel.load_scene(base, ["lubrication.oil_level=shaft_center"]).lubrication.oil_level_m == pytest.approx(0.07)
    assert kegel.load_scene(base, ["lubrication.oil_level=35 mm"]).lubrication.oil_level_m == pytest.approx(0.035)


def test_run_writes_results_plots_and_provenance_atomically(tmp_path):
    out = tmp_path / "out"
    res = run_kegel("run", str(EXAMPLES / "32216_table1.toml"), "--output", str(out),
                    "--set", "operating.temperature=50 degC", "--set", 'operating.speed=["500 rpm", "4000 rpm"]',
                    "--set", "model.slices=12")
    assert res.returncode == 0, res.stderr
    assert "M_fric [Nm]" in res.stdout and "results:" in res.stdout and "plots:" in res.stdout
    files = sorted(p.name for p in out.iterdir())
    # .kegel-manifest.json: the files kegel wrote, the only ones it will replace (issue 28)
    assert files == [".kegel-manifest.json", "breakdown.png", "results.csv", "results.json",
                     "roller_loads_and_slip.png", "torque.png"]
    assert sorted(json.loads((out / ".kegel-manifest.json").read_text())["files"]) == files[1:]
    data = json.loads((out / "results.json").read_text())
    assert data["provenance"]["kegel_version"] == kegel.__version__
    assert data["provenance"]["sundials_version"].startswith("6.")
    assert data["fidelity"]["slices"] == 12
    assert data["scene"]["resolved"]["operating"]["temperature"] == "50 degC"
    pts = data["points"]
    assert len(pts) == 2
    for p in pts:
        assert p["lubricant_state"]["dynamic_viscosity_Pas"] == pytest.approx(0.0525, rel=5e-3)
        assert abs(p["power_balance_error"]) < 5e-3
        assert p["total_torque_Nm"] == pytest.approx(p["friction_torque_Nm"] + p["hydraulic_torque_Nm"])
        assert p["hydraulic_torque_Nm"] > 0  # an oil bath
        assert sum(p["torque_by_contact_Nm"].values()) == pytest.approx(p["friction_torque_Nm"], rel=5e-3)
    assert pts[1]["friction_torque_Nm"] > pts[0]["friction_torque_Nm"]
    csv_lines = (out / "results.csv").read_text().splitlines()
    assert len(csv_lines) == 3 and csv_lines[0].startswith("index,speed_rpm")


def test_run_json_on_stdout(tmp_path):
    res = run_kegel("run", str(EXAMPLES / "32208_flooded.toml"), "--output", str(tmp_path), "--format", "json",
                    "--set", 'operating.speed=["1000 rpm", "3000 rpm"]', "--set", "model.slices=10")
    assert res.returncode == 0, res.stderr
    data = json.loads(res.stdout)
    assert len(data["points"]) == 2 and data["files"]["json"].endswith("results.json")
    assert all(p["hydraulic"]["correlation"] == "liebrecht" for p in data["points"])


def test_check_json():
    res = run_kegel("check", str(EXAMPLES / "32216_table2.toml"), "--format", "json")
    data = json.loads(res.stdout)
    assert data["valid"] is True and data["operating_point_count"] == 16


def test_atomic_write_leaves_old_file_on_failure(tmp_path):
    from kegel.io import atomic_write_json

    target = tmp_path / "r.json"
    atomic_write_json(target, {"a": 1})
    with pytest.raises(ValueError):
        atomic_write_json(target, {"a": float("nan")})  # results must be finite
    assert json.loads(target.read_text()) == {"a": 1}
    assert [p.name for p in tmp_path.iterdir()] == ["r.json"]


_AUTO = {"bearing": {"designation": "32216"}, "lubricant": {"name": "FVA3"},
         "operating": {"axial_load": "6 kN", "speed": ["500 rpm", "4000 rpm"], "temperature": "50 degC"},
         "lubrication": {"mode": "minimum_quantity"}}


@pytest.mark.parametrize("tolerance,chosen", [(0.5, "fast"), ("1 %", "default"), (1e-9, "fine")])
def test_auto_fidelity_takes_the_cheapest_level_within_the_tolerance(tolerance, chosen, tmp_path):
    from kegel.run import choose_fidelity, run_scene

    s = kegel.scene.scene_from_dict({**_AUTO, "model": {"fidelity": "auto", "tolerance": tolerance}})
    fid, rec = choose_fidelity(s)
    levels = rec["levels"]
    # the deviations are measured against fine at the first and the last point
    assert rec["checked_points"] == [0, 1] and levels["fine"]["deviation_from_fine"] == 0.0
    for name, row in levels.items():
        dev = max(abs(t / f - 1) for t, f in zip(row["torques_Nm"], levels["fine"]["torques_Nm"]))
        assert row["deviation_from_fine"] == pytest.approx(dev, rel=1e-12)
    assert rec["chosen"] == chosen and fid.name == f"auto:{chosen}"
    assert fid.slices == kegel.scene.FIDELITY_PRESETS[chosen]["slices"]
    cheaper = kegel.run.AUTO_LEVELS[:kegel.run.AUTO_LEVELS.index(chosen)]
    assert all(levels[c]["deviation_from_fine"] > rec["tolerance"] for c in cheaper)
    assert levels[chosen]["deviation_from_fine"] <= rec["tolerance"]
    # a run records the choice and runs at the chosen level
    if chosen == "default":
        res = run_scene(s, tmp_path, progress=False)
        out = json.loads((tmp_path / "results.json").read_text())
        assert out["fidelity"]["name"] == "auto:default" and out["fidelity_choice"]["chosen"] == "default"
        assert res.points[1]["friction_torque_Nm"] == pytest.approx(levels["default"]["torques_Nm"][1], rel=1e-6)


@pytest.mark.parametrize("model,key", [
    ({"fidelity": "auto", "slices": 20}, "model.slices"),
    ({"fidelity": "auto", "solution": "dynamic"}, "model.solution"),
    ({"fidelity": "default", "tolerance": 0.01}, "model.tolerance"),
    ({"fidelity": "auto", "tolerance": 0.0}, "model.tolerance"),
    ({"fidelity": "auto", "tolerance": "one percent"}, "model.tolerance"),
])
def test_auto_fidelity_keys_are_checked(model, key):
    with pytest.raises(kegel.KegelInputError, match=key.replace(".", r"\.")):
        kegel.scene.scene_from_dict({**_AUTO, "model": model})
