"""The SKF catalogue model of the frictional moment, for tapered roller bearings.

Source: SKF Rolling bearings catalogue, PUB BU/P1 10000 EN (2013 and later editions), chapter
"Friction" ("the SKF model for calculating the frictional moment"); the drag term also in the
older form of the SKF General Catalogue 6000 EN (2005). The data below were gathered for kegel in
``shared/reference/skf_friction_model.toml``; the catalogue writes every equation in its own units
(moments in N mm, lengths in mm, speeds in r/min, viscosity in mm^2/s, forces in N). This module
evaluates the equations in those units internally and converts at its boundary: every public
function takes SI values (m, N, rad/s, m^2/s) under names that carry the unit and returns N m.

The model (catalogue units)::

    M      = M_rr + M_sl + M_drag                       (no seals: open bearing)
    M_rr   = phi_ish phi_rs G_rr (nu n)^0.6,   G_rr = R1 d_m^2.38 (F_r + R2 Y F_a)^0.31
    phi_ish = 1 / (1 + 1.84e-9 (n d_m)^1.28 nu^0.64)                   inlet shear heating
    phi_rs  = exp(-K_rs nu n (d + D) sqrt(K_Z / (2 (D - d))))          kinematic replenishment
    M_sl   = G_sl mu_sl,   G_sl = S1 d_m^0.82 (F_r + S2 Y F_a)
    mu_sl  = phi_bl mu_bl + (1 - phi_bl) mu_EHL,   phi_bl = exp(-2.6e-8 (n nu)^1.4 d_m)
    M_drag = 4 V_M K_roll C_w B d_m^4 n^2
             + 1.093e-7 n^2 d_m^3 (n d_m^2 f_t / nu)^-1.379 R_s          (2013 edition)
    M_drag = 10 V_M K_roll B d_m^4 n^2                                   (2005 edition)

with ``d_m = 0.5 (d + D)`` (the catalogue's mean diameter, not the roller pitch diameter),
``K_roll = K_L K_Z (d + D) / (D - d) 1e-12``, ``C_w = 2.789e-10 l_D^3 - 2.786e-4 l_D^2 +
0.0195 l_D + 0.6439`` with ``l_D = 5 K_L B / d_m``, ``f_t = sin(t/2)`` for ``t <= pi`` and 1
above, ``R_s = 0.36 d_m^2 (t - sin t) f_A``, ``f_A = 0.05 K_Z (D + d) / (D - d)``,
``t = 2 acos((0.6 d_m - H) / (0.6 d_m))``, and the drag loss variable ``V_M`` interpolated in
the table of ``H / d_m`` (:data:`V_M_TABLE`). Tapered roller bearings: ``K_Z = 6``,
``K_L = 0.7``, ``mu_bl = 0.15``, ``mu_EHL = 0.002``; series 322: ``R1 = 2.27e-6``,
``R2 = 10.9``, ``S1 = 0.018``, ``S2 = 2``. ``K_rs = 3e-8`` for a low-level oil bath and oil jet,
``6e-8`` for grease and oil-air (as every reprint of the catalogue groups them; the project's
reference file groups oil jet with oil-air, see below).

Bearing data: ``d`` (bore), ``D`` (outer diameter), ``B`` (the cone width of the catalogue
table, ``catalogue.cone_width_B_mm``) and ``Y`` (``catalogue.axial_load_factor_Y``) come from
kegel's bearing data files (:func:`kegel.load_bearing`); the series constants from the
designation (``"32208"`` -> series ``"322"``).

Oil level. kegel measures the oil level from the lowest point of the bearing's outer diameter
(``oil_level_m`` in [0, D], as ``kegel losses``, the scenes and :mod:`.liebrecht` do); the
catalogue's ``H`` is measured from the lowest point of the circle of radius ``0.6 d_m`` about the
bearing axis. With the axis at ``D/2`` above kegel's zero::

    H = oil_level_m - D/2 + 0.6 d_m          (:func:`skf_oil_level_H_m`)

so ``H = 0.6 d_m`` is oil to the shaft centre, ``H <= 0`` gives no drag, and the bearing is
flooded at ``H >= 1.2 d_m`` (``V_M`` and ``t`` then take their values at ``1.2 d_m``, the
catalogue's rule). A kegel level at or above ``D`` (``flooded``) is flooded also for a bearing
whose ``D/2 < 0.6 d_m``. Below the table's first node (``H/d_m = 0.01``) ``V_M`` is
interpolated linearly to ``V_M = 0`` at ``H = 0``.

Values still to be checked (``verify``): the tapered-roller drag constants ``K_Z``, ``K_L``
(one of three secondary sources writes ``l_D = 5 B / d_m`` without ``K_L``) and the series
constants ``R1, R2, S1, S2`` were seen only in secondary sources that cite the catalogue, not in
the catalogue's own tables; the ``V_M`` table is a digitisation of the catalogue's diagram (two
digitisations agree within 1-5 %; the catalogue's zoomed and full diagrams differ by about 10 %
between 0.15 and 0.20); oil-jet lubrication takes ``K_rs = 3e-8`` with the low-level oil bath, as
every reprint of the catalogue found gives it (``../shared/reference/skf_friction_model.toml``
groups oil jet with oil-air at 6e-8; the catalogue's own page, whose formulas are images, could
not be read). ``B`` is taken as the cone width; the total width ``T``
would be the other reading for a tapered roller bearing. :data:`VERIFY` lists them, and
:class:`SkfFriction` carries the flag.

Reference figures (tests/python/test_skf.py): 32216, F_a = 6 kN, F_r = 0, FVA 3 at 50 degC
(nu = 60.59 mm^2/s), oil bath: M_rr + M_sl = 2.605 / 4.546 / 4.749 N m at 500 / 2000 / 4000 rpm;
kegel's quasi-static contact friction of the same point (benchmarks/results/
dynamic_vs_quasi_static.json) is 0.052 / 0.091 / 0.151 N m, 30-50 times less. 32208, 2000 rpm:
drag 127.5 N mm flooded, 66.4 N mm at H = 0.6 d_m, 11.0 N mm at H = 0.1 d_m (oil to the centre
of the lowest roller); the 2005 form gives 216.6 N mm flooded.

The moments are magnitudes that oppose the rotation; pass the magnitude of the speed.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Any

from ..model.data import BearingData
from ..base.errors import KegelInputError
from ..base.limits import check_kinematic_viscosity, check_speed_factor

__all__ = [
    "DRAG_EDITIONS",
    "K_RS",
    "MU_BL",
    "MU_EHL",
    "SERIES_CONSTANTS",
    "SkfBearing",
    "SkfDrag",
    "SkfFriction",
    "TAPERED_ROLLER_DRAG",
    "VERIFY",
    "V_M_TABLE",
    "drag_loss_variable",
    "skf_bearing",
    "skf_drag_moment",
    "skf_friction",
    "skf_oil_level_H_m",
    "skf_rolling_moment",
    "skf_sliding_moment",
]

#: The two catalogue editions whose drag equations are implemented.
DRAG_EDITIONS: dict[str, str] = {
    "2013": "SKF Rolling bearings, PUB BU/P1 10000 EN (2013 and later): "
            "4 V_M K_roll C_w B d_m^4 n^2 + 1.093e-7 n^2 d_m^3 (n d_m^2 f_t / nu)^-1.379 R_s",
    "2005": "SKF General Catalogue 6000 EN (2005): 10 V_M K_roll B d_m^4 n^2",
}

#: Drag constants of tapered roller bearings (K_Z bearing type, K_L roller bearing type).
TAPERED_ROLLER_DRAG: dict[str, float] = {"K_Z": 6.0, "K_L": 0.7}

#: Geometry constants of the rolling and sliding moments, by series.
SERIES_CONSTANTS: dict[str, dict[str, float]] = {
    "322": {"R1": 2.27e-6, "R2": 10.9, "S1": 0.018, "S2": 2.0},
}

#: Sliding friction coefficients of tapered roller bearings with mineral oil.
MU_BL = 0.15
MU_EHL = 0.002

#: Replenishment constant K_rs by lubrication method.
K_RS: dict[str, float] = {"oil_bath": 3e-8, "oil_jet": 3e-8, "oil_air": 6e-8}

#: Values seen only in secondary sources or read from a diagram, to be confirmed against the
#: catalogue's own tables (``verify = true`` in the reference data).
VERIFY: dict[str, bool] = {
    "K_Z": True,
    "K_L": True,
    "R1": True,
    "R2": True,
    "S1": True,
    "S2": True,
    "V_M_TABLE": True,
    "K_RS_oil_jet": True,
}

#: Drag loss variable V_M of roller bearings against H / d_m (digitised from the catalogue's
#: diagram; up to 0.175 from its zoomed diagram, above from the full one).
V_M_TABLE: tuple[tuple[float, float], ...] = tuple(zip(
    (0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09, 0.10, 0.11, 0.12, 0.13, 0.14,
     0.15, 0.16, 0.17, 0.175, 0.20, 0.25, 0.30, 0.35, 0.40, 0.50, 0.60, 0.70, 0.80, 0.90,
     1.00, 1.10, 1.15, 1.20),
    (5.4e-6, 1.24e-5, 2.03e-5, 2.92e-5, 4.00e-5, 5.22e-5, 6.62e-5, 8.18e-5, 9.91e-5, 1.169e-4,
     1.363e-4, 1.583e-4, 1.821e-4, 2.066e-4, 2.312e-4, 2.562e-4, 2.811e-4, 2.932e-4, 3.17e-4,
     3.97e-4, 4.59e-4, 5.20e-4, 5.78e-4, 6.87e-4, 7.86e-4, 8.89e-4, 9.86e-4, 1.093e-3, 1.202e-3,
     1.314e-3, 1.375e-3, 1.442e-3),
))

#: H / d_m at and above which the bearing is flooded.
FLOODED_H_OVER_DM = 1.2

_SOURCE = "kegel.correlations.skf"
_MM = 1e3          # m -> mm
_NU_MM2_S = 1e6    # m^2/s -> mm^2/s
_RPM = 30.0 / math.pi  # rad/s -> r/min
_NM = 1e-3         # N mm -> N m


def _require(name: str, value: float, unit: str, *, positive: bool = False) -> float:
    """A finite value >= 0 (or > 0), else a KegelInputError naming the argument."""
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise KegelInputError(_SOURCE, name, value, f"a number in {unit}") from None
    if not math.isfinite(x) or x < 0.0 or (positive and x == 0.0):
        raise KegelInputError(_SOURCE, name, value, f"a finite value {'> 0' if positive else '>= 0'} in {unit}")
    return x


def _choice(name: str, value: str, allowed: dict[str, Any]) -> str:
    if value not in allowed:
        raise KegelInputError(_SOURCE, name, value, f"one of {', '.join(allowed)}")
    return value


@dataclass(frozen=True)
class SkfBearing:
    """Catalogue data of a tapered roller bearing for the SKF model, in SI units.

    Attributes
    ----------
    designation
        Bearing designation.
    bore_diameter_m, outer_diameter_m
        ``d`` and ``D``.
    width_m
        ``B``, the cone (inner ring) width of the catalogue table.
    axial_load_factor_Y
        ``Y`` of the catalogue table (needed by the rolling and sliding moments only).
    R1, R2, S1, S2
        Geometry constants of the rolling and sliding moments (catalogue units; not needed by
        the drag moment).
    K_Z, K_L
        Bearing-type constants of the drag moment.
    """

    designation: str
    bore_diameter_m: float
    outer_diameter_m: float
    width_m: float
    axial_load_factor_Y: float | None = None
    R1: float | None = None
    R2: float | None = None
    S1: float | None = None
    S2: float | None = None
    K_Z: float = TAPERED_ROLLER_DRAG["K_Z"]
    K_L: float = TAPERED_ROLLER_DRAG["K_L"]

    def __post_init__(self) -> None:
        for name, unit in (("bore_diameter_m", "m"), ("outer_diameter_m", "m"), ("width_m", "m"),
                           ("axial_load_factor_Y", "1"), ("R1", "catalogue units"), ("R2", "1"),
                           ("S1", "catalogue units"), ("S2", "1"), ("K_Z", "1"), ("K_L", "1")):
            if getattr(self, name) is not None:
                _require(name, getattr(self, name), unit, positive=True)
        if not self.outer_diameter_m > self.bore_diameter_m:
            raise KegelInputError(_SOURCE, "outer_diameter_m", self.outer_diameter_m,
                                  f"D > d = {self.bore_diameter_m} m")

    @property
    def mean_diameter_m(self) -> float:
        """The catalogue's mean diameter ``d_m = 0.5 (d + D)``."""
        return 0.5 * (self.bore_diameter_m + self.outer_diameter_m)


