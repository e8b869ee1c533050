"""Coupling of friction and hydraulic losses and flow-force feedback into the MBS.

Mapped into the import package as ``kegel.coupling``.
"""

__all__: list[str] = []
