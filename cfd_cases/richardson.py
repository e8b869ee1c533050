"""Discretisation uncertainty of a CFD result from three mesh levels: Richardson extrapolation
and the grid convergence index (GCI), following the procedure of Celik, Ghia, Roache, Freitas,
Coleman and Raad, "Procedure for Estimation and Reporting of Uncertainty Due to Discretization
in CFD Applications", J. Fluids Eng. 130 (2008) 078001 (the ASME Journal of Fluids Engineering
editorial policy), which builds on Roache's GCI (Roache, "Quantification of uncertainty in
computational fluid dynamics", Annu. Rev. Fluid Mech. 29 (1997) 123-160).

Steps (1 = finest mesh): the representative cell size of an unstructured 3D mesh of N cells is
h = N^(-1/3) (the common volume cancels from every ratio); r21 = h2 / h1, r32 = h3 / h2; with
e21 = phi2 - phi1, e32 = phi3 - phi2 and s = sign(e32 / e21), the apparent order p solves

    p = |ln|e32 / e21| + q(p)| / ln r21,   q(p) = ln((r21^p - s) / (r32^p - s))

(fixed-point iteration; q = 0 for a constant refinement ratio). Then

    phi_ext = (r21^p phi1 - phi2) / (r21^p - 1),
    e_a = |(phi1 - phi2) / phi1|,   e_ext = |(phi_ext - phi1) / phi_ext|,
    GCI_fine = 1.25 e_a / (r21^p - 1)   (factor of safety 1.25 for three meshes).

Oscillatory convergence (s < 0), an iteration that does not converge, or an apparent order
outside [p_formal / 2, 2 p_formal] (meshes not in the asymptotic range) are flagged in ``notes``,
and the GCI then uses the formal order of the scheme (``p_formal``, 2 for kegel's second-order
schemes) with a factor of safety of 3 (Roache's value when the observed order is not trusted).
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Any

__all__ = ["RichardsonResult", "richardson_three_levels"]


@dataclass(frozen=True)
class RichardsonResult:
    """Richardson extrapolation of a quantity from three meshes (see the module docstring).

    ``phi`` and ``cells`` are ordered finest first. ``gci_fine`` is a relative uncertainty of
    the finest mesh's value (0.02: +-2 %); ``uncertainty`` is the same in the quantity's units.
    ``convergence`` is ``"monotonic"`` or ``"oscillatory"``; ``notes`` say what was assumed.
    """

    phi: tuple[float, float, float]
    cells: tuple[int, int, int]
    r21: float
    r32: float
    apparent_order: float
    order_used: float
    safety_factor: float
    phi_extrapolated: float
    relative_change_fine: float
    relative_error_extrapolated: float
    gci_fine: float
    uncertainty: float
    convergence: str
    notes: tuple[str, ...]

    def as_dict(self) -> dict[str, Any]:
        return asdict(self)


def _apparent_order(e21: float, e32: float, r21: float, r32: float, s: float) -> float | None:
    """Fixed-point iteration for the apparent order; None when it does not converge."""
    ratio = abs(e32 / e21)
    p = abs(math.log(ratio)) / math.log(r21)
    for _ in range(200):
        try:
            q = math.log((r21 ** p - s) / (r32 ** p - s))
        except (ValueError, ZeroDivisionError, OverflowError):
            return None
        p_new = abs(math.log(ratio) + q) / math.log(r21)
        if abs(p_new - p) <= 1e-12 * max(1.0, p):
            return p_new
        p = p_new
    return None


def richardson_three_levels(phi: tuple[float, float, float] | list[float], cells: tuple[int, int, int] | list[int],
                            *, p_formal: float = 2.0) -> RichardsonResult:
    """Richardson extrapolation and GCI of ``phi`` on three meshes of ``cells`` cells (finest first).

    Raises
    ------
    ValueError
        Not three values, cells not decreasing from the finest mesh, a non-finite value, or two
        equal values (no order can be observed).
    """
    if len(phi) != 3 or len(cells) != 3:
        raise ValueError(f"phi = {phi!r}, cells = {cells!r}: expected three values each, finest mesh first")
    p1, p2, p3 = (float(x) for x in phi)
    n1, n2, n3 = (int(c) for c in cells)
    if not all(math.isfinite(x) for x in (p1, p2, p3)):
        raise ValueError(f"phi = {phi!r}: expected finite values")
    if not n1 > n2 > n3 > 0:
        raise ValueError(f"cells = {cells!r}: expected decreasing positive counts, finest mesh first")
    h1, h2, h3 = (n ** (-1.0 / 3.0) for n in (n1, n2, n3))
    r21, r32 = h2 / h1, h3 / h2
    e21, e32 = p2 - p1, p3 - p2
    if e21 == 0.0 or e32 == 0.0:
        raise ValueError(f"phi = {phi!r}: two equal values, no order of convergence can be observed")
    s = math.copysign(1.0, e32 / e21)
    notes: list[str] = []
    convergence = "monotonic" if s > 0 else "oscillatory"
    p = _apparent_order(e21, e32, r21, r32, s)
    order, fs = (p if p is not None else p_formal), 1.25
    if s < 0:
        notes.append("oscillatory convergence: the apparent order is not trusted; the GCI uses the formal "
                     f"order {p_formal:g} with a factor of safety of 3")
        order, fs = p_formal, 3.0
    elif p is None:
        notes.append(f"the apparent order did not converge; the GCI uses the formal order {p_formal:g} with a "
                     "factor of safety of 3")
        order, fs = p_formal, 3.0
    elif not (0.5 * p_formal <= p <= 2.0 * p_formal):
        notes.append(f"apparent order {p:.3g} outside [{0.5 * p_formal:g}, {2 * p_formal:g}]: the meshes may not be "
                     "in the asymptotic range; the GCI uses the formal order with a factor of safety of 3")
        order, fs = p_formal, 3.0
    rp = r21 ** order
    phi_ext = (rp * p1 - p2) / (rp - 1.0)
    e_a = abs((p1 - p2) / p1)
    e_ext = abs((phi_ext - p1) / phi_ext)
    gci = fs * e_a / (rp - 1.0)
    return RichardsonResult(phi=(p1, p2, p3), cells=(n1, n2, n3), r21=r21, r32=r32,
                            apparent_order=p if p is not None else math.nan, order_used=order, safety_factor=fs,
                            phi_extrapolated=phi_ext, relative_change_fine=e_a, relative_error_extrapolated=e_ext,
                            gci_fine=gci, uncertainty=gci * abs(p1), convergence=convergence, notes=tuple(notes))