def skf_bearing(data: BearingData, *, series: str | None = None) -> SkfBearing:
    """The SKF model's data of a bearing from kegel's bearing data.

    Parameters
    ----------
    data
        Bearing data (:func:`kegel.load_bearing`): ``d``, ``D``, ``B`` (cone width) and ``Y``.
    series
        Dimension series for ``R1, R2, S1, S2``; default: the first three characters of the
        designation (``"32208"`` -> ``"322"``).

    Raises
    ------
    KegelInputError
        A series without constants in :data:`SERIES_CONSTANTS`.
    """
    key = series if series is not None else str(data.designation)[:3]
    if key not in SERIES_CONSTANTS:
        raise KegelInputError(_SOURCE, "series", key,
                              f"a series with SKF constants ({', '.join(SERIES_CONSTANTS)}); "
                              f"bearing {data.designation}")
    c = SERIES_CONSTANTS[key]
    return SkfBearing(designation=str(data.designation), bore_diameter_m=data.bore_diameter_m,
                      outer_diameter_m=data.outer_diameter_m, width_m=data.cone_width_m,
                      axial_load_factor_Y=data.axial_load_factor_Y, **c)


def drag_loss_variable(H_over_dm: float) -> float:
    """Drag loss variable ``V_M`` of roller bearings at the oil level ``H / d_m``.

    Linear interpolation in :data:`V_M_TABLE`; ``V_M = 0`` at ``H <= 0`` (linear from there to
    the first node at 0.01); above ``1.2`` the value at ``1.2`` (the catalogue's rule).

    Raises
    ------
    KegelInputError
        NaN.
    """
    x = float(H_over_dm)
    if math.isnan(x):
        raise KegelInputError(_SOURCE, "H_over_dm", H_over_dm, "a number (H / d_m)")
    if x <= 0.0:
        return 0.0
    if x >= FLOODED_H_OVER_DM:
        return V_M_TABLE[-1][1]
    x0, y0 = 0.0, 0.0
    for x1, y1 in V_M_TABLE:
        if x <= x1:
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
        x0, y0 = x1, y1
    return V_M_TABLE[-1][1]  # pragma: no cover - x < 1.2 always finds a node


