"""Layer 0, the base: what every layer uses and that knows nothing of bearings.

:mod:`~kegel.base.errors` (the two exceptions), :mod:`~kegel.base.units` (the quantity grammar),
:mod:`~kegel.base.limits` (the ranges every entry point accepts), :mod:`~kegel.base._toml`
(reading TOML with errors that name file and key), :mod:`~kegel.base.io` (atomic files,
provenance, the run folder that never loses what it did not write) and
:mod:`~kegel.base.version`. Imports nothing of kegel but the compiled core ``kegel._core``.
See docs/architecture.md.
"""
