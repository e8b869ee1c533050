"""Scene files: what to simulate, written in TOML with units (``"6 kN"``, ``"2000 rpm"``).

A scene names the bearing, the lubricant, the operating point or sweep, the lubrication and the
model fidelity. :func:`load_scene` validates it completely before anything runs; every error
names the file (or ``--set``), the dotted key, the value and what was expected.

The file (after ``--set``) is read into the typed scene model of :mod:`kegel.scene_model`
(:func:`kegel.scene_model.parse_scene`), the model the Python API and ``kegel init`` build too;
:func:`validate_scene`, the one validation layer, checks its ranges and cross-checks and
resolves it into a :class:`Scene`.

Layout (all sections but ``[scene]``, ``[model]`` and ``[output]`` are required)::

    [scene]
    name = "32216, Table 1"                  # optional
    description = "..."                      # optional

    [bearing]
    designation = "32216"                    # or "30210" (the ISO 355 series table), or a file
    material = "bearing_steel"               # optional
    # or boundary dimensions (internal geometry estimated, flagged geometry_estimated):
    # d = "50 mm", D = "90 mm", T = "21.75 mm", B = "20 mm", C = "17 mm", e = 0.43 (or
    # alpha = "16 deg"), C0r = "91.5 kN", Z = 18 (optional), Y = 1.4 (optional)

    [lubricant]
    name = "FVA3"                            # or a path to a lubricant .toml file
    # or an oil from its viscosities (laws estimated, flagged lubricant_estimated):
    # nu40_mm2_s = 220 (or iso_vg = 220), nu100_mm2_s = 19, density_15C_kg_m3 = 890

    [operating]                              # each quantity: one value, a list, or a range
    axial_load = "6 kN"                      # force-controlled (> 0) ... or instead:
    # axial_offset = "20 um"                 # displacement-controlled preload (axial offset)
    radial_load = "0 kN"                     # >= 0, optional (default 0)
    tilt_moment = "0 N m"                    # optional
    misalignment = "0 mrad"                  # optional, inner-ring tilt
    speed = { from = "500 rpm", to = "4000 rpm", points = 8 }   # inner-ring speed
    temperature = ["42 degC", "50 degC"]

    [lubrication]
    mode = "oil_bath"                        # or "minimum_quantity"
    oil_level = "half_roller"                # or none | shaft_center | flooded | a length in [0, D]
                                             # above the lowest point of the outer diameter

    [model]
    fidelity = "default"                     # fast | default | fine; the keys below override it;
                                             # or auto (with tolerance = "1 %"): kegel chooses
    # slices = 30, slice_model = "alternative_slicing", rib_model = "cell", rib_cells = 32,
    # cage = true, solution = "quasi_static", hydraulic = "correlation" (or "cfd" with
    # cfd_results = "results/cfd"), lubricant_supply = "kinematic_replenishment" (or "flooded"),
    # contact_film_limit = "0.2 mm" (the contact / CFD boundary; default: none)

    [dynamic]                                # optional, for solution = "dynamic"
    duration = "20 ms"                       # simulated time per operating point
    max_duration = "200 ms"                  # optional: run on until settled, at most this long
    output_interval = "0.1 ms"               # spacing of the recorded time series
    speed_profile = [["0 ms", "0 rpm"], ["50 ms", "4000 rpm"]]   # default: the point's speed
    hold_axial = false                       # hold the inner ring axially (partner bearing)
    tilt_free = false                        # let the inner ring tilt under operating.tilt_moment
    average_fraction = 0.5                   # steady-state averages over the last half
    tolerance = 1e-7                         # CVODE's relative tolerance
    checkpoint_interval = "5 ms"             # resume from the last checkpoint after an interrupt
    threads = 2                              # rollers in parallel (default: every available core)
    load_profile = [["0 ms", "6 kN", "0 kN"], ["20 ms", "6 kN", "8 kN"]]   # axial, radial over time

    [output]
    directory = "results/32216_table1"       # optional

A study compares lubrications and hydraulic-loss methods at the same operating points: a
``[study]`` table replaces ``[lubrication]`` (and ``model.hydraulic``); the contact friction is
solved once per operating point and lubrication (the raceway contacts' inlet supply depends on
the lubrication: :mod:`kegel.supply`) and every lubrication x method pair adds its hydraulic
loss::

    [study]
    lubrication = ["flooded", "shaft_center", "minimum_quantity"]   # oil levels as above, or
                                             # minimum_quantity (no oil bath: no hydraulic loss)
    hydraulic = ["liebrecht", "skf", "cfd"]  # methods (default: liebrecht and skf)
    cfd_results = "results/cfd"              # with "cfd": kegel cfd run results; speeds between
                                             # computed ones are interpolated (error stated),
                                             # missing ones named with the command that makes them
"""

from __future__ import annotations

import copy
import math
import itertools
import tomllib
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Any

import numpy as np

from ..base._toml import read_toml
from .data import (BearingData, LubricantData, MaterialData, bearing_from_scene, load_bearing, load_lubricant,
                   load_material, lubricant_from_scene)
from ..base.errors import KegelInputError
from .geometry import BearingGeometry, centrifugal_axial_load_N, derive_geometry
from .lubricant import TEMPERATURE_RANGE_DEGC, lubricant_state  # one temperature range for every entry point
from ..base.limits import MAX_SPEED_FACTOR_RPM_MM as _MAX_SPEED_FACTOR_RPM_MM
from .scene_model import (ALLOWED_KEYS, AUTO_TOLERANCE, HYDRAULIC_METHODS, INT_RANGES, MAX_DYNAMIC_DURATION_S,  # noqa: F401
                          MAX_DYNAMIC_OUTPUTS, MAX_OPERATING_POINTS, MIN_OUTPUT_INTERVAL_S, OIL_LEVEL_WORDS,
                          RING_TEMPERATURE_KEYS, DynamicSettings, LubricationSpec, ModelOptions, OperatingSpec, Reader,
                          SceneSpec, StudySpec, parse_scene)
from ..base.units import RPM_TO_RAD_S, parse_quantity

__all__ = [
    "HYDRAULIC_METHODS",
    "Study",
    "DYNAMIC_PRESETS",
    "DynamicSettings",
    "FIDELITY_PRESETS",
    "Fidelity",
    "Lubrication",
    "OperatingPoint",
    "Scene",
    "apply_overrides",
    "check_operating_point",
    "check_speed",
    "operating_range_error",
    "static_equivalent_load_N",
    "load_scene",
    "resolve_oil_level",
    "scene_from_dict",
    "validate_scene",
]

