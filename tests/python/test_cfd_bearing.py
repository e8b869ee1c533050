"""The bearing CFD cases: geometry, kinematics, mesh and short runs of both templates (32208, tiny)."""

from __future__ import annotations

import json
import math
import shutil

import numpy as np
import pytest

from kegel.cfd_cases.geometry import build_mesh, cfd_geometry, roller_name
from kegel.cfd_cases.mesh import check_mesh, gmsh_to_foam
from kegel.cfd_cases.run import CfdPoint, kinematics, roller_wall_rotation, run_case
from kegel.cfd_cases.template import render_case
from kegel.data import load_bearing, load_material
from kegel.geometry import derive_geometry

from conftest import run_kegel


@pytest.fixture(scope="module")
def g32208():
    return derive_geometry(load_bearing("32208"), load_material("bearing_steel"))


def _dist_to_line(p, line) -> float:
    (z0, r0), (z1, r1) = line
    u = np.array([z1 - z0, r1 - r0]) / math.hypot(z1 - z0, r1 - r0)
    v = np.asarray(p) - np.array([z0, r0])
    return abs(u[0] * v[1] - u[1] * v[0])


def test_cfd_geometry_is_derived_from_the_bearing_data(g32208):
    cg = cfd_geometry(g32208)
    assert cg.roller_count == 17
    assert cg.housing_radius_m == pytest.approx(0.040)
    assert cg.shaft_radius_m == pytest.approx(0.020)
    assert cg.gap_m == pytest.approx(0.08 * g32208.roller_mean_diameter_m)
    # the real rollers: mean diameter D_w, length L
    mid = 0.5 * (cg.roller_radii_m[0] + cg.roller_radii_m[1])
    assert mid == pytest.approx(0.5 * g32208.roller_mean_diameter_m, rel=1e-9)
    assert cg.roller_length_m == pytest.approx(g32208.roller_length_m)
    c0, a0 = cg.roller_centre_and_axis(0)
    assert c0[1] < 0 and abs(c0[0]) < 1e-12  # roller 0 at the bottom
    assert np.linalg.norm(a0) == pytest.approx(1.0)


@pytest.mark.parametrize("gap_ratio", [0.08, 0.02, 0.005])
def test_raceways_stand_the_contact_gap_off_the_real_rollers(g32208, gap_ratio):
    """Along each contact line (the roller generatrix facing a raceway, in the axial plane) the
    distance to the set-back raceway is g, at both ends of the roller; the rib face is the
    clearance c from the roller's large end, and the pockets c from the roller."""
    cg = cfd_geometry(g32208, gap_ratio=gap_ratio)
    g = gap_ratio * g32208.roller_mean_diameter_m
    a = np.array(cg.roller_axis)
    n = np.array([-a[1], a[0]])  # away from the bearing axis
    s0 = np.array(cg.roller_small_end_m)
    for xi, r in ((0.0, cg.roller_radii_m[0]), (cg.roller_length_m, cg.roller_radii_m[1])):
        foot = s0 + xi * a
        assert _dist_to_line(foot - r * n, cg.inner_raceway_line_m) == pytest.approx(g, rel=1e-6)
        assert _dist_to_line(foot + r * n, cg.outer_raceway_line_m) == pytest.approx(g, rel=1e-6)
    # the cup's bore line is the outer raceway line
    cup = cg.cup_section
    assert _dist_to_line(cup[0], cg.outer_raceway_line_m) == pytest.approx(0.0, abs=1e-12)
    # rib face (cone section points 3 -> 4) against the roller's large end face (its centre and rim)
    rib = (cg.cone_section[3], cg.cone_section[4])
    large = s0 + cg.roller_length_m * a
    for point in (large - 0.5 * cg.roller_radii_m[1] * n, large - 0.9 * cg.roller_radii_m[1] * n):
        d = _dist_to_line(point, rib)
        assert cg.clearance_m * 0.95 < d < cg.clearance_m * 1.1
    tan_g = (cg.roller_radii_m[1] - cg.roller_radii_m[0]) / cg.roller_length_m
    c = cg.clearance_m
    assert cg.pocket_radii_m[0] - (cg.roller_radii_m[0] - c * tan_g) == pytest.approx(c, rel=1e-9)
    assert cg.pocket_length_m == pytest.approx(cg.roller_length_m + 2 * c)
    assert cg.clearance_m >= g32208.cage_pocket_clearance_circumferential_m


