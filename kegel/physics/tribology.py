"""Friction of one roller/raceway contact, slice by slice (seed paper, Section 2.1.3).

The friction laws and the per-slice evaluation live in the C++ core
(``kegel._core.tribology``); this module loads their parameters from the data files and
evaluates a whole roller/raceway contact of a bearing for the ``kegel tribology`` command.

Until the slice contact model lands (issue "Contact mechanics"), the contact load is spread
evenly over the effective roller length and the kinematics are the apex-matched pure rolling of
the bearing with an optional slide-to-roll ratio; the reduced radius and the surface speeds vary
along the contact line with the real geometry.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np

from .. import _core
from ..base._toml import read_toml, require_number, require_str, require_table
from ..model.data import DATA_DIR, BearingData, LubricantData, MaterialData, _resolve
from ..base.errors import KegelInputError
from ..model.geometry import BearingGeometry

T = _core.tribology

__all__ = [
    "ROLLING_THERMAL_MODELS",
    "FrictionData",
    "ContactFriction",
    "available_friction_sets",
    "load_friction",
    "axial_roller_loads",
    "cage_speed_rad_s",
    "evaluate_raceway_contact",
    "raceway_line_point",
    "MAX_CONTACT_PRESSURE_PA",
]


def available_friction_sets() -> list[str]:
    """Names of the friction parameter sets shipped with kegel."""
    return sorted(p.stem for p in (DATA_DIR / "friction").glob("*.toml"))


@dataclass(frozen=True)
class FrictionData:
    """Friction-law parameters of a material/lubricant pair, in SI units."""

    name: str
    source_file: str
    mu_s: float
    mu_d: float
    v_s_m_s: float
    v_d_m_s: float
    c_r: float
    e_r: float
    a_v: float
    d_max_Ns_m: float
    delta_max_m: float
    gold_C1_Pa_K2: float = 0.0
    gold_C2_Pa_K: float = 0.0
    damping_time_s: float = 0.0   # dynamic model: d_max = damping_time x contact stiffness (Eq. 2)
    #: Thermal reduction of the EHL rolling force by inlet shear heating (a model option, set
    #: from a scene's ``model.rolling_thermal``): ``"aihara"`` (default; Aihara 1987,
    #: phi_T = 1/(1 + 0.29 L^0.78)), ``"zhu_cheng"`` (the film factor of Eq. 12, as Zhou and
    #: Hoeprich 1991 apply it to the rolling force) or ``"off"``.
    rolling_thermal: str = "aihara"
    #: Starvation of the raceway contacts' rolling resistance (Biboulet-Houpert Part 1, Eq. 44):
    #: inlet oil gap over the fully flooded film, >= 2; 0 = fully flooded (default). A constant for
    #: both raceways (``model.inlet_gap_ratio``), combined with the supply below: the smaller wins.
    inlet_gap_ratio: float = 0.0
    #: The lubricant supply's inlet ratio of the inner (cone) and outer (cup) raceway contacts
    #: (:func:`kegel.supply.lubricant_supply`, set per operating point); 0 = fully flooded.
    inlet_gap_ratio_inner: float = 0.0
    inlet_gap_ratio_outer: float = 0.0
    #: The contact / hydraulic boundary g [m] (``model.contact_film_limit``): the rolling force is
    #: cut off where the film reaches g (Reynolds' far field beyond g taken off per slice,
    #: docs/models.md); 0 = no cut-off.
    contact_film_limit_m: float = 0.0

    def model_options(self) -> dict[str, Any]:
        """The rolling-resistance model options, as recorded with every result."""
        return {"rolling_thermal": self.rolling_thermal, "inlet_gap_ratio": self.inlet_gap_ratio,
                "contact_film_limit_m": self.contact_film_limit_m}

    def ring_inlet_gap_ratios(self) -> tuple[float, float]:
        """The inlet ratios applied to the inner and outer raceway contacts: for each, the smaller
        (more restrictive) of the constant ``inlet_gap_ratio`` and the supply's, 0 when both are
        flooded."""
        def combine(a: float, b: float) -> float:
            vals = [v for v in (a, b) if v > 0.0]
            return min(vals) if vals else 0.0

        return (combine(self.inlet_gap_ratio, self.inlet_gap_ratio_inner),
                combine(self.inlet_gap_ratio, self.inlet_gap_ratio_outer))

    def core(self, lubricant: LubricantData) -> "_core.tribology.FrictionParameters":
        """Checked C++ parameters, with the limiting shear stress of ``lubricant`` and the
        rolling-resistance options of this object."""
        if self.rolling_thermal not in ROLLING_THERMAL_MODELS:
            raise KegelInputError("<argument>", "rolling_thermal", self.rolling_thermal,
                                  f"one of {', '.join(ROLLING_THERMAL_MODELS)}")
        v = T.FrictionParameterValues()
        v.rolling_thermal = getattr(T.RollingThermal, self.rolling_thermal)
        v.inlet_gap_ratio_inner, v.inlet_gap_ratio_outer = self.ring_inlet_gap_ratios()
        v.contact_film_limit_m = self.contact_film_limit_m
        v.tau_L0_Pa = lubricant.limiting_shear_stress_tau0_Pa
        v.gamma_L = lubricant.limiting_shear_stress_gamma
        for name in ("mu_s", "mu_d", "v_s_m_s", "v_d_m_s", "c_r", "e_r", "a_v", "d_max_Ns_m", "delta_max_m",
                     "gold_C1_Pa_K2", "gold_C2_Pa_K"):
            setattr(v, name, getattr(self, name))
        try:
            return T.FrictionParameters(v)
        except ValueError as exc:
            raise KegelInputError(self.source_file, "(parameters)", "", str(exc)) from None


from ..model.options import ROLLING_THERMAL_MODELS  # noqa: E402  (the scene checks them: kegel.model.options)


@lru_cache(maxsize=16)
def _load_friction_file(path: Path) -> FrictionData:
    raw = read_toml(path)
    sl = require_table(raw, "solid_sliding", path)
    sr = require_table(raw, "solid_rolling", path)
    hy = require_table(raw, "hysteresis", path)
    da = require_table(raw, "damping", path)
    gold = raw.get("compression_heating", {})  # optional: Eq. 9 stays off without it
    data = FrictionData(
        name=require_str(raw, "name", path),
        source_file=str(path),
        mu_s=require_number(sl, "mu_s", path, "solid_sliding.", positive=True),
        mu_d=require_number(sl, "mu_d", path, "solid_sliding.", positive=True),
        v_s_m_s=require_number(sl, "v_s_mm_s", path, "solid_sliding.", positive=True) * 1e-3,
        v_d_m_s=require_number(sl, "v_d_mm_s", path, "solid_sliding.", positive=True) * 1e-3,
        c_r=require_number(sr, "c_r_m", path, "solid_rolling.", nonnegative=True),
        e_r=require_number(sr, "e_r", path, "solid_rolling.", positive=True),
        a_v=require_number(hy, "a_v", path, "hysteresis.", nonnegative=True),
        d_max_Ns_m=require_number(da, "d_max_Ns_m", path, "damping.", nonnegative=True),
        delta_max_m=require_number(da, "delta_max_um", path, "damping.", positive=True) * 1e-6,
        damping_time_s=require_number(da, "damping_time_us", path, "damping.", nonnegative=True) * 1e-6
        if "damping_time_us" in da else 0.0,
        gold_C1_Pa_K2=require_number(gold, "C1_Pa_K2", path, "compression_heating.", positive=True)
        if gold else 0.0,
        gold_C2_Pa_K=require_number(gold, "C2_Pa_K", path, "compression_heating.", positive=True)
        if gold else 0.0,
    )
    if not data.v_d_m_s > data.v_s_m_s:
        raise KegelInputError(path, "solid_sliding.v_d_mm_s", data.v_d_m_s * 1e3, "a value > v_s_mm_s")
    return data


def load_friction(name: str = "steel_mineral_oil", *, source: str | Path = "<argument>",
                  key: str = "friction") -> FrictionData:
    """Load a friction parameter set by name or from a TOML file path."""
    return _load_friction_file(_resolve(str(name), "friction", "friction parameter set", source, key))


def cage_speed_rad_s(g: BearingGeometry, inner_speed_rad_s: float) -> float:
    """Cage speed of apex-matched pure rolling with the outer ring fixed,
    ``omega_c = omega_i d_i / (2 d_m)`` with ``d_i = d_m - D_w cos(beta)``.

    Raises
    ------
    KegelInputError
        ``inner_speed_rad_s`` not a finite number with ``|n| d_m`` within
        :data:`kegel.limits.MAX_SPEED_FACTOR_RPM_MM` (0 is accepted: a ring at rest).
    """
    from ..base.limits import check_speed_factor

    inner_speed_rad_s = check_speed_factor(inner_speed_rad_s, g.pitch_diameter_m, source="<argument>",
                                           key="inner_speed_rad_s", designation=str(g.designation))
    return inner_speed_rad_s * g.pure_rolling_cage_ratio


def axial_roller_loads(g: BearingGeometry, axial_load_N: float) -> dict[str, float]:
    """Roller loads under a pure axial load (no centrifugal force), from the force balance of
    the cup and of one roller in its axial plane.

    The cup carries the axial load through the rollers only: ``Q_o = F_a / (Z sin(alpha_o))``.
    The roller is in equilibrium under the cup, cone and rib forces along their normals, which
    gives ``Q_rib = Q_o sin(alpha_o - alpha_i) / cos(phi_rib - alpha_i)`` and
    ``Q_i = (Q_o cos(alpha_o) + Q_rib sin(phi_rib)) / cos(alpha_i)``, ``phi_rib`` the angle of
    the rib normal to the bearing axis.
    """
    from ..model.scene import operating_range_error  # the scenes' axial-load range

    expected = operating_range_error("axial_load", axial_load_N, g)
    if expected is not None:
        raise KegelInputError("<argument>", "axial_load_N", axial_load_N, expected)
    a_o, a_i = g.cup_angle_rad, g.cone_angle_rad
    phi = g.rib_face_angle_to_radial_plane_rad
    q_o = axial_load_N / (g.roller_count * math.sin(a_o))
    q_rib = q_o * math.sin(a_o - a_i) / math.cos(phi - a_i)
    q_i = (q_o * math.cos(a_o) + q_rib * math.sin(phi)) / math.cos(a_i)
    return {"outer_N": q_o, "inner_N": q_i, "rib_N": q_rib}


@dataclass(frozen=True)
class ContactFriction:
    """A roller/raceway contact evaluated slice by slice.

    ``slices`` holds one dictionary per slice (the C++ ``SliceResult`` fields plus the slice
    position, load and kinematics); ``totals`` the contact sums by mechanism.
    """

    contact: str
    temperature_K: float
    load_N: float
    slices: list[dict[str, float]]
    totals: dict[str, float]

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary (field names carry units)."""
        return {"contact": self.contact, "temperature_K": self.temperature_K, "load_N": self.load_N,
                "totals": self.totals, "slices": self.slices}


