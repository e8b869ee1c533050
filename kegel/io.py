"""Result files: written atomically, with the scene, the kegel version and the fidelity."""

from __future__ import annotations

import json
import os
import platform
import tempfile
from datetime import datetime, timezone
from pathlib import Path
from typing import Any

from . import _core

__all__ = ["atomic_write_text", "atomic_write_json", "provenance"]


def atomic_write_text(path: str | Path, text: str) -> Path:
    """Write ``text`` to ``path`` through a temporary file in the same folder and a rename,
    so that a reader never sees a half-written file."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(text)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def atomic_write_json(path: str | Path, data: Any) -> Path:
    """Atomically write ``data`` as indented JSON (NaN is refused: results must be finite)."""
    return atomic_write_text(path, json.dumps(data, indent=2, allow_nan=False) + "\n")


def provenance() -> dict[str, str]:
    """Versions and host facts written next to every result."""
    from . import __version__

    return {
        "kegel_version": __version__,
        "core_version": _core.core_version(),
        "eigen_version": _core.eigen_version(),
        "sundials_version": _core.sundials_version(),
        "python_version": platform.python_version(),
        "created_utc": datetime.now(timezone.utc).isoformat(timespec="seconds"),
    }
