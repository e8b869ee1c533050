"""Bearing, lubricant and material data files: loading and conversion to SI.

The data files under ``kegel/data`` are the one source of truth for the published values
(seed paper tables, catalogue dimensions) and for the literature values kegel adds; each file
cites its sources beside the values. Names are looked up in that folder; a path to a TOML file
of the same layout works too.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any, Callable

from .. import _core
from ..base._toml import read_toml, require_number, require_str, require_table
from ..base.errors import KegelInputError
from ..base.units import parse_quantity
from .estimate import (BoundaryDimensions, EstimateError, ReferenceDesign, estimate_internal_geometry,
                       estimate_oil)

__all__ = [
    "DATA_DIR",
    "BearingData",
    "LubricantData",
    "MaterialData",
    "available_bearings",
    "available_lubricants",
    "available_materials",
    "BEARING_SCENE_KEYS",
    "LUBRICANT_SCENE_KEYS",
    "bearing_from_boundary",
    "bearing_from_scene",
    "lubricant_from_scene",
    "lubricant_from_viscosities",
    "series_designations",
    "load_bearing",
    "load_lubricant",
    "load_material",
]

DATA_DIR = Path(__file__).resolve().parents[1] / "data"  # kegel/data, beside kegel/model
#: The table of ISO 355 metric series (boundary dimensions and ratings from one catalogue); its
#: bearings get their internal geometry estimated (:mod:`kegel.estimate`).
SERIES_TABLE = DATA_DIR / "bearing_series" / "iso355_metric.toml"
#: The measured designs whose proportions an estimate transfers (seed paper Table 4 / Table A1).
REFERENCE_BEARING = "32216"
REFERENCE_LUBRICANT = "FVA3"
MM = 1e-3
UM = 1e-6


def _available(folder: str) -> list[str]:
    return sorted(p.stem for p in (DATA_DIR / folder).glob("*.toml"))


def available_bearings() -> list[str]:
    """Designations of the bearings shipped with kegel."""
    return _available("bearings")


def available_lubricants() -> list[str]:
    """Names of the lubricants shipped with kegel."""
    return _available("lubricants")


def available_materials() -> list[str]:
    """Names of the solid materials shipped with kegel."""
    return _available("materials")


def _is_file(path: Path) -> bool:
    """``path.is_file()`` that answers False for a name the system cannot look up (too long, a NUL)."""
    try:
        return path.is_file()
    except (OSError, ValueError):
        return False


def _resolve(name: str, folder: str, what: str, source: str | Path, key: str) -> Path:
    candidate = Path(name)
    if candidate.suffix == ".toml":
        if not _is_file(candidate):
            raise KegelInputError(source, key, name, f"an existing {what} data file")
        return candidate
    path = DATA_DIR / folder / f"{name}.toml"
    if not name or "/" in name or "\x00" in name or not _is_file(path):
        known = ", ".join(_available(folder))
        raise KegelInputError(source, key, name, f"a known {what} ({known}) or a path to a .toml file")
    return path


@dataclass(frozen=True)
class BearingData:
    """Published and catalogue data of one tapered roller bearing, in SI units.

    Attributes are the values of the data file converted to SI (m, N); the ``assumed_*``
    attributes are the design assumptions documented in the data file.
    """

    designation: str
    source_file: str
    C0r_N: float
    bore_diameter_m: float
    outer_diameter_m: float
    pitch_diameter_m: float
    roller_mean_diameter_m: float
    roller_length_m: float
    roller_count: int
    profile_a_p: float
    profile_c_p_m: float
    profile_d_p_m: float
    profile_k_p_m: float
    edge_radius_m: float
    sigma_raceway_m: float
    sigma_rib_m: float
    zhou_hoeprich_raceway_B: float
    zhou_hoeprich_raceway_C: float
    zhou_hoeprich_rib_B: float
    zhou_hoeprich_rib_C: float
    total_width_m: float
    cone_width_m: float
    cup_width_m: float
    calculation_factor_e: float
    axial_load_factor_Y: float
    assumed_roller_end_radius_ratio: float
    assumed_rib_contact_height_ratio: float
    assumed_rib_height_over_contact_height: float
    assumed_cage_pitch_ratio: float
    assumed_cage_pocket_clearance_circumferential_ratio: float
    assumed_cage_pocket_clearance_axial_ratio: float
    #: the quantities kegel estimated (:mod:`kegel.estimate`); empty for a measured data file
    estimated: tuple[str, ...] = ()
    #: how they were estimated (one paragraph, for the warning ``geometry_estimated``)
    estimate_note: str = ""


@lru_cache(maxsize=32)
def _load_bearing_file(path: Path) -> BearingData:
    raw = read_toml(path)
    if "boundary" in raw and "published" not in raw:
        return _boundary_file(raw, path)
    pub = require_table(raw, "published", path)
    cat = require_table(raw, "catalogue", path)
    ass = require_table(raw, "assumed", path)

    def p(key: str, **kw: Any) -> float:
        return require_number(pub, key, path, "published.", positive=True, **kw)

    def c(key: str) -> float:
        return require_number(cat, key, path, "catalogue.", positive=True)

    def a(key: str) -> float:
        return require_number(ass, key, path, "assumed.", positive=True)

    data = BearingData(
        designation=require_str(raw, "designation", path),
        source_file=str(path),
        C0r_N=p("C0r_N"),
        bore_diameter_m=p("bore_diameter_mm") * MM,
        outer_diameter_m=p("outer_diameter_mm") * MM,
        pitch_diameter_m=p("pitch_diameter_mm") * MM,
        roller_mean_diameter_m=p("roller_diameter_mm") * MM,
        roller_length_m=p("roller_length_mm") * MM,
        roller_count=int(p("roller_count", integer=True)),
        profile_a_p=p("profile_a_p"),
        profile_c_p_m=p("profile_c_p_mm") * MM,
        profile_d_p_m=require_number(pub, "profile_d_p_mm", path, "published.", nonnegative=True) * MM,
        profile_k_p_m=p("profile_k_p_mm") * MM,
        edge_radius_m=p("edge_radius_mm") * MM,
        sigma_raceway_m=p("sigma_raceway_um") * UM,
        sigma_rib_m=p("sigma_rib_um") * UM,
        zhou_hoeprich_raceway_B=p("zhou_hoeprich_raceway_B"),
        zhou_hoeprich_raceway_C=p("zhou_hoeprich_raceway_C"),
        zhou_hoeprich_rib_B=p("zhou_hoeprich_rib_B"),
        zhou_hoeprich_rib_C=p("zhou_hoeprich_rib_C"),
        total_width_m=c("total_width_T_mm") * MM,
        cone_width_m=c("cone_width_B_mm") * MM,
        cup_width_m=c("cup_width_C_mm") * MM,
        calculation_factor_e=c("calculation_factor_e"),
        axial_load_factor_Y=c("axial_load_factor_Y"),
        assumed_roller_end_radius_ratio=a("roller_end_radius_ratio"),
        assumed_rib_contact_height_ratio=a("rib_contact_height_ratio"),
        assumed_rib_height_over_contact_height=a("rib_height_over_contact_height"),
        assumed_cage_pitch_ratio=a("cage_pitch_diameter_over_pitch_diameter"),
        assumed_cage_pocket_clearance_circumferential_ratio=a(
            "cage_pocket_clearance_circumferential_ratio"
        ),
        assumed_cage_pocket_clearance_axial_ratio=a("cage_pocket_clearance_axial_ratio"),
    )
    if not data.bore_diameter_m < data.pitch_diameter_m < data.outer_diameter_m:
        raise KegelInputError(
            path, "published.pitch_diameter_mm", data.pitch_diameter_m / MM,
            "a pitch diameter between the bore and the outer diameter",
        )
    if data.assumed_rib_contact_height_ratio >= 1.0:
        raise KegelInputError(
            path, "assumed.rib_contact_height_ratio", data.assumed_rib_contact_height_ratio,
            "a fraction < 1 of the roller large-end radius",
        )
    if not data.cone_width_m <= data.total_width_m and data.cup_width_m <= data.total_width_m:
        raise KegelInputError(
            path, "catalogue.total_width_T_mm", data.total_width_m / MM, "T >= B and T >= C"
        )
    return data


def load_bearing(name: str, *, source: str | Path = "<argument>", key: str = "bearing") -> BearingData:
    """Load a bearing by designation or from a TOML file path.

    A designation of a shipped data file (``"32216"``) gives its measured data; a designation of
    the ISO 355 series table (:func:`series_designations`, e.g. ``"30210"``) gives its catalogue
    boundary dimensions with the internal geometry estimated (:mod:`kegel.estimate`). A bearing
    file holds either measured data (``[published]``, ``[catalogue]``, ``[assumed]``) or only
    boundary dimensions (``[boundary]``, estimated).

    Raises
    ------
    KegelInputError
        Unknown designation (the message lists the known ones) or an invalid data file.
    """
    text = str(name)
    if Path(text).suffix != ".toml" and not _is_file(DATA_DIR / "bearings" / f"{text}.toml") \
            and text in _series_table():
        return _series_bearing(text)
    try:
        return _load_bearing_file(_resolve(text, "bearings", "bearing", source, key))
    except KegelInputError as exc:
        if Path(text).suffix == ".toml" or exc.key != key:
            raise
        raise KegelInputError(source, key, name, f"a known bearing ({', '.join(_available('bearings'))}), a "
                              f"designation of the ISO 355 series table ({len(_series_table())} bearings, "
                              f"{SERIES_TABLE.name}), or a path to a .toml file") from None


@lru_cache(maxsize=1)
def _series_table() -> dict[str, dict[str, Any]]:
    raw = read_toml(SERIES_TABLE)
    return {k: v for k, v in raw.items() if isinstance(v, dict)}


def series_designations() -> list[str]:
    """Designations of the ISO 355 series table (internal geometry estimated)."""
    return sorted(_series_table())


@lru_cache(maxsize=1)
def reference_design() -> ReferenceDesign:
    """The proportions an estimate transfers, read from the reference bearing's data file."""
    ref = _load_bearing_file(DATA_DIR / "bearings" / f"{REFERENCE_BEARING}.toml")
    alpha = math.atan(ref.calculation_factor_e / 1.5)
    return ReferenceDesign(
        name=f"bearing {ref.designation} ({Path(ref.source_file).name})",
        cup_length_ratio=ref.roller_length_m / (ref.cup_width_m / math.cos(alpha)),
        edge_radius_ratio=ref.edge_radius_m / ref.roller_mean_diameter_m,
        section_ratio=ref.roller_mean_diameter_m / (0.5 * (ref.outer_diameter_m - ref.bore_diameter_m)),
        profile_a_p=ref.profile_a_p,
    )