def skf_oil_level_H_m(oil_level_m: float, outer_diameter_m: float, mean_diameter_m: float) -> float:
    """The catalogue's oil level ``H`` from kegel's oil level.

    Parameters
    ----------
    oil_level_m
        Oil surface above the lowest point of the bearing's outer diameter (kegel's convention).
    outer_diameter_m
        ``D``.
    mean_diameter_m
        ``d_m = 0.5 (d + D)``.

    Returns
    -------
    float
        ``H = oil_level_m - D/2 + 0.6 d_m``, measured from the lowest point of the circle of
        radius ``0.6 d_m`` (may be negative: no drag); a level at or above ``D`` (flooded) gives
        at least ``1.2 d_m``.
    """
    h = float(oil_level_m)
    if math.isnan(h):
        raise KegelInputError(_SOURCE, "oil_level_m", oil_level_m, "a number in m")
    D = _require("outer_diameter_m", outer_diameter_m, "m", positive=True)
    dm = _require("mean_diameter_m", mean_diameter_m, "m", positive=True)
    H = h - 0.5 * D + 0.6 * dm
    if h >= D:
        H = max(H, FLOODED_H_OVER_DM * dm)
    return H


def _load_constants(b: SkfBearing) -> None:
    for name in ("axial_load_factor_Y", "R1", "R2", "S1", "S2"):
        if getattr(b, name) is None:
            raise KegelInputError(_SOURCE, name, None,
                                  f"a value for bearing {b.designation}: the rolling and sliding moments need Y and "
                                  "the series constants R1, R2, S1, S2 (use skf_bearing)")


