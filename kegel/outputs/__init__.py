"""Layer 4, the outputs: what a set of solved points becomes for a reader.

:mod:`~kegel.outputs.point_warnings` (the warnings of each point), :mod:`~kegel.outputs.study`
(the hydraulic study table: correlations and CFD beside each other) and
:mod:`~kegel.outputs.plots` (every figure). The run folder itself is :class:`kegel.base.io.RunFolder`.
See docs/architecture.md.
"""