def bearing_from_boundary(boundary: BoundaryDimensions, *, source: str | Path, key: str = "bearing",
                          axial_load_factor_Y: float | None = None) -> BearingData:
    """A bearing record from catalogue data, its internal geometry estimated (:mod:`kegel.estimate`).

    Parameters
    ----------
    boundary
        Boundary dimensions, contact angle, C0r and (optionally) the roller count.
    source, key
        Where the data came from, for messages and the record's ``source_file``.
    axial_load_factor_Y
        The catalogue's Y; default ISO 281's ``0.4 cot(alpha)``.

    Raises
    ------
    KegelInputError
        Data that admit no roller set (naming ``source`` and ``key``).
    """
    ref_data = _load_bearing_file(DATA_DIR / "bearings" / f"{REFERENCE_BEARING}.toml")
    try:
        est = estimate_internal_geometry(
            boundary, reference_design(),
            pocket_clearance_ratio=ref_data.assumed_cage_pocket_clearance_circumferential_ratio)
    except EstimateError as exc:
        raise KegelInputError(source, key, boundary.designation,
                              f"boundary dimensions that admit a set of rollers ({exc})") from None
    alpha = boundary.contact_angle_rad
    e = 1.5 * math.tan(alpha)
    estimated = est.estimated + ("roughness", "zhou_hoeprich_coefficients")
    return BearingData(
        designation=boundary.designation,
        source_file=str(source),
        C0r_N=boundary.C0r_N,
        bore_diameter_m=boundary.bore_diameter_m,
        outer_diameter_m=boundary.outer_diameter_m,
        pitch_diameter_m=est.pitch_diameter_m,
        roller_mean_diameter_m=est.roller_mean_diameter_m,
        roller_length_m=est.roller_length_m,
        roller_count=est.roller_count,
        profile_a_p=est.profile_a_p,
        profile_c_p_m=est.profile_c_p_m,
        profile_d_p_m=est.profile_d_p_m,
        profile_k_p_m=est.profile_k_p_m,
        edge_radius_m=est.edge_radius_m,
        sigma_raceway_m=ref_data.sigma_raceway_m,
        sigma_rib_m=ref_data.sigma_rib_m,
        zhou_hoeprich_raceway_B=ref_data.zhou_hoeprich_raceway_B,
        zhou_hoeprich_raceway_C=ref_data.zhou_hoeprich_raceway_C,
        zhou_hoeprich_rib_B=ref_data.zhou_hoeprich_rib_B,
        zhou_hoeprich_rib_C=ref_data.zhou_hoeprich_rib_C,
        total_width_m=boundary.total_width_m,
        cone_width_m=boundary.cone_width_m,
        cup_width_m=boundary.cup_width_m,
        calculation_factor_e=e,
        axial_load_factor_Y=axial_load_factor_Y if axial_load_factor_Y is not None else 0.4 / math.tan(alpha),
        assumed_roller_end_radius_ratio=ref_data.assumed_roller_end_radius_ratio,
        assumed_rib_contact_height_ratio=ref_data.assumed_rib_contact_height_ratio,
        assumed_rib_height_over_contact_height=ref_data.assumed_rib_height_over_contact_height,
        assumed_cage_pitch_ratio=ref_data.assumed_cage_pitch_ratio,
        assumed_cage_pocket_clearance_circumferential_ratio=(
            ref_data.assumed_cage_pocket_clearance_circumferential_ratio),
        assumed_cage_pocket_clearance_axial_ratio=ref_data.assumed_cage_pocket_clearance_axial_ratio,
        estimated=estimated,
        estimate_note=est.note + "; Zhou-Hoeprich coefficients as the reference bearing",
    )


