"""Reading the ``forces`` function object's output (force.dat, moment.dat) of OpenFOAM v1912.

Each file has lines ``time (total) (pressure) (viscous)`` with three components each. Restarted
runs write a new time folder named by their start time; the series are concatenated in time order,
and a later folder replaces everything an earlier run wrote from its start time on. A run restarted
from a time whose folder already holds an earlier run's file writes ``<stem>_<start time>.dat``
beside it, which replaces that file's series from the start time on.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .foam import FoamError

__all__ = ["ForceSeries", "read_forces"]


@dataclass(frozen=True)
class ForceSeries:
    """Force and moment time series of one ``forces`` function object (SI units).

    Attributes
    ----------
    time
        Shape (n,).
    force_total, force_pressure, force_viscous, moment_total, moment_pressure, moment_viscous
        Shape (n, 3), in the global frame; moments about the object's CofR.
    """

    time: np.ndarray
    force_total: np.ndarray
    force_pressure: np.ndarray
    force_viscous: np.ndarray
    moment_total: np.ndarray
    moment_pressure: np.ndarray
    moment_viscous: np.ndarray


def _read_dat(path: Path) -> np.ndarray:
    text = path.read_text()
    lines = text.splitlines()
    if lines and not text.endswith("\n"):
        lines.pop()  # a last line without its end: cut by a kill (a resumed run writes it anew)
    rows = []
    for line in lines:
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        nums = line.replace("(", " ").replace(")", " ").split()
        try:
            rows.append([float(x) for x in nums])
        except ValueError as exc:
            raise FoamError(f"{path}: unreadable line {line!r}") from exc
        if len(rows[-1]) != 10:
            raise FoamError(f"{path}: expected 10 columns (time, total, pressure, viscous), got "
                            f"{len(rows[-1])} in line {line!r}")
    if not rows:
        return np.empty((0, 10))
    return np.array(rows)


def _series(case: Path, name: str, file: str) -> np.ndarray:
    root = case / "postProcessing" / name
    if not root.is_dir():
        raise FoamError(f"{root}: no output of function object '{name}' (did the solver run?)")
    parts: list[np.ndarray] = []
    stem = file.removesuffix(".dat")
    for d in sorted((p for p in root.iterdir() if p.is_dir()), key=lambda p: float(p.name)):
        # A restart from time d writes into folder d; where an earlier run left its file there
        # (it was stopped before it wrote a time, so the new run starts from the same time),
        # OpenFOAM names the new one <stem>_<start time>.dat beside it: the later file wins.
        files = [f for f in d.iterdir() if f.is_file() and (f.name == file or (
            f.name.startswith(stem + "_") and f.suffix == ".dat"))]
        for f in sorted(files, key=lambda f: (f.name != file, f.stat().st_mtime_ns, f.name)):
            # a restart from time d replaces what earlier runs wrote from d on (an interrupted
            # run may have gone past its last written time; its time steps differ from the new ones)
            start = float(d.name)
            parts = [p[p[:, 0] <= start] if p[0, 0] < start else p[:0] for p in parts if len(p)]
            parts.append(_read_dat(f))
    parts = [p for p in parts if len(p)]
    if not parts:
        raise FoamError(f"{root}: no {file} in any time folder")
    arr = np.vstack(parts)
    # keep the last occurrence of each time (a restart repeats its start time)
    _, idx = np.unique(arr[::-1, 0], return_index=True)
    keep = np.sort(len(arr) - 1 - idx)
    return arr[keep]


def read_forces(case: str | Path, name: str = "forces") -> ForceSeries:
    """Read force.dat and moment.dat of function object ``name`` in ``case``."""
    case = Path(case)
    f = _series(case, name, "force.dat")
    m = _series(case, name, "moment.dat")
    n = min(len(f), len(m))
    f, m = f[:n], m[:n]
    return ForceSeries(f[:, 0], f[:, 1:4], f[:, 4:7], f[:, 7:10], m[:, 1:4], m[:, 4:7], m[:, 7:10])