#: The limits of the scene model (kegel.limits, kegel.scene_model), here under their old names too.
MAX_SPEED_FACTOR_RPM_MM = _MAX_SPEED_FACTOR_RPM_MM
#: Largest |misalignment| of the inner ring [rad].
MAX_MISALIGNMENT_RAD = 0.01
#: Largest contact / hydraulic boundary g (``model.contact_film_limit``): a film height beyond
#: 10 mm is no longer near a line contact of any bearing kegel models.
MAX_CONTACT_FILM_LIMIT_M = 0.01
_OIL_LEVEL_WORDS = OIL_LEVEL_WORDS
_ALLOWED = ALLOWED_KEYS  # the scene's sections and keys (kegel.scene_model), under their old name


@dataclass(frozen=True)
class Fidelity:
    """Model options of a scene (see ``FIDELITY_PRESETS``).

    Attributes
    ----------
    name
        Preset the options started from (``fast``, ``default``, ``fine``), ``+custom`` appended
        when a key overrides it; ``auto`` until :func:`kegel.run.run_scene` has chosen a preset
        (then ``auto:<preset>``).
    slices
        Slices per roller/raceway contact.
    slice_model
        ``"alternative_slicing"`` (slices coupled through the half-space) or ``"independent"``.
    rib_model
        ``"cell"`` (FFT + CG cell model) or ``"hertz"`` (closed-form elliptic contact).
    rib_cells
        Cells per side of the rib contact window (cell model).
    cage
        Whether the cage is modelled. Quasi-static: free rollers (each loaded roller at its own
        orbital speed, the cage at their time-mean speed, no pocket forces) in pockets of the
        bearing's clearance: where a roller's drift reaches a pocket wall, the wall holds it at
        the cage's speed for that share of the revolution (``cage_model = "mixed"``); ``false``: the
        rollers at the cage speed without pocket forces. Dynamic: the cage as a body with its
        pocket contacts.
    solution
        ``"quasi_static"`` or ``"dynamic"``.
    hydraulic
        ``"none"``, ``"correlation"`` (Liebrecht, Eq. 38-40) or ``"cfd"`` (the ``kegel cfd run``
        result of each operating point, see ``cfd_results``).
    cfd_results
        With ``hydraulic = "cfd"``: a CFD ``results.json`` or a folder holding them (relative
        paths from the working directory, as ``output.directory``); see
        :func:`kegel.coupling.find_cfd_result`.
    tolerance
        With ``fidelity = "auto"``: the largest deviation of the friction torque from the ``fine``
        level that the chosen preset may have (a fraction; default 0.01).
    rolling_thermal
        Thermal reduction of the EHL rolling resistance by inlet shear heating: ``"aihara"``
        (default), ``"zhu_cheng"`` or ``"off"`` (see :class:`kegel.FrictionData`).
    inlet_gap_ratio
        Starvation of the raceway contacts' rolling resistance (Biboulet-Houpert Part 1, Eq. 44):
        the inlet oil gap over the fully flooded film, >= 2; 0 (default) = fully flooded. A
        constant for every raceway contact, combined with the supply (the smaller ratio wins).
    lubricant_supply
        The inlet supply of the raceway contacts (:mod:`kegel.supply`): ``"kinematic_replenishment"``
        (default: SKF's kinematic replenishment factor by lubrication method, speed and viscosity,
        contacts under the oil surface flooded, mapped onto Biboulet-Houpert's starved inlet) or
        ``"flooded"`` (every contact fully flooded).
    contact_film_limit_m
        The contact / hydraulic boundary g [m] (``model.contact_film_limit = "0.2 mm"``): the
        contact model owns the oil within film height g of each line contact and cuts its rolling
        force off there (Reynolds' far field beyond g taken off, docs/models.md); 0 (default) =
        no cut-off.
    """

    name: str
    slices: int
    slice_model: str
    rib_model: str
    rib_cells: int
    cage: bool
    solution: str
    hydraulic: str
    cfd_results: str | None = None
    tolerance: float | None = None
    rolling_thermal: str = "aihara"
    inlet_gap_ratio: float = 0.0
    lubricant_supply: str = "kinematic_replenishment"
    contact_film_limit_m: float = 0.0

    def as_dict(self) -> dict[str, Any]:
        """Plain dictionary, written next to every result."""
        return dict(self.__dict__)


FIDELITY_PRESETS: dict[str, dict[str, Any]] = {
    "fast": dict(slices=10, slice_model="independent", rib_model="hertz", rib_cells=16, cage=False,
                 solution="quasi_static"),
    "default": dict(slices=30, slice_model="alternative_slicing", rib_model="cell", rib_cells=32, cage=True,
                    solution="quasi_static"),
    "fine": dict(slices=100, slice_model="alternative_slicing", rib_model="cell", rib_cells=64, cage=True,
                 solution="quasi_static"),
}
#: Contact fidelity of the dynamic simulation when the scene names only a preset: the
#: alternative slicing solves a coupled system per contact in every right-hand side (2.4x the
#: cost of independent slices at 30 slices), so the dynamic levels differ from the quasi-static
#: ones; ``benchmarks/bench_dynamics.py`` measures runtime and deviation of each. ``default``
#: uses the alternative slicing: independent slices put load on more slices near the roller
#: ends, and the EHL rolling resistance, which hardly depends on a slice's load, counts every
#: loaded slice, so 20 independent slices gave friction torques 8-10 % above the converged
#: quasi-static ones (32216, Table 1 and 2, 50 degC; 20 alternative slices: within 1 %;
#: ``benchmarks/dynamic_vs_quasi_static.py``). ``fast`` keeps the independent slices for speed.
DYNAMIC_PRESETS: dict[str, dict[str, Any]] = {
    "fast": dict(slices=10, slice_model="independent", rib_model="hertz"),
    "default": dict(slices=20, slice_model="alternative_slicing", rib_model="hertz"),
    "fine": dict(slices=40, slice_model="alternative_slicing", rib_model="hertz"),
}
@dataclass(frozen=True)
class Lubrication:
    """Lubrication of a scene.

    Attributes
    ----------
    mode
        ``"oil_bath"`` or ``"minimum_quantity"``.
    oil_level_m
        Height of the oil surface above the lowest point of the bearing's outer diameter
        (0 for minimum-quantity lubrication, ``D`` for a flooded bearing).
    oil_level_as_written
        The value as the scene wrote it.
    """

    mode: str
    oil_level_m: float
    oil_level_as_written: str


