"""The first measured validation (issue 27, item 3): kegel against the seed paper's Figure 5.

Wingertszahn et al., Lubricants 2023, 11, 369, Figure 5: the measured total torque of a 32216
under Fa = 6 kN, FVA 3, oil bath at half roller height, 42/50 degC, read off the figure by a third
party (+-10 %), ``kegel/data/validation/wingertszahn2023_fig5.toml``. kegel's total (contact
friction + the hydraulic loss of the scene's oil bath) is compared with each point.

Acceptance of issue 27: mean |deviation| <= 10 %, no point beyond 20 %. It is a check, never a
fitting target: kegel runs with its literature parameters. Where kegel misses it, the test below
is a strict xfail with the measured figure in its reason (never a looser tolerance), and a second
test keeps the figure itself as a regression so that a change of the level is seen.
"""

from __future__ import annotations

import math
import tomllib

import pytest

from conftest import EXAMPLES, SHARED_REFERENCE
from kegel.errors import KegelInputError
from kegel.scene import load_scene
from kegel.validation import (MEASURED_FILE, MEASURED_MEAN, MEASURED_WORST, measured_comparison,
                              read_measured_series)

RPM = 2.0 * math.pi / 60.0


# ---------------------------------------------------------------------------------------------
# the data file


def test_the_data_file_is_read_exactly():
    """Values and units as printed in the data file, converted by hand: rpm -> rad/s (2 pi / 60),
    degC -> K (+273.15), N mm -> N m (/1000), kN -> N."""
    s = read_measured_series()
    assert s.name == "wingertszahn2023_fig5" and s.scene == "32216_table1.toml"
    assert (s.bearing, s.lubricant, s.lubrication_mode, s.oil_level) == ("32216", "FVA3", "oil_bath", "half_roller")
    assert s.axial_load_N == 6000.0 and s.radial_load_N == 0.0
    assert s.uncertainty == 0.10
    assert "contact friction + hydraulic loss" in s.quantity
    assert "Lubricants" in s.citation and "2023" in s.citation and "Figure 5" in s.citation
    expected = [(500.0, 323.15, 1.300), (2000.0, 323.15, 2.950), (4000.0, 323.15, 3.750), (500.0, 315.15, 1.700)]
    assert len(s.points) == len(expected)
    for p, (n_rpm, T_K, M_Nm) in zip(s.points, expected):
        assert p.speed_rad_s == pytest.approx(n_rpm * RPM, rel=1e-12)
        assert p.speed_rpm == pytest.approx(n_rpm, rel=1e-12)
        assert p.temperature_K == pytest.approx(T_K, abs=1e-9)
        assert p.torque_Nm == pytest.approx(M_Nm, rel=1e-12)
    assert [p.written["torque"] for p in s.points] == ["1300 N mm", "2950 N mm", "3750 N mm", "1700 N mm"]


def test_the_data_file_is_a_verbatim_copy_of_the_project_reference():
    """Below its provenance header the file holds ../shared/reference/measured/wingertszahn2023_fig5.toml
    unchanged (where the reference is available: it lies outside the repository)."""
    ref = SHARED_REFERENCE / "measured" / "wingertszahn2023_fig5.toml"
    if not ref.is_file():
        pytest.skip(f"{ref} is not available outside the project's working environment")
    ours = MEASURED_FILE.read_text()
    assert ours.endswith(ref.read_text())
    a, b = tomllib.loads(ours), tomllib.loads(ref.read_text())
    assert a["conditions"] == b["conditions"] and a["points"] == b["points"]


