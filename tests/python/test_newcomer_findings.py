"""Issue 28, item 4: the newcomer findings. Each test names its finding and fails on the code
before the fix (checked by running it against the parent commit)."""

from __future__ import annotations

import math

import pytest

from conftest import EXAMPLES, REPO, call_kegel, run_kegel, scene_text

import kegel
from kegel.data import load_bearing, load_material
from kegel.geometry import derive_geometry


# --- Finding: `kegel bearing` labels the roller inertia in kg mm^2 with a value in g mm^2 ---------


_TO_KGM2 = {"kg m^2": 1.0, "kg mm^2": 1e-6, "g mm^2": 1e-9, "g cm^2": 1e-7}


def test_bearing_table_roller_inertia_value_matches_its_unit():
    """The printed value times its unit's factor is the inertia in kg m^2 (a hand check: a solid
    cylinder of the roller's mass and mean diameter, m D^2 / 8, within 1 %)."""
    code, out, err = call_kegel("bearing", "--bearing", "32208")
    assert code == 0, err
    rows = {}
    for line in out.splitlines():
        if line.startswith("roller inertia"):
            name, rest = line.split("  ", 1)
            value, unit = rest.split(None, 1)
            rows[name.strip()] = (float(value), unit.strip())
    g = derive_geometry(load_bearing("32208"), load_material("bearing_steel"), check_envelope=False)
    value, unit = rows["roller inertia, axial"]
    assert unit in _TO_KGM2, unit
    inertia_kgm2 = value * _TO_KGM2[unit]
    assert inertia_kgm2 == pytest.approx(g.roller_inertia_axial_kgm2, rel=1e-3)  # printed to 4 digits
    cylinder = g.roller_mass_kg * g.roller_mean_diameter_m ** 2 / 8
    assert inertia_kgm2 == pytest.approx(cylinder, rel=0.01)
    value, unit = rows["roller inertia, transverse (CoM)"]
    assert value * _TO_KGM2[unit] == pytest.approx(g.roller_inertia_transverse_kgm2, rel=1e-3)  # printed to 4 digits
