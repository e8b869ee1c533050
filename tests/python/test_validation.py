"""External validation: kegel's bearing torque beside the world outside kegel (``kegel validate``).

The measured check (the seed paper's Figure 5, with its acceptance) is in
``test_validation_measured.py``. This file holds the datasets without points and the two
independent engineering models, the SKF catalogue model and Aihara's formula. Those are shown as
information with their known scatter, never as pass/fail targets (issue 27, item 4): the tests
hold that they carry no verdict, and keep their deviations as regressions of a measured figure so
that a change of kegel's level is seen. Nothing here is a fitting target.
"""

from __future__ import annotations

import math

import pytest

from conftest import EXAMPLES
from kegel.scene import load_scene
from kegel.validation import AIHARA_SCATTER, SKF_SCATTER, measured_datasets, model_comparisons


def test_measured_datasets_are_cited_and_say_what_could_not_be_read():
    ds = {c.name: c for c in measured_datasets()}
    assert {"aihara1987", "zhou_hoeprich1991", "manjunath2023"} <= set(ds)
    assert "wingertszahn2023_fig5" not in ds  # the series with points is compared by measured_comparison
    for c in ds.values():
        assert c.citation and c.reference == "measured" and c.kind == "measured"
        # no measured torque is printed in the text of any of the three papers (figures only):
        # the comparison has no points and says so instead of passing silently
        assert not c.reference_Nm and c.meets_acceptance is None
        assert "not validated" in c.note


def test_zhang_li_2025_records_its_two_printed_torques_and_what_is_missing():
    """Machines 13 (2025) 910, Sec. 4: a 32208 pair (X), 1800 rpm, Fa 2.16 kN, oil injection; mean
    torque per bearing 0.56 N m (SR 0.85 rho_p) and 0.61 N m (SR 0.95 rho_p). Not runnable: the oil
    and its temperature are not given."""
    import tomllib

    from kegel.units import parse_quantity
    from kegel.validation import DATASET_DIR

    path = DATASET_DIR / "zhang_li2025.toml"
    raw = tomllib.loads(path.read_text())
    torques = [parse_quantity(p["torque"], "moment", source=path, key="torque") for p in raw["measured_points"]]
    assert torques == [0.56, 0.61] and raw["measured_points_in_text"] == 2
    for p in raw["measured_points"]:
        assert parse_quantity(p["speed"], "speed", source=path, key="speed") == pytest.approx(1800 * 2 * math.pi / 60)
        assert parse_quantity(p["axial_load"], "force", source=path, key="axial_load") == pytest.approx(2160.0)
    missing = " ".join(raw["test"]["missing"])
    assert "oil name" in missing and "temperature" in missing
    (c,) = [c for c in measured_datasets() if c.name == "zhang_li2025"]
    assert "not runnable" in c.note and "temperature" in c.note and "Machines 13 (2025) 910" in c.citation


# Fully flooded raceway contacts: the default before the lubricant-supply model of issue 27,
# item 1, and that model's switch-off value. The figures below were measured with them.
_SUPPLY = load_scene(EXAMPLES / "32216_table1.toml").fidelity.as_dict().get("lubricant_supply", "flooded")
FLOODED = () if _SUPPLY == "flooded" else ('model.lubricant_supply="flooded"',)


@pytest.fixture(scope="module")
def models():
    comps, _ = model_comparisons(overrides=FLOODED)
    return comps


@pytest.fixture(scope="module")
def skf(models):
    return {c.name.split(": ")[0].replace("SKF model at 32216 ", ""): c for c in models if c.name.startswith("SKF")}


@pytest.mark.slow
def test_the_engineering_models_are_information_not_targets(models):
    """No verdict on an engineering model; each carries its known scatter with its source and the
    spread between the two models (SKF up to about 41 % above Aihara at Table 1, 500 rpm, 50 degC)."""
    assert {c.name.split(" ")[0] for c in models} == {"SKF", "Aihara"}
    for c in models:
        assert c.kind == "model" and c.acceptance is None and c.meets_acceptance is None
        d = c.as_dict()
        assert d["acceptance"] is None and d["meets_acceptance"] is None and "meets_targets" not in d
        assert c.scatter.startswith(SKF_SCATTER if c.name.startswith("SKF") else AIHARA_SCATTER)
        assert "differ from each other by up to +41 %" in c.scatter
    assert "Manjunath" in SKF_SCATTER and "two hundred" in AIHARA_SCATTER


# Measured on the commit "kegel validate" (kegel friction torque against the SKF catalogue model's
# rolling + sliding moment, default fidelity, Aihara thermal factor, fully flooded contacts):
# mean |deviation| and worst deviation per scene. Tolerance: 2 percentage points. Information,
# not a target: kegel is 40-44 % below the SKF model at 500 rpm (Biboulet-Houpert's EHL rolling
# force grows as u^0.75, SKF's as (nu n)^0.6 with a load term), and under a growing radial load
# kegel's torque falls where SKF's rises (Table 3: -40 % at 15 kN); see docs/validation.md.
MEASURED = {
    "Table 1": (0.175, -0.419),
    "Table 2": (0.199, -0.444),
    "Table 3": (0.273, -0.424),  # the rollers at their pocket walls where their drift reaches one (issue 30,
    # item 3: the walls model) instead of the blend with the all-pocket solution: 15 kN 2.82 against 2.92 N m;
    # (0.264, -0.381) before. Boundary/cage friction mu 0.2 (Zhou-Hoeprich Eq. 33, issue 27 item 2)
}


@pytest.mark.slow
@pytest.mark.parametrize("table", sorted(MEASURED))
def test_kegel_beside_the_skf_catalogue_model_measured_figure(skf, table):
    c = skf[table]
    assert len(c.reference_Nm) >= 8 and all(c.converged)
    mean, worst = MEASURED[table]
    assert c.mean_abs_deviation == pytest.approx(mean, abs=0.02), c.as_dict()
    assert c.worst_deviation == pytest.approx(worst, abs=0.02), c.as_dict()


@pytest.mark.slow
def test_kegel_beside_aiharas_formula_at_table_1(models):
    """The second independent engineering model: Aihara's running-torque formula (NSK 1987,
    checked by its author against about 200 measured tapered roller bearings), at the pure axial
    load of Table 1 (the only table it applies to). Measured on the commit that added it, with
    fully flooded contacts: kegel is 0.6-17.9 % below it, mean |deviation| 7.6 %, worst -17.9 %
    (at 500 rpm, 50 degC). Tolerance of the regression: 2 percentage points."""
    (a,) = [c for c in models if c.name.startswith("Aihara")]
    assert len(a.reference_Nm) == 16 and all(a.converged)
    assert a.mean_abs_deviation == pytest.approx(0.076, abs=0.02), a.as_dict()
    assert a.worst_deviation == pytest.approx(-0.179, abs=0.02), a.as_dict()
    # below Aihara at every point, least at high speed (its thermal factor and kegel's are the same law)
    assert all(-0.20 < d < 0.0 for d in a.deviations)
