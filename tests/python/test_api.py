"""The Python facade (kegel.api): one torque in three lines, with units, in memory; short reprs;
errors that name the argument; the _core stubs in step with the built module."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import kegel
from kegel.units import RPM_TO_RAD_S

REL = 1e-12


@pytest.fixture(scope="module")
def bearing() -> kegel.Bearing:
    return kegel.Bearing("32216", fidelity="fast")


def test_import_kegel_gives_run_module_and_facade():
    # a fresh interpreter: nothing else has imported kegel.run before
    code = ("import kegel; assert callable(kegel.run.run_scene); assert kegel.run_scene is kegel.run.run_scene; "
            "assert kegel.Bearing and kegel.FrictionResult; "
            "assert {'run', 'run_scene', 'Bearing', 'FrictionResult'} <= set(kegel.__all__)")
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, res.stderr


def test_one_torque_in_three_lines_writes_no_files(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    import kegel as k

    res = k.Bearing("32216", fidelity="fast").friction(speed="2000 rpm", axial_load="6 kN", temperature="50 degC")
    assert isinstance(res, k.FrictionResult)
    assert isinstance(res.friction_torque_Nm, float)
    assert 1.0 < res.friction_torque_Nm < 20.0
    assert res.converged and res.failure is None
    # the default lubrication is an oil bath at half roller height (issue 28: minimum quantity
    # surprised a newcomer with a silent zero hydraulic loss), so Liebrecht's loss is added
    assert res.hydraulic_method == "liebrecht" and 0.0 < res.hydraulic_torque_Nm < 0.2 * res.friction_torque_Nm
    assert res.total_torque_Nm == pytest.approx(res.friction_torque_Nm + res.hydraulic_torque_Nm)
    assert list(tmp_path.iterdir()) == []


SCENE = """
[bearing]
designation = "32216"
[lubricant]
name = "FVA3"
[operating]
axial_load = "6 kN"
radial_load = "2 kN"
speed = "2000 rpm"
temperature = "50 degC"
[lubrication]
mode = "oil_bath"
oil_level = "half_roller"
[model]
fidelity = "fast"
"""


def _run_file(path: Path) -> list[dict]:
    scene = kegel.load_scene(path)
    return kegel.run_scene(scene, write=False, progress=False).points


def test_facade_equals_the_scene_file(tmp_path, bearing):
    path = tmp_path / "scene.toml"
    path.write_text(SCENE)
    ref = _run_file(path)[0]
    res = bearing.friction(speed="2000 rpm", axial_load="6 kN", radial_load="2 kN", temperature="50 degC",
                           lubrication="half_roller")
    assert res.hydraulic_method == "liebrecht" and res.hydraulic_torque_Nm > 0
    for key in ("friction_torque_Nm", "hydraulic_torque_Nm", "total_torque_Nm"):
        assert getattr(res, key) == pytest.approx(ref[key], rel=REL, abs=0.0), key
    for c, v in ref["torque_by_contact_Nm"].items():
        assert res.torque_by_contact_Nm[c] == pytest.approx(v, rel=REL, abs=1e-15), c
    for m, v in ref["torque_by_mechanism_Nm"].items():
        assert res.torque_by_mechanism_Nm[m] == pytest.approx(v, rel=REL, abs=1e-15), m
    assert res.points[0]["roller_inner_N"] == pytest.approx(ref["roller_inner_N"], rel=REL)


def test_si_floats_equal_strings_with_units(bearing):
    """Bare numbers only in the keywords that name their unit (issue 28: speed=200 was rad/s)."""
    a = bearing.friction(speed="2000 rpm", axial_load="6 kN", temperature="50 degC")
    b = bearing.friction(speed_rad_s=2000 * RPM_TO_RAD_S, axial_load_N=6000.0, temperature_K=323.15)
    assert b.speed_rpm == pytest.approx(2000.0, rel=REL)
    assert b.friction_torque_Nm == pytest.approx(a.friction_torque_Nm, rel=REL)
    b = bearing.friction(speed_rpm=2000, axial_load_kN=6, temperature_degC=50)
    assert b.friction_torque_Nm == pytest.approx(a.friction_torque_Nm, rel=REL)
    q = kegel.units.ureg.Quantity
    c = bearing.friction(speed=q(2000, "rpm"), axial_load=q(6, "kN"), temperature=q(50, "degC"))
    assert c.friction_torque_Nm == pytest.approx(a.friction_torque_Nm, rel=REL)


def test_skf_drag_equals_a_study_of_the_scene(tmp_path, bearing):
    """hydraulic="skf": the contact friction of the scene plus the SKF drag a [study] adds."""
    path = tmp_path / "study.toml"
    path.write_text(SCENE.replace('[lubrication]\nmode = "oil_bath"\noil_level = "half_roller"',
                                  '[study]\nlubrication = ["flooded"]\nhydraulic = ["skf"]'))
    ref = _run_file(path)[0]
    row = next(r for r in ref["study"] if r["method"] == "skf")
    res = bearing.friction(speed="2000 rpm", axial_load="6 kN", radial_load="2 kN", lubrication="flooded",
                           hydraulic="skf")
    assert res.hydraulic_method == "skf" and res.points[0]["hydraulic"]["correlation"] == "skf"
    assert res.friction_torque_Nm == pytest.approx(ref["friction_torque_Nm"], rel=REL)
    assert res.hydraulic_torque_Nm == pytest.approx(row["hydraulic_torque_Nm"], rel=REL)
    assert res.total_torque_Nm == pytest.approx(row["total_torque_Nm"], rel=REL)
    # and not Liebrecht's loss
    lieb = bearing.friction(speed="2000 rpm", axial_load="6 kN", radial_load="2 kN", lubrication="flooded")
    assert lieb.hydraulic_method == "liebrecht"
    assert abs(lieb.hydraulic_torque_Nm - res.hydraulic_torque_Nm) > 1e-3


def test_sweep_gives_one_row_per_point(bearing):
    pd = pytest.importorskip("pandas")
    speeds = ["500 rpm", "1000 rpm", "2000 rpm"]
    res = bearing.friction(speed=speeds, axial_load="6 kN", lubrication="flooded")
    assert len(res) == 3 and res.swept == ("speed",)
    assert isinstance(res.friction_torque_Nm, np.ndarray) and res.friction_torque_Nm.shape == (3,)
    df = res.to_dataframe()
    assert isinstance(df, pd.DataFrame) and len(df) == 3
    assert list(df["speed_rpm"]) == pytest.approx([500.0, 1000.0, 2000.0])
    assert list(df["friction_torque_Nm"]) == pytest.approx(list(res.friction_torque_Nm), rel=REL)
    for col in ("torque_outer_raceway_Nm", "torque_inner_raceway_Nm", "torque_rib_Nm", "torque_cage_Nm",
                "torque_ehl_rolling_Nm", "torque_ehl_sliding_Nm", "hydraulic_torque_Nm", "total_torque_Nm",
                "Lambda_min", "converged"):
        assert col in df.columns, col
    # flat columns only: no lists or dictionaries left in a cell
    assert not any(isinstance(v, (list, dict)) for v in df.to_numpy().ravel())
    assert list(df["torque_ehl_rolling_Nm"]) == pytest.approx(list(res.torque_by_mechanism_Nm["ehl_rolling"]))
    assert df.attrs["designation"] == "32216"
    # one point of the sweep as a result of its own
    assert res[1].friction_torque_Nm == pytest.approx(res.friction_torque_Nm[1], rel=REL)


def test_to_dataframe_without_pandas_says_so(bearing, monkeypatch):
    res = bearing.friction(speed="2000 rpm", axial_load="6 kN")
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas now raises ImportError
    with pytest.raises(ImportError, match="needs pandas"):
        res.to_dataframe()


def test_to_dict_is_json_ready(bearing):
    res = bearing.friction(speed=["1000 rpm", "2000 rpm"], axial_load="6 kN", lubrication="shaft_center")
    d = res.to_dict()
    text = json.dumps(d, allow_nan=False)  # no numpy types, no NaN
    back = json.loads(text)
    assert back["friction_torque_Nm"] == pytest.approx(list(res.friction_torque_Nm), rel=REL)
    assert len(back["points"]) == 2 and back["designation"] == "32216"


def test_reprs_are_short(bearing):
    res = bearing.friction(speed="2000 rpm", axial_load="6 kN", temperature="50 degC", lubrication="flooded")
    text = repr(res)
    assert len(text) < 300 and "\n" not in text, text
    assert text.startswith("FrictionResult(32216, 2000 rpm, Fa 6 kN, 50 degC: friction ")
    assert "converged" in text and "(liebrecht)" in text
    assert str(res) == text
    sweep = bearing.friction(speed=[f"{n} rpm" for n in range(500, 2501, 200)], axial_load="6 kN")
    lines = repr(sweep).splitlines()
    assert len(sweep) == 11 and len(lines) <= len(sweep) + 1 and len(lines) <= 8, lines
    assert "11 points over speed" in lines[0] and "5 more" in lines[-1]


def _dynamic_result(finished: bool = True) -> kegel.DynamicResult:
    """A DynamicResult with arrays the size of a short run (2001 outputs, 17 rollers)."""
    n, z = 2001, 17
    t = np.linspace(0.0, 0.02, n)
    series = {"inner_speed_rad_s": np.full(n, 209.44), "drive_torque_Nm": np.full(n, 4.07),
              "roller_inner_N": np.ones((n, z))}
    steady = {"inner_speed_rad_s": 209.44, "drive_torque_Nm": 4.07, "outer_ring_torque_Nm": 4.05}
    return kegel.DynamicResult(time_s=t, series=series, steady=steady, stats={"steps": 1234},
                               states=np.zeros((n, 12 * z + 19)), quadratures=np.zeros((n, 30)), runtime_s=12.5,
                               finished=finished, message="" if finished else "CVODE failed " + "x" * 2000)


def test_dynamic_result_repr_is_short():
    res = _dynamic_result()
    text = repr(res)
    assert len(text) < 500 and "\n" not in text, text
    assert "20 ms" in text and "2001 outputs" in text and "4.07 N m" in text and "finished" in text
    assert str(res) == text
    failed = repr(_dynamic_result(finished=False))
    assert len(failed) < 500 and "not finished: CVODE failed" in failed


def test_lubricant_state_accepts_a_temperature_with_its_unit():
    lub = kegel.load_lubricant("FVA3")
    assert kegel.lubricant_state(lub, "50 degC") == kegel.lubricant_state(lub, 323.15)
    assert kegel.lubricant_state(lub, "323.15 K") == kegel.lubricant_state(lub, 323.15)
    assert kegel.lubricant_state("FVA3", "50 degC") == kegel.lubricant_state(lub, 323.15)
    for bad in ("50 parsecs", "fifty", None, [323.15], float("nan")):
        with pytest.raises(kegel.KegelInputError, match="temperature"):
            kegel.lubricant_state(lub, bad)
    with pytest.raises(kegel.KegelInputError, match="'lub'"):
        kegel.lubricant_state(42, 323.15)


@pytest.mark.parametrize("kwargs, argument", [
    (dict(axial_load="6 parsecs"), "axial_load"),
    (dict(axial_load="-5 kN"), "axial_load"),
    (dict(axial_load=-5000.0), "axial_load"),
    (dict(axial_load=["6 kN", "-5 kN"]), "axial_load[1]"),
    (dict(axial_load="6 kN", speed="3 kN"), "speed"),
    (dict(axial_load="6 kN", speed=1e9), "speed"),
    (dict(axial_load="6 kN", speed=object()), "speed"),
    (dict(axial_load="6 kN", temperature="300 degC"), "temperature"),
    (dict(axial_load="6 kN", radial_load="-1 kN"), "radial_load"),
    (dict(axial_load="6 kN", radial_load="30 kN"), "radial_load"),
    (dict(axial_load="6 kN", axial_offset="20 um"), "axial_load"),
    (dict(), "axial_load"),
    (dict(axial_load="6 kN", lubrication="half full"), "lubrication"),
    (dict(axial_load="6 kN", lubrication="900 mm"), "lubrication"),
    (dict(axial_load="6 kN", lubrication="minimum_quantity", hydraulic="liebrecht"), "hydraulic"),
    (dict(axial_load="6 kN", lubrication="flooded", hydraulic="magic"), "hydraulic"),
])
def test_bad_input_names_the_argument(bearing, kwargs, argument):
    kwargs = {"speed": "2000 rpm", **kwargs}
    with pytest.raises(kegel.KegelInputError) as info:
        bearing.friction(**kwargs)
    assert f"'{argument}'" in str(info.value)
    assert info.value.key == argument


@pytest.mark.parametrize("kwargs, argument", [
    (dict(designation="99999"), "designation"),
    (dict(designation=None), "designation"),
    (dict(designation="32216", lubricant="water"), "lubricant"),
    (dict(designation="32216", material="cheese"), "material"),
    (dict(designation="32216", fidelity="ultra"), "fidelity"),
])
def test_bad_bearing_names_the_argument(kwargs, argument):
    with pytest.raises(kegel.KegelInputError) as info:
        kegel.Bearing(**kwargs)
    assert info.value.key == argument and f"'{argument}'" in str(info.value)


# --- type stubs of kegel._core ---------------------------------------------------------------

STUBS = Path(kegel.__file__).parent / "_core"


def test_core_stubs_match_the_built_module(tmp_path):
    """kegel/_core/*.pyi are nanobind.stubgen's output for the built module: regenerate with
    ``.venv/bin/python -m nanobind.stubgen -q -m kegel._core -r -O kegel`` after changing the
    bindings (and commit them)."""
    pytest.importorskip("nanobind.stubgen")
    res = subprocess.run([sys.executable, "-m", "nanobind.stubgen", "-q", "-m", "kegel._core", "-r", "-O",
                          str(tmp_path)], capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, res.stderr
    fresh = {p.relative_to(tmp_path / "_core"): p.read_text() for p in (tmp_path / "_core").rglob("*.pyi")}
    committed = {p.relative_to(STUBS): p.read_text() for p in STUBS.rglob("*.pyi")}
    assert fresh, "stubgen wrote no stubs"
    assert sorted(committed) == sorted(fresh), "stub files differ: regenerate (see this test's docstring)"
    stale = [str(k) for k in fresh if fresh[k] != committed[k]]
    assert not stale, f"stale stubs {stale}: regenerate with python -m nanobind.stubgen -q -m kegel._core -r -O kegel"


def test_package_is_typed():
    assert (Path(kegel.__file__).parent / "py.typed").is_file()
    assert (STUBS / "__init__.pyi").is_file()
