"""Case templates: ordinary OpenFOAM case folders whose ``*.template`` files are PyFoam templates.

A template file uses PyFoam's pyratemp syntax: ``|-expression-|`` for values and
``<!--(if flag)-->...<!--(end)-->`` for choices. :func:`render_case` copies a template folder,
renders every ``*.template`` file with the given parameters (dropping the suffix) and writes the
case atomically (into a temporary folder that is then renamed).
"""

from __future__ import annotations

import shutil
import tempfile
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from PyFoam.Basics.TemplateFile import TemplateFile
from PyFoam.Basics.TemplateFile import TemplateRenderError

from .foam import FoamError

__all__ = ["TEMPLATE_ROOT", "render_case", "render_file", "foam_vector"]

#: Folder of kegel's case templates.
TEMPLATE_ROOT = Path(__file__).resolve().parent / "templates"


def foam_vector(v: Sequence[float]) -> str:
    """OpenFOAM spelling of a 3-vector, ``(x y z)``, with round-trip precision."""
    if len(v) != 3:
        raise ValueError(f"expected a 3-vector, got {v!r}")
    return "(" + " ".join(f"{float(c):.17g}" for c in v) + ")"


def render_file(template_file: str | Path, dest: str | Path, params: Mapping[str, Any]) -> Path:
    """Render one ``*.template`` file (a path, or one relative to :data:`TEMPLATE_ROOT`) to ``dest``.

    Raises
    ------
    FoamError
        When the template names a parameter that is not given (the message names the file).
    """
    path = Path(template_file)
    if not path.is_file():
        path = TEMPLATE_ROOT / path
    if not path.is_file():
        raise FoamError(f"template file '{template_file}' not found (looked in {TEMPLATE_ROOT})")
    values = {"vec": foam_vector, **params}
    try:
        text = TemplateFile(content=path.read_text(), expressionDelimiter="|-").getString(values)
    except (TemplateRenderError, NameError, KeyError) as exc:
        raise FoamError(f"{path}: {exc}") from exc
    dest = Path(dest)
    dest.write_text(text)
    return dest


def render_case(
    template: str | Path,
    case_dir: str | Path,
    params: Mapping[str, Any],
    *,
    overwrite: bool = False,
) -> Path:
    """Create ``case_dir`` from a template folder.

    Parameters
    ----------
    template
        A folder, or the name of one under :data:`TEMPLATE_ROOT`.
    case_dir
        The case to create.
    params
        Values for the templates; ``vec`` (:func:`foam_vector`) is always available.
    overwrite
        Replace an existing ``case_dir``.

    Raises
    ------
    FoamError
        When a template names a parameter that is not given (the message names the file).
    """
    src = Path(template)
    if not src.is_dir():
        src = TEMPLATE_ROOT / str(template)
    if not src.is_dir():
        raise FoamError(f"case template '{template}' not found (looked in {TEMPLATE_ROOT})")
    case_dir = Path(case_dir)
    if case_dir.exists() and not overwrite:
        raise FoamError(f"case folder {case_dir} exists (pass overwrite=True to replace it)")
    case_dir.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{case_dir.name}.", dir=case_dir.parent))
    try:
        for path in sorted(src.rglob("*")):
            rel = path.relative_to(src)
            if path.is_dir():
                (tmp / rel).mkdir(parents=True, exist_ok=True)
                continue
            (tmp / rel).parent.mkdir(parents=True, exist_ok=True)
            if path.suffix == ".template":
                render_file(path, tmp / rel.with_suffix(""), params)
            else:
                shutil.copy2(path, tmp / rel)
        if case_dir.exists():
            shutil.rmtree(case_dir)
        tmp.rename(case_dir)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return case_dir
