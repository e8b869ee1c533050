"""Lubricant supply of the raceway contacts: how much of Biboulet-Houpert's flooded rolling force
a contact builds, from the lubrication (flooded, oil bath at a level, minimum quantity / oil-air,
oil jet), the speed, the viscosity and the geometry; and the contact / hydraulic boundary g.

Why. Biboulet and Houpert's rolling force (Part 1, Eq. 40-42: kegel's EHL rolling resistance of
every slice) is that of a *fully flooded* contact: their inlet lies about one reduced radius
upstream. A bearing running in a low oil bath or on minimum-quantity lubrication does not fill
that inlet: each overrolling pushes oil out of the track, and at high speed and viscosity the oil
has no time to flow back ("kinematic starvation"). Biboulet and Houpert computed the starved
rolling force by cutting the inlet at a meniscus (Part 1, Section 3.4, Eq. 44)::

    T / T* = (S^2 + 162.8 S) / (S^2 + 193.1 S + 1257),   S = H_a / H*_m  (S >= 2)

with ``H_a`` the gap at the inlet meniscus and ``H*_m`` the flooded (minimum) film; they add that
``H_a`` "can be difficult to evaluate especially in roller bearings. It depends on many
parameters (lubricant supply, etc.)". This module supplies it.

The supply model (no fitted constant). The SKF catalogue friction model (SKF Rolling bearings
catalogue PUB BU/P1 10000 EN, 2013, chapter "Friction"; SKF General Catalogue 6000 EN, 2005,
p. 98, "Kinematic replenishment/starvation reduction factor") reduces the rolling moment of a
bearing by::

    phi_rs = exp(-K_rs nu n (d + D) sqrt(K_Z / (2 (D - d))))

(``nu`` [mm^2/s] at the operating temperature, ``n`` [r/min], ``d``, ``D`` [mm]; ``K_Z = 6`` for
tapered roller bearings) with ``K_rs = 3e-8`` for a low-level oil bath and oil jet lubrication and
``6e-8`` for grease and oil-air lubrication, the oil-bath value for a low-level bath (reprints of
the model set ``phi_rs = 1`` for a submerged bearing: a contact under the oil surface is not
starved). ``phi_rs`` multiplies SKF's rolling
moment, the same quantity as Biboulet-Houpert's ``T / T*``, so each raceway contact gets:

1. its share of the orbit under the oil surface, ``x`` (:func:`immersed_fraction`): a contact
   point at radius ``r`` from the axis and azimuth ``psi`` from the lowest point lies at the height
   ``D/2 - r cos(psi)`` above the lowest point of the outer diameter (kegel's oil-level zero) and
   is immersed below the oil level ``H``: ``x = acos((D/2 - H) / r) / pi`` (0 with no bath, 1
   flooded);
2. the orbit mean of its rolling-force factor, ``f = x + (1 - x) phi_rs`` (immersed: flooded;
   above the oil: SKF's kinematic starvation with the ``K_rs`` of the lubrication method);
3. the inlet ratio whose Eq. 44 factor equals ``f`` (:func:`inlet_gap_ratio_for_factor`), the
   mapping onto Biboulet-Houpert's starved inlet; this ``S`` is what the contact model applies
   (``f = 1``: ``S = 0``, fully flooded; ``f`` below Eq. 44's value at its smallest computed ratio,
   0.2001 at ``S = 2``, is clamped there and flagged).

The ``K_rs`` values and their assignment are those of the catalogue as every secondary source
that reprints it gives them (oil jet with the low-level oil bath at ``3e-8``), one table with the
SKF column (``kegel.correlations.skf.K_RS``, oil jet marked ``verify`` there): the catalogue's own
page (formula images) could not be read, see docs/models.md.

The contact / hydraulic boundary g (``model.contact_film_limit``): the contact model owns the oil
within film height ``g`` of each line contact and a CFD owns the rest, so the contact's rolling
force loses what the film beyond ``g`` carries: Reynolds' far field, ``6 eta0 u_m I(g / R)`` per
unit length (``kegel._core.tribology.rolling_force_beyond_film_N_m``; between ``g`` and the
supply's meniscus when there is one, nothing when the meniscus lies within ``g``), slice by slice
(``mbs_core/src/slice.cpp``; docs/models.md). :func:`kegel.runner.film_limit.contact_loss_at_film_limit` gives the
contact friction of a point at a given ``g`` (the contact half of the CFD gap study).
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Any

from ..base.errors import KegelInputError
from ..correlations.skf import K_RS as SKF_K_RS

__all__ = [
    "K_RS",
    "K_Z_TAPERED_ROLLER",
    "SUPPLY_MODELS",
    "STARVATION_FACTOR_AT_S2",
    "ContactSupply",
    "immersed_fraction",
    "inlet_gap_ratio_for_factor",
    "lubricant_supply",
    "skf_replenishment_factor",
    "starvation_factor",
]

#: SKF's replenishment/starvation constant K_rs by lubrication method (catalogue units).
K_RS: dict[str, float] = {**SKF_K_RS, "minimum_quantity": SKF_K_RS["oil_air"], "grease": SKF_K_RS["oil_air"]}
#: SKF's bearing-type geometry constant K_Z of tapered roller bearings.
K_Z_TAPERED_ROLLER = 6.0
from ..model.options import SUPPLY_MODELS  # noqa: E402  (the scene checks them: kegel.model.options)
_A, _B, _C = 162.8, 193.1, 1257.0   # Biboulet-Houpert Part 1, Eq. 44
#: Eq. 44 at S = 2, the most starved inlet Biboulet and Houpert computed.
STARVATION_FACTOR_AT_S2 = (4.0 + 2.0 * _A) / (4.0 + 2.0 * _B + _C)


def starvation_factor(S: float) -> float:
    """Biboulet and Houpert, Proc. IMechE J 224 (2010) 765, Part 1, Eq. 44: starved over flooded
    rolling force ``(S^2 + 162.8 S) / (S^2 + 193.1 S + 1257)``; ``S <= 0`` is fully flooded (1),
    ``0 < S < 2`` is taken at 2 (their smallest computed ratio), as the C++ core does."""
    if not S > 0.0:
        return 1.0
    s = max(S, 2.0)
    return (s * s + _A * s) / (s * s + _B * s + _C)


def inlet_gap_ratio_for_factor(factor: float) -> tuple[float, bool]:
    """The inlet ratio ``S`` whose Eq. 44 factor is ``factor`` (the positive root of
    ``(1 - f) S^2 + (162.8 - 193.1 f) S - 1257 f = 0``).

    Returns
    -------
    (S, clamped)
        ``S = 0`` (fully flooded) for ``factor >= 1``; ``S = 2`` and ``clamped = True`` for a factor
        below :data:`STARVATION_FACTOR_AT_S2` (outside the range Biboulet and Houpert computed).
    """
    if not (math.isfinite(factor) and factor > 0.0):
        raise KegelInputError("<argument>", "factor", factor, "a rolling-force factor in (0, 1]")
    if factor >= 1.0:
        return 0.0, False
    if factor <= STARVATION_FACTOR_AT_S2:
        return 2.0, factor < STARVATION_FACTOR_AT_S2
    f = factor
    p = _A - _B * f
    S = (-p + math.sqrt(p * p + 4.0 * (1.0 - f) * f * _C)) / (2.0 * (1.0 - f))
    return S, False


def skf_replenishment_factor(*, K_rs: float, kinematic_viscosity_m2_s: float, speed_rpm: float, bore_m: float,
                             outer_diameter_m: float, K_Z: float = K_Z_TAPERED_ROLLER) -> float:
    """SKF's kinematic replenishment/starvation reduction factor of the rolling moment,
    ``phi_rs = exp(-K_rs nu n (d + D) sqrt(K_Z / (2 (D - d))))`` in the catalogue's units
    (``nu`` mm^2/s, ``n`` r/min, ``d``, ``D`` mm), from SI arguments (see the module docstring)."""
    nu = kinematic_viscosity_m2_s * 1e6
    d, D = bore_m * 1e3, outer_diameter_m * 1e3
    for name, v in (("K_rs", K_rs), ("kinematic_viscosity_m2_s", nu), ("bore_m", d), ("K_Z", K_Z)):
        if not (math.isfinite(v) and v > 0.0):
            raise KegelInputError("<argument>", name, v, "a positive finite value")
    if not (math.isfinite(D) and D > d):
        raise KegelInputError("<argument>", "outer_diameter_m", outer_diameter_m, "a diameter > the bore")
    if not math.isfinite(speed_rpm):
        raise KegelInputError("<argument>", "speed_rpm", speed_rpm, "a finite speed")
    return math.exp(-K_rs * nu * abs(speed_rpm) * (d + D) * math.sqrt(K_Z / (2.0 * (D - d))))


def immersed_fraction(oil_level_m: float, outer_diameter_m: float, contact_radius_m: float) -> float:
    """Share of an orbit that a contact point at ``contact_radius_m`` from the bearing axis spends
    below the oil surface, ``acos((D/2 - H) / r) / pi`` clipped to [0, 1]; ``H`` measured from the
    lowest point of the outer diameter (kegel's oil level), the axis horizontal at ``D/2``."""
    if not (0.0 < contact_radius_m < 0.5 * outer_diameter_m):
        raise KegelInputError("<argument>", "contact_radius_m", contact_radius_m,
                              f"a radius in (0, D/2 = {0.5 * outer_diameter_m:g} m)")
    c = (0.5 * outer_diameter_m - oil_level_m) / contact_radius_m
    if c >= 1.0:
        return 0.0
    if c <= -1.0:
        return 1.0
    return math.acos(c) / math.pi


@dataclass(frozen=True)
class ContactSupply:
    """The inlet supply of a bearing's raceway contacts at one operating point.

    ``rolling_force_factor_*`` is the orbit-mean factor on Biboulet-Houpert's flooded rolling force,
    ``inlet_gap_ratio_*`` the Eq. 44 ratio that gives it (0: fully flooded), ``*_clamped`` true where
    SKF's factor lies below Eq. 44's range (applied: 0.2001 at S = 2).
    """

    model: str
    mode: str
    oil_level_m: float
    K_rs: float | None
    phi_rs: float
    immersed_fraction_inner: float
    immersed_fraction_outer: float
    rolling_force_factor_inner: float
    rolling_force_factor_outer: float
    inlet_gap_ratio_inner: float
    inlet_gap_ratio_outer: float
    clamped_inner: bool = False
    clamped_outer: bool = False

    @property
    def flooded(self) -> bool:
        """True when both raceways are fully flooded."""
        return self.inlet_gap_ratio_inner == 0.0 and self.inlet_gap_ratio_outer == 0.0

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready record (written with every point)."""
        return {**asdict(self), "source": "SKF phi_rs (K_rs by method) mapped onto Biboulet-Houpert Part 1 "
                "Eq. 44; kegel.supply"}


def lubricant_supply(geometry: Any, bearing: Any, *, mode: str, oil_level_m: float, speed_rad_s: float,
                     kinematic_viscosity_m2_s: float, model: str = "kinematic_replenishment") -> ContactSupply:
    """The inlet supply of the inner and outer raceway contacts (see the module docstring).

    Parameters
    ----------
    geometry, bearing
        :class:`kegel.geometry.BearingGeometry` (raceway radii at the roller mid) and
        :class:`kegel.data.BearingData` (bore ``d``, outer diameter ``D``).
    mode
        ``"oil_bath"`` (with ``oil_level_m``; at or above ``D``: flooded), ``"minimum_quantity"``
        (oil-air), ``"oil_jet"`` or ``"grease"``.
    oil_level_m
        Oil level above the lowest point of the outer diameter (0 without an oil bath).
    speed_rad_s, kinematic_viscosity_m2_s
        Inner-ring speed (outer ring fixed) and the oil's kinematic viscosity at the operating
        temperature.
    model
        ``"kinematic_replenishment"`` or ``"flooded"`` (every contact fully flooded).
    """
    if model not in SUPPLY_MODELS:
        raise KegelInputError("<argument>", "model", model, f"one of {', '.join(SUPPLY_MODELS)}")
    if mode not in ("oil_bath", "minimum_quantity", "oil_jet", "grease", "oil_air"):
        raise KegelInputError("<argument>", "mode", mode, "oil_bath, minimum_quantity, oil_air, oil_jet or grease")
    D = bearing.outer_diameter_m
    if not (math.isfinite(oil_level_m) and oil_level_m >= 0.0):
        raise KegelInputError("<argument>", "oil_level_m", oil_level_m, "a level >= 0")
    if mode != "oil_bath" and oil_level_m > 0.0:
        raise KegelInputError("<argument>", "oil_level_m", oil_level_m, f"0 (no oil bath) for {mode}")
    flooded_bath = mode == "oil_bath" and oil_level_m >= D
    if model == "flooded" or flooded_bath:
        return ContactSupply(model=model, mode=mode, oil_level_m=oil_level_m, K_rs=None, phi_rs=1.0,
                             immersed_fraction_inner=1.0, immersed_fraction_outer=1.0,
                             rolling_force_factor_inner=1.0, rolling_force_factor_outer=1.0,
                             inlet_gap_ratio_inner=0.0, inlet_gap_ratio_outer=0.0)
    K_rs = K_RS[mode]
    phi = skf_replenishment_factor(K_rs=K_rs, kinematic_viscosity_m2_s=kinematic_viscosity_m2_s,
                                   speed_rpm=speed_rad_s * 30.0 / math.pi, bore_m=bearing.bore_diameter_m,
                                   outer_diameter_m=D)
    out: dict[str, Any] = {}
    for ring, r in (("inner", 0.5 * geometry.inner_raceway_diameter_mid_m),
                    ("outer", 0.5 * geometry.outer_raceway_diameter_mid_m)):
        x = immersed_fraction(oil_level_m, D, r) if mode == "oil_bath" else 0.0
        f = x + (1.0 - x) * phi
        S, clamped = inlet_gap_ratio_for_factor(f)
        out.update({f"immersed_fraction_{ring}": x, f"rolling_force_factor_{ring}": starvation_factor(S),
                    f"inlet_gap_ratio_{ring}": S, f"clamped_{ring}": clamped})
    return ContactSupply(model=model, mode=mode, oil_level_m=oil_level_m, K_rs=K_rs, phi_rs=phi, **out)
