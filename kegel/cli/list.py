"""``kegel list [KIND]``: what kegel ships with (bearings, lubricants, materials, friction sets,
validation data, example scenes)."""

from __future__ import annotations

import argparse
from typing import Any, Callable

from .common import _json_out, printable

__all__ = ["add_parser", "command"]


def command(args: argparse.Namespace) -> int:
    from ..model.inventory import KINDS, inventory

    kinds = [args.kind] if args.kind else list(KINDS)
    data = {k: inventory(k) for k in kinds}
    if args.format == "json":
        _json_out(data)
        return 0
    for k in kinds:
        print(f"{k}: {KINDS[k]}")
        rows = data[k]
        if not rows:
            print("  (none)")
        for r in rows:
            text = r.get("title", "")
            text = f"{text}: {r['description']}" if text and r.get("description") else (text or r.get("description", ""))
            print(printable(f"  {r['name']:<34} {text}".rstrip()))
    return 0


def add_parser(sub: Any, common: Callable[[argparse.ArgumentParser], None]) -> None:
    """The ``list`` sub-command on ``sub`` (``common`` adds ``--format``)."""
    from ..model.inventory import KINDS

    li = sub.add_parser("list", help="what kegel ships with: bearings, lubricants, materials, friction sets, "
                                     "validation data, example scenes")
    li.add_argument("kind", nargs="?", choices=tuple(KINDS), help="one kind only (default: all)")
    common(li)
    li.set_defaults(func=command)
