"""Dynamic multibody simulation: Jacobian, rigid-body validation, agreement with the
quasi-static solution, power balance, hard cases (short versions), force elements, checkpoints."""

from __future__ import annotations

import math

import numpy as np
import pytest

import kegel
from conftest import scene_text
from kegel.dynamics import D, SimulationDiverged, dynamic_model, simulate
from kegel.quasi_static import bearing_friction
from kegel.tribology import load_friction

RPM = math.pi / 30


@pytest.fixture(scope="module")
def setup():
    b = kegel.load_bearing("32216")
    m = kegel.load_material("bearing_steel")
    lub = kegel.load_lubricant("FVA3")
    g = kegel.derive_geometry(b, m)
    return g, b, m, lub, load_friction("steel_mineral_oil")


def _drive(speed, axial=6000.0, radial=0.0):
    d = D.RingDrive()
    d.time_s = [0.0]
    d.speed_rad_s = [speed]
    d.axial_N = axial
    d.radial_N = radial
    return d


@pytest.fixture(scope="module")
def loaded_state(setup):
    """A state of a running bearing under combined load (cage contacts, load zone)."""
    g, b, m, lub, fr = setup
    r = simulate(g, b, m, lub, fr, temperature_K=323.15, speed_profile=[(0, 2000 * RPM)], duration_s=2e-3,
                 axial_N=8000.0, radial_N=6000.0, slices=8, output_interval_s=1e-3)
    return r.states[-1]


def test_coloured_jacobian_matches_full_finite_differences(setup, loaded_state):
    g, b, m, lub, fr = setup
    model, _ = dynamic_model(g, b, m, lub, fr, temperature_K=323.15, slices=8)
    drive = _drive(2000 * RPM, 8000.0, 6000.0)
    y = np.asarray(loaded_state)
    J = np.asarray(D.jacobian(model, drive, 0.0, y))
    st, f0, _ = D.rhs(model, drive, 0.0, y)
    assert st == 0
    N = len(y)
    Jfd = np.zeros((N, N))
    typ = [1e-3, 1.0, 1.0, 10.0]
    for c in range(N):
        if c < model.cage_offset:
            local = (c % 12) // 3
        elif c < model.ring_offset:
            k = c - model.cage_offset
            local = 0 if k < 3 else 1 if k < 7 else 2 if k < 10 else 3
        else:
            k = c - model.ring_offset
            local = 0 if k < 3 else 2 if k < 6 else 1 if k < 8 else 3
        h = 1e-7 * max(abs(y[c]), typ[local])
        yp = y.copy()
        yp[c] += h
        ym = y.copy()
        ym[c] -= h
        Jfd[:, c] = (np.asarray(D.rhs(model, drive, 0.0, yp)[1]) - np.asarray(D.rhs(model, drive, 0.0, ym)[1])) / (2 * h)
    # the ring's tilt is held (drive.tilt_free false): its states never change (zero rows), so the
    # Jacobian leaves their columns zero (the Newton corrections never use them); compare the rest
    held = list(range(model.ring_offset + 6, N))
    assert np.all(J[:, held] == 0) and np.all(Jfd[held, :] == 0)
    Jfd[:, held] = 0.0
    # block by block (rows and columns of each body kind): relative Frobenius error
    Z = model.roller_count
    blocks = {"rollers": slice(0, 12 * Z), "cage": slice(12 * Z, 12 * Z + 13), "ring": slice(12 * Z + 13, N)}
    for rn, rs in blocks.items():
        for cn, cs in blocks.items():
            ref = Jfd[rs, cs]
            scale = np.linalg.norm(ref)
            if scale == 0:
                assert np.linalg.norm(J[rs, cs]) == 0
                continue
            err = np.linalg.norm(J[rs, cs] - ref) / scale
            assert err < 2e-3, (rn, cn, err)
    # the colouring must not mix rollers: roller j's rows do not depend on roller k's states
    assert np.all(J[0:12, 12:12 * Z] == 0)