#: Keys of a scene's ``[bearing]`` table beside ``designation`` and ``material``: boundary
#: dimensions (lengths with units), e or alpha, Z (optional), C0r (a force), Y (optional).
BEARING_SCENE_KEYS = ("d", "D", "T", "B", "C", "e", "alpha", "Z", "C0r", "Y")
#: Keys of a scene's ``[lubricant]`` table for an oil estimated from its viscosities.
LUBRICANT_SCENE_KEYS = ("nu40_mm2_s", "iso_vg", "nu100_mm2_s", "density_15C_kg_m3", "description")


def bearing_from_scene(table: dict[str, Any], *, source: Callable[[str], str]) -> BearingData:
    """The bearing of a scene's ``[bearing]`` table: a designation (a shipped file, the series
    table, or a path), or boundary dimensions (``d``, ``D``, ``T``, ``B``, ``C`` as lengths, ``e`` or
    ``alpha``, ``C0r`` as a force, optional ``Z`` and ``Y``; ``designation`` then only names it).

    Parameters
    ----------
    table
        The ``[bearing]`` table as read.
    source
        Maps a dotted key to the source to name in messages (the scene file or ``--set``).
    """
    given = [k for k in BEARING_SCENE_KEYS if k in table]
    if not given:
        if "designation" not in table:
            raise KegelInputError(source("bearing.designation"), "bearing.designation", None,
                                  "a bearing designation such as \"32216\" or \"30210\", or boundary dimensions "
                                  "(bearing.d, D, T, B, C, e or alpha, C0r; docs/bearings_and_oils.md)")
        return load_bearing(str(table["designation"]), source=source("bearing.designation"),
                            key="bearing.designation")
    missing = [k for k in ("d", "D", "T", "B", "C", "C0r") if k not in table]
    if missing:
        k = f"bearing.{missing[0]}"
        raise KegelInputError(source(k), k, None, "with boundary dimensions, all of bearing.d, D, T, B, C, C0r "
                              "(lengths and a force with units, e.g. d = \"50 mm\", C0r = \"91.5 kN\")")
    if ("e" in table) == ("alpha" in table):
        raise KegelInputError(source("bearing.e"), "bearing.e", table.get("e"),
                              "exactly one of bearing.e (ISO 281 calculation factor) or bearing.alpha (contact angle)")

    def q(k: str, kind: str) -> float:
        return parse_quantity(table[k], kind, source=source(f"bearing.{k}"), key=f"bearing.{k}")

    def num(k: str, *, integer: bool = False) -> float:
        return require_number(table, k, source(f"bearing.{k}"), "bearing.", positive=True, integer=integer)

    alpha = math.atan(num("e") / 1.5) if "e" in table else q("alpha", "angle")
    designation = str(table.get("designation", "custom"))
    boundary = BoundaryDimensions(
        designation=designation, bore_diameter_m=q("d", "length"), outer_diameter_m=q("D", "length"),
        total_width_m=q("T", "length"), cone_width_m=q("B", "length"), cup_width_m=q("C", "length"),
        contact_angle_rad=alpha, C0r_N=q("C0r", "force"),
        roller_count=int(num("Z", integer=True)) if "Z" in table else None)
    # the source names --set when it changed any of the dimensions
    src = next((source(f"bearing.{k}") for k in given if source(f"bearing.{k}") != source("bearing")),
               source("bearing"))
    try:
        boundary.check()
    except EstimateError as exc:
        raise KegelInputError(src, "bearing", designation, f"boundary dimensions of a tapered roller "
                              f"bearing ({exc})") from None
    return bearing_from_boundary(boundary, source=src, key="bearing",
                                 axial_load_factor_Y=num("Y") if "Y" in table else None)


