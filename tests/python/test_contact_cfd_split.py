"""The contact / CFD split at the raceway line contacts (issue 29): contact + CFD must not depend on
the boundary gap g.

The CFD losses are stored results of the gap study (``benchmarks/cfd_gap_study.py``: the flooded
32208 at 2000 rpm, 50 degC, one-pitch sectors with 3 cells across each gap); the contact losses are
computed here, live, by kegel's contact model with its rolling force cut off at the same g (the far
field of Reynolds' equation beyond g on every loaded slice), and so is the CFD's far field on the
unloaded stretch of the lines, which the contact model's convention does not count
(kegel.coupling.split). When g halves, the contact model hands the film between the new and the
old g to the CFD: the CFD's loss must rise by what the contact's falls plus the unloaded stretch's
far field. A CFD that ignored g (or a contact model that did not cut) would leave the sum moving by
the whole change; a double count or a hole shows the same way.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from kegel.runner.film_limit import contact_loss_at_film_limit

ROOT = Path(__file__).resolve().parents[2]
STUDY = ROOT / "benchmarks" / "results" / "cfd_gap_study.json"

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
    "wall torques to -5.2 % of the drive torque, outside the 5 % the coarser gaps meet: its housing "
    "was still spinning up (+0.5 % of the drive per 100 iterations) when a steady test that did not "
    "yet watch the resting walls stopped it (docs/cfd.md, 'Every wall, and where the oil starts')"))
def test_the_finest_gap_balances_within_five_percent():
    rows = [r for r in _rows() if r["gap_ratio"] < 0.02]
    assert rows
    for r in rows:
        assert abs(r["angular_momentum_balance"]) < 0.05, r["angular_momentum_balance"]


def _contact_Nm(gap_m: float) -> float:
    c = contact_loss_at_film_limit(gap_m, bearing="32208", speed="2000 rpm", axial_load="1 kN",
                                   temperature="50 degC", oil_level="flooded")
    assert c["converged"]
    return c["friction_torque_Nm"]


@pytest.fixture(scope="module")
def study_point():
    """The study point's geometry, load distribution and oil viscosity (for the far field)."""
    from kegel.model.data import load_bearing, load_material
    from kegel.model.geometry import derive_geometry
    from kegel.model.lubricant import lubricant_state
    from kegel.solutions.quasi_static import load_distribution

    b, m = load_bearing("32208"), load_material("bearing_steel")
    g = derive_geometry(b, m)
    return {"g": g, "dist": load_distribution(g, b, m, axial_N=1000.0),
            "eta": lubricant_state("FVA3", "50 degC").dynamic_viscosity_Pas, "w": 2000 * math.pi / 30}


def _wedge(pt, gap_m: float, loaded_length_m=None):
    from kegel.coupling.split import unloaded_line_wedge

    ll = pt["dist"].loaded_length_m if loaded_length_m is None else loaded_length_m
    return unloaded_line_wedge(pt["g"], viscosity_Pas=pt["eta"], inner_speed_rad_s=pt["w"], loaded_length_m=ll,
                               film_limit_m=gap_m)


def _sums(pt, rows: list[dict]) -> list[float]:
    """contact(g) + CFD(g) - the CFD's far field on the unloaded stretch (kegel's contact
    convention on both sides of the boundary: kegel.coupling.split)."""
    return [_contact_Nm(r["gap_m"]) + r["cfd_loss_Nm"] - _wedge(pt, r["gap_m"]).torque_Nm for r in rows]


#: Between two neighbouring gaps the sum may move by at most this fraction of the CFD's own
#: change (measured: 19 % from 0.8 to 0.4 mm, where g / R' reaches 0.19 and the thin-film far
#: field is rough; 3 % and 4 % for the smaller pairs).
SPLIT_TOLERANCE = 0.25


def test_contact_plus_cfd_does_not_depend_on_the_gap(study_point):
    rows = _rows()
    sums = _sums(study_point, rows)
    for k in range(len(rows) - 1):
        d_cfd = rows[k + 1]["cfd_loss_Nm"] - rows[k]["cfd_loss_Nm"]
        d_contact = _contact_Nm(rows[k + 1]["gap_m"]) - _contact_Nm(rows[k]["gap_m"])
        assert d_contact < 0.0 < d_cfd           # the cut takes from the contact, the CFD gains
        assert abs(sums[k + 1] - sums[k]) <= SPLIT_TOLERANCE * d_cfd, (
            f"contact + CFD - wedge moved by {1e3 * (sums[k + 1] - sums[k]):+.2f} mN m between g/D_w = "
            f"{rows[k]['gap_ratio']} and {rows[k + 1]['gap_ratio']}, the CFD by {1e3 * d_cfd:+.2f} mN m")


#: Over every stored gap (0.08 to 0.01 D_w) contact + CFD - wedge may spread by at most this
#: fraction of its mean (measured 0.55 %: 810.7, 807.2, 806.3, 808.2 mN m). Without the wedge
#: term the sum spreads by 6.1 % (822.8 to 873.8 mN m); with the older Eq. 44 cut and no wedge
#: by 3.0 % (812.4 to 836.9).
SUM_SPREAD_TOLERANCE = 0.01


def test_contact_plus_cfd_spreads_little_over_every_stored_gap(study_point):
    rows = _rows()
    assert len(rows) >= 4 and min(r["gap_ratio"] for r in rows) <= 0.01
    sums = _sums(study_point, rows)
    mean = sum(sums) / len(sums)
    assert (max(sums) - min(sums)) <= SUM_SPREAD_TOLERANCE * mean, [round(1e3 * s, 1) for s in sums]


