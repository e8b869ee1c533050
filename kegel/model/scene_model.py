"""The typed scene model: what every entry point builds before anything is solved.

A scene file (:func:`kegel.scene.load_scene`), its ``--set`` overrides, the file ``kegel init``
writes and the Python API (:class:`kegel.Bearing`) all construct one :class:`SceneSpec`: frozen
dataclasses holding the scene's values in SI units, each quantity read once by the grammar of
:mod:`kegel.units`. One validation layer, :func:`kegel.scene.validate_scene`, then checks every
range and every cross-check of a :class:`SceneSpec` against the bearing and the oil and resolves
it into the :class:`kegel.scene.Scene` the solutions take; ``kegel check`` and ``kegel run`` call
the same function.

Two layers, each with one job:

* :func:`parse_scene` (and the API's builder) turns what was written into typed values: the
  table's keys, the types, the quantity grammar, the words of a choice. Its errors name the file
  (or ``--set``), the key, the value and what was expected.
* :func:`kegel.scene.validate_scene` checks the values: ranges (speed factor, temperatures of
  the oil's formulas, loads within C0r, lift-off, slices, ...), cross-checks between sections
  (an oil level within D, hydraulic loss and lubrication, fidelity ``auto`` and its keys) and
  resolves oil levels and presets.

Every value keeps where it came from (``key``: the scene's dotted key or the API's argument;
``written``: the value as given) outside the comparison, so a scene file and the API call with
the same values give equal models (``SceneSpec.__eq__`` compares the values, not their spelling).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..base.errors import KegelInputError
from ..base.units import parse_quantity
from .options import MAX_SLICES, ROLLING_THERMAL_MODELS, SUPPLY_MODELS

__all__ = [
    "BearingSpec",
    "DynamicSettings",
    "LubricantSpec",
    "LubricationSpec",
    "ModelOptions",
    "OperatingSpec",
    "Scalar",
    "SceneSpec",
    "StudySpec",
    "Sweep",
    "parse_scene",
]

#: Largest number of operating points in one scene (the product of its sweeps), checked before
#: any point is built: a quasi-static point costs 10-1000 ms and its record about 5 kB.
MAX_OPERATING_POINTS = 100_000
#: Dynamic runs: simulated time, output interval and number of outputs per point.
MAX_DYNAMIC_DURATION_S = 10.0
MIN_OUTPUT_INTERVAL_S = 1e-6
MAX_DYNAMIC_OUTPUTS = 200_000

ALLOWED_KEYS: dict[str, set[str]] = {
    "scene": {"name", "description"},
    # a designation, or boundary dimensions (kegel.data.BEARING_SCENE_KEYS, estimated geometry)
    "bearing": {"designation", "material", "d", "D", "T", "B", "C", "e", "alpha", "Z", "C0r", "Y"},
    # a name, or viscosities (kegel.data.LUBRICANT_SCENE_KEYS, estimated laws)
    "lubricant": {"name", "nu40_mm2_s", "iso_vg", "nu100_mm2_s", "density_15C_kg_m3", "description"},
    "operating": {
        "axial_load", "axial_offset", "radial_load", "tilt_moment", "misalignment", "speed",
        "temperature", "inner_ring_temperature", "outer_ring_temperature",
    },
    "lubrication": {"mode", "oil_level"},
    "model": {"fidelity", "slices", "slice_model", "rib_model", "rib_cells", "cage", "solution", "hydraulic",
              "cfd_results", "tolerance", "rolling_thermal", "inlet_gap_ratio", "lubricant_supply",
              "contact_film_limit"},
    "dynamic": {"duration", "max_duration", "output_interval", "speed_profile", "hold_axial", "tilt_free", "average_fraction",
                "tolerance", "checkpoint_interval", "threads", "load_profile"},
    "output": {"directory"},
    "study": {"lubrication", "hydraulic", "cfd_results"},
}
REQUIRED_SECTIONS = ("bearing", "lubricant", "operating", "lubrication")
#: Hydraulic-loss methods a study compares: Liebrecht's correlation (seed paper Eq. 38-40), the
#: SKF catalogue model's drag moment, kegel's OpenFOAM results.
HYDRAULIC_METHODS = ("liebrecht", "skf", "cfd")
OIL_LEVEL_WORDS = ("none", "half_roller", "shaft_center", "flooded")
FIDELITY_NAMES = ("fast", "default", "fine", "auto")
MODEL_CHOICES: dict[str, tuple[str, ...]] = {
    "slice_model": ("alternative_slicing", "independent"),
    "rib_model": ("cell", "hertz"),
    "solution": ("quasi_static", "dynamic"),
    "hydraulic": ("none", "correlation", "cfd"),
    "rolling_thermal": ROLLING_THERMAL_MODELS,
    "lubricant_supply": SUPPLY_MODELS,
}
AUTO_TOLERANCE = 0.01
#: ``[operating]`` keys of the contact temperature per ring (issue 27, item 6): optional, one value
#: each; absent, the ring's contacts run at the oil temperature (``temperature``)
RING_TEMPERATURE_KEYS = ("inner_ring_temperature", "outer_ring_temperature")
#: operating quantity -> kind of quantity (kegel.units)
OPERATING_KINDS = {"axial_load": "force", "axial_offset": "length", "radial_load": "force",
                   "speed": "speed", "temperature": "temperature"}


# --- values that remember where they came from -----------------------------------------------------

@dataclass(frozen=True)
class Scalar:
    """One quantity in SI units, with the key that gave it and the value as written (both
    outside the comparison)."""

    value: float
    key: str = field(default="", compare=False)
    written: Any = field(default=None, compare=False)


@dataclass(frozen=True)
class Sweep:
    """The values of one swept operating quantity in SI units (one value, a list or a range).

    ``key`` is the dotted scene key (``operating.speed``) or the API's argument (``speed_rpm``);
    ``written`` the value as given (a string, a list, a ``{from, to, points}`` table, numbers).
    """

    values: tuple[float, ...]
    key: str = field(default="", compare=False)
    written: Any = field(default=None, compare=False)

    def item_key(self, i: int) -> str:
        """The key naming value ``i``: the sweep's key for a single value, ``key[i]`` in a list."""
        return f"{self.key}[{i}]" if isinstance(self.written, (list, tuple, dict)) else self.key

    def item_written(self, i: int) -> Any:
        """Value ``i`` as written (a range's values: the SI number)."""
        if isinstance(self.written, (list, tuple)):
            return self.written[i]
        if isinstance(self.written, dict):
            return self.values[i]
        return self.written