_RESULT_FIELDS = (
    "half_width_m", "max_pressure_Pa", "mean_pressure_Pa", "film_isothermal_m", "thermal_factor",
    "film_m", "Lambda", "phi", "contact_temperature_K", "eta_contact_Pas", "tau_L_Pa", "tau_ehl_Pa", "mu_solid",
    "sliding_speed_m_s", "entrainment_speed_m_s", "F_ehl_rolling_N", "rolling_starvation_factor",
    "inlet_gap_ratio", "M_solid_rolling_Nm",
    "M_hysteresis_Nm", "P_ehl_sliding_W", "P_solid_sliding_W",
)


#: The largest Hertz pressure kegel accepts at a roller/raceway contact: ISO 76's static limit for
#: roller bearings (4000 MPa, the basis of C0r); beyond it the steel yields and the elastic models fail.
MAX_CONTACT_PRESSURE_PA = 4.0e9


def raceway_line_point(g: BearingGeometry, xi_m: float, contact: str) -> tuple[float, float]:
    """Reduced radius ``R'`` [m] in the rolling direction and ring radius [m] of a raceway line
    contact at ``xi_m`` along the roller axis from its mid-point (apex-matched nominal geometry;
    ``contact`` ``"inner"`` or ``"outer"``)."""
    beta, gamma = g.roller_axis_angle_rad, g.roller_half_angle_rad
    side = -1.0 if contact == "inner" else 1.0
    rho = 0.5 * g.roller_mean_diameter_m + xi_m * math.tan(gamma)
    r_ring = 0.5 * g.pitch_diameter_m + xi_m * math.sin(beta) + side * rho * math.cos(beta)
    R_roller = rho / math.cos(gamma)
    R_ring = r_ring / math.cos(g.cone_angle_rad if contact == "inner" else g.cup_angle_rad)
    R = R_roller * R_ring / (R_ring + R_roller) if contact == "inner" else R_roller * R_ring / (R_ring - R_roller)
    return R, r_ring