#: The CFD's geometry does not depend on the load, the contact's loaded stretch does: the same
#: stored CFD losses must close the split at any load, with the contact and the wedge at that
#: load. Measured spreads: 0.69 % at 300 N (a third of each line loaded), 0.31 % at 8 kN (77 %);
#: without the wedge 13.2 % and 1.5 %.
@pytest.mark.parametrize("axial_load_N", [300.0, 8000.0])
def test_the_split_holds_at_other_loads(axial_load_N):
    from kegel.coupling.split import unloaded_line_wedge
    from kegel.model.data import load_bearing, load_material
    from kegel.model.geometry import derive_geometry
    from kegel.model.lubricant import lubricant_state
    from kegel.solutions.quasi_static import load_distribution

    b, m = load_bearing("32208"), load_material("bearing_steel")
    g = derive_geometry(b, m)
    dist = load_distribution(g, b, m, axial_N=axial_load_N)
    eta = lubricant_state("FVA3", "50 degC").dynamic_viscosity_Pas
    sums, raw = [], []
    for r in _rows():
        c = contact_loss_at_film_limit(r["gap_m"], bearing="32208", speed="2000 rpm", axial_load=f"{axial_load_N} N",
                                       temperature="50 degC", oil_level="flooded")
        assert c["converged"]
        w = unloaded_line_wedge(g, viscosity_Pas=eta, inner_speed_rad_s=2000 * math.pi / 30,
                                loaded_length_m=dist.loaded_length_m, film_limit_m=r["gap_m"])
        raw.append(c["friction_torque_Nm"] + r["cfd_loss_Nm"])
        sums.append(raw[-1] - w.torque_Nm)
    assert (max(sums) - min(sums)) <= SUM_SPREAD_TOLERANCE * (sum(sums) / len(sums)), [round(1e3 * x, 1) for x in sums]
    assert (max(raw) - min(raw)) > (max(sums) - min(sums))


def test_without_the_unloaded_stretch_the_sum_creeps(study_point):
    """The wedge term is what moves: the sum without it spreads by several per cent (the
    test above would fail without the term; this one fails if the term stopped mattering)."""
    rows = _rows()
    raw = [_contact_Nm(r["gap_m"]) + r["cfd_loss_Nm"] for r in rows]
    assert (max(raw) - min(raw)) > 4 * SUM_SPREAD_TOLERANCE * (sum(raw) / len(raw))


#: The CFD's gain between two gaps against Reynolds' far field along the whole line (the CFD's
#: straight rollers stand g off the raceways over their whole length): within 20 % from 0.8 to
#: 0.4 mm (measured -16 %: lubrication theory at g / R' up to 0.19), within 10 % below (measured
#: -3 % and +4 %). An analytic check of the CFD's wedge, independent of the contact model.
FAR_FIELD_TOLERANCE = {0.08: 0.20, 0.04: 0.10, 0.02: 0.10}


def test_the_cfd_gains_what_reynolds_far_field_predicts(study_point):
    rows = _rows()
    none = 0.0 * study_point["dist"].loaded_length_m  # the whole line
    for k in range(len(rows) - 1):
        a, b = rows[k], rows[k + 1]
        d_cfd = b["cfd_loss_Nm"] - a["cfd_loss_Nm"]
        d_far = _wedge(study_point, b["gap_m"], none).torque_Nm - _wedge(study_point, a["gap_m"], none).torque_Nm
        tol = FAR_FIELD_TOLERANCE[a["gap_ratio"]]
        assert abs(d_cfd / d_far - 1.0) <= tol, (a["gap_ratio"], 1e3 * d_cfd, 1e3 * d_far)


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


def test_kegel_run_gives_the_same_total_at_the_widest_and_the_finest_gap():
    """End to end through the runner: ``kegel run`` with ``hydraulic = "cfd"`` on the stored
    gap-study results at g = 0.08 and 0.01 D_w (the two that carry their thin films): the contact
    cut at each result's gap, the CFD less its far field on the unloaded stretch, the thin films.
    Measured: 897.2 and 894.6 mN m (-0.3 %); the CFD alone 84.0 and 181.6."""
    from kegel.model.scene import scene_from_dict
    from kegel.runner.run import run_scene

    totals = {}
    for gap in (0.08, 0.01):
        f = STUDY.parent / "cfd_gap_study" / f"32208_2000rpm_flooded_50C_tiny_g{gap}_n3_sector" / "results.json"
        raw = {"bearing": {"designation": "32208"}, "lubricant": {"name": "FVA3"},
               "operating": {"axial_load": "1 kN", "speed": "2000 rpm", "temperature": "50 degC"},
               "lubrication": {"mode": "oil_bath", "oil_level": "flooded"},
               "model": {"hydraulic": "cfd", "cfd_results": str(f)}}
        p = run_scene(scene_from_dict(raw), progress=False, write=False).points[0]
        assert p["converged"]
        bnd = p["hydraulic"]["boundary"]
        assert bnd["contact_film_limit_m"] == pytest.approx(gap * 0.010)
        assert bnd["unloaded_line_wedge_Nm"] > 0.0
        totals[gap] = p["total_torque_Nm"]
    assert abs(totals[0.01] / totals[0.08] - 1.0) <= SUM_SPREAD_TOLERANCE, totals