@dataclass(frozen=True)
class Study:
    """The ``[study]`` table: lubrications and hydraulic methods compared at every operating point.

    Attributes
    ----------
    cases
        The lubrications, in the scene's order (``mode`` ``"minimum_quantity"`` or ``"oil_bath"``).
    methods
        Hydraulic-loss methods, a subset of :data:`HYDRAULIC_METHODS` in the scene's order.
    cfd_results
        With ``"cfd"``: the folder (or file) of ``kegel cfd run`` results; it may not exist yet
        (the run then names the CFD runs that are missing).
    """

    cases: tuple["Lubrication", ...]
    methods: tuple[str, ...]
    cfd_results: str | None = None

    def as_dict(self) -> dict[str, Any]:
        """Plain dictionary, written next to the results."""
        return {"lubrication": [{"mode": c.mode, "oil_level_m": c.oil_level_m, "as_written": c.oil_level_as_written}
                                for c in self.cases],
                "hydraulic": list(self.methods), "cfd_results": self.cfd_results}


@dataclass(frozen=True)
class OperatingPoint:
    """One operating point of a scene, in SI units.

    Exactly one of ``axial_load_N`` (force-controlled) and ``axial_offset_m``
    (displacement-controlled preload) is set; the other is ``None``.
    """

    index: int
    speed_rad_s: float
    temperature_K: float
    radial_load_N: float
    axial_load_N: float | None
    axial_offset_m: float | None
    tilt_moment_Nm: float
    misalignment_rad: float
    #: contact temperature of the inner ring's contacts (raceway and rib) and of the outer ring's
    #: raceway [K] (``operating.inner_ring_temperature`` / ``outer_ring_temperature``); ``None``:
    #: the oil temperature ``temperature_K`` (:attr:`inner_contact_temperature_K` resolves it)
    inner_ring_temperature_K: float | None = None
    outer_ring_temperature_K: float | None = None

    @property
    def inner_contact_temperature_K(self) -> float:
        """Temperature of the inner ring's contacts (raceway and rib) [K]: the ring's, else the oil's."""
        return self.temperature_K if self.inner_ring_temperature_K is None else self.inner_ring_temperature_K

    @property
    def outer_contact_temperature_K(self) -> float:
        """Temperature of the outer ring's raceway contacts [K]: the ring's, else the oil's."""
        return self.temperature_K if self.outer_ring_temperature_K is None else self.outer_ring_temperature_K

    @property
    def speed_rpm(self) -> float:
        """Inner-ring speed in rpm."""
        return self.speed_rad_s / RPM_TO_RAD_S

    @property
    def temperature_degC(self) -> float:
        """Temperature in degC."""
        return self.temperature_K - 273.15

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary; field names carry their units."""
        return {
            "index": self.index,
            "speed_rpm": self.speed_rpm,
            "speed_rad_s": self.speed_rad_s,
            "temperature_degC": self.temperature_degC,
            "temperature_K": self.temperature_K,
            "axial_load_N": self.axial_load_N,
            "axial_offset_m": self.axial_offset_m,
            "radial_load_N": self.radial_load_N,
            "tilt_moment_Nm": self.tilt_moment_Nm,
            "misalignment_rad": self.misalignment_rad,
            # the contact temperatures the point used (the oil's unless a ring's was given)
            "inner_ring_temperature_degC": self.inner_contact_temperature_K - 273.15,
            "inner_ring_temperature_K": self.inner_contact_temperature_K,
            "outer_ring_temperature_degC": self.outer_contact_temperature_K - 273.15,
            "outer_ring_temperature_K": self.outer_contact_temperature_K,
        }


@dataclass(frozen=True)
class Scene:
    """A validated scene: bearing, lubricant, operating points, lubrication and fidelity."""

    source: str
    name: str
    description: str
    bearing: BearingData
    material: MaterialData
    lubricant: LubricantData
    operating_points: tuple[OperatingPoint, ...]
    swept: tuple[str, ...]
    lubrication: Lubrication
    fidelity: Fidelity
    output_directory: Path
    resolved: dict[str, Any] = field(repr=False, compare=False)
    dynamic: DynamicSettings = field(default_factory=DynamicSettings)
    study: Study | None = None
    #: the dotted keys ``--set`` changed (the name and description are the file's words)
    overridden: tuple[str, ...] = ()
    #: the typed model the scene was validated from (:mod:`kegel.scene_model`)
    spec: SceneSpec | None = field(default=None, repr=False, compare=False)

    @property
    def title(self) -> str:
        """The scene's name, with the ``--set`` changes when there are any: a title must not
        say "Fa = 6 kN" or "flooded" for a run that ``--set`` changed."""
        if not self.overridden:
            return self.name
        changes = ", ".join(f"{k}={_shown(self.resolved, k)}" for k in self.overridden)
        return f"{self.name} [--set {changes}]"

    @property
    def lubrication_label(self) -> str:
        """The lubrication as resolved, e.g. ``"oil bath, flooded"``, ``"minimum quantity"``."""
        if self.study is not None:
            return "study: " + "; ".join(_case_label(c) for c in self.study.cases)
        return _case_label(self.lubrication)

    @cached_property
    def geometry(self) -> BearingGeometry:
        """The bearing's derived internal geometry."""
        return derive_geometry(self.bearing, self.material)


def _case_label(lub: "Lubrication") -> str:
    if lub.mode == "minimum_quantity":
        return "minimum quantity"
    return f"oil bath, {lub.oil_level_as_written}"


def _shown(raw: dict[str, Any], dotted: str) -> str:
    node: Any = raw
    for part in dotted.split("."):
        node = node.get(part) if isinstance(node, dict) else None
    return str(node)


def _set_dotted(raw: dict[str, Any], dotted: str, value: Any) -> None:
    parts = dotted.split(".")
    node = raw
    for part in parts[:-1]:
        child = node.setdefault(part, {})
        if not isinstance(child, dict):
            raise KegelInputError("--set", dotted, value, f"a key below the table '{part}'")
        node = child
    node[parts[-1]] = value


