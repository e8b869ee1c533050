"""The 32216's calculation factor e is the one its data file cites (issue 27, item 6).

``kegel/data/bearings/32216.toml`` cited e = 0.43 (SKF's table) and used 0.42. The file now cites
the value it uses and its source (the project reference ``../shared/reference/bearings.toml``),
with SKF's rounding named beside it; these tests hold the citation, the value and the cup angle
derived from it (hand calculation: alpha = atan(e / 1.5), ISO 281) together.
"""

from __future__ import annotations

import math
import re
import tomllib

import pytest

from conftest import SHARED_REFERENCE
from kegel.data import load_bearing, load_material
from kegel.geometry import derive_geometry


def _file():
    b = load_bearing("32216")
    return b, open(b.source_file).read()


def test_the_cited_calculation_factors_are_the_ones_used():
    b, text = _file()
    raw = tomllib.loads(text)
    cited = re.findall(r"e = (0\.\d+), Y = (\d\.\d+)", text)
    assert cited, "the header must cite the calculation factors it uses as 'e = x, Y = y'"
    assert {(float(e), float(y)) for e, y in cited} == {(raw["catalogue"]["calculation_factor_e"],
                                                         raw["catalogue"]["axial_load_factor_Y"])}
    assert (b.calculation_factor_e, b.axial_load_factor_Y) == (0.42, 1.4)
    # the inline note of the derived cup angle matches the value used
    m = re.search(r"calculation_factor_e = [0-9.]+ .*alpha_cup = ([0-9.]+) deg", text)
    assert m and float(m.group(1)) == pytest.approx(math.degrees(math.atan(0.42 / 1.5)), abs=0.005)


def test_the_cup_angle_follows_e_by_iso_281():
    """alpha = atan(e / 1.5) = atan(0.28) = 15.6422 deg (hand calculation)."""
    b = load_bearing("32216")
    g = derive_geometry(b, load_material("bearing_steel"))
    assert math.degrees(g.cup_angle_rad) == pytest.approx(15.6422, abs=1e-4)


def test_the_values_are_those_of_the_project_reference():
    ref = SHARED_REFERENCE / "bearings.toml"
    if not ref.is_file():
        pytest.skip(f"{ref} is not available outside the project's working environment")
    r = tomllib.loads(ref.read_text())["32216"]
    b = load_bearing("32216")
    assert (b.calculation_factor_e, b.axial_load_factor_Y) == (r["e"], r["Y"])