def test_the_local_raceway_gap_is_g_on_the_contact_line_and_the_mesh_sizes_by_it(g32208):
    """kegel.cfd_cases.geometry.raceway_gap_m (what benchmarks/cfd_wedge_oil_fraction.py selects
    the wedge cells by): g midway across the gap along the contact line, in 3-D at the roller's
    azimuth; and the same number as the mesh's gmsh size expression times the cells across."""
    from kegel.cfd_cases.geometry import _gap_size_expression, raceway_gap_m

    cg = cfd_geometry(g32208, gap_ratio=0.04)
    a = np.array(cg.roller_axis)
    n = np.array([-a[1], a[0]])
    s0 = np.array(cg.roller_small_end_m)
    k = 3
    phi = cg.roller_azimuth_rad(k)
    pts, expect = [], []
    for xi in (0.1, 0.5, 0.9):
        xi_m = xi * cg.roller_length_m
        r = cg.roller_radii_m[0] + xi * (cg.roller_radii_m[1] - cg.roller_radii_m[0])
        for side, line in ((-1.0, cg.inner_raceway_line_m), (1.0, cg.outer_raceway_line_m)):
            zr = s0 + xi_m * a + side * (r + 0.5 * cg.gap_m) * n   # midway across the gap
            pts.append(((zr[1] * math.cos(phi), zr[1] * math.sin(phi), zr[0]), line))
            expect.append(xi_m)
    for ((x, y, z), line), xi_m in zip(pts, expect):
        gap, along = raceway_gap_m(cg, k, line, np.array([[x, y, z]]))
        assert gap[0] == pytest.approx(cg.gap_m, rel=1e-3)
        assert along[0] == pytest.approx(xi_m, rel=1e-3)
        expr = _gap_size_expression(cg, k, line, 3).replace("^", "**")
        size = eval(expr, {"abs": abs, "sqrt": math.sqrt, "x": x, "y": y, "z": z})  # noqa: S307 (our own expression)
        assert 3 * size == pytest.approx(gap[0], rel=1e-9)


def test_gap_and_clearance_ratios_are_checked(g32208):
    for kw in ({"gap_ratio": 0.0}, {"gap_ratio": 0.5}, {"gap_ratio": float("nan")}, {"clearance_ratio": 0.0}):
        with pytest.raises(ValueError, match=next(iter(kw))):
            cfd_geometry(g32208, **kw)
    for kw in ({"gap_ratio": -0.1}, {"cells_across_gap": 0}, {"sector": "yes"}):
        with pytest.raises(ValueError, match=next(iter(kw))):
            CfdPoint(bearing="32208", speed_rad_s=SPEED, temperature_K=323.15, oil_level_m=None, **kw).validate()
    with pytest.raises(ValueError, match="flooded"):
        CfdPoint(bearing="32208", speed_rad_s=SPEED, temperature_K=323.15, oil_level_m=0.04, sector=True).validate()


def test_sector_is_one_pitch_around_roller_0(g32208):
    cg = cfd_geometry(g32208, sector=True)
    lo, hi = cg.sector_angles_rad
    assert hi - lo == pytest.approx(2 * math.pi / 17)
    assert 0.5 * (lo + hi) == pytest.approx(cg.roller_azimuth_rad(0))
    assert cg.modelled_rollers == [0] and cg.copies == 17


def test_housing_clearance_must_be_positive(g32208):
    with pytest.raises(ValueError, match="housing_clearance_m"):
        cfd_geometry(g32208, housing_clearance_m=0.0)
    with pytest.raises(ValueError, match="housing walls"):
        cfd_geometry(g32208, housing_clearance_m=1e-4)


def test_pure_rolling_kinematics(g32208):
    w = 2000 * math.pi / 30
    k = kinematics(g32208, w)
    # no slip at the outer raceway: roller surface speed relative to the cage equals the cup's
    u_roller = -k["roller_spin_rad_s"] * 0.5 * g32208.roller_mean_diameter_m
    u_cup = k["cage_rad_s"] * 0.5 * g32208.outer_raceway_diameter_mid_m
    assert u_roller == pytest.approx(u_cup, rel=1e-12)
    assert 0 < k["cage_rad_s"] < w


@pytest.mark.parametrize("k", [0, 5])
def test_roller_wall_motion_is_orbit_plus_spin(g32208, k):
    cg = cfd_geometry(g32208)
    wc, ws = 80.0, -500.0
    r = roller_wall_rotation(cg, k, wc, ws)
    c, a = cg.roller_centre_and_axis(k)
    ez = np.array([0.0, 0.0, 1.0])
    rng = np.random.default_rng(k)
    for p in c + 0.01 * rng.standard_normal((20, 3)):
        expected = wc * np.cross(ez, p) + ws * np.cross(a, p - c)
        got = r["omega"] * np.cross(r["axis"], p - r["origin"])
        assert np.allclose(got, expected, atol=1e-12 * np.linalg.norm(expected) + 1e-14)


@pytest.mark.openfoam
@pytest.mark.parametrize("designation", ["32208", "32216"])
def test_tiny_mesh_is_clean_and_has_every_patch(designation, tmp_path):
    g = derive_geometry(load_bearing(designation), load_material("bearing_steel"))
    cg = cfd_geometry(g)
    case = render_case("check_cavity", tmp_path / "m", {"n_cells": 2, "delta_t": 1, "end_time": 1,
                                                          "n_steps": 1, "solver": "simpleFoam", "steady": True,
                                                          "lid_velocity": (0, 0, 0)})
    types = build_mesh(cg, "tiny", tmp_path / "b.msh")
    assert set(types) == {"inner_ring", "shaft", "outer_ring", "housing", "cage",
                          *[roller_name(k) for k in range(g.roller_count)]}
    gmsh_to_foam(case, tmp_path / "b.msh", types)
    q = check_mesh(case)
    assert q.ok and 20_000 < q.cells < 200_000
    assert q.max_non_orthogonality_deg < 75
    # the boundary face geometry kegel computes from polyMesh matches OpenFOAM's face centres
    from kegel.cfd_cases.foam import read_boundary_geometry, read_boundary_vectors, run_utility

    run_utility(case, "postProcess", "-func", "writeCellCentres", "-time", "0")
    ours = read_boundary_geometry(case)
    foams = read_boundary_vectors(case / "0" / "C")
    for name in ("cage", "inner_ring", roller_name(3)):
        assert np.abs(ours[name][0] - foams[name]).max() < 1e-9
        assert (np.linalg.norm(ours[name][1], axis=1) > 0).all()