def test_torque_free_roller_precesses_as_a_symmetric_top(setup):
    """Validation against the analytic solution: a roller far from every contact keeps its
    angular momentum and energy, and its axis turns about L at |L| / I_t."""
    g, b, m, lub, fr = setup
    model, qs = dynamic_model(g, b, m, lub, fr, temperature_K=323.15, slices=8, cage=False)
    Z = model.roller_count
    # the rollers at their places, 50 um off the cup; the inner ring 1 mm away (no contact)
    y = np.asarray(D.initial_state(model, kegel._core.quasi_static.BearingData(qs), 0.0, []))
    for j in range(Z):
        p = y[12 * j:12 * j + 3]
        e_r = np.array([p[0], p[1], 0.0]) / math.hypot(p[0], p[1])
        y[12 * j:12 * j + 3] = p - 50e-6 * e_r
    y[model.ring_offset + 2] = 1e-3
    a0 = y[3:6].copy()
    e_t = np.cross([0.0, 0.0, 1.0], a0)
    e_t /= np.linalg.norm(e_t)
    # spin about the axis and a small transverse rate: the axis cones about L by ~1 mrad
    w0 = 300.0 * a0 + 0.3 * e_t
    y[9:12] = w0
    st, f, out = D.rhs(model, _drive(0.0, axial=0.0), 0.0, y)
    assert st == 0 and out["max_penetration_m"] == 0.0
    drive = _drive(0.0, axial=0.0)
    s = D.IntegratorSettings()
    s.rtol = 1e-10
    s.atol_axis = 1e-12
    s.atol_rate_rad_s = 1e-9
    sim = D.DynamicSimulation(model, drive, s, 0.0, list(y))
    T = 0.04
    assert sim.advance(T) == 0, sim.message
    yT = np.asarray(sim.state)
    Ia, It = g.roller_inertia_axial_kgm2, g.roller_inertia_transverse_kgm2

    def L_of(a, w):
        return It * w + (Ia - It) * a * (a @ w)

    L0 = L_of(a0, w0)
    aT, wT = yT[3:6], yT[9:12]
    assert np.linalg.norm(L_of(aT / np.linalg.norm(aT), wT) - L0) / np.linalg.norm(L0) < 1e-7
    E0 = 0.5 * w0 @ L_of(a0, w0)
    assert 0.5 * wT @ L_of(aT, wT) == pytest.approx(E0, rel=1e-7)
    # analytic: a(t) = rotation of a(0) about L by |L| t / I_t
    k = L0 / np.linalg.norm(L0)
    phi = np.linalg.norm(L0) / It * T
    a_ref = a0 * math.cos(phi) + np.cross(k, a0) * math.sin(phi) + k * (k @ a0) * (1 - math.cos(phi))
    assert phi > 2 * math.pi                               # more than one precession cycle
    assert np.linalg.norm(aT - a0) > 1e-4                  # the axis has moved ...
    assert np.linalg.norm(aT - a_ref) < 1e-8               # ... as the analytic solution says
    assert abs(np.linalg.norm(aT) - 1.0) < 1e-8


@pytest.mark.parametrize("speed_rpm,temperature_degC,method", [(500, 42, "independent"), (2000, 50, "independent"),
                                                              (4000, 50, "independent"),
                                                              (2000, 50, "alternative_slicing")])
def test_steady_state_agrees_with_the_quasi_static_solution(setup, speed_rpm, temperature_degC, method):
    """32216, Table 1 conditions (Fa = 6 kN): the dynamic mean torque within 3 % of the
    quasi-static one at the same contact fidelity; the power balance closes within 1 %."""
    g, b, m, lub, fr = setup
    w = speed_rpm * RPM
    T = temperature_degC + 273.15
    _, q = bearing_friction(g, b, m, lub, fr, temperature_K=T, inner_speed_rad_s=w, axial_N=6000.0, slices=20,
                            method=method)
    r = simulate(g, b, m, lub, fr, temperature_K=T, speed_profile=[(0, w)], duration_s=6e-3, axial_N=6000.0,
                 slices=20, method=method, output_interval_s=3e-4)
    st = r.steady
    assert st["outer_ring_torque_Nm"] == pytest.approx(q.outer_ring_torque_Nm, rel=0.03)
    assert st["drive_torque_Nm"] == pytest.approx(q.drive_torque_Nm, rel=0.03)
    assert abs(st["power_balance_error"]) < 1e-3
    # the contact work equals the sum of the mechanism powers (the breakdown explains the torque)
    assert st["contact_work_W"] == pytest.approx(st["power_dissipated_W"], rel=1e-3)
    assert np.isfinite(r.series["kinetic_energy_J"]).all()