def _rolling(b: SkfBearing, n: float, nu: float, Fa: float, Fr: float, K_rs: float) -> tuple[float, float, float]:
    """(M_rr [N mm], phi_ish, phi_rs) in catalogue units."""
    d, D = b.bore_diameter_m * _MM, b.outer_diameter_m * _MM
    dm = 0.5 * (d + D)
    G_rr = b.R1 * dm**2.38 * (Fr + b.R2 * b.axial_load_factor_Y * Fa) ** 0.31
    phi_ish = 1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    phi_rs = math.exp(-K_rs * nu * n * (d + D) * math.sqrt(b.K_Z / (2.0 * (D - d))))
    return phi_ish * phi_rs * G_rr * (nu * n) ** 0.6, phi_ish, phi_rs


def _sliding(b: SkfBearing, n: float, nu: float, Fa: float, Fr: float) -> tuple[float, float, float]:
    """(M_sl [N mm], phi_bl, mu_sl) in catalogue units."""
    dm = 0.5 * (b.bore_diameter_m + b.outer_diameter_m) * _MM
    G_sl = b.S1 * dm**0.82 * (Fr + b.S2 * b.axial_load_factor_Y * Fa)
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    mu_sl = phi_bl * MU_BL + (1.0 - phi_bl) * MU_EHL
    return G_sl * mu_sl, phi_bl, mu_sl


