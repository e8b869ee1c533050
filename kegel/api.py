"""The Python facade: one bearing, one call, one torque, with units.

::

    import kegel
    res = kegel.Bearing("32216").friction(speed="2000 rpm", axial_load="6 kN", temperature="50 degC")
    res.friction_torque_Nm          # 3.6 (a float, N m)
    res                             # FrictionResult(32216, 2000 rpm, Fa 6 kN, 50 degC: friction 3.6 N m, converged)
    res.to_dataframe()              # one row per operating point (pandas)

:class:`Bearing` names the bearing, lubricant, material and model fidelity;
:meth:`Bearing.friction` solves operating points and returns a :class:`FrictionResult`. Every
quantity is a string with its unit (``"6 kN"``, ``"2000 rpm"``, ``"50 degC"``, read by
:func:`kegel.units.parse_quantity`, whose grammar refuses ``"6 500 N"`` or ``"6,5 kN"``) or a pint
quantity. A bare number is refused unless the keyword names its unit: ``speed_rpm=2000``,
``speed_rad_s=209.4``, ``temperature_degC=50``, ``temperature_K=323.15``, ``axial_load_N=6000``,
``axial_load_kN=6``, ``radial_load_N``, ``radial_load_kN``, ``axial_offset_m``,
``axial_offset_um`` (``speed=200`` was read as 200 rad/s, 1910 rpm). A list of values sweeps that
quantity (several lists: every combination, speed varying fastest).

The facade is a thin layer over the scene machinery: it builds the typed scene model a scene
file would give (:class:`kegel.scene_model.SceneSpec`, :meth:`Bearing.spec`; each quantity read
once), validates it with the scenes' one validation layer (:func:`kegel.scene.validate_scene`)
and solves it with :func:`kegel.run.run_scene` in memory (no files). A result therefore equals
that of the equivalent scene file, and bad input raises :class:`kegel.KegelInputError` naming the
argument as it was given (``speed_rpm[1]``).

Hydraulic losses of an oil bath: ``hydraulic=None`` takes the scene's default (Liebrecht's
correlation, seed paper Eq. 38-40, for an oil bath; none for minimum-quantity lubrication);
``"liebrecht"``, ``"skf"`` (the SKF catalogue model's drag moment, which a scene expresses only
in a ``[study]``: the facade solves the contact friction of the oil-bath scene without a
hydraulic loss and adds :func:`kegel.correlations.hydraulic_torques` ``("skf", ...)`` to each
point, as a study does) or ``"none"``. CFD losses need ``kegel cfd run`` results: use a scene file
with ``model.hydraulic = "cfd"``.

The facade solves the quasi-static model (the dynamic simulation writes its time series to files:
use a scene file with ``model.solution = "dynamic"``). As ``kegel run`` does, the run prints each
warning code once on stderr; every point's warnings are in ``FrictionResult.points`` and
``FrictionResult.warnings``.
"""

from __future__ import annotations

import dataclasses
import math
import numbers
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from .model.data import BearingData, LubricantData, MaterialData, load_bearing, load_lubricant, load_material
from .base.errors import KegelInputError
from .base.units import KINDS, parse_quantity

if TYPE_CHECKING:  # pragma: no cover
    import pandas
    from matplotlib.figure import Figure

    from .model.geometry import BearingGeometry
    from .model.scene import Scene
    from .model.scene_model import LubricationSpec, OperatingSpec, SceneSpec, Sweep

__all__ = ["Bearing", "FrictionResult"]

#: ``source`` of the errors each entry point raises (the argument is the error's ``key``).
_SOURCE_BEARING = "kegel.Bearing"
_SOURCE_FRICTION = "kegel.Bearing.friction"

#: The operating quantities of :meth:`Bearing.friction`: argument -> kind of quantity.
_QUANTITIES = {
    "speed": "speed",
    "axial_load": "force",
    "axial_offset": "length",
    "radial_load": "force",
    "temperature": "temperature",
}
#: Keywords whose name carries the unit of their bare numbers: keyword -> (quantity, unit).
UNIT_KEYWORDS: dict[str, tuple[str, str]] = {
    "speed_rpm": ("speed", "rpm"),
    "speed_rad_s": ("speed", "rad/s"),
    "temperature_degC": ("temperature", "degC"),
    "temperature_K": ("temperature", "K"),
    "axial_load_N": ("axial_load", "N"),
    "axial_load_kN": ("axial_load", "kN"),
    "radial_load_N": ("radial_load", "N"),
    "radial_load_kN": ("radial_load", "kN"),
    "axial_offset_m": ("axial_offset", "m"),
    "axial_offset_um": ("axial_offset", "um"),
}
_UNIT_KEYWORD_EXAMPLES = {"speed_rpm": "2000", "speed_rad_s": "209.4", "temperature_degC": "50",
                          "temperature_K": "323.15", "axial_load_N": "6000", "axial_load_kN": "6",
                          "radial_load_N": "2000", "radial_load_kN": "2", "axial_offset_m": "2e-05",
                          "axial_offset_um": "20"}
#: Values of the operating quantities no keyword gives.
_DEFAULTS = {"temperature": "50 degC", "radial_load": "0 kN"}
_OIL_LEVEL_WORDS = ("flooded", "shaft_center", "half_roller")
_HYDRAULIC = ("none", "liebrecht", "skf")
#: scene keys -> the argument of the facade that sets them (for the error messages)
_SCENE_KEY_ARGUMENT = {
    "bearing.designation": "designation",
    "bearing.material": "material",
    "lubricant.name": "lubricant",
    "model.fidelity": "fidelity",
    "model.tolerance": "fidelity",
    "model.hydraulic": "hydraulic",
    "lubrication": "lubrication",
}
#: Points listed by the repr of a sweep (the rest: ``to_dataframe()``).
_REPR_POINTS = 6