def lubricant_from_scene(table: dict[str, Any], *, source: Callable[[str], str]) -> LubricantData:
    """The lubricant of a scene's ``[lubricant]`` table: ``name`` of a shipped oil or a path, or an
    oil estimated from ``nu40_mm2_s`` (or ``iso_vg``), ``nu100_mm2_s`` and ``density_15C_kg_m3``
    (``name`` then only names it)."""
    given = [k for k in LUBRICANT_SCENE_KEYS if k in table and k != "description"]
    if not given:
        if "name" not in table:
            raise KegelInputError(source("lubricant.name"), "lubricant.name", None,
                                  "a lubricant name such as \"FVA3\", or viscosities (lubricant.nu40_mm2_s or iso_vg, "
                                  "nu100_mm2_s, density_15C_kg_m3; docs/bearings_and_oils.md)")
        return load_lubricant(str(table["name"]), source=source("lubricant.name"), key="lubricant.name")
    src = source("lubricant")
    nu40 = _nu40_mm2_s(table, src, "lubricant.")
    for k in ("nu100_mm2_s", "density_15C_kg_m3"):
        if k not in table:
            raise KegelInputError(src, f"lubricant.{k}", None, "with viscosities, all of lubricant.nu40_mm2_s (or "
                                  "iso_vg), nu100_mm2_s and density_15C_kg_m3 (numbers in the units of their names)")
    name = table.get("name", f"oil nu40 {nu40:g}")
    return lubricant_from_viscosities(
        str(name), nu40_mm2_s=nu40,
        nu100_mm2_s=require_number(table, "nu100_mm2_s", src, "lubricant.", positive=True),
        density_15C_kg_m3=require_number(table, "density_15C_kg_m3", src, "lubricant.", positive=True),
        description=str(table.get("description", "")), source=src, key="lubricant")