def _hard(setup, **kw):
    g, b, m, lub, fr = setup
    base = dict(temperature_K=323.15, slices=8, output_interval_s=2e-4)
    base.update(kw)
    r = simulate(g, b, m, lub, fr, **base)
    s = r.series
    assert r.finished, r.message
    for k in ("kinetic_energy_J", "mean_outer_ring_torque_Nm", "mean_drive_torque_Nm", "cage_speed_rad_s"):
        assert np.isfinite(s[k]).all(), k
    # bounded energy: never above the energy of every body turning with the inner ring, and the
    # contacts stay within elastic interferences
    w_max = max(abs(p[1]) for p in base["speed_profile"])
    rollers = g.roller_count * (0.5 * g.roller_mass_kg * (w_max * 0.5 * g.pitch_diameter_m) ** 2
                                + 0.5 * g.roller_inertia_axial_kgm2 * (w_max * g.pitch_diameter_m / g.roller_mean_diameter_m) ** 2)
    assert s["kinetic_energy_J"].max() < 4 * rollers + 1.0
    assert s["max_penetration_m"].max() < 30e-6
    return r


@pytest.mark.parametrize("case", ["start_from_rest", "light_load_skidding", "radial_most_rollers_unloaded",
                                  "tilted_edge_loading", "hot_oil_mixed_friction", "speed_reversal"])
def test_hard_cases_short_versions(setup, case):
    """The hard cases of the issue, shortened (examples/dynamic_*.toml run the full versions)."""
    if case == "start_from_rest":
        # 0 -> 4000 rpm in 50 ms: the first 4 ms of the ramp
        r = _hard(setup, speed_profile=[(0, 0), (0.05, 4000 * RPM)], duration_s=4e-3, axial_N=6000.0)
        assert r.series["cage_speed_rad_s"][-1] > 0.0
        assert r.series["kinetic_energy_J"][-1] > r.series["kinetic_energy_J"][0]
    elif case == "light_load_skidding":
        r = _hard(setup, speed_profile=[(0, 4000 * RPM)], duration_s=3e-3, axial_N=100.0, hold_axial=True)
        # the centrifugal force carries the rollers to the cup: the inner raceway loses load
        assert r.series["roller_outer_N"][-1].min() > r.series["roller_inner_N"][-1].max()
        # skidding rollers: the rolling mechanisms' powers are the work of the shifted normal
        # forces, so the power balance closes (measured 2e-4; counted at the pure-rolling rate it
        # was off by -9.9 %, the contacts' work by 1 %)
        assert abs(r.steady["power_balance_error"]) < 1e-3, r.steady["power_balance_error"]
        assert r.steady["contact_work_W"] == pytest.approx(r.steady["power_contacts_W"] + r.steady["damping_power_W"],
                                                           rel=2e-4)
    elif case == "radial_most_rollers_unloaded":
        r = _hard(setup, speed_profile=[(0, 2000 * RPM)], duration_s=3e-3, axial_offset_m=5e-6, radial_N=16000.0)
        q = r.series["roller_inner_N"][-1]
        assert (q < 1e-3 * q.max()).sum() >= g_count(setup) // 2
        # unloaded rollers slip: the balance closes (measured -2.2e-4; -2.4 % counted at the
        # pure-rolling rate)
        assert abs(r.steady["power_balance_error"]) < 1e-3, r.steady["power_balance_error"]
    elif case == "tilted_edge_loading":
        r = _hard(setup, speed_profile=[(0, 2000 * RPM)], duration_s=3e-3, axial_N=6000.0, misalignment_rad=2e-3)
        q = r.series["roller_inner_N"][-1]
        assert q.max() > 1.2 * q.min()  # the tilt loads one side
    elif case == "hot_oil_mixed_friction":
        r = _hard(setup, speed_profile=[(0, 500 * RPM)], duration_s=3e-3, axial_N=6000.0, temperature_K=373.15)
        assert r.series["Lambda_min_inner_raceway"][-1] < 1.0
        assert r.series["phi_max_inner_raceway"][-1] > 0.0
    else:
        # 2000 -> -2000 rpm in 0.1 s: the 3 ms around the reversal, started at the state the
        # ramp has there (the ring at 60 rpm, coming to rest and turning back)
        r = _hard(setup, speed_profile=[(0, 60 * RPM), (1.5e-3, 0.0), (3e-3, -60 * RPM)], duration_s=3e-3,
                  axial_N=6000.0)
        assert r.series["cage_speed_rad_s"][-1] < 0.0 < r.series["cage_speed_rad_s"][0]