@dataclass(frozen=True)
class SkfDrag:
    """Drag moment of the SKF model and its parts.

    Attributes
    ----------
    drag_Nm
        The drag moment.
    first_term_Nm, second_term_Nm
        ``4 V_M K_roll C_w B d_m^4 n^2`` (2005: ``10 V_M K_roll B d_m^4 n^2``) and the ``R_s``
        term (0 for the 2005 edition).
    V_M
        Drag loss variable used.
    C_w
        Width factor of the bearing (used by the 2013 form only).
    oil_level_H_m
        ``H`` as given (before the flooded clamp); None without an oil bath.
    flooded
        ``H >= 1.2 d_m``.
    edition
        ``"2013"`` or ``"2005"``.
    """

    drag_Nm: float
    first_term_Nm: float
    second_term_Nm: float
    V_M: float
    C_w: float
    oil_level_H_m: float | None
    flooded: bool
    edition: str


def _width_factor(b: SkfBearing) -> float:
    """``C_w`` of the 2013 drag equation (catalogue units)."""
    l_D = 5.0 * b.K_L * b.width_m / b.mean_diameter_m
    return 2.789e-10 * l_D**3 - 2.786e-4 * l_D**2 + 0.0195 * l_D + 0.6439


def _drag(b: SkfBearing, n: float, nu: float, H_m: float, edition: str) -> SkfDrag:
    d, D, B = b.bore_diameter_m * _MM, b.outer_diameter_m * _MM, b.width_m * _MM
    dm = 0.5 * (d + D)
    H = min(H_m * _MM, FLOODED_H_OVER_DM * dm)
    flooded = H_m * _MM >= FLOODED_H_OVER_DM * dm
    C_w = _width_factor(b)
    V_M = drag_loss_variable(H / dm)
    if H <= 0.0 or n == 0.0:
        return SkfDrag(0.0, 0.0, 0.0, V_M, C_w, H_m, flooded, edition)
    K_roll = b.K_L * b.K_Z * (d + D) / (D - d) * 1e-12
    if edition == "2005":
        first = 10.0 * V_M * K_roll * B * dm**4 * n**2
        return SkfDrag(first * _NM, first * _NM, 0.0, V_M, C_w, H_m, flooded, edition)
    first = 4.0 * V_M * K_roll * C_w * B * dm**4 * n**2
    c = (0.6 * dm - H) / (0.6 * dm)
    t = 2.0 * math.acos(max(-1.0, min(1.0, c)))
    f_t = math.sin(0.5 * t) if t <= math.pi else 1.0
    f_A = 0.05 * b.K_Z * (D + d) / (D - d)
    R_s = 0.36 * dm**2 * (t - math.sin(t)) * f_A
    second = 1.093e-7 * n**2 * dm**3 * (n * dm**2 * f_t / nu) ** -1.379 * R_s
    return SkfDrag((first + second) * _NM, first * _NM, second * _NM, V_M, C_w, H_m, flooded, edition)


