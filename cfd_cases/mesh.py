"""From a gmsh model to an OpenFOAM mesh: ASCII msh 2.2, gmshToFoam, patch types, checkMesh.

gmsh physical surfaces become OpenFOAM patches (gmshToFoam makes every one a ``patch``); the
types are then set from a name -> type map (``wall``, ``empty``, ``patch``). checkMesh must
report ``Mesh OK.``; otherwise :class:`MeshError` carries the failed checks.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from .foam import FoamError, run_utility

__all__ = ["MeshError", "MeshQuality", "restore_sigpipe", "write_msh22", "gmsh_to_foam", "set_patch_types", "check_mesh"]


class MeshError(FoamError):
    """A mesh failed checkMesh or could not be converted."""


@dataclass(frozen=True)
class MeshQuality:
    """What checkMesh reported.

    Attributes
    ----------
    cells, faces, points
        Sizes.
    max_non_orthogonality_deg, max_skewness, max_aspect_ratio
        Quality figures.
    ok
        checkMesh said ``Mesh OK.``
    failed
        The lines of the failed checks (``***``).
    """

    cells: int
    faces: int
    points: int
    max_non_orthogonality_deg: float
    max_skewness: float
    max_aspect_ratio: float
    ok: bool
    failed: tuple[str, ...]


def restore_sigpipe() -> None:
    """Give SIGPIPE back to Python after gmsh: ``gmsh.initialize`` sets it to the C default
    (terminate) and ``finalize`` leaves it so; a later write to a closed pipe or socket (a Dask
    comm, a pager) then killed the whole process without a word instead of raising
    BrokenPipeError. Python's own setting is to ignore it."""
    import signal

    signal.signal(signal.SIGPIPE, signal.SIG_IGN)


def write_msh22(path: str | Path) -> Path:
    """Write the current gmsh model's mesh as ASCII msh 2.2 (what gmshToFoam reads)."""
    import gmsh

    path = Path(path)
    gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
    gmsh.option.setNumber("Mesh.Binary", 0)
    gmsh.option.setNumber("Mesh.SaveAll", 0)
    tmp = path.with_suffix(".tmp.msh")
    gmsh.write(str(tmp))
    tmp.replace(path)
    return path


def gmsh_to_foam(case: str | Path, msh: str | Path, patch_types: Mapping[str, str | Mapping[str, str]]) -> None:
    """Convert ``msh`` into ``case/constant/polyMesh`` and set the patch types.

    Raises
    ------
    MeshError
        When a patch named in ``patch_types`` is not in the mesh, or a mesh patch has no type.
    """
    case = Path(case)
    run_utility(case, "gmshToFoam", str(Path(msh).resolve()))
    set_patch_types(case, patch_types)


_RE_PATCH = re.compile(r"^\s{4}(\w+)\s*\n\s{4}\{(.*?)\n\s{4}\}", re.S | re.M)


def set_patch_types(case: str | Path, patch_types: Mapping[str, str | Mapping[str, str]]) -> None:
    """Set ``type`` (and ``inGroups``) of every patch in ``constant/polyMesh/boundary``; a patch
    whose type is given as a mapping gets its other entries too (e.g. a ``cyclicAMI`` pair's
    ``neighbourPatch`` and ``transform``)."""
    path = Path(case) / "constant" / "polyMesh" / "boundary"
    text = path.read_text()
    found = set()

    def repl(m: re.Match) -> str:
        name, body = m.group(1), m.group(2)
        if name not in patch_types:
            raise MeshError(f"{path}: mesh patch '{name}' has no type (known: {sorted(patch_types)})")
        found.add(name)
        spec = patch_types[name]
        entries = dict(spec) if isinstance(spec, Mapping) else {"type": spec}
        kind = entries.pop("type")
        body = re.sub(r"\n\s*type\s+\w+;", f"\n        type            {kind};", body)
        body = re.sub(r"\n\s*physicalType\s+\w+;", "", body)
        body = re.sub(r"\n\s*inGroups\s+[^;]*;", "", body)
        extra = "".join(f"\n        {k:<15} {v};" for k, v in entries.items())
        if kind != "patch":
            extra = f"\n        inGroups        1({kind});" + extra
        body = body.replace(f"type            {kind};", f"type            {kind};" + extra, 1)
        return f"    {name}\n    {{{body}\n    }}"

    new = _RE_PATCH.sub(repl, text)
    missing = set(patch_types) - found
    if missing:
        raise MeshError(f"{path}: patches {sorted(missing)} expected but not in the mesh (has {sorted(found)})")
    tmp = path.with_suffix(".tmp")
    tmp.write_text(new)
    tmp.replace(path)


def check_mesh(case: str | Path, *, require_ok: bool = True) -> MeshQuality:
    """Run checkMesh and parse its verdict.

    Raises
    ------
    MeshError
        When ``require_ok`` and checkMesh reports failed checks (they are in the message).
    """
    out = run_utility(case, "checkMesh", "-constant")

    def grab(pattern: str, cast=float, default=float("nan")):
        m = re.search(pattern, out, re.M)
        return cast(m.group(1).rstrip(",")) if m else default

    failed = tuple(l.strip() for l in out.splitlines() if l.strip().startswith("***"))
    q = MeshQuality(
        cells=grab(r"^\s+cells:\s+(\d+)", int, 0),
        faces=grab(r"^\s+faces:\s+(\d+)", int, 0),
        points=grab(r"^\s+points:\s+(\d+)", int, 0),
        max_non_orthogonality_deg=grab(r"Mesh non-orthogonality Max: (\S+)"),
        max_skewness=grab(r"Max skewness = (\S+)"),
        max_aspect_ratio=grab(r"Max aspect ratio = (\S+)"),
        ok="Mesh OK." in out,
        failed=failed,
    )
    if require_ok and not q.ok:
        raise MeshError(f"checkMesh failed for {case}:\n  " + "\n  ".join(failed or ("(no verdict)",)))
    return q
