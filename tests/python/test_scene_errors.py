"""Every bad-input case of a scene gets an error naming the file, the key, the value and the
expectation (issue "Foundation", item 5)."""

from __future__ import annotations

import pytest

import kegel
from conftest import run_kegel


def expect_error(path, *fragments, overrides=()):
    with pytest.raises(kegel.KegelInputError) as info:
        kegel.load_scene(path, overrides)
    msg = str(info.value)
    assert str(path) in msg, msg
    for f in fragments:
        assert f in msg, f"{f!r} not in {msg!r}"
    return info.value


def test_unknown_bearing(write_scene):
    p = write_scene(replace={'designation = "32216"': 'designation = "32299"'})
    e = expect_error(p, "bearing.designation", "'32299'", "a known bearing", "32208", "32216")
    assert e.key == "bearing.designation"


def test_unknown_oil(write_scene):
    p = write_scene(replace={'name = "FVA3"': 'name = "ISO VG 46"'})
    expect_error(p, "lubricant.name", "'ISO VG 46'", "a known lubricant", "FVA3")


def test_missing_key(write_scene):
    p = write_scene(replace={'temperature = ["42 degC", "50 degC"]\n': ""})
    e = expect_error(p, "missing key 'operating.temperature'", "expected")
    assert e.value is None


def test_missing_section(write_scene):
    p = write_scene(replace={'[lubricant]\nname = "FVA3"\n': ""})
    expect_error(p, "missing key 'lubricant'", "a table [lubricant]")


def test_wrong_unit_for_load(write_scene):
    p = write_scene(replace={'axial_load = "6 kN"': 'axial_load = "6 kg"'})
    expect_error(p, "operating.axial_load", "'6 kg'", "a force", "e.g. '6 kN'", "[mass]")


def test_number_without_unit(write_scene):
    p = write_scene(replace={'axial_load = "6 kN"': "axial_load = 6000"})
    expect_error(p, "operating.axial_load", "6000", "a force with its unit")


@pytest.mark.parametrize("value", ['"0 kN"', '"-6 kN"'])
def test_zero_or_negative_axial_load(write_scene, value):
    p = write_scene(replace={'axial_load = "6 kN"': f"axial_load = {value}"})
    expect_error(p, "operating.axial_load", value.strip('"'), "a positive axial load")


def test_negative_radial_load_in_sweep(write_scene):
    p = write_scene(replace={'radial_load = "0 kN"': 'radial_load = ["1 kN", "-2 kN"]'})
    expect_error(p, "operating.radial_load[1]", "'-2 kN'", "a radial load >= 0")


def test_axial_load_and_offset_together(write_scene):
    p = write_scene(replace={'axial_load = "6 kN"': 'axial_load = "6 kN"\naxial_offset = "20 um"'})
    expect_error(p, "operating.axial_load", "exactly one of axial_load")


@pytest.mark.parametrize("level", ['"150 mm"', '"-1 mm"'])
def test_oil_level_outside_0_D(write_scene, level):
    p = write_scene(replace={'oil_level = "half_roller"': f"oil_level = {level}"})
    expect_error(p, "lubrication.oil_level", level.strip('"'), "[0, D] = [0, 140 mm]")


def test_oil_level_wrong_unit(write_scene):
    p = write_scene(replace={'oil_level = "half_roller"': 'oil_level = "3 kN"'})
    expect_error(p, "lubrication.oil_level", "'3 kN'", "a length")


@pytest.mark.parametrize("speed", ['"10000 rpm"', '"0 rpm"', '{ from = "500 rpm", to = "20000 rpm", points = 3 }'])
def test_speed_out_of_range(write_scene, speed):
    p = write_scene(replace={'speed = { from = "500 rpm", to = "4000 rpm", points = 8 }': f"speed = {speed}"})
    expect_error(p, "operating.speed", "a non-zero speed with |n| <= 9217 rpm", "32216")


def test_speed_wrong_unit(write_scene):
    p = write_scene(replace={'speed = { from = "500 rpm", to = "4000 rpm", points = 8 }': 'speed = "2000 m/s"'})
    expect_error(p, "operating.speed", "'2000 m/s'", "a rotational speed")


@pytest.mark.parametrize(
    "sweep, key",
    [
        ("[]", "operating.speed"),
        ('{ from = "500 rpm", to = "4000 rpm", points = 0 }', "operating.speed.points"),
        ('{ from = "500 rpm", points = 4 }', "operating.speed.to"),
    ],
)
def test_sweep_with_no_points(write_scene, sweep, key):
    p = write_scene(replace={'speed = { from = "500 rpm", to = "4000 rpm", points = 8 }': f"speed = {sweep}"})
    e = expect_error(p, key)
    assert "point" in e.expected or "range" in e.expected


def test_temperature_out_of_range(write_scene):
    p = write_scene(replace={'temperature = ["42 degC", "50 degC"]': 'temperature = "200 degC"'})
    expect_error(p, "operating.temperature", "'200 degC'", "[-20, 150] degC")