def g_count(setup):
    return setup[0].roller_count


def test_force_elements_act_on_the_bodies_and_enter_the_power_balance(setup):
    g, b, m, lub, fr = setup
    v = D.DragElementValues()
    v.roller_spin_drag_Nms = 1e-6  # viscous drag on each roller's spin, N m s
    drag = D.DragElement(v)
    w = 2000 * RPM
    kw = dict(temperature_K=323.15, speed_profile=[(0, w)], duration_s=4e-3, axial_N=6000.0, slices=8,
              output_interval_s=2e-4)
    free = simulate(g, b, m, lub, fr, **kw)
    oil = simulate(g, b, m, lub, fr, elements=[drag], **kw)
    P_ext = oil.steady["external_power_W"]
    assert P_ext > 1.0
    # the shaft pays for the oil: the drive torque rises by the power the oil takes (the contact
    # losses change a little with the rollers' slip)
    rise = oil.steady["drive_torque_Nm"] - free.steady["drive_torque_Nm"]
    assert rise == pytest.approx(P_ext / w, rel=0.05)
    assert abs(oil.steady["power_balance_error"]) < 0.01
    assert np.mean(oil.series["roller_spin_rad_s"][-1]) > np.mean(free.series["roller_spin_rad_s"][-1])  # spin < 0: slower
    # a churning moment -c w on the cage, which the rollers do not touch within the first
    # millisecond (its window clearance): w(t) = w0 exp(-c t / I_axial)
    v = D.DragElementValues()
    v.cage_drag_Nms = 2e-4
    r = simulate(g, b, m, lub, fr, elements=[D.DragElement(v)], **{**kw, "duration_s": 1e-3})
    assert r.series["roller_cage_N"].max() == 0.0
    model, _ = dynamic_model(g, b, m, lub, fr, temperature_K=323.15, slices=8)
    from kegel.dynamics import cage_mass_properties
    I_ax = cage_mass_properties(g, m.density_kg_m3)[1]
    wc = r.series["cage_speed_rad_s"]
    assert wc[-1] == pytest.approx(wc[0] * math.exp(-2e-4 * r.time_s[-1] / I_ax), rel=1e-6)
    with pytest.raises(ValueError, match="DragElementValues.cage_drag_Nms"):
        bad = D.DragElementValues()
        bad.cage_drag_Nms = -1.0
        D.DragElement(bad)


def test_a_failing_python_force_element_stops_the_run_with_its_message(setup):
    g, b, m, lub, fr = setup

    def element(body, p, axis, v, w, t, wi, wc):
        if t > 1e-3:
            raise RuntimeError("CFD force table has no entry here")
        return np.zeros(3), np.zeros(3)

    with pytest.raises(SimulationDiverged, match="CFD force table has no entry here"):
        simulate(g, b, m, lub, fr, temperature_K=323.15, speed_profile=[(0, 2000 * RPM)], duration_s=3e-3,
                 axial_N=6000.0, slices=8, output_interval_s=5e-4, elements=[D.PythonForceElement(element)])


def test_the_bearing_coming_apart_is_reported(setup):
    """100 N at 4000 rpm with the ring free axially: the centrifugal force pushes the rollers
    out of the cup with more than 100 N: no equilibrium exists, and the run says so."""
    g, b, m, lub, fr = setup
    with pytest.raises(SimulationDiverged, match="comes apart"):
        simulate(g, b, m, lub, fr, temperature_K=323.15, speed_profile=[(0, 4000 * RPM)], duration_s=0.02,
                 axial_N=100.0, slices=8, output_interval_s=2e-4, max_ring_displacement_m=0.05e-3)


