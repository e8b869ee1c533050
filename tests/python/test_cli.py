"""The command line as a new user meets it: `kegel list`, `kegel init`, `--help` of every command,
a closed pipe, and the exit status of a run with a point that could not be solved."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import EXAMPLES, call_kegel, run_kegel

KEGEL = str(Path(sys.executable).with_name("kegel"))
COMMANDS = ("list", "init", "bearing", "lubricant", "tribology", "losses", "cfd", "validate", "check", "run")


def test_list_names_what_kegel_ships_with():
    res = run_kegel("list")
    assert res.returncode == 0, res.stderr
    for kind in ("bearings:", "lubricants:", "materials:", "friction:", "validation:", "examples:"):
        assert kind in res.stdout
    assert "32208" in res.stdout and "32216" in res.stdout and "C0r = 94 kN" in res.stdout
    assert "FVA3" in res.stdout and "32216_table1" in res.stdout
    data = json.loads(run_kegel("list", "bearings", "--format", "json").stdout)
    assert [b["name"] for b in data["bearings"]] == ["32208", "32216"]
    assert data["bearings"][0]["bore_mm"] == pytest.approx(40.0)


def test_list_rejects_an_unknown_kind():
    res = run_kegel("list", "gears")
    assert res.returncode == 2 and "invalid choice" in res.stderr and "Traceback" not in res.stderr


def test_init_writes_a_scene_that_check_accepts(tmp_path):
    f = tmp_path / "my_scene.toml"
    res = run_kegel("init", str(f), "--bearing", "32208")
    assert res.returncode == 0, res.stderr
    text = f.read_text()
    assert 'designation = "32208"' in text and "# [study]" in text
    chk = run_kegel("check", str(f), "--format", "json")
    assert chk.returncode == 0, chk.stderr
    assert json.loads(chk.stdout)["operating_point_count"] == 8
    again = run_kegel("init", str(f))  # never replaces a file silently
    assert again.returncode == 2 and "--force" in again.stderr and str(f) in again.stderr
    assert run_kegel("init", str(f), "--force", "--bearing", "32216").returncode == 0
    assert 'designation = "32216"' in f.read_text()


def test_init_names_an_unknown_bearing_and_writes_nothing(tmp_path):
    f = tmp_path / "s.toml"
    res = run_kegel("init", str(f), "--bearing", "6205")
    assert res.returncode == 2 and "--bearing" in res.stderr and "6205" in res.stderr
    assert not f.exists()


@pytest.mark.parametrize("command", COMMANDS)
def test_every_command_has_help(command):
    res = run_kegel(command, "--help")
    assert res.returncode == 0 and "usage: kegel" in res.stdout, res.stderr
    if command != "cfd":  # cfd's subcommands take --format
        assert "--format" in res.stdout


def test_a_closed_pipe_ends_quietly():
    """`kegel list | head -1`: no BrokenPipeError traceback on stderr."""
    p = subprocess.Popen(f"'{KEGEL}' list | head -1", shell=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True)
    out, err = p.communicate(timeout=120)
    assert out.strip() and "Traceback" not in err and "BrokenPipe" not in err, err


def test_every_option_has_help_text():
    import argparse

    from kegel.cli import _parser

    missing = []

    def walk(p, prefix):
        for a in p._actions:
            if isinstance(a, argparse._SubParsersAction):
                for name, sp in a.choices.items():
                    walk(sp, prefix + [name])
            elif not a.help and not isinstance(a, (argparse._HelpAction, argparse._VersionAction)):
                missing.append(" ".join(prefix + [a.option_strings[0] if a.option_strings else a.dest]))

    walk(_parser(), ["kegel"])
    assert not missing, missing


def test_speed_means_one_speed_in_every_command():
    """issue 20: --speed was a from/to pair in `losses`, one value in `cfd run`, a list in `cfd
    sweep`. Now it is one speed everywhere (repeatable: a list); a range is --speed-range."""
    res = run_kegel("losses", "--bearing", "32208", "--speed", "500 rpm", "--speed", "1000 rpm", "--speed", "3000 rpm",
                    "--oil-level", "flooded", "--format", "json")
    assert res.returncode == 0, res.stderr
    speeds = sorted({round(p["speed_rpm"]) for p in json.loads(res.stdout)["points"] if p["correlation"] == "liebrecht"})
    assert speeds == [500, 1000, 3000]
    rng = run_kegel("losses", "--bearing", "32208", "--speed-range", "500 rpm", "4000 rpm", "--points", "3", "--oil-level",
                    "flooded", "--format", "json")
    assert rng.returncode == 0, rng.stderr
    assert sorted({round(p["speed_rpm"]) for p in json.loads(rng.stdout)["points"]}) == [500, 2250, 4000]
    bad = run_kegel("losses", "--bearing", "32208", "--speed", "500 rpm", "--points", "3")
    assert bad.returncode == 2 and "--points" in bad.stderr and "--speed-range" in bad.stderr
    sweep_help = run_kegel("cfd", "sweep", "--help").stdout
    assert "none" not in sweep_help.split("--oil-level")[1].split("--mesh")[0]  # offered, then rejected


def test_a_long_sweep_prints_the_first_and_last_rows_and_says_where_the_rest_is(tmp_path):
    """A run's table shows at most MAX_TABLE_ROWS rows (a 10^5-point sweep printed 10^5 lines):
    the first and the last half, with a line naming the hidden count and results.csv."""
    from kegel.cli import MAX_TABLE_ROWS

    code, out, err = call_kegel("run", str(EXAMPLES / "32216_table1.toml"), "--set", 'model.fidelity="fast"',
                                "--set", 'operating.speed={from="500 rpm", to="4000 rpm", points=70}',
                                "--output", str(tmp_path / "r"))
    assert code == 0, err
    rows = [ln for ln in out.splitlines() if ln[:1].isdigit()]
    assert len(rows) == MAX_TABLE_ROWS  # 140 points (70 speeds x 2 temperatures)
    assert rows[0].split()[0] == "0" and rows[-1].split()[0] == "139"
    assert "... 40 rows not shown (every row: results.csv)" in out
    with open(tmp_path / "r" / "results.csv") as fh:
        assert sum(1 for _ in fh) == 141