def _bad(*args, level: str = "flooded"):
    res = run_kegel("cfd", "run", "--oil-level", level, *args)
    assert res.returncode == 2, res.stderr
    return res.stderr


def test_cfd_run_rejects_bad_input():
    assert "--mesh" in _bad("--mesh", "huge") and "tiny" in _bad("--mesh", "huge")
    assert "--oil-level" in _bad("--oil-level", "90 mm")
    assert "--speed" in _bad("--speed", "0 rpm")
    assert "--np" in _bad("--np", "0")
    assert "--max-courant" in _bad("--max-courant", "-1") and "positive" in _bad("--max-courant", "nan")
    assert "--max-interface-courant" in _bad("--max-interface-courant", "0")
    assert "--initial-from" in _bad("--initial-from", "/nonexistent", level="shaft_center")
    assert "kegel CFD case folder" in _bad("--initial-from", "/nonexistent")  # flooded runs map too
    assert "coarser than --mesh tiny" in _bad("--start-on", "small", level="shaft_center")
    assert "coarser than --mesh small" in _bad("--start-on", "fine", "--mesh", "small", level="shaft_center")
    assert "tiny, small, fine" in _bad("--start-on", "huge", "--mesh", "small", level="shaft_center")
    assert "not both" in _bad("--start-on", "tiny", "--mesh", "small", "--initial-from", "/nonexistent",
                              level="shaft_center")
    for tol in ("1", "-0.1", "150 %", "nan", "two percent"):
        err = _bad("--steady-tolerance", tol, level="shaft_center")
        assert "--steady-tolerance" in err and repr(tol) in err and "fraction" in err


def test_cfd_modelling_choice_options_are_checked():
    assert "--housing-clearance" in _bad("--housing-clearance", "-2 mm")
    assert "--frame" in _bad("--frame", "rotor")
    for bad in (dict(frame="rotor"), dict(housing_clearance_m=0.0), dict(housing_clearance_m=math.nan)):
        with pytest.raises(ValueError, match="frame|housing_clearance_m"):
            CfdPoint(bearing="32208", speed_rad_s=200.0, temperature_K=323.15, oil_level_m=None, **bad).validate()
    # a moving mesh is the oil bath's check: a flooded bearing's flow is steady in the cage frame
    with pytest.raises(ValueError, match="frame = 'moving_mesh': only for an oil bath"):
        CfdPoint(bearing="32208", speed_rad_s=200.0, temperature_K=323.15, oil_level_m=None,
                 frame="moving_mesh").validate()
    CfdPoint(bearing="32208", speed_rad_s=200.0, temperature_K=323.15, oil_level_m=0.04, frame="moving_mesh").validate()


def test_forces_of_a_body_turning_with_the_mesh_are_read_where_it_stood_at_the_start():
    """On a moving mesh a roller orbits: the forces function object reports its force in the
    inertial frame and its moment about the fixed point where its centre was at t = 0. Taken
    back to the start position, a force and moment that are constant in the roller's own frame
    must come out constant (a roller that does not turn back gives the rotated vectors)."""
    from kegel.cfd_cases.forces import ForceSeries
    from kegel.cfd_cases.run import _to_initial_position

    omega, c0 = 87.6, np.array([0.0, -0.03, 0.0105])
    f_body, m_body = np.array([0.3, -1.2, 0.4]), np.array([-2e-3, 5e-4, 1e-3])  # about the roller's centre
    t = np.linspace(0.0, 0.2, 41)  # almost three cage revolutions
    th = omega * t
    rot = np.array([[[math.cos(a), -math.sin(a), 0.0], [math.sin(a), math.cos(a), 0.0], [0.0, 0.0, 1.0]] for a in th])
    f = rot @ f_body
    c = rot @ c0
    m_c0 = rot @ m_body + np.cross(c - c0, f)  # the same loads' moment about the fixed point c0
    series = ForceSeries(t, f, 0.25 * f, 0.75 * f, m_c0, 0.25 * m_c0, 0.75 * m_c0)
    back = _to_initial_position(series, omega, c0)
    assert np.allclose(back.force_total, f_body, atol=1e-12) and np.allclose(back.moment_total, m_body, atol=1e-12)
    assert np.allclose(back.moment_pressure + back.moment_viscous, back.moment_total, atol=1e-12)
    # the moment about the bearing axis needs no turning back: about the origin it is c x F + M
    mz = np.cross(c0, back.force_total)[:, 2] + back.moment_total[:, 2]
    assert np.allclose(mz, np.cross(c0, f)[:, 2] + m_c0[:, 2], atol=1e-12)
    assert not np.allclose(_to_initial_position(series, 0.5 * omega, c0).force_total, f_body, atol=1e-3)