def test_the_conditions_are_those_of_the_table_1_scene():
    """The measured conditions are the seed paper's Table 1, i.e. examples/32216_table1.toml."""
    s = read_measured_series()
    scene = load_scene(EXAMPLES / s.scene)
    assert scene.bearing.designation == s.bearing and scene.lubricant.name == s.lubricant
    assert scene.lubrication.mode == s.lubrication_mode
    assert scene.lubrication.oil_level_as_written == s.oil_level
    ops = scene.operating_points
    assert {op.axial_load_N for op in ops} == {s.axial_load_N} and {op.radial_load_N for op in ops} == {0.0}
    assert {round(p.temperature_K, 9) for p in s.points} <= {round(op.temperature_K, 9) for op in ops}
    lo, hi = min(op.speed_rad_s for op in ops), max(op.speed_rad_s for op in ops)
    assert all(lo * (1 - 1e-12) <= p.speed_rad_s <= hi * (1 + 1e-12) for p in s.points)


def test_the_conditions_are_those_of_table_1_in_the_project_reference():
    """../shared/reference/test_conditions.toml [table1_axial] (where available)."""
    ref = SHARED_REFERENCE / "test_conditions.toml"
    if not ref.is_file():
        pytest.skip(f"{ref} is not available outside the project's working environment")
    t1 = tomllib.loads(ref.read_text())["table1_axial"]
    s = read_measured_series()
    assert t1["bearing"] == s.bearing
    assert t1["axial_load_kN"] * 1e3 == s.axial_load_N and t1["radial_load_kN"] * 1e3 == s.radial_load_N
    assert {round(p.temperature_degC, 9) for p in s.points} <= set(t1["temperature_degC"])
    lo, hi = t1["shaft_speed_rpm"]
    assert all(lo <= round(p.speed_rpm, 9) <= hi for p in s.points)


@pytest.mark.parametrize("old,new,key", [
    ('torque = "1300 N mm"', 'torque = "1300 N"', "points[0].torque"),
    ('speed = "500 rpm"', 'speed = "-500 rpm"', "points[0].speed"),
    ("uncertainty = 0.10", "uncertainty = 10", "conditions.uncertainty"),
    ('kind = "measured_points"', 'kind = "figures"', "kind"),
    ('axial_load = "6 kN"', 'axial_load = "6 mm"', "conditions.axial_load"),
])
def test_a_bad_data_file_is_refused_with_its_key(tmp_path, old, new, key):
    text = MEASURED_FILE.read_text()
    assert old in text
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace(old, new, 1))
    with pytest.raises(KegelInputError) as exc:
        read_measured_series(bad)
    assert exc.value.key == key and str(bad) in str(exc.value)


# ---------------------------------------------------------------------------------------------
# kegel against the measurement


@pytest.fixture(scope="module")
def fig5():
    comparison, run, curves = measured_comparison()
    return comparison, run, curves


def test_the_comparison_uses_kegels_total_torque(fig5):
    """Each point compares the measured total with kegel's friction + hydraulic loss (Liebrecht,
    the oil-bath scene's method), the +-10 % uncertainty carried along."""
    c, run, curves = fig5
    assert c.kind == "measured" and c.uncertainty == 0.10 and len(c.reference_Nm) == 4 and all(c.converged)
    assert c.reference_Nm == pytest.approx([1.300, 2.950, 3.750, 1.700], rel=1e-12)
    for k, det in zip(c.kegel_Nm, c.details):
        assert det["hydraulic_method"] == "liebrecht"
        assert det["hydraulic_Nm"] > 0.0
        assert k == pytest.approx(det["friction_Nm"] + det["hydraulic_Nm"], rel=1e-12)
    assert c.acceptance == {"mean_abs_deviation": MEASURED_MEAN, "worst_abs_deviation": MEASURED_WORST}
    assert run["scene"].endswith("32216_table1.toml")
    # the curves of the plot hold every measured point (same speeds and temperatures)
    assert len(curves) == 16