def _frozen_table(table: dict[str, Any]) -> tuple[tuple[str, Any], ...]:
    return tuple(sorted(((str(k), _freeze(v)) for k, v in table.items()), key=lambda kv: kv[0]))


def _freeze(v: Any) -> Any:
    if isinstance(v, list):
        return tuple(_freeze(x) for x in v)
    if isinstance(v, dict):
        return _frozen_table(v)
    return v


def _thaw(v: Any) -> Any:
    if isinstance(v, tuple):
        return [_thaw(x) for x in v]
    return v


# --- the sections ------------------------------------------------------------------------------------

@dataclass(frozen=True)
class BearingSpec:
    """The ``[bearing]`` table: a designation (shipped data, the ISO 355 series table, a file) or
    boundary dimensions; resolved into :class:`kegel.data.BearingData` by the validation (which
    reads the data files)."""

    entries: tuple[tuple[str, Any], ...]

    @classmethod
    def of(cls, table: dict[str, Any]) -> "BearingSpec":
        return cls(_frozen_table(table))

    def table(self) -> dict[str, Any]:
        """The table as a scene file writes it."""
        return {k: _thaw(v) for k, v in self.entries}

    @property
    def material(self) -> str:
        """The material's name or file (default ``bearing_steel``)."""
        return str(self.table().get("material", "bearing_steel"))