def apply_overrides(raw: dict[str, Any], overrides: list[str] | tuple[str, ...]) -> tuple[dict, set[str]]:
    """Apply ``KEY=VALUE`` overrides (``--set``) to a raw scene dictionary.

    ``VALUE`` is read as a TOML value when it is one (``3``, ``true``, ``["1 kN", "2 kN"]``,
    ``{from = "500 rpm", to = "4000 rpm", points = 8}``) and as a plain string otherwise
    (``6.5 kN``), so shell quoting stays simple.

    Returns
    -------
    (dict, set of str)
        The new dictionary (the input is not modified) and the dotted keys that were set.
    """
    out = copy.deepcopy(raw)
    keys: set[str] = set()
    for item in overrides:
        key, sep, text = item.partition("=")
        key = key.strip()
        if not sep or not key or any(not p for p in key.split(".")):
            raise KegelInputError("--set", key, item, "KEY=VALUE with a dotted key, e.g. operating.axial_load=\"6.5 kN\"")
        text = text.strip()
        try:
            value: Any = tomllib.loads(f"v = {text}")["v"]
        except tomllib.TOMLDecodeError:
            value = text.strip("'\"")
        except RecursionError:  # tomllib recurses per nested array: thousands exhaust the stack
            raise KegelInputError("--set", key, text[:40] + ("..." if len(text) > 40 else ""),
                                  "a value with arrays nested at most a few levels deep") from None
        _set_dotted(out, key, value)
        keys.add(key)
    return out, keys


#: the reader of scene values (kegel.scene_model.Reader; the name this module used before)
_Reader = Reader


def _fidelity(reader: Reader, model: ModelOptions, lubrication_mode: str) -> Fidelity:
    """The model options' ranges and cross-checks (with the lubrication, with ``auto``), resolved
    into a :class:`Fidelity` from the preset."""
    preset = model.fidelity
    w = model.as_written
    if model.given("tolerance") and preset != "auto":
        raise reader.error("model.tolerance", w("tolerance"), 'no value unless model.fidelity = "auto"')
    if preset == "auto":
        # kegel.run chooses the preset by solving the scene's first and last points at each level
        for key in ("slices", "slice_model", "rib_model", "rib_cells", "cage"):
            if model.given(key):
                raise reader.error(f"model.{key}", w(key), 'no value with fidelity = "auto" (auto chooses it)')
        if (model.solution or "quasi_static") != "quasi_static":
            raise reader.error("model.solution", model.solution,
                               '"quasi_static" with fidelity = "auto" (it chooses among the quasi-static levels)')
    opts = dict(FIDELITY_PRESETS["default" if preset == "auto" else preset])
    if preset == "auto":
        tol = AUTO_TOLERANCE if model.tolerance is None else model.tolerance
        if not 0.0 < tol <= 0.5:
            raise reader.error("model.tolerance", w("tolerance"),
                               'a fraction in (0, 0.5] or a per-cent string such as "1 %"')
        opts["tolerance"] = float(tol)
    opts["hydraulic"] = "correlation" if lubrication_mode == "oil_bath" else "none"
    custom = False
    for key in ("slices", "rib_cells"):
        v = getattr(model, key)
        if v is not None:
            lo, hi = INT_RANGES[key]  # run's limits: one check
            if not lo <= v <= hi:
                raise reader.error(f"model.{key}", v, f"an integer in [{lo}, {hi}]")
            opts[key] = v
            custom = True
    if model.cage is not None:
        opts["cage"] = model.cage
        custom = True
    for key in ("slice_model", "rib_model", "solution", "hydraulic", "rolling_thermal"):
        if getattr(model, key) is not None:
            opts[key] = getattr(model, key)
            custom = True
    if model.inlet_gap_ratio is not None:
        v = model.inlet_gap_ratio
        if not (v == 0 or 2 <= v < 1e9):
            raise reader.error("model.inlet_gap_ratio", w("inlet_gap_ratio"),
                               "0 (fully flooded) or a ratio >= 2 (Biboulet-Houpert's starvation range)")
        opts["inlet_gap_ratio"] = float(v)
    if model.lubricant_supply is not None:
        opts["lubricant_supply"] = model.lubricant_supply
    if model.contact_film_limit_m is not None:
        g = model.contact_film_limit_m
        if not 0.0 <= g <= MAX_CONTACT_FILM_LIMIT_M:
            raise reader.error("model.contact_film_limit", w("contact_film_limit"),
                               f"a film height in [0, {MAX_CONTACT_FILM_LIMIT_M * 1e3:g} mm] (0: no cut-off), "
                               "e.g. \"0.2 mm\"")
        opts["contact_film_limit_m"] = g
    if opts["solution"] == "dynamic":
        for key, value in DYNAMIC_PRESETS[preset].items():
            if not model.given(key):
                opts[key] = value
    if opts["hydraulic"] != "none" and lubrication_mode == "minimum_quantity":
        raise reader.error("model.hydraulic", opts["hydraulic"],
                           "'none' for minimum-quantity lubrication (no oil bath to churn)")
    if model.given("cfd_results"):
        v = model.cfd_results
        if opts["hydraulic"] != "cfd":
            raise reader.error("model.cfd_results", v, 'no value unless model.hydraulic = "cfd"')
        if not isinstance(v, str) or not v or not Path(v).exists():
            raise reader.error("model.cfd_results", v,
                               "an existing CFD results.json or folder of them (relative to the working directory)")
        opts["cfd_results"] = v
    elif opts["hydraulic"] == "cfd":
        raise reader.error("model.cfd_results", None,
                           'a CFD results.json or folder of them (kegel cfd run), needed by hydraulic = "cfd"')
    return Fidelity(name=preset + ("+custom" if custom else ""), **opts)


def resolve_oil_level(written: Any, bearing: BearingData, *, source: str | Path, key: str) -> float:
    """Oil level in metres above the lowest point of the bearing's outer diameter.

    ``written`` is a length with its unit in [0, D] or one of ``none`` (0), ``half_roller`` (the
    centre of the lowest roller: the paper's "oil bath half roller height"), ``shaft_center``
    (D/2) and ``flooded`` (D).
    """
    level = written if isinstance(written, str) and written in _OIL_LEVEL_WORDS else parse_quantity(
        written, "length", source=source, key=key)
    return _oil_level_m(level, written, bearing, source=source, key=key)


