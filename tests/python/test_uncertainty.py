"""The friction torque's band from the crown data and the slice model (issue 27, item 5)."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest

import kegel
from conftest import call_kegel
from kegel.errors import KegelInputError
from kegel.run import run_scene
from kegel.scene import scene_from_dict
from kegel.uncertainty import UncertaintyOptions, loaded_length_m

TABLE1 = str(Path(__file__).resolve().parents[2] / "examples" / "32216_table1.toml")


def _scene(speed: str = "500 rpm"):
    raw = kegel.Bearing("32216").scene(speed=speed, axial_load="6 kN", temperature="50 degC")
    return scene_from_dict(raw, source="<test>")


@pytest.fixture(scope="module")
def table1_point():
    """32216, Table 1 (Fa 6 kN, 50 degC), 500 rpm, with the default band."""
    return run_scene(_scene(), write=False, progress=False, uncertainty=True).points[0]


def test_band_brackets_the_nominal_value(table1_point):
    p = table1_point
    u = p["uncertainty"]
    m = p["friction_torque_Nm"]
    assert u["friction_torque_low_Nm"] < m < u["friction_torque_high_Nm"]
    assert u["total_torque_low_Nm"] == pytest.approx(u["friction_torque_low_Nm"] + p["hydraulic_torque_Nm"])
    v = u["variants"]
    assert all(r["converged"] for r in v.values())
    # a larger crown drop shortens the touching length and with it the rolling force; a smaller one
    # lengthens both; independent slices load more slices (docs: +8-10 %)
    assert v["crown_drop_high"]["friction_torque_Nm"] < m < v["crown_drop_low"]["friction_torque_Nm"]
    assert v["crown_drop_high"]["loaded_length_m"] < u["nominal_loaded_length_m"] < v["crown_drop_low"]["loaded_length_m"]
    assert 0.05 < v["slice_model"]["friction_torque_Nm"] / m - 1.0 < 0.15
    # the figure: 12.1 of 22.7 mm touch at Table 1 (100 slices: +-0.23 mm)
    assert u["nominal_loaded_length_m"] == pytest.approx(12.1e-3, abs=0.4e-3)
    assert u["roller_length_m"] == pytest.approx(22.7e-3)


def test_zero_perturbation_gives_a_zero_band():
    sc = _scene()
    p = run_scene(sc, write=False, progress=False,
                  uncertainty=UncertaintyOptions(crown_drop_fraction=0.0, slice_model_variant=False)).points[0]
    u = p["uncertainty"]
    assert set(u["variants"]) == {"crown_drop_low", "crown_drop_high"}  # solved again, unperturbed
    for r in u["variants"].values():
        assert r["friction_torque_Nm"] == pytest.approx(p["friction_torque_Nm"], rel=1e-9)
    assert u["friction_torque_high_Nm"] - u["friction_torque_low_Nm"] <= 1e-9 * p["friction_torque_Nm"]


def test_no_band_unless_asked():
    p = run_scene(_scene(), write=False, progress=False).points[0]
    assert "uncertainty" not in p


def test_loaded_length_by_hand_for_an_unprofiled_roller():
    # a roller without crown touches over its whole length less the edge radii' drop
    b = kegel.load_bearing("32216")
    m = kegel.load_material("bearing_steel")
    g = kegel.derive_geometry(b, m)
    import dataclasses

    flat = dataclasses.replace(b, profile_a_p=0.0)
    L = loaded_length_m(flat, g, m, 1500.0)
    assert b.roller_length_m - 2 * b.edge_radius_m - 0.5e-3 < L <= b.roller_length_m


@pytest.mark.parametrize("bad", [-0.1, 1.0, float("nan"), True])
def test_bad_crown_fraction_is_refused(bad):
    with pytest.raises(KegelInputError, match="crown_drop_fraction"):
        UncertaintyOptions(crown_drop_fraction=bad)


def test_cli_uncertainty_option(tmp_path):
    code, out, err = call_kegel("run", TABLE1, "--uncertainty", "--output", str(tmp_path / "r"),
                                "--set", 'operating.speed=["500 rpm", "2000 rpm"]', "--set", "operating.temperature=50 degC")
    assert code == 0, err
    assert "uncertainty (kegel.uncertainty)" in out and "loaded length" in out
    rows = list(csv.DictReader((tmp_path / "r" / "results.csv").open()))
    assert len(rows) == 2
    for r in rows:
        assert float(r["friction_torque_low_Nm"]) < float(r["friction_torque_Nm"]) < float(r["friction_torque_high_Nm"])
        assert float(r["total_torque_low_Nm"]) < float(r["total_torque_Nm"]) < float(r["total_torque_high_Nm"])
    pts = json.loads((tmp_path / "r" / "results.json").read_text())["points"]
    assert all(p["uncertainty"]["inputs"]["crown_drop_fraction"] == 0.25 for p in pts)
    assert (tmp_path / "r" / "torque.png").stat().st_size > 0
    code, out, err = call_kegel("run", TABLE1, "--uncertainty", "--crown-drop", "1.5",
                                "--output", str(tmp_path / "s"), "--set", "operating.speed=500 rpm")
    assert code == 2 and "crown_drop_fraction" in err


def test_torque_plot_draws_the_band(table1_point):
    from kegel.plots import build_figures

    figs = build_figures([table1_point, {**table1_point, "index": 1, "speed_rpm": 1000.0}],
                         {"swept": ["speed"]})
    ax = next(a for a in figs["torque_plot"].axes if a.get_label() == "torque")
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any("band" in t for t in labels)


def test_api_keyword():
    r = kegel.Bearing("32216").friction(speed="2000 rpm", axial_load="6 kN", temperature="50 degC", uncertainty=True)
    u = r.points[0]["uncertainty"]
    assert u["friction_torque_low_Nm"] < r.friction_torque_Nm < u["friction_torque_high_Nm"]
    assert "uncertainty" not in kegel.Bearing("32216").friction(speed="2000 rpm", axial_load="6 kN").points[0]
    with pytest.raises(KegelInputError, match="uncertainty"):
        kegel.Bearing("32216").friction(speed="2000 rpm", axial_load="6 kN", uncertainty="yes")