def _contact_angle(table: dict[str, Any], path: str | Path, prefix: str) -> float:
    """The cup angle from ``alpha_deg`` or ``e`` (ISO 281: e = 1.5 tan(alpha)); exactly one."""
    if ("alpha_deg" in table) == ("e" in table):
        raise KegelInputError(path, f"{prefix}e", table.get("e"), "exactly one of e (ISO 281 calculation factor) "
                              "or alpha_deg (contact angle)")
    if "e" in table:
        return math.atan(require_number(table, "e", path, prefix, positive=True) / 1.5)
    return math.radians(require_number(table, "alpha_deg", path, prefix, positive=True))


def _boundary_file(raw: dict[str, Any], path: Path) -> BearingData:
    """A bearing file with only ``[boundary]`` data (keys as the series table's)."""
    tab = require_table(raw, "boundary", path)
    designation = require_str(raw, "designation", path)
    return _boundary_record(designation, tab, path, "boundary.")


def _boundary_record(designation: str, tab: dict[str, Any], path: str | Path, prefix: str) -> BearingData:
    def mm(k: str) -> float:
        return require_number(tab, k, path, prefix, positive=True) * MM

    Z = int(require_number(tab, "Z", path, prefix, positive=True, integer=True)) if "Z" in tab else None
    boundary = BoundaryDimensions(
        designation=designation, bore_diameter_m=mm("d_mm"), outer_diameter_m=mm("D_mm"),
        total_width_m=mm("T_mm"), cone_width_m=mm("B_mm"), cup_width_m=mm("C_mm"),
        contact_angle_rad=_contact_angle(tab, path, prefix),
        C0r_N=require_number(tab, "C0r_kN", path, prefix, positive=True) * 1e3, roller_count=Z)
    Y = require_number(tab, "Y", path, prefix, positive=True) if "Y" in tab else None
    return bearing_from_boundary(boundary, source=path, key=f"{prefix.rstrip('.') or 'boundary'}",
                                 axial_load_factor_Y=Y)


