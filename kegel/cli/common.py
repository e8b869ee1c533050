"""What every command prints with: the table, JSON on stdout, text made safe for a terminal."""

from __future__ import annotations

import json
import sys
from typing import Any, Sequence

__all__ = ["MAX_TABLE_ROWS", "printable"]


#: A run's table shows at most this many rows (the first and the last half); every row is in
#: results.csv and results.json.
MAX_TABLE_ROWS = 100


def _print_table(headers: Sequence[str], rows: Sequence[Sequence[Any]], out=None, *,
                 max_rows: int | None = None, where: str = "") -> None:
    out = out if out is not None else sys.stdout  # at call time (a redirected stdout included)
    def fmt(v: Any) -> str:
        if isinstance(v, float):
            return f"{v:.4g}"  # engineers read 3-4 figures; every digit is in --format json
        return "" if v is None else str(v)

    hidden = 0
    if max_rows is not None and len(rows) > max_rows:
        hidden = len(rows) - max_rows
        rows = [*rows[:max_rows // 2], *rows[len(rows) - (max_rows - max_rows // 2):]]
    cells = [[fmt(v) for v in row] for row in rows]
    widths = [max(len(h), *(len(r[i]) for r in cells)) if cells else len(h) for i, h in enumerate(headers)]
    print("  ".join(h.ljust(w) for h, w in zip(headers, widths)).rstrip(), file=out)
    print("  ".join("-" * w for w in widths), file=out)
    for k, r in enumerate(cells):
        if hidden and k == max_rows // 2:
            print(f"... {hidden} rows not shown (every row: {where or 'the result files'})", file=out)
        print("  ".join(c.rjust(w) if i else c.ljust(w) for i, (c, w) in enumerate(zip(r, widths))).rstrip(), file=out)


_BIDI_CONTROLS = frozenset("\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069")


def printable(text: str) -> str:
    """``text`` safe for a terminal: control characters (escape sequences, carriage returns, C1
    controls) and bidirectional overrides written as Python escapes (``\\x1b``), the rest kept
    (scene names and descriptions come from files a user may not have written)."""
    import unicodedata

    return "".join(ch.encode("unicode_escape").decode("ascii")
                   if unicodedata.category(ch) == "Cc" or ch in _BIDI_CONTROLS else ch for ch in str(text))


def _json_out(data: Any) -> None:
    json.dump(data, sys.stdout, indent=2, allow_nan=False)
    sys.stdout.write("\n")
