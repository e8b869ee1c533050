"""One import package `kegel` with the top-level folders mapped in; editable and wheel builds."""

from __future__ import annotations

import subprocess
import sys
import zipfile

import pytest

import kegel
from conftest import REPO


def test_mapped_subpackages_import():
    import kegel.cfd_cases
    import kegel.correlations
    import kegel.coupling

    assert kegel.correlations.__file__.endswith("correlations/__init__.py")


def test_public_api_is_exported():
    for name in kegel.__all__:
        assert hasattr(kegel, name), name


def test_core_reports_versions():
    assert kegel._core.eigen_version().startswith("3.4")
    assert kegel._core.sundials_version().startswith("6.")
    assert kegel._core.core_version() == kegel.__version__


@pytest.mark.slow
def test_wheel_build_contains_everything(tmp_path):
    res = subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "-w", str(tmp_path), str(REPO)],
        capture_output=True, text=True, timeout=900,
    )
    assert res.returncode == 0, res.stdout[-3000:] + res.stderr[-3000:]
    (wheel,) = tmp_path.glob("kegel-*.whl")
    names = zipfile.ZipFile(wheel).namelist()
    for must in ("kegel/__init__.py", "kegel/cli/main.py", "kegel/model/scene.py", "kegel/runner/run.py",
                 "kegel/correlations/__init__.py", "kegel/coupling/__init__.py", "kegel/cfd_cases/__init__.py",
                 "kegel/data/bearings/32216.toml", "kegel/data/lubricants/FVA3.toml"):
        assert must in names, must
    assert any(n.startswith("kegel/_core") and n.endswith(".so") for n in names)
