"""Find the CFD result (``results.json`` of ``kegel cfd run`` or ``kegel cfd sweep``) that belongs
to an operating point.

A scene with ``[model] hydraulic = "cfd"`` names a results file or a folder of them
(``cfd_results``); each operating point takes the result computed for it: the same bearing and
lubricant, the speed within 0.5 %, the temperature within 0.5 K and the same oil level (flooded,
or the level within 0.1 mm). A CFD result is one frozen-rotor solution at one point, so kegel does
not scale it to other speeds or temperatures: a point without its result is an error that lists
the points available.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

from ..errors import KegelInputError

__all__ = ["find_cfd_result", "cfd_result_files", "read_cfd_results"]

SPEED_TOLERANCE = 0.005       # relative
TEMPERATURE_TOLERANCE_K = 0.5
OIL_LEVEL_TOLERANCE_M = 1e-4


def cfd_result_files(path: str | Path) -> list[Path]:
    """``path`` itself when it is a file, else every ``results.json`` below it (sorted)."""
    p = Path(path)
    if p.is_file():
        return [p]
    return sorted(p.rglob("results.json")) if p.is_dir() else []


def _describe(point: dict[str, Any]) -> str:
    level = point.get("oil_level_m")
    lvl = "flooded" if level is None else f"oil level {1e3 * level:.1f} mm"
    return (f"{point.get('bearing')} {point.get('lubricant')} at {point.get('speed_rad_s', 0.0) * 30 / math.pi:.0f} rpm, "
            f"{point.get('temperature_K', 0.0) - 273.15:.1f} degC, {lvl}")


def read_cfd_results(path: str | Path, *, source: str = "<argument>",
                     key: str = "model.cfd_results") -> list[tuple[Path, dict[str, Any]]]:
    """Every ``kegel cfd run`` result at ``path`` (a ``results.json`` or a folder searched
    recursively), as (file, contents); other programs' ``results.json`` files are skipped.

    Raises
    ------
    KegelInputError
        No file at ``path``, or a file that is not readable JSON.
    """
    files = cfd_result_files(path)
    if not files:
        raise KegelInputError(source, key, str(path), "a kegel cfd results.json or a folder holding them")
    out = []
    for f in files:
        try:
            data = json.loads(f.read_text())
        except (OSError, json.JSONDecodeError) as exc:
            raise KegelInputError(str(f), "(file)", "", f"a readable CFD results.json ({exc})") from None
        if isinstance(data.get("point"), dict) and "kinematics" in data and "loss_torque_at_shaft_Nm" in data:
            out.append((f, data))
    return out


def find_cfd_result(path: str | Path, *, bearing: str, lubricant: str, speed_rad_s: float, temperature_K: float,
                    oil_level_m: float, flooded: bool, source: str = "<argument>", key: str = "model.cfd_results",
                    results: list[tuple[Path, dict[str, Any]]] | None = None) -> tuple[dict[str, Any], Path]:
    """The CFD result for one operating point, and its file.

    Parameters
    ----------
    path
        A ``results.json`` or a folder searched recursively for them.
    bearing, lubricant, speed_rad_s, temperature_K
        The operating point.
    oil_level_m, flooded
        The oil level above the lowest point of the outer diameter; ``flooded`` for a full bearing
        (the CFD's single-phase case).
    source, key
        Where ``path`` was written, for the error message.
    results
        What :func:`read_cfd_results` read from ``path`` already (a sweep reads the files once).

    Raises
    ------
    KegelInputError
        No readable result matches; the message lists the points that were found.
    """
    if results is None:
        results = read_cfd_results(path, source=source, key=key)
    found = []
    for f, data in results:
        pt = data["point"]
        found.append(_describe(pt))
        level = pt.get("oil_level_m")
        if (pt.get("bearing") == bearing and pt.get("lubricant") == lubricant
                and abs(pt.get("speed_rad_s", 0.0) / speed_rad_s - 1.0) <= SPEED_TOLERANCE
                and abs(pt.get("temperature_K", 0.0) - temperature_K) <= TEMPERATURE_TOLERANCE_K
                and ((level is None) == flooded)
                and (flooded or abs(level - oil_level_m) <= OIL_LEVEL_TOLERANCE_M)):
            return data, f
    want = _describe({"bearing": bearing, "lubricant": lubricant, "speed_rad_s": speed_rad_s,
                      "temperature_K": temperature_K, "oil_level_m": None if flooded else oil_level_m})
    have = "; ".join(found) if found else "no kegel cfd results"
    raise KegelInputError(source, key, str(path),
                          f"a CFD result for {want} (found: {have}); run `kegel cfd run` for this point")