@dataclass(frozen=True)
class LubricantSpec:
    """The ``[lubricant]`` table: a shipped oil's name (or a file) or viscosities."""

    entries: tuple[tuple[str, Any], ...]

    @classmethod
    def of(cls, table: dict[str, Any]) -> "LubricantSpec":
        return cls(_frozen_table(table))

    def table(self) -> dict[str, Any]:
        """The table as a scene file writes it."""
        return {k: _thaw(v) for k, v in self.entries}


@dataclass(frozen=True)
class OperatingSpec:
    """The ``[operating]`` table in SI units: exactly one of ``axial_load`` [N] and
    ``axial_offset`` [m]; ``radial_load`` [N] (default 0), ``speed`` [rad/s], ``temperature``
    [K]; ``tilt_moment`` [N m] and ``misalignment`` [rad] (default 0); ``inner_ring_temperature``
    and ``outer_ring_temperature`` [K]: the contact temperature of each ring's contacts (the inner
    ring's raceway and rib, the outer ring's raceway), one value each (not swept); ``None``: the
    oil temperature of the point."""

    speed: Sweep
    temperature: Sweep
    axial_load: Sweep | None = None
    axial_offset: Sweep | None = None
    radial_load: Sweep = Sweep((0.0,), "operating.radial_load", "0 kN")
    tilt_moment: Scalar = Scalar(0.0, "operating.tilt_moment", "0 N m")
    misalignment: Scalar = Scalar(0.0, "operating.misalignment", "0 rad")
    inner_ring_temperature: Scalar | None = None
    outer_ring_temperature: Scalar | None = None
    #: the dotted keys given (the others are defaults)
    given: tuple[str, ...] = field(default=(), compare=False)

    def sweeps(self) -> dict[str, Sweep]:
        """The swept quantities present, by name."""
        out = {"axial_load": self.axial_load, "axial_offset": self.axial_offset, "radial_load": self.radial_load,
               "speed": self.speed, "temperature": self.temperature}
        return {k: v for k, v in out.items() if v is not None}


@dataclass(frozen=True)
class LubricationSpec:
    """The ``[lubrication]`` table: ``mode`` (``oil_bath`` or ``minimum_quantity``) and the oil
    level as a word of :data:`OIL_LEVEL_WORDS` or a height [m] above the lowest point of the outer
    diameter (resolved against the bearing's D by the validation); ``None``: not given."""

    mode: str
    oil_level: str | float | None
    key: str = field(default="lubrication.oil_level", compare=False)
    written: Any = field(default=None, compare=False)


@dataclass(frozen=True)
class ModelOptions:
    """The ``[model]`` table: the fidelity preset and the keys that override it (``None``: the
    preset's value). The validation checks the ranges and the cross-checks and resolves them
    into a :class:`kegel.scene.Fidelity`."""

    fidelity: str = "default"
    tolerance: float | None = None
    slices: int | None = None
    slice_model: str | None = None
    rib_model: str | None = None
    rib_cells: int | None = None
    cage: bool | None = None
    solution: str | None = None
    hydraulic: str | None = None
    cfd_results: str | None = None
    rolling_thermal: str | None = None
    inlet_gap_ratio: float | None = None
    lubricant_supply: str | None = None
    contact_film_limit_m: float | None = None
    #: each key as written (for the messages)
    written: tuple[tuple[str, Any], ...] = field(default=(), compare=False)

    def given(self, key: str) -> bool:
        """Whether the scene wrote ``model.<key>``."""
        return any(k == key for k, _ in self.written)

    def as_written(self, key: str) -> Any:
        """``model.<key>`` as written (None when not given)."""
        return next((v for k, v in self.written if k == key), None)


@dataclass(frozen=True)
class StudySpec:
    """The ``[study]`` table: lubrications (oil levels, ``minimum_quantity``) and methods."""

    #: each lubrication: ``minimum_quantity``/``none``, an oil-level word or a height [m]
    levels: tuple[str | float, ...]
    methods: tuple[str, ...]
    cfd_results: str | None = None
    #: the lubrications as written
    lubrication: tuple[Any, ...] = field(default=(), compare=False)