def test_an_interrupted_run_resumes_from_its_checkpoint(setup, tmp_path):
    g, b, m, lub, fr = setup
    kw = dict(temperature_K=323.15, speed_profile=[(0, 2000 * RPM)], duration_s=4e-3, axial_N=6000.0, slices=8,
              output_interval_s=2e-4, checkpoint_interval_s=1e-3, checkpoint_key="test")
    ref = simulate(g, b, m, lub, fr, **kw)
    ck = tmp_path / "ck.npz"

    def interrupt(body, p, axis, v, w, t, wi, wc):
        if t > 2.5e-3:
            raise KeyboardInterrupt  # stands for a user's Ctrl-C
        return np.zeros(3), np.zeros(3)

    part = simulate(g, b, m, lub, fr, checkpoint=ck, elements=[D.PythonForceElement(interrupt)],
                    raise_on_failure=False, **kw)
    assert not part.finished and ck.exists()
    done = simulate(g, b, m, lub, fr, checkpoint=ck, **kw)
    assert done.stats["resumed_from_s"] == pytest.approx(2e-3, abs=1e-9)
    assert not ck.exists()  # a finished run removes its checkpoint
    assert len(done.time_s) == len(ref.time_s)
    assert done.steady["outer_ring_torque_Nm"] == pytest.approx(ref.steady["outer_ring_torque_Nm"], rel=2e-3)
    # a checkpoint written for other inputs is not used
    part = simulate(g, b, m, lub, fr, checkpoint=ck, elements=[D.PythonForceElement(interrupt)],
                    raise_on_failure=False, **kw)
    other = simulate(g, b, m, lub, fr, checkpoint=ck, **{**kw, "checkpoint_key": "other"})
    assert other.stats["resumed_from_s"] is None


def test_a_truncated_checkpoint_is_named_and_discarded(setup, tmp_path, capsys):
    """issue 21: a checkpoint cut short (full disk, kill) blocked every rerun with a BadZipFile
    traceback naming no file; now it is named, discarded, and the point starts afresh."""
    g, b, m, lub, fr = setup
    ck = tmp_path / "checkpoint.npz"
    ck.write_bytes(b"PK\x03\x04 cut short")
    res = simulate(g, b, m, lub, fr, temperature_K=323.15, speed_profile=[(0, 2000 * RPM)], duration_s=1e-3,
                   axial_N=6000.0, slices=8, output_interval_s=2e-4, checkpoint=ck, checkpoint_key="k")
    assert res.finished and res.stats["resumed_from_s"] is None
    err = capsys.readouterr().err
    assert str(ck) in err and "unreadable" in err and "starts afresh" in err
    assert not list(tmp_path.glob(".*.tmp.npz"))


def test_bad_inputs_raise_clear_errors(setup):
    g, b, m, lub, fr = setup
    with pytest.raises(kegel.KegelInputError, match="speed_profile"):
        simulate(g, b, m, lub, fr, temperature_K=323.15, speed_profile=[(0, 1.0), (0, 2.0)], duration_s=1e-3,
                 axial_N=6000.0)
    with pytest.raises(kegel.KegelInputError, match="duration_s"):
        simulate(g, b, m, lub, fr, temperature_K=323.15, speed_profile=[(0, 1.0)], duration_s=0.0, axial_N=6000.0)
    T = kegel._core.tribology
    race = T.SurfacePair(1e-7, 2.0, 1.0, 2.3e11)
    state = T.make_contact_lubricant_state(lub.core, 323.15)
    _, qs = dynamic_model(g, b, m, lub, fr, temperature_K=323.15, slices=8)
    with pytest.raises(ValueError, match="DynamicValues.roller_mass_kg = 0"):
        D.DynamicModel(qs, D.DynamicValues(), fr.core(lub), race, race, state)


DYNAMIC_SCENE = scene_text(model='solution = "dynamic"\ncage = true\n[dynamic]\nduration = "2 ms"\n'
                                 'output_interval = "0.2 ms"')


def test_a_scene_runs_dynamically_and_writes_series_vtk_and_plots(tmp_path):
    from conftest import run_kegel

    (tmp_path / "dyn.toml").write_text(DYNAMIC_SCENE)
    res = run_kegel("run", "dyn.toml", cwd=tmp_path, timeout=300)
    assert res.returncode == 0, res.stderr
    assert "dynamic (2 ms)" in res.stdout and "power balance" in res.stdout
    import json

    doc = json.loads((tmp_path / "out" / "results.json").read_text())
    assert doc["fidelity"]["solution_used"] == "dynamic"
    assert doc["fidelity"]["dynamic"]["duration_s"] == pytest.approx(2e-3)
    p = doc["points"][0]
    assert p["friction_torque_Nm"] > 0 and abs(p["power_balance_error"]) < 0.02
    d = tmp_path / "out" / "dynamic" / "point_000"
    for f in ("dynamic.json", "series.csv", "roller_series.npz", "bodies.pvd", "dynamic.png"):
        assert (d / f).is_file(), f
    import meshio

    vtus = sorted((d / "vtk").glob("*.vtu"))
    mesh = meshio.read(vtus[-1])
    assert set(np.unique(mesh.cell_data["body"][0])) == set(range(-1, 16))
    meta = json.loads((d / "dynamic.json").read_text())
    assert meta["provenance"]["kegel_version"] and meta["meta"]["fidelity"]["solution"] == "dynamic"
    assert not (d / "checkpoint.npz").exists()