def skf_drag_moment(bearing: SkfBearing, *, speed_rad_s: float, kinematic_viscosity_m2_s: float,
                    oil_level_m: float | None = None, oil_level_H_m: float | None = None,
                    edition: str = "2013") -> SkfDrag:
    """Drag moment of the SKF model in an oil bath.

    Parameters
    ----------
    bearing
        :func:`skf_bearing`.
    speed_rad_s
        Magnitude of the rotational speed.
    kinematic_viscosity_m2_s
        Kinematic viscosity of the oil at the operating temperature (> 0).
    oil_level_m
        Oil level above the lowest point of the outer diameter (kegel's convention), converted
        by :func:`skf_oil_level_H_m`; give this or ``oil_level_H_m``.
    oil_level_H_m
        The catalogue's ``H`` directly (from the lowest point of the circle of radius 0.6 d_m).
    edition
        ``"2013"`` (default) or ``"2005"``, see :data:`DRAG_EDITIONS`.

    Returns
    -------
    SkfDrag

    Raises
    ------
    KegelInputError
        A negative or NaN speed or oil level, a viscosity <= 0, neither or both oil levels, an
        unknown edition.
    """
    w, nu = _speed_viscosity(bearing, speed_rad_s, kinematic_viscosity_m2_s)
    _choice("edition", edition, DRAG_EDITIONS)
    if (oil_level_m is None) == (oil_level_H_m is None):
        raise KegelInputError(_SOURCE, "oil_level_m", oil_level_m,
                              "exactly one of oil_level_m (kegel's convention) and oil_level_H_m (SKF's H)")
    if oil_level_m is not None:
        H = skf_oil_level_H_m(_require("oil_level_m", oil_level_m, "m"), bearing.outer_diameter_m,
                              bearing.mean_diameter_m)
    else:
        H = float(oil_level_H_m)
        if math.isnan(H):
            raise KegelInputError(_SOURCE, "oil_level_H_m", oil_level_H_m, "a number in m")
    return _drag(bearing, w * _RPM, nu * _NU_MM2_S, H, edition)


def _speed_viscosity(bearing: SkfBearing, speed_rad_s: float, nu_m2_s: float) -> tuple[float, float]:
    """The speed magnitude (>= 0, ``n d_m`` within :data:`kegel.limits.MAX_SPEED_FACTOR_RPM_MM`
    with the catalogue's d_m) and the kinematic viscosity (within
    :data:`kegel.limits.KINEMATIC_VISCOSITY_RANGE_M2_S`), checked."""
    w = _require("speed_rad_s", speed_rad_s, "rad/s")
    w = check_speed_factor(w, bearing.mean_diameter_m, source=_SOURCE, key="speed_rad_s",
                           designation=bearing.designation, signed=False)
    _require("kinematic_viscosity_m2_s", nu_m2_s, "m^2/s", positive=True)
    nu = check_kinematic_viscosity(nu_m2_s, source=_SOURCE, key="kinematic_viscosity_m2_s")
    return w, nu