class Bearing:
    """A tapered roller bearing with its lubricant, material and model fidelity.

    Parameters
    ----------
    designation
        A bearing of kegel's data (``"32216"``, see :func:`kegel.available_bearings`) or the path
        of a bearing ``.toml`` file.
    lubricant
        A lubricant name (``"FVA3"``, see :func:`kegel.available_lubricants`) or a data file.
    material
        A material name (``"bearing_steel"``) or a data file.
    fidelity
        Model fidelity: ``"fast"``, ``"default"``, ``"fine"`` (see
        :data:`kegel.scene.FIDELITY_PRESETS`) or ``"auto"`` (kegel chooses the cheapest preset
        within 1 % of ``fine``).

    Raises
    ------
    KegelInputError
        Unknown bearing, lubricant, material or fidelity; the message names the argument.

    Examples
    --------
    >>> b = kegel.Bearing("32216", fidelity="fast")
    >>> b.friction(speed="2000 rpm", axial_load="6 kN").friction_torque_Nm  # doctest: +SKIP
    4.0695...
    """

    def __init__(self, designation: str | Path, *, lubricant: str | Path = "FVA3",
                 material: str | Path = "bearing_steel", fidelity: str = "default") -> None:
        from .model.scene import FIDELITY_PRESETS

        self._designation = _name_argument(designation, "designation", "a bearing designation such as '32216' or "
                                           "the path of a bearing .toml file")
        self._lubricant = _name_argument(lubricant, "lubricant", "a lubricant name such as 'FVA3' or a data file")
        self._material = _name_argument(material, "material", "a material name such as 'bearing_steel' or a data "
                                        "file")
        # loaded now: a misspelt name fails here, with the known names listed
        self.data: BearingData = load_bearing(self._designation, source=_SOURCE_BEARING, key="designation")
        self.lubricant: LubricantData = load_lubricant(self._lubricant, source=_SOURCE_BEARING, key="lubricant")
        self.material: MaterialData = load_material(self._material, source=_SOURCE_BEARING, key="material")
        choices = (*FIDELITY_PRESETS, "auto")
        if not isinstance(fidelity, str) or fidelity not in choices:
            raise KegelInputError(_SOURCE_BEARING, "fidelity", fidelity, f"one of {', '.join(choices)}")
        self.fidelity: str = fidelity

    @property
    def designation(self) -> str:
        """The bearing's designation (from its data file)."""
        return str(self.data.designation)

    @cached_property
    def geometry(self) -> "BearingGeometry":
        """The bearing's derived internal geometry (:func:`kegel.derive_geometry`)."""
        from .model.geometry import derive_geometry

        return derive_geometry(self.data, self.material)

    def __repr__(self) -> str:
        return (f"Bearing({self.designation!r}, lubricant={self.lubricant.name!r}, material={self.material.name!r}, "
                f"fidelity={self.fidelity!r})")

    def spec(self, speed: Any = None, axial_load: Any = None, *, temperature: Any = None, radial_load: Any = None,
             axial_offset: Any = None, lubrication: Any = "half_roller", hydraulic: str | None = None,
             speed_rpm: Any = None, speed_rad_s: Any = None, temperature_degC: Any = None,
             temperature_K: Any = None, axial_load_N: Any = None, axial_load_kN: Any = None,
             radial_load_N: Any = None, radial_load_kN: Any = None, axial_offset_m: Any = None,
             axial_offset_um: Any = None, inner_ring_temperature: Any = None,
             outer_ring_temperature: Any = None) -> "SceneSpec":
        """The typed scene model (:class:`kegel.scene_model.SceneSpec`) that :meth:`friction`
        validates and solves; the arguments are those of :meth:`friction`. Each quantity is read
        once, by the grammar of :mod:`kegel.units`; a scene file with the same values gives an
        equal model.

        Raises
        ------
        KegelInputError
            An argument that is not what it should be (type, unit, grammar, word); the message
            names it. Ranges and cross-checks: :func:`kegel.scene.validate_scene`.
        """
        from .model.scene_model import BearingSpec, LubricantSpec, ModelOptions, SceneSpec

        given = {k: v for k, v in locals().items() if k in _QUANTITIES or k in UNIT_KEYWORDS}
        operating, texts = _operating_spec(given)
        operating, texts = _with_ring_temperatures(operating, texts, {"inner_ring_temperature": inner_ring_temperature,
                                                                      "outer_ring_temperature": outer_ring_temperature})
        lub = _lubrication_spec(lubrication)
        method = _hydraulic_method(hydraulic, lub.mode)
        model_table: dict[str, Any] = {"fidelity": self.fidelity}
        if hydraulic is not None:
            model_table["hydraulic"] = {"none": "none", "liebrecht": "correlation", "skf": "none"}[method]
        model = ModelOptions(fidelity=self.fidelity, hydraulic=model_table.get("hydraulic"),
                             written=tuple(model_table.items()))
        lub_table: dict[str, Any] = {"mode": lub.mode}
        if lub.oil_level is not None:
            lub_table["oil_level"] = (lub.written if isinstance(lub.written, str) else f"{lub.oil_level!r} m")
        bearing = {"designation": self._designation, "material": self._material}
        name = f"{self.designation}, kegel.Bearing.friction"
        raw = {"scene": {"name": name}, "bearing": dict(bearing), "lubricant": {"name": self._lubricant},
               "operating": texts, "lubrication": lub_table, "model": model_table}
        return SceneSpec(name=name, description="", bearing=BearingSpec.of(bearing),
                         lubricant=LubricantSpec.of({"name": self._lubricant}), operating=operating,
                         lubrication=lub, model=model, source=_SOURCE_FRICTION, raw=raw)

    def scene(self, speed: Any = None, axial_load: Any = None, *, temperature: Any = None, radial_load: Any = None,
              axial_offset: Any = None, lubrication: Any = "half_roller", hydraulic: str | None = None,
              speed_rpm: Any = None, speed_rad_s: Any = None, temperature_degC: Any = None,
              temperature_K: Any = None, axial_load_N: Any = None, axial_load_kN: Any = None,
              radial_load_N: Any = None, radial_load_kN: Any = None, axial_offset_m: Any = None,
              axial_offset_um: Any = None, inner_ring_temperature: Any = None,
              outer_ring_temperature: Any = None) -> dict[str, Any]:
        """The scene dictionary (the content of a scene file, see :mod:`kegel.scene`) of
        :meth:`spec`: written as a scene file, it loads into an equal typed model.

        With ``hydraulic="skf"`` the scene has an oil bath and no hydraulic loss
        (``model.hydraulic = "none"``): :meth:`friction` adds the SKF drag to its points.

        Raises
        ------
        KegelInputError
            An argument that is not what it should be; the message names it.
        """
        args = {k: v for k, v in locals().items() if k != "self"}
        return self.spec(**args).raw

    def friction(self, speed: Any = None, axial_load: Any = None, *, temperature: Any = None,
                 radial_load: Any = None, axial_offset: Any = None, lubrication: Any = "half_roller",
                 hydraulic: str | None = None, speed_rpm: Any = None, speed_rad_s: Any = None,
                 temperature_degC: Any = None, temperature_K: Any = None, axial_load_N: Any = None,
                 axial_load_kN: Any = None, radial_load_N: Any = None, radial_load_kN: Any = None,
                 axial_offset_m: Any = None, axial_offset_um: Any = None,
                 inner_ring_temperature: Any = None, outer_ring_temperature: Any = None,
                 uncertainty: Any = False) -> "FrictionResult":
        """Friction torque (and hydraulic loss) at one operating point or a sweep.

        Every quantity is given once: as a string with its unit (``speed="2000 rpm"``, grammar
        of :mod:`kegel.units`) or a pint quantity, or as a number in the keyword that names its
        unit (``speed_rpm=2000``). A bare number in a keyword without a unit is refused.

        Parameters
        ----------
        speed, speed_rpm, speed_rad_s
            Inner-ring speed (outer ring fixed), e.g. ``"2000 rpm"``; required.
        axial_load, axial_load_N, axial_load_kN
            Axial load (force-controlled), e.g. ``"6 kN"``. Exactly one of the axial load and
            the axial offset is given.
        temperature, temperature_degC, temperature_K
            Oil and bearing temperature, e.g. ``"50 degC"`` (the default).
        inner_ring_temperature, outer_ring_temperature
            Contact temperature per ring, e.g. ``inner_ring_temperature="60 degC"`` (a string with
            its unit or a pint quantity; one value, not swept): the inner ring's raceway and rib
            contacts, or the outer raceway's, take the oil's properties at this temperature; the
            hydraulic loss keeps ``temperature``. Default: ``temperature`` (every point reports
            the temperatures it used, ``points[i]["inner_ring_temperature_degC"]``).
        radial_load, radial_load_N, radial_load_kN
            Radial load, e.g. ``"2 kN"`` (default 0).
        axial_offset, axial_offset_m, axial_offset_um
            Axial offset of the inner ring towards the apex (displacement-controlled preload),
            e.g. ``"20 um"``.
        lubrication
            The oil level of an oil bath: ``"half_roller"`` (the default: the oil at the centre of
            the lowest roller, SKF's recommended level and the seed paper's tests), ``"flooded"``,
            ``"shaft_center"`` or a height above the lowest point of the outer diameter with its
            unit (``"40 mm"``, or a pint quantity); or ``"minimum_quantity"`` (no oil bath).
        hydraulic
            Hydraulic loss of the oil bath: ``None`` (Liebrecht for an oil bath, none for minimum
            quantity), ``"liebrecht"``, ``"skf"`` (SKF catalogue drag moment) or ``"none"``.
        uncertainty
            ``True`` (or a :class:`kegel.uncertainty.UncertaintyOptions`): every point also gets
            its friction torque band from the crown data (drop -+25 %) and the other slice model,
            ``points[i]["uncertainty"]`` (three extra solves per point; see
            :mod:`kegel.uncertainty`). Default ``False``.

        Each quantity may be a list (or 1-D array): the result then holds one point per
        combination (speed varying fastest), and its figures are arrays.

        Returns
        -------
        FrictionResult

        Raises
        ------
        KegelInputError
            A bad argument (wrong unit, bare number, out of range, unknown word); the message
            names it.
        """
        from .runner.run import run_scene
        from .model.scene import validate_scene

        args = {k: v for k, v in locals().items() if k not in ("self", "run_scene", "validate_scene", "uncertainty")}
        spec = self.spec(**args)
        method = _hydraulic_method(hydraulic, spec.lubrication.mode)
        try:
            scene = validate_scene(spec)
        except KegelInputError as exc:
            raise _as_argument_error(exc) from None
        run = run_scene(scene, write=False, progress=False, uncertainty=uncertainty)
        points = run.points
        if method == "skf":
            points = [_with_skf_drag(scene, p) for p in points]
        return FrictionResult._from_points(
            points, designation=self.designation, lubricant=scene.lubricant.name, material=scene.material.name,
            fidelity=scene.fidelity.name, lubrication=scene.lubrication_label, hydraulic_method=method,
            swept=scene.swept, runtime_s=run.runtime_s)