@lru_cache(maxsize=256)
def _series_bearing(designation: str) -> BearingData:
    return _boundary_record(designation, _series_table()[designation], SERIES_TABLE, f"{designation}.")


@dataclass(frozen=True)
class LubricantData:
    """A lubricant's parameters (SI) and its citations; :attr:`core` computes properties."""

    name: str
    description: str
    source_file: str
    parameters: _core.LubricantParameters
    limiting_shear_stress_tau0_Pa: float
    limiting_shear_stress_gamma: float
    cragoe_a_J_kgK: float
    cragoe_b_J_kgK2: float
    #: the quantities kegel estimated (:mod:`kegel.estimate`); empty for a measured data file
    estimated: tuple[str, ...] = ()
    #: how they were estimated (one paragraph, for the warning ``lubricant_estimated``)
    estimate_note: str = ""

    @property
    def core(self) -> _core.Lubricant:
        """The validated C++ lubricant object."""
        return _core.Lubricant(self.parameters)


@lru_cache(maxsize=32)
def _load_lubricant_file(path: Path) -> LubricantData:
    raw = read_toml(path)
    if "viscosity" in raw and "published" not in raw:
        tab = require_table(raw, "viscosity", path)
        nu40 = _nu40_mm2_s(tab, path, "viscosity.")
        return lubricant_from_viscosities(
            require_str(raw, "name", path), nu40_mm2_s=nu40,
            nu100_mm2_s=require_number(tab, "nu100_mm2_s", path, "viscosity.", positive=True),
            density_15C_kg_m3=require_number(tab, "density_15C_kg_m3", path, "viscosity.", positive=True),
            description=require_str(raw, "description", path, default=""), source=path, key="viscosity")
    pub = require_table(raw, "published", path)
    lit = require_table(raw, "literature", path)
    tau = require_table(lit, "limiting_shear_stress", path, "literature.")
    cp = require_table(lit, "specific_heat", path, "literature.")

    def n(key: str, **kw: Any) -> float:
        return require_number(pub, key, path, "published.", **kw)

    par = _core.LubricantParameters()
    par.vogel_K_Pas = n("vogel_K_mPas", positive=True) * 1e-3
    par.vogel_B_K = n("vogel_B_degC", positive=True)
    par.vogel_C_degC = n("vogel_C_degC")
    par.dicke_a1_bar = n("dicke_a1_bar", positive=True)
    par.dicke_a2_bar_per_K = n("dicke_a2_bar_per_degC")
    par.dicke_b1 = n("dicke_b1")
    par.dicke_b2_per_K = n("dicke_b2_per_degC")
    par.density_ref_kg_m3 = n("density_15C_kg_m3", positive=True)
    par.density_ref_temperature_K = n("density_reference_temperature_degC") + 273.15
    # g/(ml K) -> kg/(m^3 K): 1 g/ml = 1000 kg/m^3
    par.density_slope_kg_m3_K = n("density_temperature_coefficient_g_per_ml_K") * 1000.0
    par.thermal_conductivity_W_mK = n("thermal_conductivity_W_mK", positive=True)
    try:
        _core.Lubricant(par)  # the C++ value type checks every field
    except ValueError as exc:
        raise KegelInputError(path, "published", "(parameters)", str(exc)) from None
    return LubricantData(
        name=require_str(raw, "name", path),
        description=require_str(raw, "description", path, default=""),
        source_file=str(path),
        parameters=par,
        limiting_shear_stress_tau0_Pa=require_number(
            tau, "tau_L0_MPa", path, "literature.limiting_shear_stress.", nonnegative=True
        ) * 1e6,
        limiting_shear_stress_gamma=require_number(
            tau, "gamma_L", path, "literature.limiting_shear_stress.", positive=True
        ),
        cragoe_a_J_kgK=require_number(cp, "cragoe_a_kJ_kgK", path, "literature.specific_heat.", positive=True) * 1e3,
        cragoe_b_J_kgK2=require_number(cp, "cragoe_b_kJ_kgK2", path, "literature.specific_heat.") * 1e3,
    )


