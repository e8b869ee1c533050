"""OpenFOAM case templates, gmsh geometry and the case runner.

Mapped into the import package as ``kegel.cfd_cases``.
"""

__all__: list[str] = []