def _oil_level_m(level: str | float, written: Any, bearing: BearingData, *, source: str | Path, key: str) -> float:
    """An oil level (a word of ``OIL_LEVEL_WORDS`` or a height [m]) in metres, within [0, D]."""
    D = bearing.outer_diameter_m
    if isinstance(level, str):
        return {
            "none": 0.0,
            "half_roller": 0.5 * (D - bearing.pitch_diameter_m),
            "shaft_center": 0.5 * D,
            "flooded": D,
        }[level]
    if not 0.0 <= level <= D:
        raise KegelInputError(
            source, key, written,
            f"an oil level in [0, D] = [0, {D * 1e3:g} mm] above the lowest point of the "
            f"outer diameter of bearing {bearing.designation}",
        )
    return float(level)


def _study(reader: Reader, spec: StudySpec, bearing: BearingData) -> Study:
    """The study's lubrications resolved against the bearing, its methods' cross-checks."""
    out: list[Lubrication] = []
    for i, (level, c) in enumerate(zip(spec.levels, spec.lubrication)):
        key = f"study.lubrication[{i}]"
        if level in ("minimum_quantity", "none"):
            lub = Lubrication(mode="minimum_quantity", oil_level_m=0.0, oil_level_as_written="none")
        else:
            level_m = _oil_level_m(level, c, bearing, source=reader.src("study.lubrication"), key=key)
            if level_m == 0.0:
                raise reader.error(key, c, "an oil level > 0 (minimum_quantity for no oil bath)")
            lub = Lubrication(mode="oil_bath", oil_level_m=level_m, oil_level_as_written=c)
        if any(lub.mode == o.mode and abs(lub.oil_level_m - o.oil_level_m) < 1e-9 for o in out):
            raise reader.error(key, c, "a lubrication not listed before (each case once)")
        out.append(lub)
    methods = list(spec.methods)
    if len(set(methods)) != len(methods):
        raise reader.error("study.hydraulic", methods, "each method once")
    cfd = spec.cfd_results
    if "cfd" in methods:
        if not isinstance(cfd, str) or not cfd:
            raise reader.error("study.cfd_results", cfd, 'a folder (or results.json) of kegel cfd run results, '
                               'needed by hydraulic "cfd" (it may not exist yet: the run names the missing runs)')
    elif cfd is not None:
        raise reader.error("study.cfd_results", cfd, 'no value unless study.hydraulic lists "cfd"')
    return Study(cases=tuple(out), methods=tuple(methods), cfd_results=cfd)


def _lubrication(reader: Reader, spec: LubricationSpec, bearing: BearingData) -> Lubrication:
    """The lubrication's oil level resolved against the bearing, and its cross-check with the mode."""
    mode, key = spec.mode, spec.key
    if spec.oil_level is None:
        if mode == "oil_bath":
            raise reader.error(key, None, f"an oil level ({', '.join(_OIL_LEVEL_WORDS)}, or a length in [0, D])")
        return Lubrication(mode=mode, oil_level_m=0.0, oil_level_as_written="none")
    level = _oil_level_m(spec.oil_level, spec.written, bearing, source=reader.src(key), key=key)
    if mode == "minimum_quantity" and level != 0.0:
        raise reader.error(key, spec.written, "no oil level (or 'none') for minimum-quantity lubrication")
    if mode == "oil_bath" and level == 0.0:
        raise reader.error(key, spec.written, "an oil level > 0 for an oil bath")
    return Lubrication(mode=mode, oil_level_m=level, oil_level_as_written=str(spec.written))


def _operating_points(reader: Reader, op: OperatingSpec, bearing: BearingData) -> tuple[list[OperatingPoint], tuple[str, ...]]:
    """Every operating quantity within its range (:func:`operating_range_error`), the tilt moment's
    limits, the number of points; the points (every combination, speed varying fastest)."""
    sweeps = op.sweeps()
    for key in ("axial_load", "axial_offset", "radial_load", "speed", "temperature"):
        s = sweeps.get(key)
        if s is None:
            continue
        for i, v in enumerate(s.values):
            expected = operating_range_error(key, v, bearing)
            if expected is not None:
                raise reader.error(s.item_key(i), s.item_written(i), expected)
    values = {k: list(s.values) for k, s in sweeps.items()}

    ring_T = {}
    for key in RING_TEMPERATURE_KEYS:  # a contact temperature per ring: the temperature's range
        sc = getattr(op, key)
        if sc is None:
            continue
        expected = operating_range_error("temperature", sc.value, bearing)
        if expected is not None:
            raise reader.error(sc.key, sc.written, expected)
        ring_T[key] = sc.value

    tilt, mis = op.tilt_moment.value, op.misalignment.value
    expected = operating_range_error("misalignment", mis, bearing)
    if expected is not None:
        raise reader.error(op.misalignment.key, op.misalignment.written, expected)
    if tilt != 0.0:
        expected = _tilt_moment_error(tilt, min(values["axial_load"]) if "axial_load" in values else None, mis,
                                      bearing)
        if expected is not None:
            raise reader.error(op.tilt_moment.key, op.tilt_moment.written, expected)

    axial_key = "axial_load" if "axial_load" in values else "axial_offset"
    order = ("temperature", axial_key, "radial_load", "speed")  # speed varies fastest
    swept = tuple(k for k in order if len(values[k]) > 1)
    total = math.prod(len(values[k]) for k in order)
    if total > MAX_OPERATING_POINTS:
        sizes = " x ".join(f"{k} {len(values[k])}" for k in order if len(values[k]) > 1)
        raise reader.error("operating", f"{total} points ({sizes})",
                           f"at most {MAX_OPERATING_POINTS} operating points in one scene (kegel's sweep limit; "
                           "split the study into several scenes)")
    points = []
    for i, combo in enumerate(itertools.product(*(values[k] for k in order))):
        d = dict(zip(order, combo))
        points.append(
            OperatingPoint(
                index=i,
                speed_rad_s=d["speed"],
                temperature_K=d["temperature"],
                radial_load_N=d["radial_load"],
                axial_load_N=d.get("axial_load"),
                axial_offset_m=d.get("axial_offset"),
                tilt_moment_Nm=tilt,
                misalignment_rad=mis,
                inner_ring_temperature_K=ring_T.get("inner_ring_temperature"),
                outer_ring_temperature_K=ring_T.get("outer_ring_temperature"),
            )
        )
    return points, swept