@dataclass(frozen=True)
class DynamicSettings:
    """The ``[dynamic]`` table of a scene (SI units; see :mod:`kegel.scene`).

    ``speed_profile`` is a tuple of (time_s, speed_rad_s) pairs, or empty for a constant speed at
    the operating point's speed.
    """

    duration_s: float = 0.02
    output_interval_s: float = 1e-4
    speed_profile: tuple[tuple[float, float], ...] = ()
    hold_axial: bool = False
    tilt_free: bool = False
    average_fraction: float = 0.5
    tolerance: float = 1e-7
    checkpoint_interval_s: float = 5e-3
    threads: int = 0   # 0: every core the process may use
    load_profile: tuple[tuple[float, float, float], ...] = ()
    #: automatic duration (``dynamic.max_duration``): a point whose torques and cage speed have not
    #: settled by ``duration_s`` runs on, a quarter of it at a time, up to this; None: exactly
    #: ``duration_s`` (:func:`kegel.dynamics.simulate`)
    max_duration_s: float | None = None

    def as_dict(self) -> dict[str, Any]:
        """Plain dictionary, written next to every result."""
        d = dict(self.__dict__)
        d["speed_profile"] = [list(p) for p in self.speed_profile]
        d["load_profile"] = [list(p) for p in self.load_profile]
        return d


@dataclass(frozen=True)
class SceneSpec:
    """A scene as written, typed: what :func:`kegel.scene.validate_scene` checks and resolves.

    ``source`` (the file, ``kegel.Bearing.friction``), ``overridden`` (the keys ``--set``
    changed) and ``raw`` (the scene dictionary, written next to the results) are outside the
    comparison.
    """

    name: str
    description: str
    bearing: BearingSpec
    lubricant: LubricantSpec
    operating: OperatingSpec
    lubrication: LubricationSpec | None
    model: ModelOptions = ModelOptions()
    dynamic: DynamicSettings = DynamicSettings()
    study: StudySpec | None = None
    output_directory: str | None = None
    source: str = field(default="<dict>", compare=False)
    overridden: tuple[str, ...] = field(default=(), compare=False)
    raw: dict[str, Any] = field(default_factory=dict, compare=False, repr=False)
    #: the [dynamic] table as written (the validation names its entries)
    dynamic_written: dict[str, Any] = field(default_factory=dict, compare=False, repr=False)


# --- the parser of scene dictionaries (TOML files, --set, kegel init) ---------------------------------

class Reader:
    """Reading helper that knows where each value came from: ``source`` is the file (or the
    API's entry point), ``overridden`` the dotted keys ``--set`` gave."""

    def __init__(self, path: str, overridden: set[str] | tuple[str, ...] = ()) -> None:
        self.path = path
        self.overridden = set(overridden)

    def src(self, key: str) -> str:
        """The source to name for ``key``: the file, or the file with ``(--set key)``."""
        top = key.split("[")[0]
        hit = key if key in self.overridden else (top if top in self.overridden else None)
        return f"{self.path} (--set {hit})" if hit else self.path

    def error(self, key: str, value: Any, expected: str) -> KegelInputError:
        """A :class:`KegelInputError` naming the source of ``key``."""
        return KegelInputError(self.src(key), key, value, expected)

    def quantity(self, value: Any, kind: str, key: str) -> float:
        """One quantity in SI units (grammar of :mod:`kegel.units`)."""
        return parse_quantity(value, kind, source=self.src(key), key=key)

    def sweep(self, value: Any, kind: str, key: str) -> list[float]:
        """One value, a list of values, or {from, to, points}: a list of SI floats."""
        if isinstance(value, str):
            return [self.quantity(value, kind, key)]
        if isinstance(value, list):
            if not value:
                raise self.error(key, value, "a sweep with at least one point")
            return [self.quantity(v, kind, f"{key}[{i}]") for i, v in enumerate(value)]
        if isinstance(value, dict):
            unknown = set(value) - {"from", "to", "points"}
            if unknown:
                raise self.error(f"{key}.{sorted(unknown)[0]}", value[sorted(unknown)[0]],
                                 "only the keys from, to, points in a range")
            for k in ("from", "to", "points"):
                if k not in value:
                    raise self.error(f"{key}.{k}", None, "a range {from = ..., to = ..., points = N}")
            points = value["points"]
            if isinstance(points, bool) or not isinstance(points, int) or points < 1:
                raise self.error(f"{key}.points", points, "a sweep with at least one point (an integer >= 1)")
            if points > MAX_OPERATING_POINTS:
                raise self.error(f"{key}.points", points, f"at most {MAX_OPERATING_POINTS} points (kegel's sweep limit)")
            lo = self.quantity(value["from"], kind, f"{key}.from")
            hi = self.quantity(value["to"], kind, f"{key}.to")
            if points == 1:
                if lo != hi:
                    raise self.error(f"{key}.points", points, "points >= 2 when from and to differ")
                return [lo]
            return [float(v) for v in np.linspace(lo, hi, points)]
        # a bare number or another type: the quantity parser explains what a value needs
        return [self.quantity(value, kind, key)]

    def choice(self, table: dict, key: str, prefix: str, choices: tuple[str, ...], default: str | None) -> str:
        """``table[key]``, one of ``choices`` (``default`` when absent; None: required)."""
        full = f"{prefix}.{key}"
        if key not in table:
            if default is None:
                raise self.error(full, None, f"one of {', '.join(choices)}")
            return default
        value = table[key]
        if not isinstance(value, str) or value not in choices:
            raise self.error(full, value, f"one of {', '.join(choices)}")
        return value