@dataclass(frozen=True, eq=False, repr=False)
class FrictionResult:
    """The result of :meth:`Bearing.friction`: its main figures and every point's record.

    The figures are floats for one operating point and arrays (one value per point, NaN where a
    point failed) for a sweep. ``points`` holds the full records of :func:`kegel.run.run_scene`
    (load distribution, breakdown by contact and mechanism, film parameters, the SKF catalogue
    model beside kegel, warnings).

    Attributes
    ----------
    designation, lubricant, material
        What was solved.
    fidelity
        The fidelity preset as given (``"fast"``, ``"default"``, ``"fine"``, ``"auto"``).
    lubrication
        E.g. ``"minimum quantity"``, ``"oil bath, flooded"``.
    hydraulic_method
        ``"none"``, ``"liebrecht"`` or ``"skf"``.
    speed_rpm, temperature_degC, axial_load_N, axial_offset_m, radial_load_N
        The operating point(s); ``axial_load_N`` is None (NaN) for displacement-controlled points.
    friction_torque_Nm
        Contact friction torque at the inner ring (drive torque) [N m].
    hydraulic_torque_Nm
        Hydraulic loss of the oil bath [N m] (0 without one).
    total_torque_Nm
        ``friction_torque_Nm + hydraulic_torque_Nm``.
    converged
        Whether every point converged (``points[i]["converged"]`` for each).
    failure
        The first failure message, or None.
    swept
        The quantities that vary over the points.
    points
        The records, one per operating point.
    runtime_s
        Wall time of the run.
    """

    designation: str
    lubricant: str
    material: str
    fidelity: str
    lubrication: str
    hydraulic_method: str
    speed_rpm: float | np.ndarray
    temperature_degC: float | np.ndarray
    axial_load_N: float | None | np.ndarray
    axial_offset_m: float | None | np.ndarray
    radial_load_N: float | np.ndarray
    friction_torque_Nm: float | np.ndarray
    hydraulic_torque_Nm: float | np.ndarray
    total_torque_Nm: float | np.ndarray
    converged: bool
    failure: str | None
    swept: tuple[str, ...] = ()
    points: list[dict[str, Any]] = field(default_factory=list)
    runtime_s: float = 0.0

    @classmethod
    def _from_points(cls, points: list[dict[str, Any]], **meta: Any) -> "FrictionResult":
        def per_point(key: str) -> Any:
            values = [p.get(key) for p in points]
            if len(values) == 1:
                return None if values[0] is None else float(values[0])
            if all(v is None for v in values) and key.startswith("axial_"):
                return None
            return np.array([np.nan if v is None else float(v) for v in values])

        failures = [p.get("failure") for p in points if not p.get("converged", False)]
        return cls(**meta, speed_rpm=per_point("speed_rpm"), temperature_degC=per_point("temperature_degC"),
                   axial_load_N=per_point("axial_load_N"), axial_offset_m=per_point("axial_offset_m"),
                   radial_load_N=per_point("radial_load_N"), friction_torque_Nm=_nan(per_point("friction_torque_Nm")),
                   hydraulic_torque_Nm=_nan(per_point("hydraulic_torque_Nm")),
                   total_torque_Nm=_nan(per_point("total_torque_Nm")),
                   converged=bool(points) and all(bool(p.get("converged")) for p in points),
                   failure=next((str(f) for f in failures if f), "not converged" if failures else None),
                   points=points)

    # --- sequence of points ------------------------------------------------------------------
    def __len__(self) -> int:
        return len(self.points)

    def __getitem__(self, index: int) -> "FrictionResult":
        """The result of one operating point of a sweep."""
        if isinstance(index, bool) or not isinstance(index, numbers.Integral):
            raise TypeError(f"FrictionResult indices are integers, not {type(index).__name__}")
        point = self.points[index]  # IndexError when out of range
        meta = {f.name: getattr(self, f.name) for f in dataclasses.fields(self)
                if f.name in ("designation", "lubricant", "material", "fidelity", "lubrication",
                              "hydraulic_method", "runtime_s")}
        return FrictionResult._from_points([point], **meta, swept=())

    def __iter__(self):
        return (self[i] for i in range(len(self)))

    # --- breakdowns --------------------------------------------------------------------------
    @property
    def torque_by_contact_Nm(self) -> dict[str, float | np.ndarray]:
        """Friction torque by contact (outer and inner raceway, rib, cage) [N m]."""
        return self._breakdown("torque_by_contact_Nm")

    @property
    def torque_by_mechanism_Nm(self) -> dict[str, float | np.ndarray]:
        """Friction torque by mechanism (EHL sliding and rolling, solid sliding and rolling,
        hysteresis) [N m]."""
        return self._breakdown("torque_by_mechanism_Nm")

    @property
    def power_loss_W(self) -> float | np.ndarray:
        """Power lost in the bearing, ``total_torque_Nm`` times the shaft speed [W] (friction and
        hydraulic loss; the table of ``kegel run`` prints it as ``P_loss``)."""
        vals = [abs(p["total_torque_Nm"] * p["speed_rad_s"]) if p.get("total_torque_Nm") is not None else math.nan
                for p in self.points]
        return float(vals[0]) if len(vals) == 1 else np.array(vals, dtype=float)

    @property
    def Lambda_min(self) -> float | np.ndarray:
        """Smallest film parameter Lambda over the contacts (< 1: mixed lubrication)."""
        vals = [min((p.get("Lambda_min") or {}).values(), default=math.nan) for p in self.points]
        return float(vals[0]) if len(vals) == 1 else np.array(vals, dtype=float)

    @property
    def warnings(self) -> list[str]:
        """The warning codes of the points (each once; see :mod:`kegel.point_warnings`)."""
        return list(dict.fromkeys(w["code"] for p in self.points for w in p.get("warnings", ())))

    def _breakdown(self, key: str) -> dict[str, float | np.ndarray]:
        names = list(dict.fromkeys(k for p in self.points for k in (p.get(key) or {})))
        if len(self.points) == 1:
            return {k: float(self.points[0][key][k]) for k in names}
        return {k: np.array([(p.get(key) or {}).get(k, np.nan) for p in self.points], dtype=float) for k in names}

    # --- output ------------------------------------------------------------------------------
    def __repr__(self) -> str:
        if len(self.points) == 1:
            return f"FrictionResult({self.designation}, {_point_line(self.points[0], self.hydraulic_method)})"
        n = len(self.points)
        ok = sum(bool(p.get("converged")) for p in self.points)
        head = (f"FrictionResult({self.designation}, {n} points over {', '.join(self.swept) or 'operating points'}, "
                f"{ok}/{n} converged)")
        lines = [head] + [f"  [{i}] {_point_line(p, self.hydraulic_method)}"
                          for i, p in enumerate(self.points[:_REPR_POINTS])]
        if n > _REPR_POINTS:
            lines.append(f"  ... {n - _REPR_POINTS} more (to_dataframe() for every point)")
        return "\n".join(lines)

    def plot(self, path: str | Path | None = None, *, which: str = "torque") -> "Figure | Path":
        """The plot ``kegel run`` writes for these points: torque against the swept quantity
        (``which="torque"``), its breakdown by contact and mechanism (``"breakdown"``) or the
        roller loads and cage slip (``"loads"``); see :func:`kegel.plots.build_figures`.

        Parameters
        ----------
        path
            A figure file to write (``.png``, ``.pdf``, ``.svg``, ...: :data:`kegel.plots.FIGURE_SUFFIXES`);
            None returns the matplotlib figure instead (for a notebook or further drawing).
        which
            ``"torque"``, ``"breakdown"`` or ``"loads"``.

        Returns
        -------
        matplotlib.figure.Figure or Path
            The figure (``path`` None), else the file written.

        Raises
        ------
        KegelInputError
            An unknown ``which``, or a ``path`` that is a folder, has an unknown suffix or lies in a
            folder that does not exist.
        """
        import matplotlib

        if path is not None:
            matplotlib.use("Agg")  # writing a file needs no window
        import matplotlib.pyplot as plt

        from .outputs.plots import PlotMeta, build_figures, check_figure_path, save_figure

        keys = {"torque": "torque_plot", "breakdown": "breakdown_plot", "loads": "loads_plot"}
        if which not in keys:
            raise KegelInputError("FrictionResult.plot", "which", which, "one of " + ", ".join(keys))
        target = None if path is None else check_figure_path(path, source="FrictionResult.plot", key="path")
        meta = PlotMeta(title=f"kegel.Bearing({self.designation!r}).friction", bearing=self.designation,
                        lubricant=self.lubricant, lubrication=self.lubrication,
                        fidelity=f"{self.fidelity}, quasi_static", swept=list(self.swept) or ["speed"],
                        hydraulic={"liebrecht": "Liebrecht", "skf": "SKF", "cfd": "CFD"}.get(self.hydraulic_method))
        figs = build_figures(self.points, meta)
        fig = figs.pop(keys[which])
        for other in figs.values():
            plt.close(other)
        if target is None:
            return fig
        try:
            return Path(save_figure(fig, target))
        finally:
            plt.close(fig)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary: the figures and every point's record (no numpy types; NaN
        becomes None)."""
        out = {f.name: getattr(self, f.name) for f in dataclasses.fields(self)}
        out["swept"] = list(self.swept)
        return _json_ready(out)

    def to_dataframe(self) -> "pandas.DataFrame":
        """One row per operating point with flat columns: the point's scalars,
        ``torque_<contact>_Nm``, ``torque_<mechanism>_Nm``, ``power_<contact>_<mechanism>_W``,
        ``Lambda_min`` and ``Lambda_min_<contact>``, the hydraulic loss's components
        (``hydraulic_*``), the SKF catalogue model (``skf_*``), the oil's properties
        (``lubricant_*``) and the warning codes. ``DataFrame.attrs`` holds the bearing,
        lubricant, material, fidelity, lubrication and hydraulic method.

        Raises
        ------
        ImportError
            When pandas is not installed.
        """
        try:
            import pandas as pd
        except ImportError as exc:
            raise ImportError("FrictionResult.to_dataframe() needs pandas, which is not installed "
                              "(pip install pandas); to_dict() needs nothing") from exc
        df = pd.DataFrame([_flat_row(p) for p in self.points])
        df.attrs.update({k: getattr(self, k) for k in ("designation", "lubricant", "material", "fidelity",
                                                        "lubrication", "hydraulic_method")})
        return df


# --- helpers ---------------------------------------------------------------------------------

def _name_argument(value: Any, name: str, expected: str) -> str:
    if isinstance(value, Path):
        return str(value)
    if isinstance(value, bool) or not isinstance(value, (str, numbers.Integral)) or not str(value).strip():
        raise KegelInputError(_SOURCE_BEARING, name, value, expected)
    return str(value)


def _operating_spec(given: dict[str, Any]) -> tuple["OperatingSpec", dict[str, Any]]:
    """The typed ``[operating]`` table from the quantity arguments (``given``: every quantity
    keyword and unit-named keyword with its value, None when not given), each value read once;
    and the table as a scene file would write it."""
    from .model.scene_model import OperatingSpec

    sweeps: dict[str, Sweep] = {}
    texts: dict[str, Any] = {}
    for name in _QUANTITIES:
        keys = [name, *(k for k, (q, _) in UNIT_KEYWORDS.items() if q == name)]
        present = [k for k in keys if given.get(k) is not None]
        if len(present) > 1:
            raise KegelInputError(_SOURCE_FRICTION, present[1], given[present[1]],
                                  f"one of {', '.join(keys)}, not both {present[0]} and {present[1]}")
        if not present:
            if name in _DEFAULTS:
                sweeps[name], texts[name] = _quantity_sweep(_DEFAULTS[name], name, name)
            continue
        key = present[0]
        if key == name:
            sweeps[name], texts[name] = _quantity_sweep(given[key], key, name)
        else:
            sweeps[name], texts[name] = _unit_keyword_sweep(given[key], key)
    if "speed" not in sweeps:
        raise KegelInputError(_SOURCE_FRICTION, "speed", None,
                              "a speed: speed='2000 rpm' (a string with its unit or a pint quantity), "
                              "speed_rpm=2000 or speed_rad_s=209.4")
    if ("axial_load" in sweeps) == ("axial_offset" in sweeps):
        key = next((k for k in ("axial_load", "axial_load_N", "axial_load_kN") if given.get(k) is not None),
                   "axial_load")
        raise KegelInputError(_SOURCE_FRICTION, key, given.get(key),
                              "exactly one of axial_load (force-controlled, e.g. '6 kN' or axial_load_kN=6) and "
                              "axial_offset (displacement-controlled preload, e.g. '20 um' or axial_offset_um=20)")
    order = ("speed", "axial_load", "axial_offset", "radial_load", "temperature")
    spec = OperatingSpec(**sweeps, given=tuple(f"operating.{k}" for k in order if k in sweeps))
    return spec, {k: texts[k] for k in order if k in texts}


def _with_ring_temperatures(operating: "OperatingSpec", texts: dict[str, Any],
                            given: dict[str, Any]) -> tuple["OperatingSpec", dict[str, Any]]:
    """The typed operating table with the contact temperature per ring (``operating.inner_ring_temperature``,
    ``outer_ring_temperature``): one temperature with its unit each, or None (the oil's)."""
    from .model.scene_model import Scalar

    extra: dict[str, Any] = {}
    for key, value in given.items():
        if value is None:
            continue
        if isinstance(value, (list, tuple, np.ndarray)):
            raise KegelInputError(_SOURCE_FRICTION, key, value, "one temperature with its unit, e.g. '60 degC' (a "
                                  "contact temperature per ring is not swept; sweep temperature)")
        if isinstance(value, str) or _is_pint_quantity(value):
            si = parse_quantity(value, "temperature", source=_SOURCE_FRICTION, key=key)
        else:
            raise KegelInputError(_SOURCE_FRICTION, key, value, "a temperature with its unit, e.g. '60 degC' (or a "
                                  "pint quantity), or None for the oil temperature")
        text = value if isinstance(value, str) else f"{si!r} K"
        extra[key] = Scalar(si, key, value)
        texts = {**texts, key: text}
    if not extra:
        return operating, texts
    given_keys = operating.given + tuple(f"operating.{k}" for k in extra)
    return dataclasses.replace(operating, **extra, given=given_keys), texts


def _items(value: Any, name: str) -> list[Any] | None:
    """The values of a sweep (a list, tuple or 1-D array), or None for a single value."""
    if isinstance(value, (list, tuple, np.ndarray)):
        items = np.asarray(value, dtype=object).ravel().tolist() if isinstance(value, np.ndarray) else list(value)
        if not items:
            raise KegelInputError(_SOURCE_FRICTION, name, value, "a sweep with at least one value")
        return items
    return None


def _quantity_sweep(value: Any, key: str, name: str) -> tuple["Sweep", str | list[str]]:
    """An operating quantity given with its unit (a string, checked by the grammar of
    :mod:`kegel.units`, or a pint quantity), or a list of them: its SI values, named by the
    argument, and its scene text (a pint quantity as its SI value with the SI unit)."""
    from .model.scene_model import Sweep

    items = _items(value, key)
    if items is not None:
        pairs = [_one_quantity(v, f"{key}[{i}]", name) for i, v in enumerate(items)]
        return Sweep(tuple(p[0] for p in pairs), key, items), [p[1] for p in pairs]
    si, text = _one_quantity(value, key, name)
    return Sweep((si,), key, value), text


def _one_quantity(value: Any, key: str, name: str) -> tuple[float, str]:
    kind = KINDS[_QUANTITIES[name]]
    if isinstance(value, str):
        return parse_quantity(value, _QUANTITIES[name], source=_SOURCE_FRICTION, key=key), value
    if _is_pint_quantity(value):
        si = parse_quantity(value, _QUANTITIES[name], source=_SOURCE_FRICTION, key=key)
        return si, f"{si!r} {kind.si_unit}"
    unit_keys = " or ".join(f"{k}=" for k, (q, _) in UNIT_KEYWORDS.items() if q == name)
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        raise KegelInputError(_SOURCE_FRICTION, key, value,
                              f"{kind.description} with its unit, e.g. {name}='{kind.example}' (or a pint quantity); "
                              f"a bare number only in a keyword that names its unit: {unit_keys}")
    raise KegelInputError(_SOURCE_FRICTION, key, value,
                          f"{kind.description} with its unit, e.g. '{kind.example}', a pint quantity, or a list of "
                          f"them (a sweep); numbers in {unit_keys}")


def _unit_keyword_sweep(value: Any, keyword: str) -> tuple["Sweep", str | list[str]]:
    """A number (or a list of them) of a keyword that names its unit: SI values and scene text."""
    from .model.scene_model import Sweep

    items = _items(value, keyword)
    if items is not None:
        pairs = [_unit_number(v, f"{keyword}[{i}]", keyword) for i, v in enumerate(items)]
        return Sweep(tuple(p[0] for p in pairs), keyword, items), [p[1] for p in pairs]
    si, text = _unit_number(value, keyword, keyword)
    return Sweep((si,), keyword, value), text


def _unit_number(value: Any, key: str, keyword: str) -> tuple[float, str]:
    name, unit = UNIT_KEYWORDS[keyword]
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or _is_pint_quantity(value):
        raise KegelInputError(_SOURCE_FRICTION, key, value,
                              f"a number in {unit} (the keyword names the unit), e.g. {keyword}={_UNIT_KEYWORD_EXAMPLES[keyword]}; a string with "
                              f"its unit or a pint quantity goes to {name}=")
    v = float(value)
    if not math.isfinite(v):
        raise KegelInputError(_SOURCE_FRICTION, key, value, f"a finite number in {unit}")
    text = f"{v!r} {unit}"
    # the same conversion as the scene file's text "<number> <unit>": equal models either way
    return parse_quantity(text, _QUANTITIES[name], source=_SOURCE_FRICTION, key=key), text


def _is_pint_quantity(value: Any) -> bool:
    """A pint quantity (of any registry; :func:`kegel.units.parse_quantity` converts it)."""
    import pint

    return isinstance(value, pint.Quantity)


def _lubrication_spec(lubrication: Any) -> "LubricationSpec":
    """The ``lubrication`` argument as the typed lubrication (the oil level is checked against
    the bearing by the validation)."""
    from .model.scene_model import LubricationSpec

    expected = ("'minimum_quantity' or the oil level of an oil bath: 'flooded', 'shaft_center', 'half_roller' or a "
                "height above the lowest point of the outer diameter with its unit, e.g. '40 mm' (or a pint quantity)")
    if isinstance(lubrication, str) and lubrication in ("minimum_quantity", "none"):
        return LubricationSpec("minimum_quantity", None, "lubrication", lubrication)
    if isinstance(lubrication, str) and lubrication in _OIL_LEVEL_WORDS:
        return LubricationSpec("oil_bath", lubrication, "lubrication", lubrication)
    if isinstance(lubrication, str):
        try:
            level = parse_quantity(lubrication, "length", source=_SOURCE_FRICTION, key="lubrication")
        except KegelInputError as exc:
            raise KegelInputError(_SOURCE_FRICTION, "lubrication", lubrication,
                                  f"{expected}; here {exc.expected}") from None
        return LubricationSpec("oil_bath", level, "lubrication", lubrication)
    if _is_pint_quantity(lubrication):
        level = parse_quantity(lubrication, "length", source=_SOURCE_FRICTION, key="lubrication")
        return LubricationSpec("oil_bath", level, "lubrication", lubrication)
    raise KegelInputError(_SOURCE_FRICTION, "lubrication", lubrication, expected)


def _hydraulic_method(hydraulic: Any, mode: str) -> str:
    oil_bath = mode == "oil_bath"
    if hydraulic is None:
        return "liebrecht" if oil_bath else "none"
    if not isinstance(hydraulic, str) or hydraulic not in _HYDRAULIC:
        raise KegelInputError(_SOURCE_FRICTION, "hydraulic", hydraulic,
                              f"None or one of {', '.join(_HYDRAULIC)} (CFD losses: a scene file with "
                              "model.hydraulic = \"cfd\", see kegel.scene)")
    if hydraulic != "none" and not oil_bath:
        raise KegelInputError(_SOURCE_FRICTION, "hydraulic", hydraulic,
                              "None or 'none' for minimum-quantity lubrication (no oil bath to churn); give "
                              "lubrication an oil level for a hydraulic loss")
    return hydraulic


def _as_argument_error(exc: KegelInputError, used: dict[str, str] | None = None) -> KegelInputError:
    """A validation error as the facade's: the operating quantities' keys are the arguments
    already (the typed model the facade builds names them); the others (``model.fidelity``,
    ``bearing.material``, ``operating``) map to the argument that set them (``used``: quantity ->
    keyword, for a key still written ``operating.<quantity>``)."""
    key = exc.key
    if key.startswith("operating."):
        key = key[len("operating."):]
        name, sep, rest = key.partition("[")
        key = (used or {}).get(name, name) + sep + rest
    elif key.startswith("lubrication"):
        key = "lubrication"
    else:
        key = _SCENE_KEY_ARGUMENT.get(key, key)
    # the scene's advice names its keys ("use operating.axial_offset"): the facade's are the arguments
    expected = exc.expected.replace("operating.", "")
    return KegelInputError(_SOURCE_FRICTION, key, exc.value, expected)


def _with_skf_drag(scene: "Scene", point: dict[str, Any]) -> dict[str, Any]:
    """A point's record with the SKF drag moment as its hydraulic loss (as a study adds it)."""
    from .correlations import hydraulic_torques
    from .model.lubricant import lubricant_state

    state = lubricant_state(scene.lubricant, point["temperature_K"], source=scene.source, key="temperature")
    h = hydraulic_torques("skf", scene.geometry, state, shaft_speed_rad_s=point["speed_rad_s"],
                          oil_level_m=scene.lubrication.oil_level_m)
    friction = point.get("friction_torque_Nm")
    out = {**point, "hydraulic_torque_Nm": h.total_Nm,
           "total_torque_Nm": None if friction is None else friction + h.total_Nm, "hydraulic": h.as_dict()}
    warnings = list(point.get("warnings", ()))
    if all(w.get("code") != "skf_constants_to_verify" for w in warnings):
        warnings.append({"code": "skf_constants_to_verify",
                         "message": "the SKF drag moment uses the V_M diagram digitisation and constants marked "
                                    "verify (kegel.correlations.skf)"})
    out["warnings"] = warnings
    return out


def _nan(value: Any) -> Any:
    return math.nan if value is None else value


def _fmt(value: Any, spec: str) -> str:
    return "-" if value is None or (isinstance(value, float) and math.isnan(value)) else format(value, spec)


def _point_line(p: dict[str, Any], method: str) -> str:
    """One operating point in a line: conditions, torques, convergence."""
    cond = [f"{_fmt(p.get('speed_rpm'), '.6g')} rpm"]
    if p.get("axial_load_N") is not None:
        cond.append(f"Fa {p['axial_load_N'] / 1e3:.4g} kN")
    elif p.get("axial_offset_m") is not None:
        cond.append(f"offset {p['axial_offset_m'] * 1e6:.4g} um")
    if p.get("radial_load_N"):
        cond.append(f"Fr {p['radial_load_N'] / 1e3:.4g} kN")
    cond.append(f"{_fmt(p.get('temperature_degC'), '.4g')} degC")
    figures = [f"friction {_fmt(p.get('friction_torque_Nm'), '.3g')} N m"]
    if method != "none":
        figures.append(f"hydraulic {_fmt(p.get('hydraulic_torque_Nm'), '.3g')} N m ({method})")
        figures.append(f"total {_fmt(p.get('total_torque_Nm'), '.3g')} N m")
    if p.get("converged"):
        state = "converged"
    else:
        msg = " ".join(str(p.get("failure") or "").split())
        state = "NOT converged" + (f": {msg[:60]}{'...' if len(msg) > 60 else ''}" if msg else "")
    return f"{', '.join(cond)}: {', '.join(figures)}, {state}"


def _json_ready(x: Any) -> Any:
    """Plain Python types for JSON: numpy arrays and scalars converted, NaN and inf as None."""
    if isinstance(x, dict):
        return {str(k): _json_ready(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_json_ready(v) for v in x]
    if isinstance(x, np.ndarray):
        return [_json_ready(v) for v in x.tolist()]
    if isinstance(x, np.generic):
        return _json_ready(x.item())
    if isinstance(x, float) and not math.isfinite(x):
        return None
    if isinstance(x, Path):
        return str(x)
    return x


#: Sub-dictionaries of a record flattened into columns with a prefix (others: by their own rule).
_FLAT_PREFIX = {"skf_catalogue_model": "skf_", "lubricant_state": "lubricant_"}


def _flat_row(p: dict[str, Any]) -> dict[str, Any]:
    """A point's record as one flat row (scalars only; the per-roller lists stay in ``points``)."""
    row: dict[str, Any] = {}
    for key, value in p.items():
        if value is None or isinstance(value, (bool, int, float, str, np.generic)):
            row[key] = value.item() if isinstance(value, np.generic) else value
        elif key == "torque_by_contact_Nm" or key == "torque_by_mechanism_Nm":
            row.update({f"torque_{k}_Nm": v for k, v in value.items()})
        elif key == "power_W":
            row.update({f"power_{c}_{k}_W": v for c, ks in value.items() if isinstance(ks, dict)
                        for k, v in ks.items()})
        elif key in ("Lambda_min", "phi_max") and isinstance(value, dict):
            if key == "Lambda_min":
                row["Lambda_min"] = min(value.values(), default=None)
                row["Lambda_min_contact"] = min(value, key=value.get) if value else None
            row.update({f"{key}_{c}": v for c, v in value.items()})
        elif key == "hydraulic" and isinstance(value, dict):
            for k, v in value.items():
                if k in ("correlation", "source"):
                    row["hydraulic_source"] = v
                elif k == "components" and isinstance(v, dict):
                    row.update({f"hydraulic_{c}": cv for c, cv in v.items() if _scalar(cv)})
                elif _scalar(v):
                    row[f"hydraulic_{k}"] = v
        elif key in _FLAT_PREFIX and isinstance(value, dict):
            skip = {"name", "temperature_K", "temperature_degC"}
            row.update({f"{_FLAT_PREFIX[key]}{k}": v for k, v in value.items() if k not in skip and _scalar(v)})
        elif key == "warnings":
            row["warnings"] = "; ".join(w.get("code", "") for w in value)
    return row


def _scalar(v: Any) -> bool:
    return v is None or isinstance(v, (bool, int, float, str, np.generic))