def operating_range_error(quantity: str, value: float, bearing: BearingData) -> str | None:
    """The range of one operating quantity, as every entry point checks it (scene files,
    ``--set``, the Python API, and the public functions that take SI floats).

    Parameters
    ----------
    quantity
        ``"axial_load"`` [N], ``"axial_offset"`` [m], ``"radial_load"`` [N], ``"speed"`` [rad/s],
        ``"temperature"`` [K] or ``"misalignment"`` [rad].
    value
        The value in SI units.
    bearing
        The bearing (the speed limit n d_m depends on its pitch diameter).

    Returns
    -------
    str or None
        None when ``value`` is inside the range, else what was expected, in words (the scenes'
        message).
    """
    v = float(value)
    if not math.isfinite(v):
        return "a finite number"
    if quantity == "axial_load":
        return None if v > 0.0 else ("a positive axial load (> 0 N); a tapered roller bearing needs axial load to "
                                     "keep its rollers seated")
    if quantity == "axial_offset":
        return None if v > 0.0 else "a positive axial offset (> 0 m, preload)"
    if quantity == "radial_load":
        return None if v >= 0.0 else "a radial load >= 0 N"
    if quantity == "speed":
        return None if 0.0 < abs(v) / RPM_TO_RAD_S <= max_speed_rpm(bearing) else (
            f"a non-zero speed with {_speed_limit_text(bearing)}")
    if quantity == "temperature":
        lo, hi = TEMPERATURE_RANGE_DEGC
        return None if lo <= v - 273.15 <= hi else f"a temperature in [{lo:g}, {hi:g}] degC"
    if quantity == "misalignment":
        return None if abs(v) <= MAX_MISALIGNMENT_RAD else f"|misalignment| <= {MAX_MISALIGNMENT_RAD * 1e3:g} mrad"
    raise ValueError(f"unknown operating quantity {quantity!r}")


def _tilt_moment_error(tilt_Nm: float, axial_min_N: float | None, misalignment_rad: float,
                       bearing: BearingData) -> str | None:
    """The tilt moment's limits: finite, below Fa d_m / 2 (a single TRB holds a tilt moment
    through its axial load: beyond it every roller on one side would have to carry the whole axial
    load at the pitch radius, tipping), and not together with a misalignment."""
    if not math.isfinite(tilt_Nm):
        return "a finite tilt moment"
    if tilt_Nm != 0.0 and axial_min_N is not None:
        limit = axial_min_N * 0.5 * bearing.pitch_diameter_m
        if abs(tilt_Nm) >= limit:
            return (f"|tilt moment| < Fa d_m / 2 = {limit:.4g} N m (smallest axial load {axial_min_N:.4g} N, "
                    f"d_m = {bearing.pitch_diameter_m * 1e3:.4g} mm): beyond it the inner ring tips over")
    if tilt_Nm != 0.0 and misalignment_rad != 0.0:
        return ("either a tilt moment (the inner ring tilts freely under it) or a misalignment (its tilt imposed), "
                "not both")
    return None


def check_operating_point(bearing: BearingData, g: BearingGeometry, *, lubricant: LubricantData | None = None,
                          temperature_K: float | None = None, speed_rad_s: float | None = None,
                          axial_N: float | None = None, axial_offset_m: float | None = None,
                          radial_N: float = 0.0, tilt_moment_Nm: float = 0.0, misalignment_rad: float = 0.0,
                          names: dict[str, str] | None = None, source: str = "<argument>") -> None:
    """The scenes' checks of one operating point given as SI floats, for the public functions
    that take them (:func:`kegel.quasi_static.bearing_friction`, ...): every range of
    :func:`operating_range_error`, the lubricant's temperature range and formulas (with
    ``lubricant``), the tilt moment's limits and, for a force-controlled point, the lift-off of a
    single tapered roller bearing and the static load rating C0r (ISO 76).

    ``None`` skips ``temperature_K`` and ``speed_rad_s``. ``names`` maps the quantities
    (``temperature``, ``speed``, ``axial_load``, ``axial_offset``, ``radial_load``,
    ``tilt_moment``, ``misalignment``) to the caller's argument names for the message (default:
    ``temperature_K``, ``speed_rad_s``, ``axial_N``, ``axial_offset_m``, ``radial_N``,
    ``tilt_moment_Nm``, ``misalignment_rad``).

    Raises
    ------
    KegelInputError
        Naming ``source``, the argument and its value, with the scenes' message.
    """
    names = {"temperature": "temperature_K", "speed": "speed_rad_s", "axial_load": "axial_N",
             "axial_offset": "axial_offset_m", "radial_load": "radial_N", "tilt_moment": "tilt_moment_Nm",
             "misalignment": "misalignment_rad", **(names or {})}

    def real(quantity: str, value: Any) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
            raise KegelInputError(source, names[quantity], value, "a number in SI units")
        return float(value)

    values = {"temperature": temperature_K, "speed": speed_rad_s, "axial_load": axial_N,
              "axial_offset": axial_offset_m, "radial_load": radial_N, "misalignment": misalignment_rad}
    for quantity, value in values.items():
        if value is None:
            continue
        expected = operating_range_error(quantity, real(quantity, value), bearing)
        if expected is not None:
            if quantity == "temperature" and math.isfinite(value):
                expected += f" (here {value - 273.15:g} degC)"
            raise KegelInputError(source, names[quantity], value, expected)
    if temperature_K is not None and lubricant is not None:
        lubricant_state(lubricant, float(temperature_K), source=source, key=names["temperature"])
    expected = _tilt_moment_error(real("tilt_moment", tilt_moment_Nm), axial_N, float(misalignment_rad), bearing)
    if expected is not None:
        raise KegelInputError(source, names["tilt_moment"], tilt_moment_Nm, expected)
    if axial_N is not None:
        expected = _lift_off_error(g, float(axial_N), float(radial_N)) or _static_load_error(
            g, bearing, float(axial_N), float(radial_N))
        if expected is not None:
            key = names["axial_load"] if _iso76_y0(g) * axial_N >= 0.5 * radial_N else names["radial_load"]
            raise KegelInputError(source, key, axial_N if key == names["axial_load"] else radial_N, expected)