def check_keys(reader: Reader, raw: dict[str, Any]) -> None:
    """The scene's sections and keys: known, tables where tables belong, the required ones."""
    for section, value in raw.items():
        if section not in ALLOWED_KEYS:
            raise reader.error(section, value if not isinstance(value, dict) else "(table)",
                               f"a known section ({', '.join(ALLOWED_KEYS)})")
        if not isinstance(value, dict):
            raise reader.error(section, value, f"a table [{section}]")
        for key in value:
            if key not in ALLOWED_KEYS[section]:
                raise reader.error(f"{section}.{key}", value[key],
                                   f"a known key of [{section}] ({', '.join(sorted(ALLOWED_KEYS[section]))})")
    for section in REQUIRED_SECTIONS:
        if section not in raw and not (section == "lubrication" and "study" in raw):
            raise reader.error(section, None, f"a table [{section}]")
    if "study" in raw:
        if "lubrication" in raw:
            raise reader.error("lubrication", "(table)", "no [lubrication] table beside [study] "
                               "(study.lubrication lists the lubrications compared)")
        if "hydraulic" in raw.get("model", {}):
            raise reader.error("model.hydraulic", raw["model"]["hydraulic"],
                               "no value beside [study] (study.hydraulic lists the methods compared)")


def parse_operating(reader: Reader, op: dict[str, Any]) -> OperatingSpec:
    """The ``[operating]`` table as an :class:`OperatingSpec` (grammar and structure; the ranges
    are the validation's)."""
    if ("axial_load" in op) == ("axial_offset" in op):
        raise reader.error(
            "operating.axial_load", op.get("axial_load"),
            "exactly one of axial_load (force-controlled) and axial_offset (displacement-controlled preload)",
        )
    for key in ("speed", "temperature"):
        if key not in op:
            raise reader.error(f"operating.{key}", None, "a value, a list or a range {from, to, points}")
    sweeps: dict[str, Sweep] = {}
    for key, kind in OPERATING_KINDS.items():
        if key in op:
            values = reader.sweep(op[key], kind, f"operating.{key}")
            sweeps[key] = Sweep(tuple(values), f"operating.{key}", op[key])
    kw: dict[str, Any] = dict(sweeps)
    for key, kind in (("tilt_moment", "moment"), ("misalignment", "angle")):
        if key in op:
            kw[key] = Scalar(reader.quantity(op[key], kind, f"operating.{key}"), f"operating.{key}", op[key])
    for key in RING_TEMPERATURE_KEYS:  # one value each (a contact temperature per ring), not swept
        if key in op:
            if isinstance(op[key], (list, dict)):
                raise reader.error(f"operating.{key}", op[key], "one temperature with its unit, e.g. '60 degC' (a "
                                   "contact temperature per ring is not swept; sweep operating.temperature)")
            kw[key] = Scalar(reader.quantity(op[key], "temperature", f"operating.{key}"), f"operating.{key}", op[key])
    return OperatingSpec(**kw, given=tuple(f"operating.{k}" for k in op))


