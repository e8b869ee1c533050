"""External validation (issue 18, item 5): kegel's bearing torque against the world outside kegel.

The targets are mean |deviation| <= 15 % and no point beyond 30 % per dataset. Where a dataset
misses them with kegel's literature parameters, the test states the measured figure (a regression
of the deviation with its tolerance) and a strict xfail keeps the target: it starts to fail when
the target is met, so the README and this file must then be updated. Nothing here is a fitting
target.
"""

from __future__ import annotations

import pytest

from kegel.validation import TARGET_MEAN, TARGET_WORST, measured_datasets, model_comparisons


def test_measured_datasets_are_cited_and_say_what_could_not_be_read():
    ds = {c.name: c for c in measured_datasets()}
    assert {"aihara1987", "zhou_hoeprich1991", "manjunath2023"} <= set(ds)
    for c in ds.values():
        assert c.citation and c.reference == "measured"
        # no measured torque is printed in the text of any of the three papers (figures only):
        # the comparison has no points and says so instead of passing silently
        assert not c.reference_Nm and c.meets_targets is None
        assert "not validated" in c.note


@pytest.fixture(scope="module")
def models():
    comps, _ = model_comparisons()
    return comps


@pytest.fixture(scope="module")
def skf(models):
    return {c.name.split(": ")[0].replace("SKF model at 32216 ", ""): c for c in models if c.name.startswith("SKF")}


# Measured on commit "kegel validate" (kegel friction torque against the SKF catalogue model's
# rolling + sliding moment, default fidelity, Aihara thermal factor, fully flooded contacts):
# mean |deviation| and worst deviation per scene. Tolerance: 2 percentage points.
MEASURED = {
    "Table 1": (0.175, -0.419),
    "Table 2": (0.199, -0.444),
    "Table 3": (0.268, -0.402),
}


@pytest.mark.slow
@pytest.mark.parametrize("table", sorted(MEASURED))
def test_kegel_against_the_skf_catalogue_model_measured_figure(skf, table):
    c = skf[table]
    assert len(c.reference_Nm) >= 8
    mean, worst = MEASURED[table]
    assert c.mean_abs_deviation == pytest.approx(mean, abs=0.02), c.as_dict()
    assert c.worst_deviation == pytest.approx(worst, abs=0.02), c.as_dict()


@pytest.mark.slow
@pytest.mark.xfail(strict=True, reason="kegel is 40-44 % below the SKF model at 500 rpm (Biboulet-Houpert's EHL "
                                       "rolling force grows as u^0.75, SKF's as (nu n)^0.6 with a load term), and "
                                       "under a growing radial load kegel's torque falls where SKF's rises (Table 3: "
                                       "-40 % at 15 kN); see docs/validation.md")
@pytest.mark.parametrize("table", sorted(MEASURED))
def test_kegel_against_the_skf_catalogue_model_meets_the_targets(skf, table):
    c = skf[table]
    assert c.mean_abs_deviation <= TARGET_MEAN
    assert abs(c.worst_deviation) <= TARGET_WORST
    assert all(c.converged)


@pytest.mark.slow
def test_kegel_against_aiharas_formula_at_table_1(models):
    """The second independent engineering model: Aihara's running-torque formula (NSK 1987,
    checked by its author against about 200 measured tapered roller bearings), at the pure axial
    load of Table 1 (the only table it applies to). Measured on the commit that added it: kegel is
    0.6-17.9 % below it, mean |deviation| 7.6 %, worst -17.9 % (at 500 rpm, 50 degC): the
    targets are met. Tolerance of the regression: 2 percentage points."""
    (a,) = [c for c in models if c.name.startswith("Aihara")]
    assert len(a.reference_Nm) == 16 and all(a.converged)
    assert a.mean_abs_deviation == pytest.approx(0.076, abs=0.02), a.as_dict()
    assert a.worst_deviation == pytest.approx(-0.179, abs=0.02), a.as_dict()
    assert a.meets_targets
    # below Aihara at every point, least at high speed (its thermal factor and kegel's are the same law)
    assert all(-0.20 < d < 0.0 for d in a.deviations)