@pytest.mark.openfoam
def test_absolute_frame_case_has_no_mrf_and_absolute_wall_velocities(tmp_path):
    """frame = "absolute": MRF inactive, and the wall velocities are the walls' own (tangential)
    velocities: the cage turns at omega_c, so each of its faces gets the tangential part of
    omega_c e_z x r (all of it on the conical shell, less on the pocket walls)."""
    from kegel.cfd_cases.foam import read_boundary_geometry
    from kegel.cfd_cases.run import prepare_case

    p = CfdPoint(bearing="32208", speed_rad_s=SPEED, temperature_K=323.15, oil_level_m=None, frame="absolute",
                 n_procs=1)
    case = prepare_case(p, tmp_path / "abs", log=lambda s: None)
    mrf = (case / "constant" / "MRFProperties").read_text()
    assert "active      no;" in mrf
    meta = json.loads((case / "kegel-case.json").read_text())
    assert meta["point"]["frame"] == "absolute"
    cf, _ = read_boundary_geometry(case)["cage"]
    text = (case / "0" / "wallVelocity" / "cage").read_text()
    rows = text[text.index("(\n") + 2:text.rindex(")")].split("\n")
    u = np.array([[float(v) for v in r.strip("()").split()] for r in rows if r.strip()])
    w_c = meta["kinematics"]["cage_rad_s"]
    speed = np.linalg.norm(u, axis=1)
    r = np.hypot(cf[:, 0], cf[:, 1])
    ratio = speed / (abs(w_c) * r)
    # the tangential part of omega_c e_z x r: equal on the shell faces, less on the pocket walls
    assert np.all(ratio <= 1.0 + 1e-9) and np.median(ratio) == pytest.approx(1.0, abs=1e-3)


@pytest.mark.openfoam
def test_a_case_without_the_cage_has_no_cage_patch_and_zero_cage_forces(tmp_path):
    """--no-cage (a modelling-choice check): the mesh has every patch but the cage, its space is
    oil (more cells than the reference's walls leave), and the post-processing reads the missing
    cage as zero forces instead of failing."""
    from kegel.cfd_cases.foam import read_boundary_geometry
    from kegel.cfd_cases.run import _forces, prepare_case

    p = CfdPoint(bearing="32208", speed_rad_s=SPEED, temperature_K=323.15, oil_level_m=None, cage=False,
                 n_procs=1)
    case = prepare_case(p, tmp_path / "nocage", log=lambda s: None)
    patches = set(read_boundary_geometry(case))
    assert "cage" not in patches and {"inner_ring", "outer_ring", "shaft", "housing", roller_name(0)} <= patches
    assert not (case / "0" / "wallVelocity" / "cage").exists()
    assert "forces_cage" not in (case / "system" / "controlDict").read_text()
    assert json.loads((case / "kegel-case.json").read_text())["point"]["cage"] is False
    d = case / "postProcessing" / "forces_inner_ring" / "0"
    d.mkdir(parents=True)
    row = "\t".join(["1"] + ["(1 2 3)"] * 3)
    for f in ("force.dat", "moment.dat"):
        (d / f).write_text(f"# Time total pressure viscous\n{row}\n")
    cage = _forces(case, "cage")
    assert cage.time.tolist() == [1.0] and not cage.moment_total.any() and not cage.force_total.any()


def test_no_cage_option_reaches_the_point_and_the_case_name():
    from kegel.cfd_cases.cli import _case_name

    p = CfdPoint(bearing="32208", speed_rad_s=SPEED, temperature_K=323.15, oil_level_m=None, cage=False)
    assert _case_name(p, "flooded").endswith("_tiny_nocage")
    with pytest.raises(ValueError, match="cage"):
        CfdPoint(bearing="32208", speed_rad_s=SPEED, temperature_K=323.15, oil_level_m=None, cage="no").validate()
    assert "--no-cage" in run_kegel("cfd", "run", "--help").stdout


def test_cfd_point_steady_tolerance_is_a_fraction():
    ok = CfdPoint(bearing="32208", speed_rad_s=200.0, temperature_K=323.15, oil_level_m=0.04,
                  steady_tolerance=0.0)
    ok.validate()  # 0: no steady stop (a reference run to the end time)
    for bad in (-0.01, 1.0, math.nan, math.inf):
        with pytest.raises(ValueError, match="steady_tolerance"):
            CfdPoint(bearing="32208", speed_rad_s=200.0, temperature_K=323.15, oil_level_m=0.04,
                     steady_tolerance=bad).validate()


SPEED = 2000 * math.pi / 30


def _finite(x) -> bool:
    return all(math.isfinite(v) for v in np.ravel(x))


def test_oil_bath_write_times_do_not_follow_the_end_time():
    from kegel.cfd_cases.run import oil_bath_write_interval_s

    rev = 2 * math.pi / SPEED
    for end in (0.6, 0.9, 20 * rev, 7.3):
        assert oil_bath_write_interval_s(SPEED, end) == pytest.approx(rev)
    assert oil_bath_write_interval_s(SPEED, 1e-4) == 1e-4