def parse_lubrication(reader: Reader, table: dict[str, Any]) -> LubricationSpec:
    """The ``[lubrication]`` table: the mode's word, the oil level's word or length."""
    mode = reader.choice(table, "mode", "lubrication", ("oil_bath", "minimum_quantity"), None)
    key = "lubrication.oil_level"
    if "oil_level" not in table:
        return LubricationSpec(mode, None, key, None)
    written = table["oil_level"]
    return LubricationSpec(mode, parse_oil_level(reader, written, key), key, written)


def parse_oil_level(reader: Reader, written: Any, key: str) -> str | float:
    """An oil level: one of :data:`OIL_LEVEL_WORDS`, or a length [m]."""
    if isinstance(written, str) and written in OIL_LEVEL_WORDS:
        return written
    return reader.quantity(written, "length", key)


def parse_model(reader: Reader, model: dict[str, Any]) -> ModelOptions:
    """The ``[model]`` table's types and words (ranges and cross-checks: the validation)."""
    kw: dict[str, Any] = {}
    preset = model.get("fidelity", "default")
    if not isinstance(preset, str) or preset not in FIDELITY_NAMES:
        raise reader.error("model.fidelity", preset, f"one of {', '.join(FIDELITY_NAMES[:-1])} or auto")
    kw["fidelity"] = preset
    if "tolerance" in model:
        v = model["tolerance"]
        x: Any = v
        if isinstance(v, str) and v.strip().endswith("%"):
            try:
                x = float(v.strip()[:-1]) / 100.0
            except ValueError:
                x = None
        if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x):
            raise reader.error("model.tolerance", v, 'a fraction in (0, 0.5] or a per-cent string such as "1 %"')
        kw["tolerance"] = float(x)
    for key in ("slices", "rib_cells"):
        if key in model:
            v = model[key]
            if isinstance(v, bool) or not isinstance(v, int):
                lo, hi = INT_RANGES[key]
                raise reader.error(f"model.{key}", v, f"an integer in [{lo}, {hi}]")
            kw[key] = v
    if "cage" in model:
        if not isinstance(model["cage"], bool):
            raise reader.error("model.cage", model["cage"], "true or false")
        kw["cage"] = model["cage"]
    for key, choices in MODEL_CHOICES.items():
        if key in model:
            kw[key] = reader.choice(model, key, "model", choices, None)
    if "inlet_gap_ratio" in model:
        v = model["inlet_gap_ratio"]
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise reader.error("model.inlet_gap_ratio", v,
                               "0 (fully flooded) or a ratio >= 2 (Biboulet-Houpert's starvation range)")
        kw["inlet_gap_ratio"] = float(v)
    if "contact_film_limit" in model:
        kw["contact_film_limit_m"] = reader.quantity(model["contact_film_limit"], "length", "model.contact_film_limit")
    if "cfd_results" in model:
        kw["cfd_results"] = model["cfd_results"]
    return ModelOptions(**kw, written=tuple((k, _freeze(v)) for k, v in model.items()))


#: model.slices and model.rib_cells: the ranges the run accepts (the validation checks them)
INT_RANGES = {"slices": (2, MAX_SLICES), "rib_cells": (4, 512)}


