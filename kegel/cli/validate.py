"""``kegel validate``: kegel's bearing torque against measured data and the SKF catalogue model."""

from __future__ import annotations

import argparse
import sys
from typing import Any, Callable

__all__ = ["add_parser", "command"]


def command(args: argparse.Namespace) -> int:
    from ..runner.validation import print_report, run_validation

    result = run_validation(args.output, progress=sys.stderr.isatty())
    print_report(result)
    return 0


def add_parser(sub: Any, common: Callable[[argparse.ArgumentParser], None]) -> None:
    """The ``validate`` sub-command on ``sub`` (``common`` adds ``--format``)."""
    va = sub.add_parser("validate", help="kegel's bearing torque against measured data and the SKF catalogue model")
    va.add_argument("--output", default="results/validation", help="result folder (default: results/validation)")
    common(va)
    va.set_defaults(func=command)