def _nu40_mm2_s(tab: dict[str, Any], path: str | Path, prefix: str) -> float:
    """nu40 from ``nu40_mm2_s`` or ``iso_vg`` (ISO 3448: the VG is the mid-point nu40); exactly one."""
    if ("nu40_mm2_s" in tab) == ("iso_vg" in tab):
        raise KegelInputError(path, f"{prefix}nu40_mm2_s", tab.get("nu40_mm2_s"),
                              "exactly one of nu40_mm2_s or iso_vg (ISO 3448 grade, its mid-point viscosity at "
                              "40 degC)")
    if "iso_vg" in tab:
        vg = require_number(tab, "iso_vg", path, prefix, positive=True)
        if vg not in ISO_VG_GRADES:
            raise KegelInputError(path, f"{prefix}iso_vg", vg, "an ISO 3448 grade (" + ", ".join(
                f"{g:g}" for g in ISO_VG_GRADES) + ")")
        return float(vg)
    return require_number(tab, "nu40_mm2_s", path, prefix, positive=True)


#: ISO 3448 viscosity grades (mid-point kinematic viscosity at 40 degC, mm^2/s).
ISO_VG_GRADES = (2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680, 1000, 1500, 2200, 3200)


def lubricant_from_viscosities(name: str, *, nu40_mm2_s: float, nu100_mm2_s: float, density_15C_kg_m3: float,
                               description: str = "", source: str | Path = "<argument>",
                               key: str = "lubricant") -> LubricantData:
    """A lubricant from two kinematic viscosities and its density, the laws estimated.

    Vogel (Eq. 8) through the two viscosities and a third on their ASTM D341 line, Dicke's ``a1``,
    ``a2`` (Eq. 7) from the So-Klaus pressure-viscosity coefficient (:func:`kegel.estimate.estimate_oil`).
    What two viscosities cannot give is transferred from the reference oil FVA 3 (Table A1 and its
    data file): the density's temperature coefficient, Dicke's ``b1``, ``b2``, the thermal
    conductivity, the limiting shear stress and Cragoe's specific heat.

    Raises
    ------
    KegelInputError
        Viscosities or density no lubricating oil has (naming ``source`` and ``key``).
    """
    ref = _load_lubricant_file(DATA_DIR / "lubricants" / f"{REFERENCE_LUBRICANT}.toml")
    rp = ref.parameters
    try:
        est = estimate_oil(nu40_mm2_s, nu100_mm2_s, density_15C_kg_m3, rp.density_slope_kg_m3_K)
    except EstimateError as exc:
        raise KegelInputError(source, key, f"nu40 = {nu40_mm2_s:g} mm^2/s, nu100 = {nu100_mm2_s:g} mm^2/s",
                              f"the viscosities of a lubricating oil ({exc})") from None
    par = _core.LubricantParameters()
    par.vogel_K_Pas = est.vogel_K_mPas * 1e-3
    par.vogel_B_K = est.vogel_B_degC
    par.vogel_C_degC = est.vogel_C_degC
    par.dicke_a1_bar = est.dicke_a1_bar
    par.dicke_a2_bar_per_K = est.dicke_a2_bar_per_degC
    par.dicke_b1 = rp.dicke_b1
    par.dicke_b2_per_K = rp.dicke_b2_per_K
    par.density_ref_kg_m3 = density_15C_kg_m3
    par.density_ref_temperature_K = 15.0 + 273.15
    par.density_slope_kg_m3_K = rp.density_slope_kg_m3_K
    par.thermal_conductivity_W_mK = rp.thermal_conductivity_W_mK
    try:
        _core.Lubricant(par)
    except ValueError as exc:
        raise KegelInputError(source, key, name, f"viscosities whose estimated laws are valid ({exc})") from None
    return LubricantData(
        name=name, description=description or f"estimated from nu40 = {nu40_mm2_s:g}, nu100 = {nu100_mm2_s:g} mm^2/s",
        source_file=str(source), parameters=par,
        limiting_shear_stress_tau0_Pa=ref.limiting_shear_stress_tau0_Pa,
        limiting_shear_stress_gamma=ref.limiting_shear_stress_gamma,
        cragoe_a_J_kgK=ref.cragoe_a_J_kgK, cragoe_b_J_kgK2=ref.cragoe_b_J_kgK2,
        estimated=("vogel", "pressure_viscosity", "density_temperature_coefficient", "dicke_b",
                   "thermal_conductivity", "limiting_shear_stress"),
        estimate_note=est.note + f"; density slope, Dicke b1/b2, conductivity, limiting shear stress from {ref.name}",
    )