@pytest.mark.parametrize("key,value,expected", [
    ("duration", '"-2 ms"', "a time > 0"),
    ("output_interval", '"5 ms"', "at most the duration"),
    ("speed_profile", '[["0 ms", "0 rpm"], ["0 ms", "10 rpm"]]', "times increasing"),
    ("hold_axial", '"yes"', "true or false"),
    ("tolerance", "0.5", "a number in"),
    ("speed_profile", '[["0 ms", "0 kN"]]', "speed"),
    ("load_profile", '[["0 ms", "6 kN"]]', "a triple"),
    ("load_profile", '[["0 ms", "6 kN", "-1 kN"]]', "loads >= 0"),
    ("threads", "0", "an integer in [1, 64]"),
])
def test_dynamic_table_errors_name_the_key(tmp_path, key, value, expected):
    from kegel.scene import load_scene

    text = "\n".join(line for line in DYNAMIC_SCENE.splitlines() if not line.startswith(f"{key} ="))
    text = text.replace("[dynamic]\n", f"[dynamic]\n{key} = {value}\n")
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(kegel.KegelInputError) as err:
        load_scene(path)
    msg = str(err.value)
    assert f"dynamic.{key}" in msg and expected in msg and "bad.toml" in msg


def test_a_tilt_free_ring_finds_the_quasi_static_tilt(setup):
    """Inner ring free to tilt under a 50 N m moment (and 6 kN): starting untilted, it tilts to
    the quasi-static tilt-free solution (within the friction moments the quasi-static load
    distribution leaves out), about the moment's axis."""
    from kegel.quasi_static import load_distribution

    g, b, m, lub, fr = setup
    d = load_distribution(g, b, m, axial_N=6000.0, tilt_moment_Nm=50.0, tilt_free=True, slices=8,
                          method="independent")
    r = simulate(g, b, m, lub, fr, temperature_K=323.15, speed_profile=[(0, 2000 * RPM)], duration_s=0.01,
                 axial_N=6000.0, slices=8, output_interval_s=5e-4, tilt_free=True, tilt_moment_Nm=50.0)
    rx, ry = r.states[-1][-4], r.states[-1][-3]
    assert r.states[0][-3] == 0.0
    assert ry == pytest.approx(d.ring_tilt_rad[1], rel=0.1)
    assert abs(rx) < 0.05 * abs(ry)
    assert abs(r.steady["power_balance_error"]) < 0.02


def test_regression_against_the_stored_reference():
    """A loaded 32216 (Fa 8 kN, Fr 4 kN, 2000 rpm) against the values stored when the dynamic
    model was accepted (tests/python/reference/make_dynamic_reference.py writes them). Torques
    within 0.5 %, cage speed within 1e-4, roller loads within 0.5 % of the largest."""
    import json
    import sys
    from pathlib import Path

    ref_dir = Path(__file__).parent / "reference"
    sys.path.insert(0, str(ref_dir))
    try:
        from make_dynamic_reference import compute
    finally:
        sys.path.pop(0)
    ref = json.loads((ref_dir / "dynamic_32216_combined_load.json").read_text())["values"]
    now = compute()
    for k in ("outer_ring_torque_Nm", "drive_torque_Nm", "torque_outer_raceway_Nm", "torque_inner_raceway_Nm",
              "torque_rib_Nm", "power_contacts_W"):
        assert now[k] == pytest.approx(ref[k], rel=5e-3), k
    assert now["cage_speed_rad_s"] == pytest.approx(ref["cage_speed_rad_s"], rel=1e-4)
    q, q_ref = np.asarray(now["roller_inner_N_final"]), np.asarray(ref["roller_inner_N_final"])
    assert np.max(np.abs(q - q_ref)) < 5e-3 * q_ref.max()


