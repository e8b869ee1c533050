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
from typing import Any

from . import _core
from ._toml import read_toml, require_number, require_str, require_table
from .errors import KegelInputError

__all__ = [
    "DATA_DIR",
    "BearingData",
    "LubricantData",
    "MaterialData",
    "available_bearings",
    "available_lubricants",
    "available_materials",
    "load_bearing",
    "load_lubricant",
    "load_material",
]

DATA_DIR = Path(__file__).resolve().parent / "data"
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


@lru_cache(maxsize=32)
def _load_bearing_file(path: Path) -> BearingData:
    raw = read_toml(path)
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
    """Load a bearing by designation (``"32216"``) or from a TOML file path.

    Raises
    ------
    KegelInputError
        Unknown designation (the message lists the known ones) or an invalid data file.
    """
    return _load_bearing_file(_resolve(str(name), "bearings", "bearing", source, key))


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

    @property
    def core(self) -> _core.Lubricant:
        """The validated C++ lubricant object."""
        return _core.Lubricant(self.parameters)


@lru_cache(maxsize=32)
def _load_lubricant_file(path: Path) -> LubricantData:
    raw = read_toml(path)
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
