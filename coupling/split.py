"""The contact / CFD split along the raceway lines: what the CFD counts that the contact model
does not (docs/cfd.md, "The contact / CFD split: a gap study").

At a film limit g (``model.contact_film_limit``) the contact model hands the CFD the oil beyond
film g of every *loaded* slice: its rolling force loses the far-field force of Reynolds' equation
beyond g (:func:`kegel._core.tribology.rolling_force_beyond_film_N_m`). The CFD's rollers are
straight (no crown) and stand g off the raceways along the *whole* line, so the CFD counts the
same far field on the unloaded stretch of each line too (the crowned ends beside the loaded
zone, about half the line of the 32208 at 1 kN). There the contact model counts no rolling
resistance at all, within g or beyond: a slice without load has no film in kegel's slice model
(Zhou-Hoeprich's and Aihara's whole-length formulas credit it, Biboulet-Houpert Part 2 puts a
quarter of a point contact's rolling moment outside the Hertz zone). The CFD's share on that
stretch grows as 1/sqrt(g), and contact + CFD with it.

:func:`unloaded_line_wedge` is that share, the far field beyond g over the unloaded stretch,
so that ``contact(g) + CFD(g) - wedge(g)`` keeps kegel's contact convention (no rolling
resistance off the loaded stretch) on both sides of the boundary and no longer depends on g.
What the convention leaves out, the hydrodynamic rolling resistance of the nearly touching
crowned ends, is a term of its own (docs/cfd.md, "Open").
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Any

import numpy as np

from ..base.errors import KegelInputError
from ..model.geometry import BearingGeometry

__all__ = ["UnloadedLineWedge", "unloaded_line_wedge"]


@dataclass(frozen=True)
class UnloadedLineWedge:
    """The CFD's far field beyond g on the unloaded stretch of the raceway lines.

    Attributes
    ----------
    torque_Nm
        Its loss torque at the shaft (the dissipation over the shaft speed).
    inner_Nm, outer_Nm
        The inner (cone) and outer (cup) raceways' parts.
    unloaded_fraction_inner, unloaded_fraction_outer
        The unloaded share of the line contacts' length, over all rollers.
    film_limit_m
        g [m].
    """

    torque_Nm: float
    inner_Nm: float
    outer_Nm: float
    unloaded_fraction_inner: float
    unloaded_fraction_outer: float
    film_limit_m: float

    def as_dict(self) -> dict[str, Any]:
        return asdict(self)


def unloaded_line_wedge(g: BearingGeometry, *, viscosity_Pas: float, inner_speed_rad_s: float,
                        loaded_length_m: np.ndarray, film_limit_m: float) -> UnloadedLineWedge:
    """The CFD's far field beyond the film limit g over the unloaded stretch of every raceway
    line: what contact(g) + CFD(g) counts that the contact model's convention does not.

    Per unit length and surface the far field is ``f = 6 eta0 u_m I(g / R)``
    (:func:`kegel._core.tribology.rolling_force_beyond_film_N_m`), its dissipation ``2 f u_m``.
    Each roller's unloaded length (the roller length less ``loaded_length_m``) is taken half at
    each end, with ``R`` and ``u_m`` of pure rolling at the middle of each half.

    Parameters
    ----------
    g
        The bearing's derived geometry.
    viscosity_Pas
        The oil's dynamic viscosity at the bulk temperature (ambient pressure).
    inner_speed_rad_s
        Inner-ring speed (outer ring fixed).
    loaded_length_m
        Loaded length of each roller's line contacts, shape ``(Z, 2)``, columns (inner, outer)
        (:attr:`kegel.solutions.quasi_static.LoadDistribution.loaded_length_m`).
    film_limit_m
        g [m] (> 0).

    Raises
    ------
    KegelInputError
        A non-positive g, viscosity or speed, or loaded lengths outside ``[0, roller length]``.
    """
    from .. import _core
    from ..physics.tribology import cage_speed_rad_s, raceway_line_point

    for key, v in (("film_limit_m", film_limit_m), ("viscosity_Pas", viscosity_Pas)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise KegelInputError("<argument>", key, v, "a positive finite number")
    if not (math.isfinite(inner_speed_rad_s) and inner_speed_rad_s > 0):
        raise KegelInputError("<argument>", "inner_speed_rad_s", inner_speed_rad_s, "a positive speed in rad/s")
    L = g.roller_length_m
    ll = np.asarray(loaded_length_m, dtype=float)
    if ll.ndim != 2 or ll.shape[1] != 2:
        raise KegelInputError("<argument>", "loaded_length_m", f"an array of shape {ll.shape}",
                              "an array of shape (rollers, 2): the inner and outer loaded lengths")
    bad = ~(np.isfinite(ll) & (ll >= 0) & (ll <= L * (1 + 1e-9)))
    if bad.any():
        k, c = np.argwhere(bad)[0]
        raise KegelInputError("<argument>", f"loaded_length_m[{k}, {c}]", float(ll[k, c]),
                              f"a length in [0, {L:g} m] (the roller length)")
    wc = cage_speed_rad_s(g, inner_speed_rad_s)
    far = _core.tribology.rolling_force_beyond_film_N_m
    parts: dict[str, float] = {}
    fractions: dict[str, float] = {}
    for col, contact in enumerate(("inner", "outer")):
        omega_ring = inner_speed_rad_s - wc if contact == "inner" else -wc
        P = 0.0
        for loaded in ll[:, col]:
            unloaded = max(L - loaded, 0.0)
            if unloaded == 0.0:
                continue
            xi = 0.5 * L - 0.25 * unloaded  # the middle of each end's unloaded half
            for s in (-1.0, 1.0):
                R, r_ring = raceway_line_point(g, s * xi, contact)
                u = abs(omega_ring) * r_ring  # pure rolling, the cage frame
                P += 2.0 * far(viscosity_Pas, u, R, film_limit_m) * u * 0.5 * unloaded
        parts[contact] = P / inner_speed_rad_s
        fractions[contact] = float(1.0 - ll[:, col].sum() / (L * len(ll)))
    return UnloadedLineWedge(torque_Nm=parts["inner"] + parts["outer"], inner_Nm=parts["inner"],
                             outer_Nm=parts["outer"], unloaded_fraction_inner=fractions["inner"],
                             unloaded_fraction_outer=fractions["outer"], film_limit_m=float(film_limit_m))
