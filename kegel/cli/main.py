"""The ``kegel`` command.

Commands
--------
``kegel bearing --bearing 32216``
    Derived internal geometry of a bearing, as a table.
``kegel lubricant FVA3 --temperature "50 degC"``
    Dynamic and kinematic viscosity, density and pressure-viscosity coefficient.
``kegel check SCENE [--set KEY=VALUE ...]``
    Validate a scene file.
``kegel tribology [--bearing 32216 --speed "2000 rpm" --axial-load "6 kN" ...]``
    Film state and friction by mechanism of one roller/raceway contact.
``kegel losses --bearing 32208 [--oil-level flooded ...] [--plot losses.png]``
    Hydraulic losses by correlation against speed and oil level: Liebrecht and the SKF drag
    moment side by side, with the SKF rolling + sliding moment as a check of contact friction.
``kegel run SCENE [--set KEY=VALUE ...] [--output DIR]``
    Run a scene: quasi-static load distribution, friction by contact and mechanism, hydraulic
    loss of an oil bath; a table, results.json, results.csv and plots.

Every command takes ``--format json`` for machine-readable output on stdout (field names carry
their units, see README.md). Input errors print one line naming the file, key, value and
expectation to stderr and exit with status 2.
"""

from __future__ import annotations

import argparse
import sys
from typing import Sequence

from ..base.errors import KegelInputError, KegelSolverError
from . import bearing, check, init, losses, lubricant, run, tribology, validate
from . import list as list_
from .common import printable

__all__ = ["main"]


def _parser() -> argparse.ArgumentParser:
    from ..base.version import __version__

    p = argparse.ArgumentParser(prog="kegel", description="Power losses of tapered roller bearings.")
    p.add_argument("--version", action="version", version=f"kegel {__version__}")
    sub = p.add_subparsers(dest="command", required=True)

    def common(sp: argparse.ArgumentParser) -> None:
        sp.add_argument("--format", choices=("table", "json"), default="table",
                        help="table for people, json for programs (default: table)")

    # one module per command, in the order of `kegel --help`
    for command in (list_, init, bearing, lubricant, tribology, losses):
        command.add_parser(sub, common)

    from ..cfd_cases.cli import add_cfd_parser

    add_cfd_parser(sub, common)

    for command in (validate, check, run):
        command.add_parser(sub, common)
    return p


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``kegel`` command; returns the exit status."""
    from ..outputs.point_warnings import warnings_once_per_command

    args = _parser().parse_args(argv)
    try:
        with warnings_once_per_command():
            return args.func(args)
    except KegelInputError as exc:
        print(f"kegel: error: {printable(str(exc))}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as exc:
        signum = getattr(exc, "signum", 2)  # kegel.io.Terminated: SIGTERM, SIGHUP
        print("kegel: interrupted" if signum == 2 else f"kegel: terminated ({exc})", file=sys.stderr)
        return 128 + signum
    except KegelSolverError as exc:
        print(f"kegel: solver failed: {exc}", file=sys.stderr)
        return 1
    except BrokenPipeError:
        # `kegel ... | head`: the reader has gone; no traceback, and none at exit either
        import os

        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 141
    except OSError as exc:
        # a full disk, a vanished or read-only output folder: one line naming the file
        where = f"{exc.filename}: " if exc.filename else ""
        print(f"kegel: error: cannot write {where}{exc.strerror or exc}", file=sys.stderr)
        return 1
    except RuntimeError as exc:
        from ..cfd_cases.foam import FoamError, FoamInterrupted

        if not isinstance(exc, FoamError):
            raise
        if isinstance(exc, FoamInterrupted):
            print(f"kegel: {str(exc).splitlines()[0]}\n  case: {exc.case}", file=sys.stderr)
            return 130
        print(f"kegel: OpenFOAM error: {exc}", file=sys.stderr)
        return 1


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