def _loaded_point(bearing: SkfBearing, speed_rad_s: float, nu_m2_s: float, Fa_N: float,
                  Fr_N: float) -> tuple[float, float, float, float]:
    """Checked operating point of the rolling and sliding terms in the catalogue's units
    (n in r/min, nu in mm^2/s, forces in N); the bearing's series constants must exist."""
    w, nu = _speed_viscosity(bearing, speed_rad_s, nu_m2_s)
    Fa = _require("axial_load_N", Fa_N, "N")
    Fr = _require("radial_load_N", Fr_N, "N")
    _load_constants(bearing)
    return w * _RPM, nu * _NU_MM2_S, Fa, Fr


def skf_rolling_moment(bearing: SkfBearing, *, speed_rad_s: float, kinematic_viscosity_m2_s: float,
                       axial_load_N: float, radial_load_N: float = 0.0,
                       lubrication: str = "oil_bath") -> tuple[float, float, float]:
    """Rolling frictional moment ``M_rr = phi_ish phi_rs G_rr (nu n)^0.6``.

    Parameters
    ----------
    bearing
        :func:`skf_bearing`.
    speed_rad_s
        Magnitude of the rotational speed.
    kinematic_viscosity_m2_s
        Kinematic viscosity at the operating temperature (> 0).
    axial_load_N, radial_load_N
        ``F_a`` and ``F_r`` (>= 0).
    lubrication
        Key of :data:`K_RS` (``oil_bath``, ``oil_air``, ``oil_jet``).

    Returns
    -------
    tuple of float
        ``(M_rr [N m], phi_ish, phi_rs)``.

    Raises
    ------
    KegelInputError
        A negative or NaN input, a viscosity <= 0, an unknown lubrication, a bearing without
        Y or series constants.
    """
    n, nu, Fa, Fr = _loaded_point(bearing, speed_rad_s, kinematic_viscosity_m2_s, axial_load_N, radial_load_N)
    _choice("lubrication", lubrication, K_RS)
    M, phi_ish, phi_rs = _rolling(bearing, n, nu, Fa, Fr, K_RS[lubrication])
    return M * _NM, phi_ish, phi_rs


def skf_sliding_moment(bearing: SkfBearing, *, speed_rad_s: float, kinematic_viscosity_m2_s: float,
                       axial_load_N: float, radial_load_N: float = 0.0) -> tuple[float, float, float]:
    """Sliding frictional moment ``M_sl = G_sl mu_sl``.

    Parameters
    ----------
    bearing
        :func:`skf_bearing`.
    speed_rad_s
        Magnitude of the rotational speed.
    kinematic_viscosity_m2_s
        Kinematic viscosity at the operating temperature (> 0).
    axial_load_N, radial_load_N
        ``F_a`` and ``F_r`` (>= 0).

    Returns
    -------
    tuple of float
        ``(M_sl [N m], phi_bl, mu_sl)``.

    Raises
    ------
    KegelInputError
        A negative or NaN input, a viscosity <= 0, a bearing without Y or series constants.
    """
    n, nu, Fa, Fr = _loaded_point(bearing, speed_rad_s, kinematic_viscosity_m2_s, axial_load_N, radial_load_N)
    M, phi_bl, mu_sl = _sliding(bearing, n, nu, Fa, Fr)
    return M * _NM, phi_bl, mu_sl