def _lift_off_error(g: BearingGeometry, axial_N: float, radial_N: float) -> str | None:
    """A single TRB under a force-controlled axial load needs Fa / Fr > tan(alpha_o) (one
    roller carrying everything); below it the inner ring lifts off."""
    tan_a = math.tan(g.cup_angle_rad)
    if radial_N > 0 and axial_N / radial_N <= tan_a:
        return (f"Fa / Fr > tan(alpha_o) = {tan_a:.3f} for a single tapered roller bearing (here Fa = "
                f"{axial_N / 1e3:.4g} kN, Fr = {radial_N / 1e3:.4g} kN, ratio {axial_N / radial_N:.3f}: the inner ring "
                "would lift off); use operating.axial_offset (displacement-controlled) for such load cases")
    return None


def centrifugal_seating_error(g: BearingGeometry, axial_N: float, speed_rad_s: float) -> str | None:
    """A force-controlled axial load must exceed :func:`kegel.model.geometry.centrifugal_axial_load_N`."""
    f_c = centrifugal_axial_load_N(g, speed_rad_s)
    if axial_N > f_c:
        return None
    return (f"an axial load above the {f_c:.4g} N that the rollers' centrifugal force puts on the cup at "
            f"{abs(speed_rad_s) / RPM_TO_RAD_S:.6g} rpm (Z m r_M w_c^2 tan(alpha_o); here Fa = {axial_N:.4g} N): below it "
            "the rollers leave the cone and a single tapered roller bearing has no quasi-static state; use a "
            "displacement-controlled axial offset (operating.axial_offset; axial_offset_m in Python), or the "
            "dynamic solution with the ring held axially (dynamic.hold_axial = true: the partner bearing)")


def _check_centrifugal_seating(reader: Reader, op: OperatingSpec, points: list[OperatingPoint],
                               g: BearingGeometry) -> None:
    """Every force-controlled quasi-static point's axial load above the rollers' centrifugal
    share (:func:`kegel.model.geometry.centrifugal_axial_load_N`), checked for the scene so that ``kegel check``
    refuses what the run's load distribution cannot solve."""
    for p in points:
        if p.axial_load_N is None:
            continue
        expected = centrifugal_seating_error(g, p.axial_load_N, p.speed_rad_s)
        if expected is not None:
            s = op.axial_load
            raise reader.error(s.key, s.written, f"at every point (here point {p.index}): {expected}")


def _static_load_error(g: BearingGeometry, bearing: BearingData, axial_N: float, radial_N: float) -> str | None:
    """The ISO 76 static equivalent load within the basic static load rating C0r."""
    p0 = static_equivalent_load_N(g, axial_N, radial_N)
    if p0 > bearing.C0r_N:
        return (f"loads whose ISO 76 static equivalent load P0 stays within C0r = {bearing.C0r_N / 1e3:g} kN of bearing "
                f"{bearing.designation} (here P0 = {p0 / 1e3:.4g} kN at Fa = {axial_N / 1e3:.4g} kN, Fr = "
                f"{radial_N / 1e3:.4g} kN: beyond it the raceways deform permanently and the elastic contact models "
                "do not hold)")
    return None


def static_equivalent_load_N(g: BearingGeometry, axial_N: float, radial_N: float) -> float:
    """ISO 76 static equivalent radial load of a single-row tapered roller bearing:
    P0 = 0.5 Fr + Y0 Fa with Y0 = 0.22 cot(alpha) (alpha: the cup angle), and at least Fr.
    (For the 32216, Y0 = 0.79; SKF's catalogue gives 0.8.)"""
    return max(radial_N, 0.5 * radial_N + _iso76_y0(g) * axial_N)


def _iso76_y0(g: BearingGeometry) -> float:
    """ISO 76 axial load factor Y0 = 0.22 cot(alpha) of a single-row tapered roller bearing."""
    return 0.22 / math.tan(g.cup_angle_rad)


def _check_static_load(reader: Reader, op: OperatingSpec, points: list[OperatingPoint], bearing: BearingData,
                       g: BearingGeometry) -> None:
    """Loads against the basic static load rating C0r: the contact models are elastic, and a
    static equivalent load above C0r (ISO 76: 4000 MPa at the most loaded roller contact) means
    permanent deformation of the raceways. Displacement-controlled points are checked in the run."""
    # the lift-off of a single TRB (Fa / Fr > tan(alpha_o)) is checked for every point here, not
    # at the point in the run: kegel check must reject what kegel run would (a lift-off needs Fr > 0)
    for p in points:
        expected = None if p.axial_load_N is None else _lift_off_error(g, p.axial_load_N, p.radial_load_N)
        if expected is not None:
            s = op.radial_load
            raise reader.error(s.key, s.written, f"at every point (here point {p.index}): {expected}")
    worst = max((p for p in points if p.axial_load_N is not None),
                key=lambda p: static_equivalent_load_N(g, p.axial_load_N, p.radial_load_N), default=None)
    if worst is None:
        return
    expected = _static_load_error(g, bearing, worst.axial_load_N, worst.radial_load_N)
    if expected is not None:
        # name the load whose term dominates P0
        s = op.axial_load if _iso76_y0(g) * worst.axial_load_N >= 0.5 * worst.radial_load_N else op.radial_load
        raise reader.error(s.key, s.written, expected)

def _check_dynamic_profiles(reader: "_Reader", table: dict[str, Any], dyn: "DynamicSettings", bearing: BearingData,
                            g: BearingGeometry) -> None:
    """The dynamic profiles within the same limits as the operating points: speeds with
    |n| d_m <= MAX_SPEED_FACTOR_RPM_MM (0 allowed: a start from rest), axial loads > 0, radial
    loads >= 0, and the static equivalent load within C0r (a profile to 1e9 rpm or to Fa = 0
    crashed in the run)."""
    n_max = max_speed_rpm(bearing)
    for i, (_, w) in enumerate(dyn.speed_profile):
        if not abs(w) / RPM_TO_RAD_S <= n_max:
            raise reader.error(f"dynamic.speed_profile[{i}][1]", table["speed_profile"][i][1], _speed_limit_text(bearing))
    for i, (_, fa, fr) in enumerate(dyn.load_profile):
        if not fa > 0.0:
            raise reader.error(f"dynamic.load_profile[{i}][1]", table["load_profile"][i][1],
                               "an axial load > 0 (a single TRB needs an axial load to hold its rollers)")
        if not fr >= 0.0:
            raise reader.error(f"dynamic.load_profile[{i}][2]", table["load_profile"][i][2], "a radial load >= 0")
        p0 = static_equivalent_load_N(g, fa, fr)
        if p0 > bearing.C0r_N:
            raise reader.error(f"dynamic.load_profile[{i}]", table["load_profile"][i],
                               f"loads whose ISO 76 static equivalent load stays within C0r = {bearing.C0r_N / 1e3:g} kN "
                               f"(here P0 = {p0 / 1e3:.4g} kN)")


