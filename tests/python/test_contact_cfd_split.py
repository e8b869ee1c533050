"""The contact / CFD split at the raceway line contacts (issue 29): contact + CFD must not depend on
the boundary gap g.

The CFD losses are stored results of the gap study (``benchmarks/cfd_gap_study.py``: the flooded
32208 at 2000 rpm, 50 degC, one-pitch sectors with 3 cells across each gap); the contact losses are
computed here, live, by kegel's contact model with its rolling force cut off at the same g. When g
halves, the contact model hands the film between the new and the old g to the CFD: the CFD's loss
must rise by what the contact's falls. A CFD that ignored g (or a contact model that did not cut)
would leave the sum moving by the whole contact change; a double count or a hole shows the same way.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from kegel.runner.film_limit import contact_loss_at_film_limit

ROOT = Path(__file__).resolve().parents[2]
STUDY = ROOT / "benchmarks" / "results" / "cfd_gap_study.json"

#: The sum may move by at most this fraction of the contact model's own change between the two
#: gaps (measured: 0.15 at g/D_w = 0.08 -> 0.04; the CFD's 3 cells across a gap under-read the
#: wedge's dissipation by about 5 %, the rolling-cylinder verification case says).
SPLIT_TOLERANCE = 0.25


def _rows() -> list[dict]:
    rows = [r for r in json.loads(STUDY.read_text())["rows"]
            if r["sector"] and r["cells_across_gap"] == 3 and r["mesh"] == "tiny"]
    return sorted(rows, key=lambda r: -r["gap_ratio"])


def test_the_stored_gap_study_is_the_documented_point():
    data = json.loads(STUDY.read_text())
    assert "32208" in data["point"] and "2000 rpm" in data["point"] and "flooded" in data["point"]
    gaps = [r["gap_ratio"] for r in _rows()]
    assert 0.08 in gaps and 0.04 in gaps
    for r in _rows():
        assert r["gap_m"] == pytest.approx(r["gap_ratio"] * 0.010)   # D_w = 10 mm
        assert 0.0 < r["cfd_loss_Nm"] < 1.0
        if r["gap_ratio"] >= 0.02:
            assert abs(r["angular_momentum_balance"]) < 0.05


@pytest.mark.xfail(strict=True, reason=(
    "the 0.01 D_w run (1.81 M cells, stopped by the steady test at iteration 972) balances its "
    "wall torques to -5.2 % of the drive torque, outside the 5 % the coarser gaps meet (docs/cfd.md)"))
def test_the_finest_gap_balances_within_five_percent():
    rows = [r for r in _rows() if r["gap_ratio"] < 0.02]
    assert rows
    for r in rows:
        assert abs(r["angular_momentum_balance"]) < 0.05, r["angular_momentum_balance"]


def test_contact_plus_cfd_does_not_depend_on_the_gap():
    rows = [r for r in _rows() if r["gap_ratio"] in (0.08, 0.04)]
    sums, contacts = [], []
    for r in rows:
        c = contact_loss_at_film_limit(r["gap_m"], bearing="32208", speed="2000 rpm", axial_load="1 kN",
                                       temperature="50 degC", oil_level="flooded")
        assert c["converged"]
        contacts.append(c["friction_torque_Nm"])
        sums.append(c["friction_torque_Nm"] + r["cfd_loss_Nm"])
    d_contact = contacts[1] - contacts[0]
    d_cfd = rows[1]["cfd_loss_Nm"] - rows[0]["cfd_loss_Nm"]
    assert d_contact < 0.0 < d_cfd           # the cut takes from the contact, the CFD gains
    assert abs(sums[1] - sums[0]) <= SPLIT_TOLERANCE * abs(d_contact), (
        f"contact + CFD moved by {1e3 * (sums[1] - sums[0]):+.2f} mN m between g/D_w = 0.08 and 0.04, "
        f"the contact by {1e3 * d_contact:+.2f} mN m")


#: Over the stored gaps from 0.08 to 0.02 D_w contact + CFD may spread by at most this fraction
#: of its mean (measured 1.2 %: 812.4, 814.7, 821.9 mN m; the sum creeps up as g shrinks, the
#: CFD gaining 30 % more than the contact gives up between 0.04 and 0.02: docs/cfd.md). With the
#: 0.01 D_w gap the sum reaches 836.9 mN m: a 3.0 % spread, reported by the strict xfail below.
SUM_SPREAD_TOLERANCE = 0.015


def test_contact_plus_cfd_spreads_little_down_to_two_percent_of_the_roller_diameter():
    _check_sum_spread([r for r in _rows() if r["gap_ratio"] >= 0.02])


@pytest.mark.xfail(strict=True, reason=(
    "contact + CFD is 812.4 / 814.7 / 821.9 / 836.9 mN m at g = 0.08 / 0.04 / 0.02 / 0.01 D_w: "
    "3.0 % spread, the sum creeping up faster as g shrinks (+2.3, +7.2, +15.0 mN m per halving): "
    "below 0.2 mm the CFD's wedge and the contact model's inlet count the same oil (docs/cfd.md)"))
def test_contact_plus_cfd_spreads_little_over_every_stored_gap():
    rows = _rows()
    assert any(r["gap_ratio"] < 0.02 for r in rows)
    _check_sum_spread(rows)


def _check_sum_spread(rows: list[dict]) -> None:
    assert len(rows) >= 3
    sums = []
    for r in rows:
        c = contact_loss_at_film_limit(r["gap_m"], bearing="32208", speed="2000 rpm", axial_load="1 kN",
                                       temperature="50 degC", oil_level="flooded")
        sums.append(c["friction_torque_Nm"] + r["cfd_loss_Nm"])
    mean = sum(sums) / len(sums)
    assert (max(sums) - min(sums)) <= SUM_SPREAD_TOLERANCE * mean, [round(1e3 * s, 1) for s in sums]


#: The mesh study at the default gap (g = 0.08 D_w) and at 0.04 D_w, stored rows: 6 instead of 3
#: cells across each gap moved the CFD loss by -0.3 % at 0.08 D_w (83.99 -> 83.76 mN m) and by
#: +0.9 % at 0.04 D_w (102.11 -> 103.04 mN m; the rolling-cylinder case had predicted up to +5 %
#: of the wedge part); the background mesh, tiny -> small, by +4.8 %. A CFD loss at 3 cells
#: across is therefore within this of the 6-cell one.
CELLS_ACROSS_TOLERANCE = 0.01


@pytest.mark.parametrize("gap_ratio", [0.08, 0.04])
def test_three_cells_across_each_gap_are_enough(gap_ratio):
    rows = {(r["cells_across_gap"], r["mesh"]): r for r in json.loads(STUDY.read_text())["rows"]
            if r["sector"] and r["gap_ratio"] == gap_ratio}
    n3, n6 = rows[(3, "tiny")], rows[(6, "tiny")]
    assert n6["cells"] > 5 * n3["cells"]
    assert abs(n3["cfd_loss_Nm"] / n6["cfd_loss_Nm"] - 1.0) <= CELLS_ACROSS_TOLERANCE, (n3["cfd_loss_Nm"],
                                                                                         n6["cfd_loss_Nm"])