@dataclass(frozen=True)
class SkfFriction:
    """Frictional moment of the SKF model, by term [N m], with its factors.

    Attributes
    ----------
    rolling_Nm, sliding_Nm, drag_Nm
        ``M_rr``, ``M_sl``, ``M_drag``.
    phi_ish, phi_rs, phi_bl
        Inlet shear heating, kinematic replenishment and boundary-lubrication weighting factors.
    mu_sl
        Sliding friction coefficient.
    drag
        The drag moment's parts (:class:`SkfDrag`).
    lubrication
        Key of :data:`K_RS` used for ``phi_rs``.
    verify
        True: some constants are still to be confirmed against the catalogue (:data:`VERIFY`).
    """

    rolling_Nm: float
    sliding_Nm: float
    drag_Nm: float
    phi_ish: float
    phi_rs: float
    phi_bl: float
    mu_sl: float
    drag: SkfDrag
    lubrication: str
    verify: bool = True

    @property
    def total_Nm(self) -> float:
        """``M_rr + M_sl + M_drag``."""
        return self.rolling_Nm + self.sliding_Nm + self.drag_Nm

    @property
    def rolling_sliding_Nm(self) -> float:
        """``M_rr + M_sl``: the contact friction, kegel's multibody model's counterpart."""
        return self.rolling_Nm + self.sliding_Nm

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary (field names carry units)."""
        return {**asdict(self), "total_Nm": self.total_Nm, "rolling_sliding_Nm": self.rolling_sliding_Nm}


def skf_friction(bearing: SkfBearing, *, speed_rad_s: float, kinematic_viscosity_m2_s: float,
                 axial_load_N: float, radial_load_N: float = 0.0, oil_level_m: float | None = None,
                 oil_level_H_m: float | None = None, lubrication: str = "oil_bath",
                 edition: str = "2013") -> SkfFriction:
    """Frictional moment of the SKF model: rolling, sliding and (in an oil bath) drag.

    Parameters
    ----------
    bearing
        :func:`skf_bearing`.
    speed_rad_s
        Magnitude of the rotational speed.
    kinematic_viscosity_m2_s
        Kinematic viscosity at the operating temperature (> 0).
    axial_load_N, radial_load_N
        ``F_a`` and ``F_r`` (>= 0).
    oil_level_m, oil_level_H_m
        Oil level in kegel's convention or as the catalogue's ``H``
        (see :func:`skf_drag_moment`); neither: no drag (e.g. oil-air lubrication).
    lubrication
        Key of :data:`K_RS`.
    edition
        Drag equation, ``"2013"`` or ``"2005"``.

    Returns
    -------
    SkfFriction

    Raises
    ------
    KegelInputError
        A negative or NaN input, a viscosity <= 0, an unknown lubrication or edition.
    """
    M_rr, phi_ish, phi_rs = skf_rolling_moment(bearing, speed_rad_s=speed_rad_s,
                                               kinematic_viscosity_m2_s=kinematic_viscosity_m2_s,
                                               axial_load_N=axial_load_N, radial_load_N=radial_load_N,
                                               lubrication=lubrication)
    M_sl, phi_bl, mu_sl = skf_sliding_moment(bearing, speed_rad_s=speed_rad_s,
                                             kinematic_viscosity_m2_s=kinematic_viscosity_m2_s,
                                             axial_load_N=axial_load_N, radial_load_N=radial_load_N)
    if oil_level_m is None and oil_level_H_m is None:
        _choice("edition", edition, DRAG_EDITIONS)
        drag = SkfDrag(0.0, 0.0, 0.0, 0.0, _width_factor(bearing), None, False, edition)
    else:
        drag = skf_drag_moment(bearing, speed_rad_s=speed_rad_s, kinematic_viscosity_m2_s=kinematic_viscosity_m2_s,
                               oil_level_m=oil_level_m, oil_level_H_m=oil_level_H_m, edition=edition)
    return SkfFriction(rolling_Nm=M_rr, sliding_Nm=M_sl, drag_Nm=drag.drag_Nm, phi_ish=phi_ish, phi_rs=phi_rs,
                       phi_bl=phi_bl, mu_sl=mu_sl, drag=drag, lubrication=lubrication, verify=any(VERIFY.values()))
