"""Estimates for what a catalogue does not print: a tapered roller bearing's internal geometry from
its boundary dimensions, and an oil's viscosity-temperature-pressure law from two viscosities.

Everything here is an estimate, and every result that uses one says so (the warnings
``geometry_estimated`` and ``lubricant_estimated`` on every point, :mod:`kegel.point_warnings`).
This module holds the formulas only (no data files); :mod:`kegel.data` builds the bearing and
lubricant records from them. The guide is ``docs/bearings_and_oils.md``.

Bearing: internal geometry from boundary dimensions
===================================================
Inputs: bore ``d``, outer diameter ``D``, total width ``T``, cone width ``B``, cup width ``C``,
contact angle ``alpha`` (or ``e = 1.5 tan(alpha)``, ISO 281), static load rating ``C0r`` and,
when known, the roller count ``Z``.

1. Pitch diameter ``d_m = (d + D) / 2`` (the mean diameter of ISO 281 and of the SKF friction
   model).
2. Roller length along its axis ``L = k_L C / cos(alpha)``: the cup raceway runs across the cup
   width, inclined by ``alpha``; ``k_L`` is the share of that raceway length the roller takes, taken
   from the reference design (the seed paper's 32216, Table 4: ``k_L = 0.781``).
3. Edge radius ``r_e = k_e D_w`` and effective length ``L_we = L - 2 r_e`` (``k_e`` from the
   reference design, 1.0 mm / 17 mm).
4. Roller mean diameter ``D_w`` from the static load rating of ISO 76:2006, clause 6.1.1 (radial
   roller bearings, 4000 MPa contact stress)::

       C0r = 44 (1 - D_we cos(alpha) / D_pw) i Z L_we D_we cos(alpha)      [N, mm]

   solved for ``D_we = D_w`` with ``i = 1`` (:func:`iso76_static_rating_N`). Without ``Z``, a first
   roller diameter ``D_w0 = k_D (D - d) / 2`` (``k_D`` from the reference design) gives ``Z`` as the
   nearest integer of the same formula solved for ``Z``, and then ``D_w`` is solved with that ``Z``.
5. If the rollers so found do not fit side by side on the pitch circle (with the assumed pocket
   clearance), ``D_w`` is set to the largest that fits and ``L_we`` is solved from ISO 76 instead,
   up to the whole cup raceway length.

The proportions ``k_L``, ``k_e``, ``k_D``, the roller profile (logarithmic, ``a_p`` as the reference,
``c_p = L_we``, ``k_p = 2 r_e``, ``d_p = 0``) and the roughness are transferred from one measured
design (geometric similarity); no published set of internal-design proportions of tapered roller
bearings could be read (docs/bearings_and_oils.md says what was searched). They are not fitted to
any torque. ``tests/python/test_bearing_estimate.py`` states how far the estimate lands from the
32208 and 32216.

Oil: Vogel and pressure-viscosity from two viscosities
======================================================
Inputs: kinematic viscosities at 40 and 100 degC (``nu40`` may be given as the ISO VG, whose mid-point
viscosity at 40 degC it is, ISO 3448) and the density at 15 degC.

1. The Walther (Ubbelohde-Walther) line of ASTM D341 through the two viscosities:
   ``log10 log10(nu + 0.7) = A - B log10(T)`` (nu in mm^2/s, T in K; the simple form of D341 valid
   for nu >= 2 mm^2/s). ``B`` is the ASTM slope.
2. A third viscosity interpolated on that line at 70 degC, between the two measured ones (no
   extrapolation).
3. Vogel's law ``eta = K exp(B_V / (theta + C_V))`` (the seed paper's Eq. 8) through the three
   dynamic viscosities ``eta = nu rho(theta)``, solved exactly (:func:`vogel_through_points`).
4. The pressure-viscosity coefficient from the correlation of So and Klaus (B.Y.C. So, E.E. Klaus:
   Viscosity-pressure correlation of liquids. ASLE Transactions 23 (1980) 409-421; as reproduced
   in Hamrock, Schmid, Jacobson: Fundamentals of Fluid Film Lubrication, 2nd ed., 2004, ch. 4)::

       alpha = 1.216 + 4.143 X^3.0627 + 2.848e-4 b^5.1903 X^1.5976 - 3.999 X^3.0975 rho^0.1162

   with ``X = log10(nu0)``, nu0 in mm^2/s and rho in g/cm^3 at the temperature, ``b`` the ASTM
   slope, and alpha in 1e-8 m^2/N (:func:`so_klaus_alpha_per_Pa`). The primary source could not be
   read through kegel's search tools (the textbook form is used; it lands within 4-14 % of FVA 3's
   measured coefficient at 50-100 degC, tests/python/test_oil_estimate.py). Evaluated at 40 and
   100 degC, it fixes Dicke's ``a1 + a2 theta = 1 / alpha0`` (the seed paper's Eq. 7).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from scipy.optimize import brentq, minimize_scalar

__all__ = [
    "BoundaryDimensions",
    "InternalEstimate",
    "OilEstimate",
    "ReferenceDesign",
    "WALTHER_THIRD_POINT_DEGC",
    "astm_d341_line",
    "astm_d341_viscosity_mm2_s",
    "estimate_internal_geometry",
    "estimate_oil",
    "iso76_static_rating_N",
    "so_klaus_alpha_per_Pa",
    "vogel_through_points",
]

#: ISO 76 contact-stress constant of radial roller bearings [N/mm^2 = 1e6 Pa].
ISO76_ROLLER_CONSTANT_PA = 44.0e6
#: Temperature of the third viscosity interpolated on the ASTM D341 line [degC].
WALTHER_THIRD_POINT_DEGC = 70.0


class EstimateError(ValueError):
    """The inputs of an estimate admit no consistent answer (the message says why)."""


# ---------------------------------------------------------------------------------------------
# Bearing
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class BoundaryDimensions:
    """Catalogue data of a single-row tapered roller bearing (SI units)."""

    designation: str
    bore_diameter_m: float
    outer_diameter_m: float
    total_width_m: float
    cone_width_m: float
    cup_width_m: float
    contact_angle_rad: float
    C0r_N: float
    roller_count: int | None = None

    def check(self) -> None:
        """Raise :class:`EstimateError` for dimensions no tapered roller bearing has."""
        d, D = self.bore_diameter_m, self.outer_diameter_m
        T, B, C = self.total_width_m, self.cone_width_m, self.cup_width_m
        for name, v in (("d", d), ("D", D), ("T", T), ("B", B), ("C", C), ("C0r", self.C0r_N)):
            if not (math.isfinite(v) and v > 0.0):
                raise EstimateError(f"{name} = {v}: expected a positive finite value")
        if not d < D:
            raise EstimateError(f"d = {d * 1e3:g} mm, D = {D * 1e3:g} mm: expected d < D")
        if not (B <= T and C <= T):
            raise EstimateError(f"T = {T * 1e3:g} mm, B = {B * 1e3:g} mm, C = {C * 1e3:g} mm: expected B <= T "
                                "and C <= T")
        if not math.radians(5.0) <= self.contact_angle_rad <= math.radians(35.0):
            raise EstimateError(f"contact angle {math.degrees(self.contact_angle_rad):g} deg: expected 5-35 deg "
                                "(e = 0.13-0.84), the range of tapered roller bearings")
        if self.roller_count is not None and not 6 <= self.roller_count <= 200:
            raise EstimateError(f"Z = {self.roller_count}: expected 6-200 rollers")


@dataclass(frozen=True)
class ReferenceDesign:
    """Dimensionless proportions of one measured design, transferred to the estimated bearing.

    Attributes
    ----------
    name
        Where the proportions come from (a data file).
    cup_length_ratio
        ``k_L = L / (C / cos(alpha))``.
    edge_radius_ratio
        ``k_e = r_e / D_w``.
    section_ratio
        ``k_D = D_w / ((D - d) / 2)`` (only without a roller count).
    profile_a_p
        Logarithmic crown parameter ``a_p`` (dimensionless).
    """

    name: str
    cup_length_ratio: float
    edge_radius_ratio: float
    section_ratio: float
    profile_a_p: float


@dataclass(frozen=True)
class InternalEstimate:
    """The estimated internal dimensions (SI units) and how they were found."""

    pitch_diameter_m: float
    roller_mean_diameter_m: float
    roller_length_m: float
    roller_count: int
    edge_radius_m: float
    profile_a_p: float
    profile_c_p_m: float
    profile_d_p_m: float
    profile_k_p_m: float
    #: names of the estimated quantities
    estimated: tuple[str, ...]
    #: the method in one paragraph, with the constraint that decided the roller size
    note: str
    #: ISO 76 rating of the estimated geometry (equals C0r unless the packing limit was active)
    iso76_C0r_N: float = field(default=0.0)


def iso76_static_rating_N(roller_diameter_m: float, effective_length_m: float, roller_count: float,
                          pitch_diameter_m: float, contact_angle_rad: float, rows: int = 1) -> float:
    """Basic static radial load rating of a radial roller bearing, ISO 76:2006 clause 6.1.1.

    ``C0r = 44 (1 - D_we cos(alpha) / D_pw) i Z L_we D_we cos(alpha)`` with lengths in mm and C0r in N
    (44 N/mm^2 is the constant of a 4000 MPa contact stress); here in SI units.
    """
    c = math.cos(contact_angle_rad)
    return (ISO76_ROLLER_CONSTANT_PA * (1.0 - roller_diameter_m * c / pitch_diameter_m) * rows * roller_count
            * effective_length_m * roller_diameter_m * c)


def estimate_internal_geometry(b: BoundaryDimensions, ref: ReferenceDesign, *,
                               pocket_clearance_ratio: float = 0.02) -> InternalEstimate:
    """Estimate the internal geometry of a tapered roller bearing (see the module docstring).

    Parameters
    ----------
    b
        The catalogue data.
    ref
        The measured design whose proportions are transferred.
    pocket_clearance_ratio
        Circumferential cage pocket clearance over ``D_w`` (the rollers must fit side by side on the
        pitch circle with it).

    Raises
    ------
    EstimateError
        Dimensions that admit no roller set (the message names the conflicting data).
    """
    b.check()
    alpha = b.contact_angle_rad
    c = math.cos(alpha)
    d_m = 0.5 * (b.bore_diameter_m + b.outer_diameter_m)
    raceway = b.cup_width_m / c                       # cup raceway length along its generator
    L = ref.cup_length_ratio * raceway
    k_e = ref.edge_radius_ratio
    estimated = ["pitch_diameter", "roller_mean_diameter", "roller_length", "edge_radius", "roller_profile"]
    steps = [f"d_m = (d + D)/2 = {d_m * 1e3:.4g} mm",
             f"L = {ref.cup_length_ratio:.3f} C/cos(alpha) = {L * 1e3:.4g} mm"]

    def rating(Dw: float, Z: float, length: float) -> float:
        return iso76_static_rating_N(Dw, length - 2.0 * k_e * Dw, Z, d_m, alpha)

    Z = b.roller_count
    if Z is None:
        Dw0 = ref.section_ratio * 0.5 * (b.outer_diameter_m - b.bore_diameter_m)
        per_roller = rating(Dw0, 1.0, L)
        if per_roller <= 0.0:
            raise EstimateError("the section height and cup width leave no roller length: check D, d and C")
        Z = max(6, int(round(b.C0r_N / per_roller)))
        estimated.append("roller_count")
        steps.append(f"Z = {Z} from ISO 76 with D_w0 = {ref.section_ratio:.3f} (D - d)/2 = {Dw0 * 1e3:.4g} mm")

    # ISO 76 as a function of D_w (L fixed) rises to a maximum, then falls (1 - D_w cos/d_m, L - 2 r_e)
    hi = min(d_m / c, L / (2.0 * k_e)) if k_e > 0 else d_m / c
    best = minimize_scalar(lambda x: -rating(x, Z, L), bounds=(1e-9, hi), method="bounded",
                           options={"xatol": 1e-12})
    Dw_peak, c0_peak = float(best.x), -float(best.fun)
    spacing = d_m * math.sin(math.pi / Z)
    Dw_pack = spacing / (1.0 + pocket_clearance_ratio) * (1.0 - 1e-3)
    if c0_peak >= b.C0r_N:
        Dw = brentq(lambda x: rating(x, Z, L) - b.C0r_N, 1e-9, Dw_peak, xtol=1e-12)
        constraint = "ISO 76 with the roller length from the cup width"
    else:
        Dw = math.inf
        constraint = ""
    if Dw > Dw_pack:
        # the rollers would not fit side by side: the largest that fit, the length from ISO 76
        Dw = Dw_pack
        Lwe = b.C0r_N / iso76_static_rating_N(Dw, 1.0, Z, d_m, alpha)
        L = Lwe + 2.0 * k_e * Dw
        if L > raceway:
            raise EstimateError(
                f"C0r = {b.C0r_N / 1e3:g} kN needs more roller line than fits: {Z} rollers of at most "
                f"D_w = {Dw * 1e3:.3g} mm (pitch circle d_m = {d_m * 1e3:.4g} mm) would need L = {L * 1e3:.3g} mm, "
                f"longer than the cup raceway C/cos(alpha) = {raceway * 1e3:.3g} mm; check C0r, Z and C")
        constraint = (f"the pitch circle (Z = {Z} rollers of D_w <= {Dw * 1e3:.4g} mm fit); L_we from ISO 76 "
                      f"(L = {L * 1e3:.4g} mm instead of the cup-width estimate)")
    steps.append(f"D_w = {Dw * 1e3:.4g} mm from {constraint}")
    r_e = k_e * Dw
    Lwe = L - 2.0 * r_e
    note = ("internal geometry estimated from the boundary dimensions (kegel.estimate): " + "; ".join(steps)
            + f"; r_e = {k_e:.4f} D_w, roller profile (a_p, c_p = L_we, k_p = 2 r_e) and roughness transferred "
            f"from {ref.name}")
    return InternalEstimate(
        pitch_diameter_m=d_m, roller_mean_diameter_m=Dw, roller_length_m=L, roller_count=int(Z),
        edge_radius_m=r_e, profile_a_p=ref.profile_a_p, profile_c_p_m=Lwe, profile_d_p_m=0.0,
        profile_k_p_m=2.0 * r_e, estimated=tuple(estimated), note=note,
        iso76_C0r_N=iso76_static_rating_N(Dw, Lwe, Z, d_m, alpha),
    )


# ---------------------------------------------------------------------------------------------
# Oil
# ---------------------------------------------------------------------------------------------
def astm_d341_line(nu1_mm2_s: float, theta1_degC: float, nu2_mm2_s: float, theta2_degC: float) -> tuple[float, float]:
    """Constants ``(A, B)`` of the ASTM D341 (Walther) line through two kinematic viscosities.

    ``log10(log10(nu + 0.7)) = A - B log10(T)``, nu in mm^2/s, T in K (ASTM D341, simple form for
    nu >= 2 mm^2/s). ``B`` is the ASTM slope.
    """
    for nu in (nu1_mm2_s, nu2_mm2_s):
        if not (math.isfinite(nu) and nu >= 2.0):
            raise EstimateError(f"kinematic viscosity {nu} mm^2/s: expected >= 2 mm^2/s (ASTM D341's simple form)")
    if not theta1_degC != theta2_degC:
        raise EstimateError("two viscosities at two different temperatures are needed")
    y1 = math.log10(math.log10(nu1_mm2_s + 0.7))
    y2 = math.log10(math.log10(nu2_mm2_s + 0.7))
    x1 = math.log10(theta1_degC + 273.15)
    x2 = math.log10(theta2_degC + 273.15)
    B = (y1 - y2) / (x2 - x1)
    return y1 + B * x1, B


def astm_d341_viscosity_mm2_s(A: float, B: float, theta_degC: float) -> float:
    """Kinematic viscosity [mm^2/s] on the ASTM D341 line ``(A, B)`` at ``theta_degC``."""
    return 10.0 ** (10.0 ** (A - B * math.log10(theta_degC + 273.15))) - 0.7


def vogel_through_points(points: list[tuple[float, float]]) -> tuple[float, float, float]:
    """Vogel's ``eta = K exp(B / (theta + C))`` through three points ``(theta_degC, eta)`` exactly.

    Returns ``(K, B, C)`` with ``K`` in the unit of ``eta``, ``B`` and ``C`` in degC. From the three
    equations ``ln eta_i = ln K + B / (theta_i + C)``: the ratio
    ``r = (ln eta_1 - ln eta_2) / (ln eta_2 - ln eta_3) = (theta_2 - theta_1)(theta_3 + C) /
    ((theta_3 - theta_2)(theta_1 + C))`` is linear in ``C``.
    """
    if len(points) != 3:
        raise EstimateError("Vogel's law needs exactly three points")
    (t1, e1), (t2, e2), (t3, e3) = sorted(points)
    if not (t1 < t2 < t3 and e1 > e2 > e3 > 0.0):
        raise EstimateError("Vogel's law needs viscosities that fall with temperature")
    r = (math.log(e1) - math.log(e2)) / (math.log(e2) - math.log(e3))
    a = r * (t3 - t2)
    k = t2 - t1
    if a == k:
        raise EstimateError("the three viscosities lie on an Arrhenius line: Vogel's C is undefined")
    C = (k * t3 - a * t1) / (a - k)
    if not t1 + C > 0.0:
        raise EstimateError(f"Vogel's C = {C:.4g} degC puts the pole above {t1:g} degC: these viscosities are not "
                            "those of a lubricating oil")
    B = (math.log(e1) - math.log(e2)) / (1.0 / (t1 + C) - 1.0 / (t2 + C))
    K = e1 / math.exp(B / (t1 + C))
    return K, B, C


def so_klaus_alpha_per_Pa(nu_mm2_s: float, density_g_cm3: float, astm_slope: float) -> float:
    """Pressure-viscosity coefficient [1/Pa] by So and Klaus (ASLE Trans. 23, 1980, 409-421).

    ``alpha = 1.216 + 4.143 X^3.0627 + 2.848e-4 b^5.1903 X^1.5976 - 3.999 X^3.0975 rho^0.1162`` in
    1e-8 m^2/N, with ``X = log10(nu)`` (nu in mm^2/s, at ambient pressure and the temperature),
    ``rho`` in g/cm^3 at the temperature and ``b`` the ASTM D341 slope.
    """
    if not (nu_mm2_s > 1.0 and density_g_cm3 > 0.0 and astm_slope > 0.0):
        raise EstimateError("So-Klaus needs nu > 1 mm^2/s, a positive density and ASTM slope")
    X = math.log10(nu_mm2_s)
    a = (1.216 + 4.143 * X**3.0627 + 2.848e-4 * astm_slope**5.1903 * X**1.5976
         - 3.999 * X**3.0975 * density_g_cm3**0.1162)
    return a * 1e-8


@dataclass(frozen=True)
class OilEstimate:
    """Vogel and Dicke parameters estimated from two viscosities (the data files' units)."""

    vogel_K_mPas: float
    vogel_B_degC: float
    vogel_C_degC: float
    dicke_a1_bar: float
    dicke_a2_bar_per_degC: float
    astm_A: float
    astm_slope_B: float
    alpha_40_per_Pa: float
    alpha_100_per_Pa: float
    note: str


def estimate_oil(nu40_mm2_s: float, nu100_mm2_s: float, density_15C_kg_m3: float,
                 density_slope_kg_m3_K: float) -> OilEstimate:
    """Vogel's law and Dicke's ``a1, a2`` from ``nu40``, ``nu100`` and the density (module docstring).

    Parameters
    ----------
    nu40_mm2_s, nu100_mm2_s
        Kinematic viscosities at 40 and 100 degC [mm^2/s].
    density_15C_kg_m3
        Density at 15 degC [kg/m^3].
    density_slope_kg_m3_K
        Its temperature coefficient [kg/(m^3 K)] (negative).
    """
    if not nu40_mm2_s > nu100_mm2_s:
        raise EstimateError(f"nu40 = {nu40_mm2_s:g} mm^2/s, nu100 = {nu100_mm2_s:g} mm^2/s: expected nu40 > nu100")
    if not 600.0 <= density_15C_kg_m3 <= 1300.0:
        raise EstimateError(f"density {density_15C_kg_m3:g} kg/m^3: expected 600-1300 kg/m^3 (lubricating oils)")
    A, B = astm_d341_line(nu40_mm2_s, 40.0, nu100_mm2_s, 100.0)
    t3 = WALTHER_THIRD_POINT_DEGC
    nu3 = astm_d341_viscosity_mm2_s(A, B, t3)

    def rho(theta: float) -> float:
        return density_15C_kg_m3 + density_slope_kg_m3_K * (theta - 15.0)

    # dynamic viscosity in mPa s: nu [mm^2/s] * rho [kg/m^3] * 1e-3
    pts = [(40.0, nu40_mm2_s * rho(40.0) * 1e-3), (t3, nu3 * rho(t3) * 1e-3), (100.0, nu100_mm2_s * rho(100.0) * 1e-3)]
    K, Bv, Cv = vogel_through_points(pts)
    a40 = so_klaus_alpha_per_Pa(nu40_mm2_s, rho(40.0) * 1e-3, B)
    a100 = so_klaus_alpha_per_Pa(nu100_mm2_s, rho(100.0) * 1e-3, B)
    # Dicke: alpha0 = 1 / (a1 + a2 theta), alpha in 1/bar (1 bar = 1e5 Pa)
    inv40, inv100 = 1.0 / (a40 * 1e5), 1.0 / (a100 * 1e5)
    a2 = (inv100 - inv40) / 60.0
    a1 = inv40 - 40.0 * a2
    note = (f"Vogel through nu40 = {nu40_mm2_s:g}, nu100 = {nu100_mm2_s:g} mm^2/s and nu{t3:g} = {nu3:.4g} mm^2/s "
            f"interpolated on their ASTM D341 line (slope {B:.3f}); pressure-viscosity by So-Klaus (1980): "
            f"{a40 * 1e9:.3g} / {a100 * 1e9:.3g} 1/GPa at 40 / 100 degC")
    return OilEstimate(vogel_K_mPas=K, vogel_B_degC=Bv, vogel_C_degC=Cv, dicke_a1_bar=a1, dicke_a2_bar_per_degC=a2,
                       astm_A=A, astm_slope_B=B, alpha_40_per_Pa=a40, alpha_100_per_Pa=a100, note=note)