def load_lubricant(name: str, *, source: str | Path = "<argument>", key: str = "lubricant") -> LubricantData:
    """Load a lubricant by name (``"FVA3"``) or from a TOML file path."""
    return _load_lubricant_file(_resolve(str(name), "lubricants", "lubricant", source, key))


@dataclass(frozen=True)
class MaterialData:
    """An elastic solid material in SI units."""

    name: str
    youngs_modulus_Pa: float
    poisson_ratio: float
    density_kg_m3: float

    @property
    def core(self) -> _core.ElasticMaterial:
        """The validated C++ material object."""
        return _core.ElasticMaterial(self.youngs_modulus_Pa, self.poisson_ratio, self.density_kg_m3)


@lru_cache(maxsize=32)
def _load_material_file(path: Path) -> MaterialData:
    raw = read_toml(path)
    nu = require_number(raw, "poisson_ratio", path)
    if not -1.0 < nu < 0.5:
        raise KegelInputError(path, "poisson_ratio", nu, "a value in (-1, 0.5)")
    mat = MaterialData(
        name=require_str(raw, "name", path),
        youngs_modulus_Pa=require_number(raw, "youngs_modulus_GPa", path, positive=True) * 1e9,
        poisson_ratio=nu,
        density_kg_m3=require_number(raw, "density_kg_m3", path, positive=True),
    )
    return mat


def load_material(name: str, *, source: str | Path = "<argument>", key: str = "material") -> MaterialData:
    """Load a solid material by name (``"bearing_steel"``) or from a TOML file path."""
    return _load_material_file(_resolve(str(name), "materials", "material", source, key))


def cragoe_specific_heat_J_kgK(lub: LubricantData, temperature_K: float) -> float:
    """Specific heat of a petroleum oil by Cragoe's correlation (see the data file)."""
    sg = lub.parameters.density_ref_kg_m3 / 999.0
    theta = temperature_K - 273.15
    return (lub.cragoe_a_J_kgK + lub.cragoe_b_J_kgK2 * theta) / math.sqrt(sg)
