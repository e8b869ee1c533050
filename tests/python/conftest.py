from __future__ import annotations

import io
import json
import subprocess
import sys
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"
SHARED_REFERENCE = REPO.parent / "shared" / "reference"


def run_kegel(*args: str, cwd: Path | None = None, timeout: float = 120) -> subprocess.CompletedProcess:
    """Run the installed `kegel` command (the entry point users call)."""
    exe = Path(sys.executable).with_name("kegel")
    return subprocess.run([str(exe), *args], capture_output=True, text=True, cwd=cwd, timeout=timeout)


def call_kegel(*argv: str) -> tuple[int, str, str]:
    """kegel's command line in this process (exit status, stdout, stderr): faster than
    :func:`run_kegel` and open to monkeypatching."""
    from kegel.cli import main

    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        try:
            code = main(list(argv))
        except SystemExit as exc:  # argparse
            code = int(exc.code or 0)
    return code, out.getvalue(), err.getvalue()


@pytest.fixture
def kegel_json():
    def call(*args: str) -> dict:
        res = run_kegel(*args, "--format", "json")
        assert res.returncode == 0, res.stderr
        return json.loads(res.stdout)

    return call


def scene_text(*, speed: str = '"2000 rpm"', lubrication: str = 'mode = "minimum_quantity"',
               model: str = "") -> str:
    """A 32216 scene at 6 kN and 50 degC, fidelity fast, output to "out": the speed (TOML value),
    the [lubrication] lines and further [model] lines (tables such as [dynamic] may follow them)."""
    return f"""
[bearing]
designation = "32216"
[lubricant]
name = "FVA3"
[operating]
axial_load = "6 kN"
speed = {speed}
temperature = "50 degC"
[lubrication]
{lubrication}
[model]
fidelity = "fast"
{model}
[output]
directory = "out"
"""


@pytest.fixture
def write_scene(tmp_path):
    """Write a scene file from the text of a valid base scene with replacements."""
    base = (EXAMPLES / "32216_table1.toml").read_text()

    def make(text: str | None = None, *, replace: dict[str, str] | None = None, name: str = "scene.toml") -> Path:
        body = base if text is None else text
        for old, new in (replace or {}).items():
            assert old in body, old
            body = body.replace(old, new)
        path = tmp_path / name
        path.write_text(body)
        return path

    return make


@pytest.fixture(autouse=True)
def _sigint_as_python_sets_it(request):
    """Every test starts with Python's own SIGINT handler. In the full clean-clone run the tests
    that interrupt a live run (test_dynamic_interrupt, test_output_folder, test_run_survival,
    test_reliability_cases) failed while they pass alone: an earlier test left SIGINT ignored in
    the pytest process, and the kegel processes they start inherit an ignored SIGINT. The culprit
    is not found yet; the warning names the test after which the handler was found changed."""
    import signal
    import warnings

    h = signal.getsignal(signal.SIGINT)
    if h is not signal.default_int_handler:
        warnings.warn(f"SIGINT handler was {h!r} before {request.node.nodeid}: restored to Python's "
                      f"default (an earlier test changed it)")
        signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