def parse_study(reader: Reader, table: dict[str, Any]) -> StudySpec:
    """The ``[study]`` table's types (the oil levels are resolved by the validation)."""
    cases = table.get("lubrication")
    if not isinstance(cases, list) or not cases:
        raise reader.error("study.lubrication", cases, "a list of lubrications, e.g. [\"flooded\", "
                           "\"shaft_center\", \"minimum_quantity\"] (oil levels or minimum_quantity)")
    levels: list[str | float] = []
    for i, c in enumerate(cases):
        if not isinstance(c, str):
            raise reader.error(f"study.lubrication[{i}]", c, f"minimum_quantity or an oil level "
                               f"({', '.join(OIL_LEVEL_WORDS[1:])}, or a length in (0, D])")
        levels.append(c if c in ("minimum_quantity", "none") else
                      parse_oil_level(reader, c, f"study.lubrication[{i}]"))
    methods = table.get("hydraulic", ["liebrecht", "skf"])
    if isinstance(methods, str):
        methods = [methods]
    if not isinstance(methods, list) or not methods:
        raise reader.error("study.hydraulic", methods, f"a list of methods among {', '.join(HYDRAULIC_METHODS)}")
    for i, m in enumerate(methods):
        if not isinstance(m, str) or m not in HYDRAULIC_METHODS:
            raise reader.error(f"study.hydraulic[{i}]", m, f"one of {', '.join(HYDRAULIC_METHODS)}")
    return StudySpec(tuple(levels), tuple(methods), table.get("cfd_results"), lubrication=tuple(cases))


def parse_dynamic(reader: Reader, table: dict[str, Any]) -> DynamicSettings:
    """The ``[dynamic]`` table as :class:`DynamicSettings` (its own limits included: they need
    nothing but the table; the profiles' limits against the bearing are the validation's)."""
    kw: dict[str, Any] = {}
    for key, attr in (("duration", "duration_s"), ("output_interval", "output_interval_s"),
                      ("checkpoint_interval", "checkpoint_interval_s"), ("max_duration", "max_duration_s")):
        if key in table:
            v = reader.quantity(table[key], "time", f"dynamic.{key}")
            if not v > 0:
                raise reader.error(f"dynamic.{key}", table[key], "a time > 0")
            kw[attr] = v
    if kw.get("output_interval_s", 1e-4) > kw.get("duration_s", 0.02):
        raise reader.error("dynamic.output_interval", table.get("output_interval"), "at most the duration")
    if kw.get("duration_s", 0.02) > MAX_DYNAMIC_DURATION_S:
        raise reader.error("dynamic.duration", table.get("duration"),
                           f"at most {MAX_DYNAMIC_DURATION_S:g} s of simulated time (time steps are microseconds)")
    if "max_duration_s" in kw and not kw.get("duration_s", 0.02) <= kw["max_duration_s"] <= MAX_DYNAMIC_DURATION_S:
        raise reader.error("dynamic.max_duration", table.get("max_duration"),
                           f"a time from dynamic.duration ({kw.get('duration_s', 0.02) * 1e3:g} ms) to "
                           f"{MAX_DYNAMIC_DURATION_S:g} s: how long a point that has not settled may run on")
    if kw.get("output_interval_s", 1e-4) < MIN_OUTPUT_INTERVAL_S:
        raise reader.error("dynamic.output_interval", table.get("output_interval"),
                           f"at least {MIN_OUTPUT_INTERVAL_S * 1e6:g} us")
    outputs = max(kw.get("duration_s", 0.02), kw.get("max_duration_s") or 0.0) / kw.get("output_interval_s", 1e-4)
    if outputs > MAX_DYNAMIC_OUTPUTS:
        raise reader.error("dynamic.output_interval", table.get("output_interval"),
                           f"at most {MAX_DYNAMIC_OUTPUTS} outputs per point (here {outputs:.3g}: every output keeps "
                           "the state of every body)")
    for key in ("hold_axial", "tilt_free"):
        if key in table:
            if not isinstance(table[key], bool):
                raise reader.error(f"dynamic.{key}", table[key], "true or false")
            kw[key] = table[key]
    if "load_profile" in table:
        prof = table["load_profile"]
        if not isinstance(prof, list) or not prof:
            raise reader.error("dynamic.load_profile", prof, 'a list of ["time", "axial load", "radial load"] triples')
        pts = []
        for i, row in enumerate(prof):
            if not (isinstance(row, list) and len(row) == 3):
                raise reader.error(f"dynamic.load_profile[{i}]", row, 'a triple ["10 ms", "6 kN", "2 kN"]')
            t = reader.quantity(row[0], "time", f"dynamic.load_profile[{i}][0]")
            fa = reader.quantity(row[1], "force", f"dynamic.load_profile[{i}][1]")
            fr = reader.quantity(row[2], "force", f"dynamic.load_profile[{i}][2]")
            if fa < 0 or fr < 0:
                raise reader.error(f"dynamic.load_profile[{i}]", row, "loads >= 0")
            if pts and not t > pts[-1][0]:
                raise reader.error(f"dynamic.load_profile[{i}][0]", row[0], "times increasing along the profile")
            pts.append((t, fa, fr))
        kw["load_profile"] = tuple(pts)
    if "threads" in table:
        v = table["threads"]
        if isinstance(v, bool) or not isinstance(v, int) or not 1 <= v <= 64:
            raise reader.error("dynamic.threads", v, "an integer in [1, 64]")
        kw["threads"] = v
    for key, lo, hi in (("average_fraction", 0.0, 1.0), ("tolerance", 1e-12, 1e-3)):
        if key in table:
            v = table[key]
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not (lo < v <= hi):
                raise reader.error(f"dynamic.{key}", v, f"a number in ({lo:g}, {hi:g}]")
            kw[key] = float(v)
    if "speed_profile" in table:
        prof = table["speed_profile"]
        if not isinstance(prof, list) or not prof:
            raise reader.error("dynamic.speed_profile", prof, 'a list of ["time", "speed"] pairs')
        pts2 = []
        for i, pair in enumerate(prof):
            if not (isinstance(pair, list) and len(pair) == 2):
                raise reader.error(f"dynamic.speed_profile[{i}]", pair, 'a pair ["10 ms", "2000 rpm"]')
            t = reader.quantity(pair[0], "time", f"dynamic.speed_profile[{i}][0]")
            w = reader.quantity(pair[1], "speed", f"dynamic.speed_profile[{i}][1]")
            if pts2 and not t > pts2[-1][0]:
                raise reader.error(f"dynamic.speed_profile[{i}][0]", pair[0], "times increasing along the profile")
            pts2.append((t, w))
        kw["speed_profile"] = tuple(pts2)
    return DynamicSettings(**kw)