def check_speed(speed_rad_s: float, bearing: BearingData, *, source: str | Path, key: str, text: Any = None) -> float:
    """The one speed check of every entry point (scene files, the command line, the CFD runner):
    a non-zero speed with |n| d_m <= :data:`MAX_SPEED_FACTOR_RPM_MM`. Returns the speed.

    Raises
    ------
    KegelInputError
        Naming ``source``, ``key`` and the value as written (``text``).
    """
    expected = operating_range_error("speed", speed_rad_s, bearing)
    if expected is not None:
        raise KegelInputError(source, key, text if text is not None else speed_rad_s, expected)
    return speed_rad_s


def max_speed_rpm(bearing: BearingData) -> float:
    """The largest |n| kegel accepts for ``bearing``: n d_m <= :data:`MAX_SPEED_FACTOR_RPM_MM`."""
    return MAX_SPEED_FACTOR_RPM_MM / (bearing.pitch_diameter_m * 1e3)


def _speed_limit_text(bearing: BearingData) -> str:
    return (f"|n| <= {max_speed_rpm(bearing):.0f} rpm (n*d_m <= {MAX_SPEED_FACTOR_RPM_MM:.0e} rpm mm for bearing "
            f"{bearing.designation})")


def validate_scene(spec: SceneSpec) -> Scene:
    """The one validation layer: check a :class:`kegel.scene_model.SceneSpec` (from a scene file,
    ``--set``, ``kegel init`` or the Python API) and resolve it into a :class:`Scene`.

    Loads the bearing, material and oil; checks every operating quantity's range (speed factor,
    the oil's formulas at every temperature, misalignment, tilt moment), the loads (lift-off of a
    single TRB, ISO 76 static load within C0r), the lubrication against the bearing (oil level in
    [0, D]) and against the model (hydraulic loss, CFD results), the model options' ranges and
    ``auto``'s keys, and the dynamic profiles. ``kegel check`` and ``kegel run`` both call it.

    Raises
    ------
    KegelInputError
        Naming the source (file, ``--set`` or the API's entry point), the key (or argument), the
        value as written and what was expected.
    """
    reader = Reader(spec.source, set(spec.overridden))
    # a designation (shipped data, the ISO 355 series table, a file) or boundary dimensions
    bearing = bearing_from_scene(spec.bearing.table(), source=reader.src)
    material = load_material(spec.bearing.material, source=reader.src("bearing.material"), key="bearing.material")
    # a shipped oil's name (or a file), or viscosities from which its laws are estimated
    lubricant = lubricant_from_scene(spec.lubricant.table(), source=reader.src)

    points, swept = _operating_points(reader, spec.operating, bearing)
    # the bearing's derived geometry must fit its envelope (a custom data file may not)
    g = derive_geometry(bearing, material)
    _check_static_load(reader, spec.operating, points, bearing, g)
    temperature = spec.operating.temperature
    for T in sorted({p.temperature_K for p in points}):
        # the oil's formulas must hold at every temperature of the scene (checked now, not in the run)
        lubricant_state(lubricant, T, source=reader.src(temperature.key), key=temperature.key)
    for key in RING_TEMPERATURE_KEYS:  # and at each ring's contact temperature
        sc = getattr(spec.operating, key)
        if sc is not None:
            lubricant_state(lubricant, sc.value, source=reader.src(sc.key), key=sc.key)
    study = _study(reader, spec.study, bearing) if spec.study is not None else None
    # a study solves the contact friction alone; its lubrications add their hydraulic losses
    if study is None:
        assert spec.lubrication is not None
        lubrication = _lubrication(reader, spec.lubrication, bearing)
    else:
        lubrication = Lubrication(mode="minimum_quantity", oil_level_m=0.0, oil_level_as_written="none")
    fidelity = _fidelity(reader, spec.model, lubrication.mode)
    if fidelity.solution == "quasi_static":
        _check_centrifugal_seating(reader, spec.operating, points, g)
    _check_dynamic_profiles(reader, spec.dynamic_written, spec.dynamic, bearing, g)

    stem = Path(spec.source).stem if spec.source != "<dict>" else "scene"
    return Scene(
        source=spec.source,
        name=spec.name,
        description=spec.description,
        bearing=bearing,
        material=material,
        lubricant=lubricant,
        operating_points=tuple(points),
        swept=swept,
        lubrication=lubrication,
        fidelity=fidelity,
        output_directory=Path(spec.output_directory or f"results/{stem}"),
        resolved=spec.raw,
        dynamic=spec.dynamic,
        study=study,
        overridden=tuple(spec.overridden),
        spec=spec,
    )


def scene_from_dict(raw: dict[str, Any], *, source: str | Path = "<dict>", overridden: set[str] | None = None) -> Scene:
    """Validate a raw scene dictionary (as read from TOML) and build a :class:`Scene`:
    :func:`kegel.scene_model.parse_scene`, then :func:`validate_scene`."""
    return validate_scene(parse_scene(raw, source=source, overridden=overridden))

def load_scene(path: str | Path, overrides: list[str] | tuple[str, ...] = ()) -> Scene:
    """Read, override (``--set``) and validate a scene file.

    Parameters
    ----------
    path
        Scene TOML file.
    overrides
        ``KEY=VALUE`` strings applied before validation, e.g. ``operating.axial_load=6.5 kN``.

    Raises
    ------
    KegelInputError
        On any invalid input; the message names the file, key, value and expectation.
    """
    path = Path(path)
    raw = read_toml(path)
    raw, keys = apply_overrides(raw, overrides)
    return scene_from_dict(raw, source=path, overridden=keys)
