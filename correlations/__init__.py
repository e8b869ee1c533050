"""Hydraulic-loss correlations (Liebrecht, SKF drag, ...): issue "Hydraulic-loss correlations".

Mapped into the import package as ``kegel.correlations``.
"""

__all__: list[str] = []