def evaluate_raceway_contact(
    g: BearingGeometry,
    bearing: BearingData,
    material: MaterialData,
    lubricant: LubricantData,
    friction: FrictionData,
    *,
    temperature_K: float,
    load_N: float,
    shaft_speed_rad_s: float,
    contact: str = "inner",
    slices: int = 30,
    slide_to_roll: float = 0.0,
) -> ContactFriction:
    """Evaluate every friction mechanism of one roller/raceway contact, slice by slice.

    Parameters
    ----------
    g, bearing, material, lubricant, friction
        Derived geometry and the data it came from; lubricant and friction parameter sets.
    temperature_K
        Bulk oil temperature.
    load_N
        Normal load of the contact, spread evenly over the effective roller length.
    shaft_speed_rad_s
        Inner-ring speed (outer ring fixed).
    contact
        ``"inner"`` or ``"outer"`` raceway.
    slices
        Number of slices.
    slide_to_roll
        ``(u_ring - u_roller) / u_mean`` imposed on every slice (0 = pure rolling).

    Returns
    -------
    ContactFriction
        Per-slice results and contact totals: sliding forces (x along rolling), rolling force,
        rolling moments, and the dissipated power of each mechanism. Rolling losses:
        ``P = (M_hysteresis + M_solid_rolling) u_av / R'`` (Johnson's moment acts on both
        bodies, each turning at u/R_k) and ``P = F_ehl_rolling (u_1 + u_2)`` (Biboulet and
        Houpert's force acts on each surface).
    """
    if contact not in ("inner", "outer"):
        raise KegelInputError("<argument>", "contact", contact, "'inner' or 'outer'")
    if not (isinstance(slices, int) and 1 <= slices <= 1000):
        raise KegelInputError("<argument>", "slices", slices, "an integer in [1, 1000]")
    if not (math.isfinite(load_N) and load_N > 0):
        raise KegelInputError("<argument>", "load", load_N, "a positive contact load in N")
    if not (math.isfinite(slide_to_roll) and abs(slide_to_roll) < 2.0):
        raise KegelInputError("<argument>", "slide_to_roll", slide_to_roll, "a value in (-2, 2)")
    # the ranges of every other entry point (scene files, kegel tribology): the lubricant's
    # temperature range and formulas, the speed limit n d_m, and (below) the Hertz pressure
    from ..model.lubricant import lubricant_state
    from ..model.scene import check_speed

    lubricant_state(lubricant, temperature_K, key="temperature_K")
    check_speed(shaft_speed_rad_s, bearing, source="<argument>", key="shaft_speed_rad_s")

    steel = material.core
    E = _core.reduced_modulus_Pa(steel, steel)
    # the paper gives one raceway roughness for both rings
    pair = T.SurfacePair(bearing.sigma_raceway_m, bearing.zhou_hoeprich_raceway_B,
                         bearing.zhou_hoeprich_raceway_C, E)
    state = T.make_contact_lubricant_state(lubricant.core, temperature_K)
    fp = friction.core(lubricant)

    L_eff = g.roller_effective_length_m
    omega_c = cage_speed_rad_s(g, shaft_speed_rad_s)
    omega_ring = shaft_speed_rad_s - omega_c if contact == "inner" else -omega_c  # in the cage frame
    width = L_eff / slices / math.cos(g.roller_half_angle_rad)  # along the roller generator

    rows: list[dict[str, float]] = []
    tot = dict.fromkeys(
        ("F_ehl_sliding_x_N", "F_solid_sliding_x_N", "F_ehl_rolling_N", "M_solid_rolling_Nm", "M_hysteresis_Nm",
         "P_ehl_sliding_W", "P_solid_sliding_W", "P_ehl_rolling_W", "P_solid_rolling_W", "P_hysteresis_W"), 0.0)
    for xi in (np.arange(slices) + 0.5) / slices * L_eff - 0.5 * L_eff:
        R, r_ring = raceway_line_point(g, float(xi), contact)
        u_mean = abs(omega_ring) * r_ring
        s = T.SliceInput()
        s.load_N = load_N / slices
        s.width_m = width
        s.reduced_radius_m = R
        s.u2_x_m_s = u_mean * (1.0 + 0.5 * slide_to_roll)  # ring
        s.u1_x_m_s = u_mean * (1.0 - 0.5 * slide_to_roll)  # roller
        s.outer_ring = contact == "outer"  # its raceway's inlet supply
        r = T.evaluate_slice(s, pair, state, fp)
        row = {"xi_m": float(xi), "load_N": s.load_N, "width_m": width, "reduced_radius_m": float(R),
               "u_roller_m_s": s.u1_x_m_s, "u_ring_m_s": s.u2_x_m_s}
        row.update({k: float(getattr(r, k)) for k in _RESULT_FIELDS})
        row["F_ehl_sliding_x_N"] = r.F_ehl_sliding_N[0]
        row["F_solid_sliding_x_N"] = r.F_solid_sliding_N[0]
        u_av = r.entrainment_speed_m_s
        row["P_ehl_rolling_W"] = r.F_ehl_rolling_N * (s.u1_x_m_s + s.u2_x_m_s)
        row["P_solid_rolling_W"] = float(r.M_solid_rolling_Nm * u_av / R)
        row["P_hysteresis_W"] = float(r.M_hysteresis_Nm * u_av / R)
        for k in tot:
            tot[k] += row[k]
        rows.append(row)
    tot["P_total_W"] = sum(tot[k] for k in tot if k.startswith("P_"))
    for k in ("film_m", "Lambda", "phi", "max_pressure_Pa"):
        vals = [row[k] for row in rows]
        tot[f"{k}_min"] = min(vals)
        tot[f"{k}_max"] = max(vals)
    tot["cage_speed_rpm"] = omega_c * 60 / (2 * math.pi)
    if not tot["max_pressure_Pa_max"] <= MAX_CONTACT_PRESSURE_PA:
        raise KegelInputError("<argument>", "load_N", load_N,
                              f"a load whose Hertz pressure stays within {MAX_CONTACT_PRESSURE_PA / 1e6:.0f} MPa "
                              f"(ISO 76's static limit for roller bearings; here p0 = "
                              f"{tot['max_pressure_Pa_max'] / 1e6:.0f} MPa)")
    return ContactFriction(contact=contact, temperature_K=temperature_K, load_N=load_N, slices=rows, totals=tot)
