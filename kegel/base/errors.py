"""Errors raised for bad input: each names the file, the key, the value and what was expected."""

from __future__ import annotations

from pathlib import Path
from typing import Any

__all__ = ["KegelInputError", "KegelSolverError"]


class KegelInputError(ValueError):
    """Invalid input (scene file, data file or command-line value).

    Parameters
    ----------
    source
        File the value came from (a path), or a description such as ``"--set"``.
    key
        Dotted key of the value inside the source, e.g. ``"operating.axial_load"``.
    value
        The offending value as written (``None`` when the key is missing).
    expected
        What would have been accepted, in words.
    line, column
        Position in the file where known (malformed TOML).
    """

    def __init__(
        self,
        source: str | Path,
        key: str,
        value: Any,
        expected: str,
        *,
        line: int | None = None,
        column: int | None = None,
    ) -> None:
        self.source = str(source)
        self.key = key
        self.value = value
        self.expected = expected
        self.line = line
        self.column = column
        where = self.source
        if line is not None:
            where += f":{line}" + (f":{column}" if column is not None else "")
        if value is None:
            what = f"missing key '{key}'" if key else "missing value"
        else:
            what = f"key '{key}' = {value!r}" if key else f"value {value!r}"
        super().__init__(f"{where}: {what}: expected {expected}")


class KegelSolverError(RuntimeError):
    """A solver found no solution for valid input (e.g. a load distribution that does not
    converge: the loads exceed what the bearing can carry in the model). The message names the
    operating point's loads and the residual that was left; the ``kegel`` command prints it as one
    line and exits with status 1."""
