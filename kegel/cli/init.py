"""``kegel init FILE``: write a commented scene file to start from."""

from __future__ import annotations

import argparse
from typing import Any, Callable

from .common import _json_out

__all__ = ["add_parser", "command"]


def command(args: argparse.Namespace) -> int:
    from ..model.inventory import write_scene_template

    path = write_scene_template(args.file, bearing=args.bearing, lubricant=args.lubricant, force=args.force)
    if args.format == "json":
        _json_out({"file": str(path)})
        return 0
    print(f"wrote {path}: check it with `kegel check {path}`, run it with `kegel run {path}`")
    return 0


def add_parser(sub: Any, common: Callable[[argparse.ArgumentParser], None]) -> None:
    """The ``init`` sub-command on ``sub`` (``common`` adds ``--format``)."""
    it = sub.add_parser("init", help="write a commented scene file to start from")
    it.add_argument("file", help="the scene .toml file to write")
    it.add_argument("--bearing", default="32216", help="bearing designation or .toml file (default 32216)")
    it.add_argument("--lubricant", default="FVA3", help="lubricant name or .toml file (default FVA3)")
    it.add_argument("--force", action="store_true", help="replace an existing file")
    common(it)
    it.set_defaults(func=command)