@pytest.mark.openfoam
def test_tiny_flooded_case_runs_and_resumes(tmp_path):
    """Both ways of stopping: an iteration limit, then a resumed run that goes on from there; and
    a resume after a kill that cut the latest write (one processor's field half written, the
    force file's last line cut) goes on from the write before it, to the same answer as a resume
    of the whole case, and keeps the cut write (moved aside, not deleted)."""
    case = tmp_path / "flooded"
    p = CfdPoint(bearing="32208", speed_rad_s=SPEED, temperature_K=323.15, oil_level_m=None,
                 mesh="tiny", n_procs=2, max_iterations=20)
    res = run_case(p, case, progress=False, log=lambda s: None)
    data = json.loads((case / "results.json").read_text())
    t = data["torques_Nm"]
    assert _finite([t[k]["total"] for k in ("inner_ring", "outer_ring", "cage")])
    assert t["inner_ring"]["total"] < 0  # the oil brakes the turning inner ring
    assert t["outer_ring"]["total"] > 0  # and drags the fixed outer ring along
    assert data["power_loss_W"] > 0 and res.loss_torque_at_shaft_Nm > 0
    assert data["provenance"]["kegel_version"] and data["fidelity"]["mesh"] == "tiny"
    assert data["fidelity"]["steady_tolerance"] == 0.02
    assert len(data["rollers"]) == 17 and _finite([r["force_N"] for r in data["rollers"]])
    assert data["iterations"] == pytest.approx(20)
    # resume with more iterations: continues from iteration 20 (and writes iteration 40)
    p2 = CfdPoint(**{**p.__dict__, "max_iterations": 40})
    run_case(p2, case, progress=False, log=lambda s: None)
    data2 = json.loads((case / "results.json").read_text())
    assert data2["iterations"] == pytest.approx(40)
    assert data2["runtime_s"] > data["runtime_s"]
    # another point in the same folder is refused
    with pytest.raises(Exception, match="another point"):
        run_case(CfdPoint(**{**p.__dict__, "speed_rad_s": 2 * SPEED}), case, progress=False, log=lambda s: None)
    # a kill while writing iteration 40: processor1's U half written, a force line cut
    killed = tmp_path / "killed"
    shutil.copytree(case, killed, symlinks=True)
    u = killed / "processor1" / "40" / "U"
    u.write_bytes(u.read_bytes()[: u.stat().st_size // 2])
    cut_u = u.read_bytes()
    forces = sorted((killed / "postProcessing" / "forces_inner_ring").glob("*/force.dat"))[-1]
    forces.write_bytes(forces.read_bytes()[:-25])
    said: list[str] = []
    p3 = CfdPoint(**{**p.__dict__, "max_iterations": 50})
    whole = run_case(p3, case, progress=False, log=lambda s: None)
    resumed = run_case(p3, killed, progress=False, log=said.append)
    assert any("time 40 cannot be restarted" in s and "processor1/40/U" in s for s in said)
    for proc in ("processor0", "processor1"):
        assert (killed / proc / "40.cut").is_dir()
    assert (killed / "processor1" / "40.cut" / "U").read_bytes() == cut_u
    assert json.loads((killed / "results.json").read_text())["iterations"] == pytest.approx(50)
    # the last iteration is written although 50 is off the write interval (20): a resume goes on from it
    for folder in (case, killed):
        assert all((folder / proc / "50" / "U").is_file() for proc in ("processor0", "processor1"))
    # iterations 21-40 are repeated as they ran the first time: the same flow at 50
    assert resumed.loss_torque_at_shaft_Nm == pytest.approx(whole.loss_torque_at_shaft_Nm, rel=1e-8)


@pytest.mark.openfoam
def test_flooded_sector_starts_from_a_run_with_fewer_cells_across_the_gap(tmp_path):
    """A fine flooded mesh (more cells across each contact gap) starts from a coarser run's flow:
    the mapped velocity is the source's (not the start rotation), the walls keep this case's own
    velocities, and a run of another gap is refused."""
    from kegel.cfd_cases.foam import FoamError, read_field
    from kegel.cfd_cases.run import prepare_case

    base = dict(bearing="32208", speed_rad_s=SPEED, temperature_K=323.15, oil_level_m=None, mesh="tiny",
                sector=True, gap_ratio=0.08)
    source = tmp_path / "n2"
    run_case(CfdPoint(**base, n_procs=2, max_iterations=30, cells_across_gap=2), source, progress=False,
             log=lambda s: None)
    case = prepare_case(CfdPoint(**base, n_procs=1, cells_across_gap=3, initial_from=str(source)),
                        tmp_path / "n3", log=lambda s: None)
    init = json.loads((case / "kegel-case.json").read_text())["initial_state"]
    assert init["source_time_s"] == 30 and init["iterations_before"] == 30
    assert init["source_cells_across_gap"] == 2 and "oil_volume_change" not in init
    u, u_src = read_field(case / "0" / "U"), read_field(source / "30" / "U")
    assert len(u) > len(u_src)
    speed, speed_src = np.linalg.norm(u, axis=1), np.linalg.norm(u_src, axis=1)
    # the source's flow, not the start's rigid rotation with the cage
    assert np.percentile(speed, 90) == pytest.approx(np.percentile(speed_src, 90), rel=0.05)
    assert np.ptp(read_field(case / "0" / "p")) > 0
    assert '#include "wallVelocity/inner_ring"' in (case / "0" / "U").read_text()
    with pytest.raises(FoamError, match="another point.*gap_ratio"):
        prepare_case(CfdPoint(**{**base, "gap_ratio": 0.04}, n_procs=1, initial_from=str(source)),
                     tmp_path / "other", log=lambda s: None)


@pytest.mark.openfoam
def test_tiny_flooded_case_converges_and_balances_angular_momentum(tmp_path):
    """Run to a steady torque: the wall torques about the axis must nearly cancel. The finite-volume
    scheme does not conserve angular momentum exactly; with the cell-limited gradient in the
    viscous stress and the wall forces the sum was -45 % of the drive torque on this mesh (the
    limiter acts on the solid-body rotation of the oil near every wall), with the unlimited one
    (limited only in the convection) -14 %, of which about -10 % is the MRF frame's (a run with the
    frame at rest balanced to -3.5 %). Regression: the loss torque within 3 % of the 74.2 mN m
    this run gives with the real rollers and the raceways set back by 0.08 D_w (59.3 mN m with
    the former shrunk rollers; the sector with 3 cells across each gap gives 84.0). Started from
    oil at rest it stopped at iteration 470 (74.2 mN m, balance -14 %); started with the oil
    turning with the cage and every wall's torque in the steady test, at 447 (74.02 mN m,
    -11.1 %)."""
    case = tmp_path / "flooded"
    p = CfdPoint(bearing="32208", speed_rad_s=SPEED, temperature_K=323.15, oil_level_m=None,
                 mesh="tiny", n_procs=2, max_iterations=600)
    run_case(p, case, progress=False, log=lambda s: None)
    data = json.loads((case / "results.json").read_text())
    assert data["steady"] and data["stopped_by"] == "steady torque"
    assert abs(data["angular_momentum_balance"]["relative_to_drive_torque"]) < 0.2
    assert data["loss_torque_at_shaft_Nm"] == pytest.approx(74.2e-3, rel=0.03)


@pytest.fixture(scope="module")
def tiny_bath(tmp_path_factory):
    """The tiny oil-bath case of the 32208, run through the command line for 0.3 ms."""
    case = tmp_path_factory.mktemp("cfd") / "bath"
    res = run_kegel("cfd", "run", "--bearing", "32208", "--speed", "2000 rpm", "--temperature", "50 degC",
                    "--oil-level", "shaft_center", "--mesh", "tiny", "--np", "2", "--end-time", "0.3 ms",
                    "--output", str(case), "--quiet", "--format", "json", timeout=900)
    return case, res


@pytest.mark.openfoam
def test_tiny_oil_bath_case_runs_with_conserved_oil(tiny_bath):
    """Through the command line, as a user runs it: results, torque history and oil picture."""
    case, res = tiny_bath
    assert res.returncode == 0, res.stderr[-3000:]
    data = json.loads(res.stdout)
    assert data["fidelity"]["max_courant"] == 5.0
    # the steady test's window is half a cage revolution; 0.3 ms is far too short for an estimate
    assert data["loss_torque_drift"]["window_s"] == pytest.approx(math.pi / data["kinematics"]["cage_rad_s"])
    assert "estimated_steady_Nm" not in data["loss_torque_drift"] and not data["steady"]
    t = data["torques_Nm"]
    assert _finite([t[k]["total"] for k in ("inner_ring", "outer_ring", "cage")])
    assert t["inner_ring"]["total"] < 0
    assert data["simulated_time_s"] == pytest.approx(3e-4, rel=1e-3)
    vol = np.array(data["liquid_volume"]["volume_m3"])
    assert len(vol) > 10 and _finite(vol)
    assert abs(vol[-1] - vol[0]) / vol[0] < 1e-3  # MRF and closed walls keep the oil
    # the balance counts the moment of the oil's weight, from the state written at the end
    bal = data["angular_momentum_balance"]
    assert bal["weight_moment_states_s"] == [pytest.approx(3e-4)] and math.isfinite(bal["weight_moment_on_fluid_Nm"])
    # the oil still lies level: its weight's moment is that of a centre of mass within 0.5 mm of the axis
    assert abs(bal["weight_moment_on_fluid_Nm"]) < 0.034 * 9.81 * 0.5e-3
    # every wall's torque series (kegel.cfd_cases.run.wall_torque_series), averaged over the
    # result's window, is the torque results.json gives, and they sum to the balance's sum
    from kegel.cfd_cases.run import wall_torque_series

    ts, walls = wall_torque_series(case, json.loads((case / "kegel-case.json").read_text()))
    lo, hi = data["averaging_window"]
    sel = (ts >= lo) & (ts <= hi)
    means = {name: float(v[sel].mean()) for name, v in walls.items()}
    assert means == pytest.approx({name: t[name]["total"] for name in walls}, rel=1e-9, abs=1e-15)
    assert sum(means.values()) == pytest.approx(bal["sum_of_wall_torques_Nm"], rel=1e-9)
    for name in ("torque_history", "oil_distribution"):
        assert (case / f"{name}.png").stat().st_size > 10_000
    assert data["liebrecht_Nm"]["total_Nm"] > 0


@pytest.mark.openfoam
def test_oil_bath_starts_from_a_run_on_another_mesh(tiny_bath, tmp_path):
    """Coarse-to-fine start: the mapped state keeps the oil volume and this case's own walls."""
    from kegel.cfd_cases.foam import FoamError, read_field
    from kegel.cfd_cases.run import prepare_case

    source, res = tiny_bath
    assert res.returncode == 0, res.stderr[-3000:]
    level = 0.5 * load_bearing("32208").outer_diameter_m
    p = CfdPoint(bearing="32208", speed_rad_s=SPEED, temperature_K=323.15, oil_level_m=level, mesh="tiny",
                 n_procs=1, initial_from=str(source))
    case = prepare_case(p, tmp_path / "mapped", log=lambda s: None)
    meta = json.loads((case / "kegel-case.json").read_text())
    init = meta["initial_state"]
    assert init["source_time_s"] == pytest.approx(3e-4, rel=1e-3)
    assert abs(init["oil_volume_change"]) < 2e-3
    # the oil moves as in the source (not the 1 % start rotation) ...
    u = read_field(case / "0" / "U")
    u_src = read_field(source / f"{init['source_time_s']:g}" / "U")
    speed, speed_src = np.linalg.norm(u, axis=1), np.linalg.norm(u_src, axis=1)
    assert np.percentile(speed, 90) == pytest.approx(np.percentile(speed_src, 90), rel=0.05)
    # ... and the walls keep their exact velocities
    text = (case / "0" / "U").read_text()
    assert '#include "wallVelocity/inner_ring"' in text
    with pytest.raises(FoamError, match="another point"):
        prepare_case(CfdPoint(bearing="32208", speed_rad_s=0.5 * SPEED, temperature_K=323.15, oil_level_m=level,
                              mesh="tiny", n_procs=1, initial_from=str(source)), tmp_path / "other")


@pytest.mark.openfoam
def test_a_moving_mesh_releases_the_frozen_rotor_and_turns_every_wall_with_it(tiny_bath, tmp_path):
    """frame = moving_mesh starts from the frozen rotor's state (cage frame) and turns the whole
    mesh with the cage: after n steps every wall's velocity is the frozen rotor's, turned by the
    mesh's angle (the expressions against the per-face values kegel writes for the frozen rotor),
    the oil is kept, and the forces are read. A moving-mesh state cannot start another case."""
    from kegel.cfd_cases.foam import FoamError
    from kegel.cfd_cases.run import _write_wall_velocities, prepare_case

    source, res = tiny_bath
    assert res.returncode == 0, res.stderr[-3000:]
    level = 0.5 * load_bearing("32208").outer_diameter_m
    end = 1e-4
    p = CfdPoint(bearing="32208", speed_rad_s=SPEED, temperature_K=323.15, oil_level_m=level, mesh="tiny",
                 n_procs=1, frame="moving_mesh", initial_from=str(source), end_time_s=end, steady_tolerance=0.0)
    case = tmp_path / "moving"
    result = run_case(p, case, log=lambda s: None, progress=False)
    meta = json.loads((case / "kegel-case.json").read_text())
    omega_c = meta["kinematics"]["cage_rad_s"]
    assert meta["mesh_motion_rad_s"] == omega_c and "staticFvMesh" not in (case / "constant" / "dynamicMeshDict").read_text()
    assert math.isfinite(result.loss_torque_at_shaft_Nm) and result.loss_torque_at_shaft_Nm > 0
    vol = np.array(result.liquid_volume["volume_m3"])
    assert abs(vol[-1] - vol[0]) / vol[0] < 1e-4  # a solid-body turn of the whole mesh: no interpolation
    # the frozen rotor's wall velocities at t = 0, as kegel writes them per face
    frozen = tmp_path / "frozen"
    shutil.copytree(case / "constant", frozen / "constant")
    shutil.copytree(case / "system", frozen / "system")
    (frozen / "0").mkdir()
    shutil.copy(case / "0" / "U", frozen / "0" / "U")
    rollers = [{"name": r["name"], "omega": r["wall_rotation_rad_s"], "axis": np.array(r["wall_rotation_axis"]),
                "origin": np.array(r["wall_rotation_origin_m"])} for r in meta["rollers"]]
    _write_wall_velocities(frozen, meta["kinematics"], rollers, omega_c)
    th = omega_c * end
    rot = np.array([[math.cos(th), -math.sin(th), 0.0], [math.sin(th), math.cos(th), 0.0], [0.0, 0.0, 1.0]])
    text = (case / f"{end:g}" / "U").read_text()
    for name in ("roller_00", "roller_09", "inner_ring", "cage", "housing"):
        u0_text = (frozen / "0" / "wallVelocity" / name).read_text()
        u0 = np.array([[float(v) for v in r.strip("()").split()] for r in u0_text.split("\n") if r.startswith("(") and len(r) > 2])
        seg = text[text.index(f"\n    {name}\n"):]
        seg = seg[seg.index("value"):]
        n = len(u0)
        rows = [r for r in seg.split("\n") if r.startswith("(") and len(r) > 2][:n]
        u = np.array([[float(v) for v in r.strip("()").split()] for r in rows])
        assert u.shape == u0.shape and np.abs(u - u0 @ rot.T).max() < 1e-8 * max(1.0, np.abs(u0).max()), name
    with pytest.raises(FoamError, match="moving-mesh run"):
        prepare_case(CfdPoint(bearing="32208", speed_rad_s=SPEED, temperature_K=323.15, oil_level_m=level,
                              mesh="tiny", n_procs=1, frame="moving_mesh", initial_from=str(case)), tmp_path / "again")


@pytest.mark.openfoam
def test_start_on_runs_the_coarse_mesh_first_and_resumes_without_it(tmp_path):
    """``--mesh small --start-on tiny``: the tiny run, the mapping and the small run in one call;
    calling it again resumes the small case and leaves the start run alone."""
    case = tmp_path / "bath_small"
    cmd = ("cfd", "run", "--bearing", "32208", "--speed", "2000 rpm", "--temperature", "50 degC",
           "--oil-level", "shaft_center", "--mesh", "small", "--start-on", "tiny", "--np", "2",
           "--max-courant", "10", "--max-interface-courant", "3", "--output", str(case), "--quiet",
           "--format", "json")
    res = run_kegel(*cmd, "--end-time", "0.1 ms", timeout=900)
    assert res.returncode == 0, res.stderr[-3000:]
    data = json.loads(res.stdout)
    start = data["start_run"]
    assert start["mesh"] == "tiny" and start["simulated_time_s"] == pytest.approx(1e-4, rel=1e-3)
    assert start["case"] == str((tmp_path / "bath_small_start_tiny").resolve())
    assert 0 < start["cells"] < data["fidelity"]["cells"]
    init = data["fidelity"]["initial_state"]
    assert init["source_mesh"] == "tiny" and init["source_time_s"] == pytest.approx(1e-4, rel=1e-3)
    assert abs(init["oil_volume_change"]) < 2e-3
    assert data["chain_wall_time_s"] > start["runtime_s"] + data["runtime_s"]
    assert data["simulated_time_s"] == pytest.approx(1e-4, rel=1e-3)
    stamp = (tmp_path / "bath_small_start_tiny" / "results.json").stat().st_mtime_ns
    res = run_kegel(*cmd, "--end-time", "0.15 ms", timeout=900)
    assert res.returncode == 0, res.stderr[-3000:]
    assert "resuming the case" in res.stderr and "start run" not in res.stderr
    again = json.loads(res.stdout)
    assert "start_run" not in again
    # the solver ends within half a step of the end time (0.15 ms is no write time: steps of ~7 us)
    assert data["simulated_time_s"] < again["simulated_time_s"] == pytest.approx(1.5e-4, rel=0.05)
    assert (tmp_path / "bath_small_start_tiny" / "results.json").stat().st_mtime_ns == stamp
    # the state a steady stop leaves for a finer run is reconstructed from the processors when missing
    from kegel.cfd_cases.foam import time_dirs
    from kegel.cfd_cases.run import _restart_state

    source = tmp_path / "bath_small_start_tiny"
    written = time_dirs(source)[-1]
    shutil.rmtree(written)
    assert _restart_state(source, 2, 2 * float(written.name)) == float(written.name)
    assert (source / written.name / "alpha.oil").is_file()


@pytest.mark.openfoam
def test_sweep_writes_table_and_plot(tmp_path):
    res = run_kegel("cfd", "sweep", "--bearing", "32208", "--speed", "1000 rpm", "--speed", "2000 rpm",
                    "--oil-level", "flooded", "--mesh", "tiny", "--max-iterations", "15",
                    "--output", str(tmp_path), "--quiet", timeout=900)
    assert res.returncode == 0, res.stderr[-3000:]
    rows = (tmp_path / "sweep.csv").read_text().splitlines()
    assert len(rows) == 3 and rows[0].startswith("oil_level,speed_rpm")
    torques = [float(r.split(",")[2]) for r in rows[1:]]
    assert 0 < torques[0] < torques[1]  # more loss at the higher speed
    assert (tmp_path / "sweep.png").stat().st_size > 10_000


def test_meshing_leaves_sigpipe_to_python(g32208, tmp_path):
    """gmsh.initialize sets SIGPIPE to the C default (terminate); after a mesh kegel gives it back
    to Python (ignore: a write to a closed pipe raises BrokenPipeError). Without this the whole
    test run died at the Dask test after the meshing tests ("make: Broken pipe")."""
    import ctypes

    libc = ctypes.CDLL(None)
    libc.signal.restype = ctypes.c_void_p
    libc.signal.argtypes = [ctypes.c_int, ctypes.c_void_p]
    cg = cfd_geometry(g32208, sector=True)
    build_mesh(cg, "tiny", tmp_path / "b.msh")
    prev = libc.signal(13, ctypes.c_void_p(1))  # SIGPIPE: read the C-level handler (1 = SIG_IGN)
    libc.signal(13, ctypes.c_void_p(prev))
    assert prev == 1