def test_threads_give_identical_results_faster(setup):
    """Rollers evaluated on two threads: bit-identical states (the sums run in roller order)."""
    g, b, m, lub, fr = setup
    kw = dict(temperature_K=323.15, speed_profile=[(0, 2000 * RPM)], duration_s=2e-3, axial_N=8000.0,
              radial_N=4000.0, slices=8, output_interval_s=5e-4)
    one = simulate(g, b, m, lub, fr, threads=1, **kw)
    two = simulate(g, b, m, lub, fr, threads=2, **kw)
    assert np.array_equal(one.states, two.states)
    assert one.stats["steps"] == two.stats["steps"]


def test_a_load_change_settles_on_the_quasi_static_equilibrium(setup):
    """Radial load ramped from 0 to 4 kN in 2 ms under 8 kN axial: 6 ms later the inner ring sits
    where the quasi-static load distribution puts it for the final loads."""
    from kegel.quasi_static import load_distribution

    g, b, m, lub, fr = setup
    r = simulate(g, b, m, lub, fr, temperature_K=323.15, speed_profile=[(0, 2000 * RPM)], duration_s=8e-3,
                 axial_N=8000.0, slices=8, output_interval_s=5e-4,
                 load_profile=[(0.0, 8000.0, 0.0), (2e-3, 8000.0, 4000.0)])
    Z = g.roller_count
    d0 = r.states[0][12 * Z + 13:12 * Z + 16]
    d = r.states[-1][12 * Z + 13:12 * Z + 16]
    assert abs(d0[0]) < 1e-9  # no radial load at the start: centred
    qs = load_distribution(g, b, m, axial_N=8000.0, radial_N=4000.0, slices=8, method="independent",
                           cage_speed_rad_s=r.steady["cage_speed_rad_s"])
    # (the pivots differ: the quasi-static ring turns about the origin, but it is not tilted)
    assert d[0] == pytest.approx(qs.ring_displacement_m[0], rel=0.02)
    assert d[2] == pytest.approx(qs.ring_displacement_m[2], rel=0.01)
    F = r.series["ring_force_N"][-1]  # the rollers carry the loads
    assert F[0] == pytest.approx(-4000.0, rel=1e-3) and F[2] == pytest.approx(8000.0, rel=1e-3)
    with pytest.raises(kegel.KegelInputError, match="load_profile"):
        simulate(g, b, m, lub, fr, temperature_K=323.15, speed_profile=[(0, 1.0)], duration_s=1e-3, axial_N=1.0,
                 load_profile=[(0.0, 1.0, 0.0), (0.0, 2.0, 0.0)])


def test_under_combined_load_the_rollers_do_not_touch_the_cage(setup):
    """32216, Table 2 loads (Fa 6 kN, Fr 6.5 kN), 2000 rpm: the rollers move only microns in
    their pockets and never touch the cage, so the dynamic torque matches the quasi-static one
    with free rollers (the default); the quasi-static pocket model (each roller's
    circumferential load on its pocket, Eq. 37) adds about 3 % here (15 % before the rolling
    resistance was corrected, when sliding friction dominated). The dynamic model is why the
    quasi-static default is the free-roller model."""
    g, b, m, lub, fr = setup
    w = 2000 * RPM
    kw = dict(temperature_K=323.15, inner_speed_rad_s=w, axial_N=6000.0, radial_N=6500.0, slices=8,
              method="independent")
    _, with_pockets = bearing_friction(g, b, m, lub, fr, cage="pocket", **kw)
    _, free = bearing_friction(g, b, m, lub, fr, cage=True, **kw)
    assert free.cage_model == "free_rollers"
    r = simulate(g, b, m, lub, fr, temperature_K=323.15, speed_profile=[(0, w)], duration_s=0.012, axial_N=6000.0,
                 radial_N=6500.0, slices=8, output_interval_s=4e-4, threads=2)
    assert r.series["roller_cage_N"].max() == 0.0
    assert r.steady["outer_ring_torque_Nm"] == pytest.approx(free.outer_ring_torque_Nm, rel=0.02)
    assert with_pockets.outer_ring_torque_Nm > 1.02 * r.steady["outer_ring_torque_Nm"]


