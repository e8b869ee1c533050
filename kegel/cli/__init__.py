"""Layer 6, the command line ``kegel``: :mod:`~kegel.cli.main` builds the parser and dispatches,
one module per command does the command (docs/architecture.md)."""

from __future__ import annotations

from .main import MAX_LOSS_POINTS, MAX_TABLE_ROWS, _parser, main

__all__ = ["main"]