def test_malformed_file_points_at_line_and_column(write_scene):
    p = write_scene(replace={'axial_load = "6 kN"': 'axial_load = = "6 kN"'})
    e = expect_error(p, "well-formed TOML")
    text = p.read_text().splitlines()
    assert e.line is not None and "axial_load = =" in text[e.line - 1]
    assert f"{p}:{e.line}:{e.column}" in str(e)


def test_missing_file(tmp_path):
    expect_error(tmp_path / "nope.toml", "an existing TOML file")


def test_unknown_key_is_rejected(write_scene):
    p = write_scene(replace={'axial_load = "6 kN"': 'axial_load = "6 kN"\naxial_lod = "1 kN"'})
    expect_error(p, "operating.axial_lod", "a known key of [operating]", "axial_load")


def test_unknown_choice(write_scene):
    p = write_scene(replace={'mode = "oil_bath"': 'mode = "grease"'})
    expect_error(p, "lubrication.mode", "'grease'", "oil_bath, minimum_quantity")


def test_bad_fidelity_option(write_scene):
    p = write_scene(replace={'fidelity = "default"': 'fidelity = "default"\nslices = 1'})
    expect_error(p, "model.slices", "an integer in [2, 400]")


def test_hydraulic_loss_without_oil_bath(write_scene):
    p = write_scene(replace={'mode = "oil_bath"\noil_level = "half_roller"': 'mode = "minimum_quantity"',
                             'fidelity = "default"': 'hydraulic = "cfd"'})
    expect_error(p, "model.hydraulic", "'none' for minimum-quantity")


def test_override_errors_name_the_override(write_scene):
    p = write_scene()
    expect_error(p, "(--set operating.axial_load)", "'6 kg'", overrides=["operating.axial_load=6 kg"])
    expect_error(p, "operating.nonsense", overrides=["operating.nonsense=1"])


def test_malformed_override():
    with pytest.raises(kegel.KegelInputError, match="KEY=VALUE"):
        kegel.scene.apply_overrides({}, ["operating.axial_load"])


def test_cli_reports_error_and_exit_status_2(write_scene):
    p = write_scene(replace={'axial_load = "6 kN"': 'axial_load = "6 kg"'})
    for cmd in ("check", "run"):
        res = run_kegel(cmd, str(p))
        assert res.returncode == 2
        assert res.stdout == ""
        line = res.stderr.strip()
        assert line.startswith("kegel: error: ") and str(p) in line and "operating.axial_load" in line
        assert "Traceback" not in res.stderr


def test_bad_bearing_data_file_names_file_and_key(tmp_path):
    src = (kegel.data.DATA_DIR / "bearings" / "32216.toml").read_text()
    bad = tmp_path / "bad_bearing.toml"
    bad.write_text(src.replace("roller_count = 16", "roller_count = -16"))
    with pytest.raises(kegel.KegelInputError) as info:
        kegel.load_bearing(str(bad))
    assert str(bad) in str(info.value) and "published.roller_count" in str(info.value)
    assert "-16" in str(info.value) and "> 0" in str(info.value)


def test_tilt_moment_beyond_tipping_or_with_misalignment(write_scene):
    """issue 21: a quasi-static scene ignored tilt_moment = "1e12 N m" and echoed it."""
    p = write_scene()
    expect_error(p, "operating.tilt_moment", "1e12 N m", "tips over", overrides=['operating.tilt_moment="1e12 N m"'])
    expect_error(p, "operating.tilt_moment", "not both",
                 overrides=['operating.tilt_moment="10 N m"', 'operating.misalignment="1 mrad"'])


def test_quasi_static_run_takes_the_tilt_moment_and_reports_a_failed_solve_in_one_line(tmp_path):
    """The tilt moment tilts the ring in the quasi-static solution (the torque changes); a load the
    solver cannot carry ends with one line on stderr and exit 1, no traceback."""
    import json

    base = ["examples/32216_table1.toml", "--set", 'operating.speed="2000 rpm"', "--set",
            'operating.temperature="50 degC"', "--format", "json"]
    res0 = run_kegel("run", *base, "--output", str(tmp_path / "a"))
    res1 = run_kegel("run", *base, "--set", 'operating.tilt_moment="100 N m"', "--output", str(tmp_path / "b"))
    assert res0.returncode == 0 and res1.returncode == 0, res1.stderr
    p0 = json.loads((tmp_path / "a" / "results.json").read_text())["points"][0]
    p1 = json.loads((tmp_path / "b" / "results.json").read_text())["points"][0]
    assert p1["tilt_moment_Nm"] == 100.0 and p1["converged"]
    assert abs(p1["friction_torque_Nm"] / p0["friction_torque_Nm"] - 1.0) > 0.02
    assert max(p1["roller_inner_N"]) > 2 * min(p1["roller_inner_N"])  # the moment loads one side
    bad = run_kegel("run", *base, "--set", 'operating.tilt_moment="300 N m"', "--output", str(tmp_path / "c"))
    assert bad.returncode == 1
    assert "Traceback" not in bad.stderr and "solver failed" in bad.stderr and "300" in bad.stderr


