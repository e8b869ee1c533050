"""Layer 6, the command line ``kegel``: :mod:`~kegel.cli.main` builds the parser and dispatches;
one module per command (``kegel.cli.run`` for ``kegel run``, ...) adds its parser
(``add_parser``) and does the command (``command``); :mod:`~kegel.cli.common` prints tables and
JSON. ``kegel cfd ...`` is :mod:`kegel.cfd_cases.cli` (docs/architecture.md)."""

from __future__ import annotations

from .common import MAX_TABLE_ROWS
from .losses import MAX_LOSS_POINTS
from .main import _parser, main

__all__ = ["MAX_LOSS_POINTS", "MAX_TABLE_ROWS", "main"]
