"""Issue 28, item 4: the newcomer findings. Each test names its finding and fails on the code
before the fix (checked by running it against the parent commit)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import EXAMPLES, call_kegel, scene_text

import kegel
from kegel.data import load_bearing, load_lubricant, load_material
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


# --- Finding: the console table's "sliding, rolling, rib" do not add up (rib is inside sliding) ---


def _printed_table(out: str) -> tuple[list[str], list[list[str]]]:
    """Header cells and data rows of the table `kegel run` prints (split on two spaces)."""
    lines = out.splitlines()
    i = next(k for k, line in enumerate(lines) if line.startswith("#  "))
    header = [c.strip() for c in lines[i].split("  ") if c.strip()]
    rows = []
    for line in lines[i + 2:]:
        if not line[:1].isdigit():
            break
        rows.append(line.split())
    return header, rows


def _scene_32208(tmp_path, lubrication='mode = "minimum_quantity"', name="s") -> str:
    path = tmp_path / f"{name}.toml"
    path.write_text(scene_text(speed='["1000 rpm", "3000 rpm"]', lubrication=lubrication)
                    .replace('"32216"', '"32208"'))
    return str(path)


def test_run_table_torque_split_adds_up_and_power_loss_is_beside_the_torque(tmp_path):
    """The columns the table gives as the split of M_fric add up to it (a part shown inside
    another is labelled "of which" and the note says so), and P_loss = M_total x omega."""
    code, out, err = call_kegel("run", _scene_32208(tmp_path), "--output", str(tmp_path / "o"))
    assert code == 0, err
    header, rows = _printed_table(out)
    col = {h: k for k, h in enumerate(header)}
    parts = [h for h in header if h in ("sliding [Nm]", "rolling [Nm]", "rib [Nm]")]
    assert "of which rib [Nm]" in header
    assert "sliding + rolling = M_fric" in out
    assert len(rows) == 2
    for row, rpm in zip(rows, (1000, 3000)):
        m_fric = float(row[col["M_fric [Nm]"]])
        assert sum(float(row[col[h]]) for h in parts) == pytest.approx(m_fric, rel=2e-3)
        assert float(row[col["of which rib [Nm]"]]) < float(row[col["sliding [Nm]"]]) \
            + float(row[col["rolling [Nm]"]])
        p_loss = float(row[col["P_loss [W]"]])
        assert p_loss == pytest.approx(float(row[col["M_total [Nm]"]]) * rpm * 2 * math.pi / 60, rel=2e-3)


# --- Finding: the 32208 study's first table shows "hydraulic none" ------------------------------


def test_study_first_table_does_not_say_hydraulic_none(tmp_path):
    """`kegel run examples/32208_study.toml`: the header names the study's hydraulic methods, and
    the first table (contact friction, flooded contacts) has no M_hyd / M_total of "none"."""
    code, out, err = call_kegel("run", str(EXAMPLES / "32208_study.toml"), "--set", 'model.fidelity="fast"',
                                "--output", str(tmp_path / "o"))
    assert code == 0, err
    head = out.split("Study: total torque")[0]
    assert "hydraulic none" not in head
    assert "hydraulic loss by the study's methods (liebrecht, skf, cfd)" in head
    header, rows = _printed_table(head)
    assert "M_hyd [Nm]" not in header and "M_total [Nm]" not in header
    assert len(rows) == 5


# --- Finding: `kegel validate` prints each warning three times and writes validation_3..6.png ------


def test_validate_prints_each_warning_once_and_names_its_plots(tmp_path):
    """One `kegel validate`: every warning line once (the command solves four scenes), and the
    plots named after what they compare, each printed with its path."""
    out_dir = tmp_path / "val"
    code, out, err = call_kegel("validate", "--output", str(out_dir))
    assert code == 0, err
    lines = [line for line in err.splitlines() if line.startswith("kegel: warning [")]
    # the same code and message (the point index aside) printed once
    bodies = [line.split("): ", 1)[1] if "): " in line else line for line in lines]
    assert lines and len(bodies) == len(set(bodies)), "\n".join(lines)
    pngs = sorted(p.name for p in out_dir.glob("*.png"))
    assert not [n for n in pngs if n[len("validation_"):-4].isdigit()], pngs
    for stem in ("skf_32216_table1", "skf_32216_table2", "skf_32216_table3", "aihara_32216_table1"):
        assert f"validation_{stem}.png" in pngs
        assert str(out_dir / f"validation_{stem}.png") in out


# --- Finding: `--plot` to a folder or an unknown suffix gives a matplotlib traceback -------------


@pytest.mark.parametrize("target", ["folder", "losses.xyz", "losses", "missing/losses.png"])
def test_losses_plot_to_a_folder_or_unknown_suffix_is_one_line_naming_the_option(tmp_path, target):
    path = tmp_path if target == "folder" else tmp_path / target
    code, out, err = call_kegel("losses", "--bearing", "32208", "--plot", str(path))
    assert code == 2
    assert err.count("\n") == 1 and "Traceback" not in err, err
    assert "--plot" in err and str(path) in err
    assert (".png" in err) if target != "missing/losses.png" else ("does not exist" in err)
    assert not list(tmp_path.rglob("*.*"))  # nothing written


def test_losses_plot_accepts_a_known_suffix_in_any_case(tmp_path):
    code, out, err = call_kegel("losses", "--bearing", "32208", "--plot", str(tmp_path / "l.PDF"))
    assert code == 0, err
    assert (tmp_path / "l.PDF").stat().st_size > 0


# --- Finding: a scene with a UTF-8 BOM gives "Invalid statement" at 1:1 --------------------------


def test_a_scene_with_a_utf8_byte_order_mark_is_read(tmp_path):
    plain = tmp_path / "plain.toml"
    plain.write_text(scene_text())
    bom = tmp_path / "bom.toml"
    bom.write_bytes(b"\xef\xbb\xbf" + plain.read_bytes())
    code, out, err = call_kegel("check", str(bom))
    assert code == 0, err
    assert "valid scene" in out and "32216" in out
    from kegel.scene import load_scene

    a, b = load_scene(plain), load_scene(bom)
    assert [op.speed_rpm for op in a.operating_points] == [op.speed_rpm for op in b.operating_points]


# --- Finding: 50 000 nested arrays give a RecursionError traceback ------------------------------


def test_deeply_nested_arrays_are_one_line_errors(tmp_path):
    deep = "[" * 50_000 + "]" * 50_000
    path = tmp_path / "deep.toml"
    path.write_text(scene_text().replace('temperature = "50 degC"', f'temperature = "50 degC"\nextra = {deep}'))
    code, out, err = call_kegel("check", str(path))
    assert code == 2
    assert err.count("\n") == 1 and "Recursion" not in err and str(path) in err and "nested" in err
    deep_table = "{a = " * 50_000 + "1" + "}" * 50_000
    path.write_text(scene_text().replace('temperature = "50 degC"', f'temperature = "50 degC"\nextra = {deep_table}'))
    code, out, err = call_kegel("check", str(path))
    assert code == 2 and err.count("\n") == 1 and "nested" in err
    plain = tmp_path / "plain.toml"
    plain.write_text(scene_text())
    code, out, err = call_kegel("check", str(plain), "--set", f"operating.speed={deep}")
    assert code == 2
    assert err.count("\n") == 1 and "--set" in err and "operating.speed" in err and "nested" in err


# --- Finding: `check` accepts `slices = 1000`, which `run` refuses -------------------------------


@pytest.mark.parametrize("slices", [1000, 401, 1, 2, 400])
def test_check_refuses_what_run_refuses_slices(tmp_path, slices):
    """`kegel check` and `kegel run` agree on model.slices: both refuse it or both accept it."""
    path = tmp_path / "s.toml"
    path.write_text(scene_text(model=f"slices = {slices}").replace('"32216"', '"32208"'))
    c_code, _, c_err = call_kegel("check", str(path))
    r_code, _, r_err = call_kegel("run", str(path), "--output", str(tmp_path / "o"))
    assert (c_code == 0) == (r_code == 0), (c_err, r_err)
    if slices in (1000, 401, 1):
        assert c_code == 2 and "model.slices" in c_err and "[2, 400]" in c_err
    else:
        assert c_code == 0 and r_code == 0


# --- Finding: terminal escape codes in a scene name reach the terminal raw -----------------------


def test_control_characters_of_a_scene_name_are_escaped_when_printed(tmp_path):
    path = tmp_path / "evil.toml"
    path.write_text('[scene]\nname = "evil\\u001b[31mRED\\u001b]0;title\\u0007"\n'
                    'description = "one\\rtwo \\u202e three"\n' + scene_text().replace('"32216"', '"32208"'))
    for argv in (("check", str(path)), ("run", str(path), "--output", str(tmp_path / "o"))):
        code, out, err = call_kegel(*argv)
        assert code == 0, err
        for ch in ("\x1b", "\x07", "\r", "\u202e"):
            assert ch not in out and ch not in err
        assert "evil\\x1b[31mRED\\x1b]0;title\\x07" in out
    assert "one\\rtwo \\u202e three" in out
    # an error naming such a file name escapes it too
    bad = tmp_path / "bad\x1b[2J.toml"
    bad.write_text("[bearing\n")
    code, out, err = call_kegel("check", str(bad))
    assert code == 2 and "\x1b" not in err and "bad\\x1b[2J.toml" in err


# --- Finding: `kegel list` cuts descriptions mid-sentence ---------------------------------------


def test_list_gives_whole_sentences():
    """Every description `kegel list` prints ends a sentence or is a data line (bearings,
    materials): none stops mid-sentence as the first comment line of a file did."""
    from kegel.inventory import KINDS, inventory

    for kind in KINDS:
        for row in inventory(kind):
            text = row.get("description", "")
            if kind in ("friction", "validation"):
                assert text.endswith((".", ")")), (kind, row["name"], text)
    friction = {r["name"]: r["description"] for r in inventory("friction")}
    assert friction["steel_mineral_oil"].endswith("without additives (FVA 3).")
    code, out, err = call_kegel("list", "validation")
    assert code == 0 and "under pure axial load: Figure 5 of the seed paper" in out


# --- Finding: `kegel init`'s description does not follow the values it describes ----------------


@pytest.mark.parametrize("bearing", ["32208", "32216"])
def test_init_description_says_what_the_scene_holds(tmp_path, bearing):
    from kegel.scene import load_scene

    path = tmp_path / "mine.toml"
    code, out, err = call_kegel("init", str(path), "--bearing", bearing)
    assert code == 0, err
    scene = load_scene(path)
    d = scene.description
    speeds = [op.speed_rpm for op in scene.operating_points]
    op = scene.operating_points[0]
    assert d.startswith(f"{scene.bearing.designation}, {scene.lubricant.name}:")
    assert f"Fa = {op.axial_load_N / 1e3:g} kN" in d and f"Fr = {op.radial_load_N / 1e3:g} kN" in d
    assert f"{min(speeds):g}-{max(speeds):g} rpm ({len(speeds)} speeds)" in d
    assert f"{op.temperature_degC:g} degC" in d
    assert scene.lubrication.mode == "oil_bath" and "oil bath at half roller height" in d


# --- Finding: `kegel losses --points 1000000` runs for minutes with 5 GB and no progress ---------


def test_losses_refuses_a_million_points_at_once():
    import time

    from kegel.cli import MAX_LOSS_POINTS

    t0 = time.perf_counter()
    code, out, err = call_kegel("losses", "--bearing", "32208", "--points", "1000000")
    assert time.perf_counter() - t0 < 30
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and "--points" in err and "1000000" in err and f"[1, {MAX_LOSS_POINTS}]" in err
    code, out, err = call_kegel("losses", "--bearing", "32208", "--points", str(MAX_LOSS_POINTS),
                                "--oil-level", "flooded", "--format", "json")
    assert code == 0, err
    import json

    assert len([r for r in json.loads(out)["points"] if r["correlation"] == "liebrecht"]) == MAX_LOSS_POINTS


# --- Finding: -20 degC is refused (the FVA 3 pressure-viscosity formula's domain): no cold start ---


def test_cold_start_error_states_the_covered_range_and_why(tmp_path):
    """FVA 3 (seed paper Table A1): b1 + b2 theta = 0 at theta = -4.419e-3 / 3.0115e-4 =
    -14.674 degC; at -20 degC Eq. 7's denominator 268.07 bar - 1.604e-3 p vanishes at
    p = 167 100 bar = 16.7 GPa (hand calculation)."""
    from kegel.errors import KegelInputError
    from kegel.lubricant import lubricant_state, temperature_domain_degC

    lo, hi, why = temperature_domain_degC(load_lubricant("FVA3"))
    assert lo == pytest.approx(-4.419e-3 / 3.0115e-4, rel=1e-12) == pytest.approx(-14.674, abs=1e-3)
    assert hi == 150.0 and "Eq. 7" in why
    assert lubricant_state("FVA3", "-14.6 degC").dynamic_viscosity_Pas > 1.0
    with pytest.raises(KegelInputError) as exc:
        lubricant_state("FVA3", "-20 degC")
    text = str(exc.value)
    assert "[-14.67, 150] degC" in text and "Eq. 7" in text and "16.7 GPa" in text
    # the same line from `kegel check` on a scene at -20 degC
    path = tmp_path / "cold.toml"
    path.write_text(scene_text().replace('"50 degC"', '"-20 degC"'))
    code, out, err = call_kegel("check", str(path))
    assert code == 2 and err.count("\n") == 1 and "[-14.67, 150] degC" in err and "cold-start" in err


# --- item 4: result.plot() in the API, and the power loss beside the torque --------------------


def test_api_result_plot_writes_a_file_or_returns_the_figure_and_gives_the_power_loss(tmp_path):
    from matplotlib.figure import Figure

    from kegel.errors import KegelInputError

    r = kegel.Bearing("32208", fidelity="fast").friction(speed=["500 rpm", "2000 rpm"], axial_load="1 kN",
                                                         temperature="50 degC")
    written = r.plot(tmp_path / "torque.png")
    assert written == tmp_path / "torque.png" and written.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    fig = r.plot(which="breakdown")
    assert isinstance(fig, Figure) and "breakdown" in [a.get_label() for a in fig.axes]
    assert r[1].plot(tmp_path / "one.svg").read_text().lstrip().startswith("<?xml")
    with pytest.raises(KegelInputError, match="path"):
        r.plot(tmp_path)  # a folder
    with pytest.raises(KegelInputError, match="which"):
        r.plot(which="everything")
    # power loss: M_total x omega, by hand at each speed
    omega = np.array([500.0, 2000.0]) * 2 * math.pi / 60
    assert r.power_loss_W == pytest.approx(r.total_torque_Nm * omega, rel=1e-12)
    assert r[0].power_loss_W == pytest.approx(float(r.total_torque_Nm[0]) * omega[0], rel=1e-12)


def test_printed_reports_follow_a_redirect_made_after_import():
    """The CI run printed the validation report past ``call_kegel``'s redirect: ``print_report``
    had bound ``sys.stdout`` as a default argument when kegel.validation was first imported (by
    an earlier test), so its lines went to the stream of that moment."""
    import io
    from contextlib import redirect_stdout

    from kegel.validation import print_report

    buf = io.StringIO()
    with redirect_stdout(buf):
        print_report({"objects": [], "file": "x.json", "plots": {"a name": "a.png"}})
    assert "x.json" in buf.getvalue()