def test_a_state_of_the_wrong_length_names_both_lengths(setup):
    g, b, m, lub, fr = setup
    model, _ = dynamic_model(g, b, m, lub, fr, temperature_K=323.15, slices=8)
    d = D.RingDrive()
    d.time_s, d.speed_rad_s, d.axial_N = [0.0], [0.0], 0.0
    n = model.state_size
    with pytest.raises(ValueError, match=f"rhs: y: 5 values: expected {n}"):
        D.rhs(model, d, 0.0, np.zeros(5), [])
    with pytest.raises(ValueError, match=f"jacobian: y: 5 values: expected {n}"):
        D.jacobian(model, d, 0.0, np.zeros(5))


def test_block_arrow_solver_and_state_quadratures_match_the_dense_reference(setup):
    """The fast numerics (block-arrow LU of the Newton matrix, the torque and power integrals as
    states) against SUNDIALS' dense LU with CVODES' quadratures: the same means under combined
    load (cage contacts, a load zone) to the integrator's tolerance."""
    g, b, m, lub, fr = setup
    kw = dict(temperature_K=323.15, speed_profile=[(0, 2000 * RPM)], duration_s=2e-3, axial_N=8000.0,
              radial_N=4000.0, slices=8, output_interval_s=5e-4)
    fast = simulate(g, b, m, lub, fr, **kw)
    ref = simulate(g, b, m, lub, fr, integrator_options={"structured_linear_solver": False,
                                                         "quadratures_in_state": False}, **kw)
    for k in ("drive_torque_Nm", "outer_ring_torque_Nm", "power_contacts_W", "cage_speed_rad_s"):
        assert fast.steady[k] == pytest.approx(ref.steady[k], rel=2e-3), k
    np.testing.assert_allclose(fast.quadratures[-1], ref.quadratures[-1], rtol=2e-3, atol=1e-9)


def test_unknown_integrator_options_are_named(setup):
    g, b, m, lub, fr = setup
    with pytest.raises(kegel.KegelInputError, match="integrator_options.no_such_switch"):
        simulate(g, b, m, lub, fr, temperature_K=323.15, speed_profile=[(0, 2000 * RPM)], duration_s=1e-4,
                 axial_N=6000.0, slices=8, output_interval_s=1e-4, integrator_options={"no_such_switch": 1})


def test_a_settled_point_whose_power_does_not_balance_is_no_answer(tmp_path, monkeypatch):
    """The power-balance gate: a settled dynamic point is an answer only where input power =
    dissipated power + the kinetic-energy rate within POWER_BALANCE_TOLERANCE. With the gate at
    its value the point converges (its balance is ~1e-5); with the gate tightened below that
    balance the same run fails, its figures kept, with a message that names the powers."""
    import kegel.solutions.dynamics as dyn
    from kegel.scene import load_scene

    path = tmp_path / "dyn.toml"
    path.write_text(scene_text(model='solution = "dynamic"\ncage = true\n[dynamic]\nduration = "8 ms"\n'
                                     'output_interval = "0.2 ms"'))
    monkeypatch.chdir(tmp_path)  # the scene's output folder, "out", is relative to the working directory
    good = kegel.run.run_scene(load_scene(path), write=False, progress=False).points[0]
    assert good["converged"], good.get("failure")
    # write=False writes nothing: the dynamic point's own files went to a removed temporary folder
    assert not (tmp_path / "out").exists() and good["dynamic"]["files"] == {}
    err = good["power_balance_error"]
    assert 0 < abs(err) < dyn.POWER_BALANCE_TOLERANCE
    monkeypatch.setattr(dyn, "POWER_BALANCE_TOLERANCE", 0.5 * abs(err))
    bad = kegel.run.run_scene(load_scene(path), write=False, progress=False).points[0]
    assert not bad["converged"] and bad["power_balance_error"] == pytest.approx(err, rel=1e-9)
    assert bad["friction_torque_Nm"] == pytest.approx(good["friction_torque_Nm"], rel=1e-12)
    msg = bad["failure"]
    assert "power does not balance" in msg and "dynamic.tolerance" in msg
    assert f"{bad['power_input_W']:.6g} W" in msg and f"{bad['power_dissipated_W']:.6g} W" in msg
    # a resumed run does not take a stored converged record outside the gate (one of a kegel
    # before the gate): it solves the point again
    from kegel.runner.run import _check_record

    monkeypatch.undo()
    scene = load_scene(path)
    assert _check_record(scene, good) is None
    key, value, _ = _check_record(scene, {**good, "power_balance_error": -3.4e-3})
    assert (key, value) == ("power_balance_error", -3.4e-3)