# Whether the raceway contacts are fully flooded by default (every contact of every scene before the
# lubricant-supply model of issue 27, item 1; "flooded" is also that model's switch-off value).
_SUPPLY = load_scene(EXAMPLES / "32216_table1.toml").fidelity.as_dict().get("lubricant_supply", "flooded")
FLOODED_BY_DEFAULT = _SUPPLY == "flooded"
#: The scene options that give fully flooded contacts (none needed where that is the default).
FLOODED = () if FLOODED_BY_DEFAULT else ('model.lubricant_supply="flooded"',)

# Measured with fully flooded raceway contacts (default fidelity, Aihara's thermal factor,
# Liebrecht's hydraulic loss), on the commit that added this test: kegel's total is +17.4 / +24.8 /
# +28.0 % above the 50 degC points (500 / 2000 / 4000 rpm) and +17.1 % above 42 degC, 500 rpm;
# mean |deviation| 21.9 %, worst +28.0 %. The contact friction alone is +16.4 / +22.1 / +22.9 /
# +16.1 %.
FLOODED_MEAN_ABS = 0.219
FLOODED_WORST_DEV = 0.280


@pytest.mark.xfail(FLOODED_BY_DEFAULT, strict=True, reason=(
    "with fully flooded raceway contacts kegel's total torque is 17-28 % above the measured Figure 5 torque (mean "
    "|deviation| 21.9 %, worst +28.0 % at 4000 rpm, 50 degC): the Biboulet-Houpert rolling force of a flooded "
    "contact needs oil about one reduced radius upstream, which an oil bath at half roller height does not supply "
    "(issue 27, item 1: lubricant supply); the hydraulic loss adds 1-4 %. Literature parameters, nothing tuned."))
def test_kegel_meets_the_acceptance_against_figure_5(fig5):
    """The acceptance of issue 27 at kegel's default (with the lubricant-supply model, where present)."""
    c, _, _ = fig5
    assert c.mean_abs_deviation <= MEASURED_MEAN, c.as_dict()
    assert all(abs(d) <= MEASURED_WORST for d in c.deviations), c.as_dict()
    assert all(c.converged)
    assert c.meets_acceptance is True


# Measured at kegel's default with the lubricant-supply model (kinematic replenishment, commit
# 16c76c1) on the commit that added it here: +12.9 / +6.9 / -4.8 % at 50 degC (500 / 2000 /
# 4000 rpm), +10.7 % at 42 degC, 500 rpm; mean |deviation| 8.8 %, worst +12.9 %.
DEFAULT_MEAN_ABS = 0.088
DEFAULT_WORST_DEV = 0.129


@pytest.mark.skipif(FLOODED_BY_DEFAULT, reason="the contacts are flooded by default: the flooded figure applies")
def test_kegel_against_figure_5_measured_figure_at_the_default(fig5):
    """The default figure above as a regression (2 percentage points): a change of kegel's level
    shows here, and this file and docs/validation.md must then be updated with the new figure."""
    c, _, _ = fig5
    assert c.mean_abs_deviation == pytest.approx(DEFAULT_MEAN_ABS, abs=0.02), c.as_dict()
    assert c.worst_deviation == pytest.approx(DEFAULT_WORST_DEV, abs=0.02), c.as_dict()


def test_fully_flooded_contacts_against_figure_5_measured_figure():
    """The flooded figure above as a regression (2 percentage points): a change of the contact
    friction shows here, and this file and docs/validation.md must then be updated."""
    c, run, _ = measured_comparison(overrides=FLOODED)
    assert c.mean_abs_deviation == pytest.approx(FLOODED_MEAN_ABS, abs=0.02), c.as_dict()
    assert c.worst_deviation == pytest.approx(FLOODED_WORST_DEV, abs=0.02), c.as_dict()
    assert c.meets_acceptance is False
    # above the measurement at every point: the level, not the scatter, is what is missed
    assert all(0.10 < d < 0.35 for d in c.deviations)


def test_the_measured_conditions_cannot_be_overridden():
    with pytest.raises(KegelInputError, match="operating.speed"):
        measured_comparison(overrides=['operating.speed="1000 rpm"'])