def test_temperature_outside_the_oil_formulas_is_found_by_check(write_scene):
    """issue 21: -20 ... -11 degC passed check and crashed in run (Eq. 7's domain)."""
    p = write_scene()
    expect_error(p, "operating.temperature", "-15 degC", "domain", "FVA3", overrides=['operating.temperature="-15 degC"'])


def test_loads_beyond_C0r_are_rejected(write_scene):
    """issue 21: Fa = 5 MN (19 x C0r) ran and was reported as converged."""
    p = write_scene()
    expect_error(p, "operating.axial_load", "5 MN", "C0r = 260 kN", "P0", overrides=['operating.axial_load="5 MN"'])


def test_custom_bearing_outside_its_envelope_is_rejected(write_scene, tmp_path):
    """issue 21: overlapping rollers (Z = 200) ran to a torque; kegel bearing listed the violation."""
    from pathlib import Path

    src = Path(kegel.__file__).parent / "data" / "bearings" / "32216.toml"
    bad = tmp_path / "crowded.toml"
    bad.write_text(src.read_text().replace("roller_count = 16", "roller_count = 200"))
    p = write_scene(replace={'designation = "32216"': f'designation = "{bad}"'})
    with pytest.raises(kegel.KegelInputError) as info:
        kegel.load_scene(p)
    assert str(bad) in str(info.value) and "overlap" in str(info.value)
    listed = run_kegel("bearing", "--bearing", str(bad))
    assert listed.returncode == 0 and "overlap" in listed.stdout


@pytest.mark.parametrize("args, key, words", [
    (("lubricant", "FVA3", "--temperature", "1000 degC"), "--temperature", "[-20, 150] degC"),
    (("tribology", "--axial-load", "1e9 N"), "--axial-load", "4000 MPa"),
    (("tribology", "--speed", "1e7 rpm"), "--speed", "rpm mm"),
    (("tribology", "--temperature", "-15 degC"), "--temperature", "domain"),
    (("losses", "--bearing", "32208", "--speed", "500 rpm", "--speed", "1e7 rpm"), "--speed", "rpm mm"),
    (("cfd", "run", "--max-iterations", "-5"), "--max-iterations", "at least 1"),
    (("cfd", "run", "--temperature", "1000 degC"), "--temperature", "[-20, 150] degC"),
    (("cfd", "run", "--speed", "1e7 rpm"), "--speed", "rpm mm"),
])
def test_every_command_checks_its_ranges(args, key, words):
    """issue 21: lubricant, tribology, losses and cfd run had no range checks (FVA 3 at 1000 degC,
    p0 = 507 GPa, 1e7 rpm, --max-iterations -5)."""
    res = run_kegel(*args)
    assert res.returncode == 2, res.stderr
    assert "Traceback" not in res.stderr and key in res.stderr and words in res.stderr, res.stderr
    assert len(res.stderr.strip().splitlines()) == 1


def test_a_named_pipe_is_no_scene_file(tmp_path):
    """issue 21: a named pipe as the scene file hung kegel check for good."""
    import os

    fifo = tmp_path / "scene.toml"
    os.mkfifo(fifo)
    res = run_kegel("check", str(fifo), timeout=30)
    assert res.returncode == 2 and "regular TOML file" in res.stderr and str(fifo) in res.stderr


def test_sweep_size_is_limited_before_anything_is_built(write_scene):
    """issue 21: a 10^6 x 10^6 sweep was built in memory by kegel check (MemoryError after 80 s)."""
    import time

    from kegel.scene import MAX_OPERATING_POINTS

    p = write_scene()
    t0 = time.perf_counter()
    expect_error(p, ".points' = 1000000", "at most", overrides=[
        'operating.speed={from="500 rpm", to="4000 rpm", points=1000000}',
        'operating.axial_load={from="1 kN", to="6 kN", points=1000000}'])
    expect_error(p, "operating", "operating points in one scene", str(MAX_OPERATING_POINTS), overrides=[
        'operating.speed={from="500 rpm", to="4000 rpm", points=1000}',
        'operating.axial_load={from="1 kN", to="6 kN", points=1000}'])
    assert time.perf_counter() - t0 < 10.0


@pytest.mark.parametrize("override, key, words", [
    ('dynamic.speed_profile=[["0 ms", "0 rpm"], ["10 ms", "1e9 rpm"]]', "dynamic.speed_profile[1][1]", "rpm mm"),
    ('dynamic.load_profile=[["0 ms", "0 kN", "0 kN"]]', "dynamic.load_profile[0][1]", "axial load > 0"),
    ('dynamic.load_profile=[["0 ms", "6 kN", "5 MN"]]', "dynamic.load_profile[0]", "C0r"),
    ('dynamic.duration="1e9 s"', "dynamic.duration", "at most 10 s"),
    ('dynamic.output_interval="1 ns"', "dynamic.output_interval", "at least 1 us"),
])
def test_dynamic_profiles_and_times_are_checked(write_scene, override, key, words):
    """issue 21: profiles to 1e9 rpm or Fa = 0, a duration of 1e9 s and a 1 ns output interval
    passed check and crashed (or never ended) in the run."""
    p = write_scene()
    expect_error(p, key, words, overrides=['model.solution="dynamic"', override])