def parse_scene(raw: dict[str, Any], *, source: str | Path = "<dict>",
                overridden: set[str] | tuple[str, ...] | None = None) -> SceneSpec:
    """A scene dictionary (a TOML file as read, after ``--set``) as a :class:`SceneSpec`.

    Checks the structure, the types, the quantity grammar and the words; the ranges and the
    cross-checks are :func:`kegel.scene.validate_scene`'s.

    Raises
    ------
    KegelInputError
        Naming the file (or ``--set``), the dotted key, the value and what was expected.
    """
    reader = Reader(str(source), set(overridden or ()))
    check_keys(reader, raw)
    meta = raw.get("scene", {})
    for key in ("name", "description"):
        if key in meta and not isinstance(meta[key], str):
            raise reader.error(f"scene.{key}", meta[key], "a string")
    stem = Path(str(source)).stem if str(source) != "<dict>" else "scene"
    out = raw.get("output", {}).get("directory")
    if "directory" in raw.get("output", {}) and (not isinstance(out, str) or not out):
        raise reader.error("output.directory", out, "a non-empty path string")
    operating = parse_operating(reader, raw["operating"])
    study = parse_study(reader, raw["study"]) if "study" in raw else None
    lubrication = parse_lubrication(reader, raw["lubrication"]) if study is None else None
    return SceneSpec(
        name=meta.get("name", stem),
        description=meta.get("description", ""),
        bearing=BearingSpec.of(raw["bearing"]),
        lubricant=LubricantSpec.of(raw["lubricant"]),
        operating=operating,
        lubrication=lubrication,
        model=parse_model(reader, raw.get("model", {})),
        dynamic=parse_dynamic(reader, raw.get("dynamic", {})),
        study=study,
        output_directory=out,
        source=str(source),
        overridden=tuple(sorted(overridden or ())),
        raw=raw,
        dynamic_written=raw.get("dynamic", {}),
    )

