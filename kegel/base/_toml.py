"""Reading TOML input files with errors that name the file, the key and the position."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path
from typing import Any

from .errors import KegelInputError

__all__ = ["read_toml", "require_table", "require_number", "require_str"]


#: Largest input file kegel reads (scene, bearing, lubricant, friction data are a few kB).
MAX_INPUT_BYTES = 10_000_000


def read_toml(path: Path) -> dict[str, Any]:
    """Read a TOML file; a malformed file raises KegelInputError with line and column.

    Only regular files are read (a named pipe would block the read for good; a device or a folder
    is no input file), and at most :data:`MAX_INPUT_BYTES`."""
    import os
    import stat

    path = Path(path)
    try:
        st = os.stat(path)
    except FileNotFoundError:
        raise KegelInputError(path, "", str(path), "an existing TOML file") from None
    except OSError as exc:
        raise KegelInputError(path, "", str(path), f"a readable UTF-8 TOML file ({exc})") from None
    if not stat.S_ISREG(st.st_mode):
        raise KegelInputError(path, "", str(path), "a regular TOML file (not a folder, pipe or device)")
    if st.st_size > MAX_INPUT_BYTES:
        raise KegelInputError(path, "", f"{st.st_size} bytes", f"a TOML file of at most {MAX_INPUT_BYTES} bytes")
    try:
        # utf-8-sig: a byte order mark (U+FEFF, written by some Windows editors) is no TOML
        # statement; it is dropped, as the TOML spec's UTF-8 allows the editor to add it
        text = path.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise KegelInputError(path, "", str(path), "an existing TOML file") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise KegelInputError(path, "", str(path), f"a readable UTF-8 TOML file ({exc})") from None
    try:
        return tomllib.loads(text)
    except RecursionError:
        # tomllib parses nested arrays and inline tables recursively: a file nested thousands
        # deep exhausts Python's stack (no input of kegel nests more than three deep)
        raise KegelInputError(path, "", "(file)", "well-formed TOML with arrays and inline tables nested at most "
                              "a few levels deep (this file nests them too deep to read)") from None
    except tomllib.TOMLDecodeError as exc:
        line = getattr(exc, "lineno", None)
        col = getattr(exc, "colno", None)
        msg = getattr(exc, "msg", str(exc))
        if line is None:  # Python < 3.14: position only inside the message "(at line L, column C)"
            import re

            m = re.search(r"\(at line (\d+), column (\d+)\)", str(exc))
            if m:
                line, col = int(m.group(1)), int(m.group(2))
                msg = str(exc)[: m.start()].strip()
        raise KegelInputError(
            path, "", "(file)", f"well-formed TOML ({msg})", line=line, column=col
        ) from None


def require_table(data: dict[str, Any], key: str, source: Path | str, prefix: str = "") -> dict:
    """Return the sub-table ``data[key]``, or raise naming the missing/invalid key."""
    full = f"{prefix}{key}"
    if key not in data:
        raise KegelInputError(source, full, None, f"a table [{full}]")
    value = data[key]
    if not isinstance(value, dict):
        raise KegelInputError(source, full, value, f"a table [{full}]")
    return value


def require_number(
    data: dict[str, Any],
    key: str,
    source: Path | str,
    prefix: str = "",
    *,
    positive: bool = False,
    nonnegative: bool = False,
    integer: bool = False,
    default: float | None = None,
) -> float:
    """Return ``data[key]`` as a finite number with the stated sign, or raise."""
    full = f"{prefix}{key}"
    if key not in data:
        if default is not None:
            return default
        raise KegelInputError(source, full, None, "a number")
    value = data[key]
    kind = "an integer" if integer else "a number"
    if isinstance(value, bool) or not isinstance(value, (int, float)) or (
        integer and not isinstance(value, int)
    ):
        raise KegelInputError(source, full, value, kind)
    if not math.isfinite(value):
        raise KegelInputError(source, full, value, f"{kind} that is finite")
    if positive and not value > 0:
        raise KegelInputError(source, full, value, f"{kind} > 0")
    if nonnegative and value < 0:
        raise KegelInputError(source, full, value, f"{kind} >= 0")
    return value


def require_str(
    data: dict[str, Any], key: str, source: Path | str, prefix: str = "", *, default: str | None = None
) -> str:
    """Return ``data[key]`` as a string, or raise."""
    full = f"{prefix}{key}"
    if key not in data:
        if default is not None:
            return default
        raise KegelInputError(source, full, None, "a string")
    value = data[key]
    if not isinstance(value, str):
        raise KegelInputError(source, full, value, "a string")
    return value
