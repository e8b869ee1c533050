"""Warnings of a result: what a reader must know before trusting a point's figures.

Every warning has a code and a message. :func:`point_warnings` gives a point's warnings (they go
into ``results.json`` and the ``warnings`` column of ``results.csv``); :class:`WarningLog` prints
each code once per run on stderr and counts the points that carry it.

Codes
-----
``not_converged``
    The point failed its plausibility gates (power, force or moment balance, torque sign): its
    figures are not an answer (the record keeps them, with the residuals, for diagnosis); or its
    solver raised, and it has no figures (the message is the record's ``failure``).
``cage_pocket_fallback``
    The free-roller cage solution failed its balances; the cage pockets carry every roller.
``rib_edge_loading``
    The Hertz ellipse of some rollers' contact with the rib is cut by the rib's top or by the edge
    of the roller end's spherical cap (``rib_edge_rollers``): the contact runs on an edge, where
    its pressure peaks and wear and scuffing start. The rib cell model solves those contacts'
    pressure from the exact gap. The closed-form rib (``rib_model = "hertz"``) does not check.
``mixed_lubrication``
    A contact's film parameter Lambda < 1: asperity contact carries load and the solid friction
    parameters (textbook values, marked ``verify``) enter the answer.
``outside_compared_range``
    The point lies outside the conditions at which kegel's friction torque has been compared with
    anything outside kegel (:data:`COMPARED_RANGE`: the SKF catalogue model at the seed paper's
    Table 1-3 conditions, which hold the measured Figure 5 torques of the 32216 at 50 degC too;
    see ``kegel validate``).
``parameters_to_verify``
    Friction or lubricant parameters marked ``verify = true`` in their data files (textbook values
    not yet confirmed for this pair) enter the answer.
``skf_constants_to_verify``
    The SKF catalogue model shown beside kegel uses constants marked ``verify``
    (``kegel.correlations.skf.VERIFY``).
``liebrecht_extrapolated``
    Liebrecht's correlation (seed paper Eq. 38-40) was fitted on a 32208 with a vertical shaft:
    another bearing, or a partial oil level of a horizontal shaft, is an extrapolation.
``cfd_not_steady``
    The CFD result used did not reach a steady loss torque.
``cfd_unbalanced``
    The CFD result used is not in angular-momentum balance (its wall torques do not sum to zero
    within ``kegel.coupling.cfd_results.BALANCE_LIMIT`` of the drive torque): either the oil is
    still gaining or losing angular momentum, or the mesh and the frozen rotor's MRF term miss the
    balance by more than the shipped cases do; its loss is not confirmed
    (``kegel.coupling.cfd_results.unbalanced_reason``).
``contacts_fully_flooded``
    Minimum-quantity lubrication (a scene's, or a study's case) with fully flooded contacts
    (``model.lubricant_supply = "flooded"`` and no ``model.inlet_gap_ratio``): the contact
    friction is that of an unlimited oil supply. With the default supply model
    (:mod:`kegel.supply`) the raceway contacts' inlet is modelled and the warning does not appear.
``supply_beyond_source_range``
    The supply model's starvation factor (SKF's ``phi_rs``) lies below Biboulet-Houpert's Eq. 44
    at its most starved computed inlet (S = 2, factor 0.2001): the contacts get that factor, a
    smaller reduction than SKF's.
``geometry_estimated``
    The bearing's internal geometry (pitch diameter, roller size and count, profile, roughness) was
    estimated from its boundary dimensions (:mod:`kegel.estimate`: a designation of the ISO 355
    series table, a ``[boundary]`` bearing file, or boundary dimensions in the scene), not measured.
``lubricant_estimated``
    The oil's Vogel law and pressure-viscosity coefficient were estimated from its viscosities at
    40 and 100 degC (:mod:`kegel.estimate`); its other properties are those of FVA 3.
``cfd_interpolated`` / ``cfd_missing``
    A study's CFD loss interpolated between computed speeds (with its error), or not computed.
"""

from __future__ import annotations

import sys
import tomllib
from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any, TextIO

from ..coupling.cfd_results import is_unbalanced, unbalanced_reason

__all__ = ["COMPARED_RANGE", "Warning_", "WarningLog", "liebrecht_warning", "point_warnings", "verify_tables",
           "warnings_once_per_command"]

#: Conditions at which kegel's friction torque has been compared with an outside answer: the SKF
#: catalogue model at the seed paper's Table 1-3 points (``kegel validate``; examples/32216_table*.toml:
#: 32216, d_m = 108.5 mm, 500-4000 rpm, FVA 3 at 42 and 50 degC, nu = 60.6-87.7 mm^2/s).
#: ``tests/python/test_outputs.py`` recomputes them from the example scenes.
COMPARED_RANGE = {
    "speed_factor_rpm_mm": (5.4e4, 4.4e5),        # n d_m
    "nu_n_mm2_s_rpm": (3.0e4, 3.55e5),            # nu n, the EHL film's speed-viscosity variable
}


@dataclass(frozen=True)
class Warning_:
    """One warning of a point: a code (see the module docstring) and a message."""

    code: str
    message: str

    def as_dict(self) -> dict[str, str]:
        """JSON-ready form."""
        return {"code": self.code, "message": self.message}


@lru_cache(maxsize=16)
def verify_tables(path: str) -> tuple[str, ...]:
    """The tables of a data file marked ``verify = true`` (empty when it cannot be read)."""
    try:
        raw = tomllib.loads(Path(path).read_text())
    except (OSError, tomllib.TOMLDecodeError):
        return ()
    out: list[str] = []

    def walk(node: dict[str, Any], prefix: str) -> None:
        for k, v in node.items():
            if isinstance(v, dict):
                if v.get("verify") is True:
                    out.append(prefix + k)
                walk(v, prefix + k + ".")

    walk(raw, "")
    return tuple(out)


def liebrecht_warning(bearing: str, flooded: bool) -> Warning_ | None:
    """The ``liebrecht_extrapolated`` warning for a bearing and oil level, or None."""
    why = []
    if bearing != "32208":
        why.append(f"bearing {bearing} (fitted on a 32208)")
    if not flooded:
        why.append("a partial oil level of a horizontal shaft (fitted with a vertical shaft)")
    if not why:
        return None
    return Warning_("liebrecht_extrapolated",
                    "Liebrecht's correlation (Eq. 38-40) is extrapolated here: " + "; ".join(why))


def point_warnings(scene: Any, point: dict[str, Any], friction: Any = None) -> list[Warning_]:
    """The warnings of one operating point's record (see the module docstring).

    Parameters
    ----------
    scene
        The :class:`kegel.scene.Scene` the point belongs to.
    point
        The point's record (``kegel.run``): ``converged``, ``failure``, ``cage_model``,
        ``Lambda_min``, ``skf_catalogue_model``, ``hydraulic``, speeds and temperature.
    friction
        The friction parameters used (:class:`kegel.FrictionData`), for ``parameters_to_verify``.
    """
    out: list[Warning_] = []
    if point.get("converged") is False and not point.get("solved", True):
        out.append(Warning_("not_converged", f"point {point.get('index')} has no answer: its solver failed "
                            "(the failure is in the record)"))
    elif point.get("converged") is False:
        out.append(Warning_("not_converged", f"point {point.get('index')} failed its plausibility gates "
                            f"({point.get('failure') or 'see the record'}): its figures are not an answer"))
    if scene.fidelity.cage is True and point.get("cage_model") == "pocket":
        out.append(Warning_("cage_pocket_fallback", "the free-roller cage solution failed its balances: the cage "
                            "pockets carry every roller (pocket model)"))
    mql = scene.lubrication.mode == "minimum_quantity" if getattr(scene, "study", None) is None else any(
        c.mode == "minimum_quantity" for c in scene.study.cases)
    supply_modelled = getattr(scene.fidelity, "lubricant_supply", "flooded") != "flooded"
    if mql and not supply_modelled and not scene.fidelity.inlet_gap_ratio and point.get("solved", True):
        out.append(Warning_("contacts_fully_flooded", "minimum-quantity lubrication: the contact friction is "
                            "that of fully flooded raceway contacts (model.lubricant_supply = \"flooded\"; the "
                            "default \"kinematic_replenishment\" models their inlet, kegel.supply)"))
    supplies = [point.get("lubricant_supply")] + [c.get("lubricant_supply")
                                                  for c in (point.get("study_friction") or {}).values()]
    if any(s and (s.get("clamped_inner") or s.get("clamped_outer")) for s in supplies):
        out.append(Warning_("supply_beyond_source_range", "the oil supply's starvation factor (SKF phi_rs) is below "
                            "Biboulet-Houpert's Eq. 44 at its most starved computed inlet (S = 2, factor 0.2001): "
                            "the raceway contacts get that factor, a smaller reduction than SKF's"))
    edge = point.get("rib_edge_rollers") or 0
    if edge > 0:
        out.append(Warning_("rib_edge_loading", f"{edge} roller(s) run on an edge at the rib: their Hertz ellipse "
                            "is cut by the rib's top or the roller end's cap (edge loading; the cell model solves "
                            "their pressure from the exact gap)"))
    lam = point.get("Lambda_min") or {}
    if isinstance(lam, dict) and lam:
        worst = min(lam, key=lambda k: lam[k])
        if lam[worst] < 1.0:
            out.append(Warning_("mixed_lubrication", f"film parameter Lambda = {lam[worst]:.2f} < 1 at the "
                                f"{worst.replace('_', ' ')} contact: mixed lubrication, the solid friction "
                                "parameters (textbook values) carry part of the answer"))
    d_m_mm = scene.geometry.pitch_diameter_m * 1e3
    n = abs(point["speed_rpm"])
    nu = (point.get("lubricant_state") or {}).get("kinematic_viscosity_m2_s")
    outside = []
    lo, hi = COMPARED_RANGE["speed_factor_rpm_mm"]
    if not lo <= n * d_m_mm <= hi:
        outside.append(f"n d_m = {n * d_m_mm:.3g} rpm mm (compared: {lo:.3g}-{hi:.3g})")
    if nu is not None:
        lo, hi = COMPARED_RANGE["nu_n_mm2_s_rpm"]
        v = nu * 1e6 * n
        if not lo <= v <= hi:
            outside.append(f"nu n = {v:.3g} mm^2/s rpm (compared: {lo:.3g}-{hi:.3g})")
    if outside:
        out.append(Warning_("outside_compared_range", "outside the conditions kegel's friction torque has been "
                            "compared at (SKF model at the seed's Tables 1-3; measured: its Figure 5, inside "
                            "them): " + "; ".join(outside)))
    marked = []
    for name, path in ((getattr(friction, "name", None), getattr(friction, "source_file", None)),
                       (scene.lubricant.name, getattr(scene.lubricant, "source_file", None))):
        tables = verify_tables(path) if path else ()
        if tables:
            marked.append(f"{name} ({', '.join(tables)})")
    if marked:
        out.append(Warning_("parameters_to_verify", "parameters marked verify (textbook values, not confirmed "
                            "for this pair) enter the answer: " + "; ".join(marked)))
    skf = point.get("skf_catalogue_model")
    if skf and skf.get("verify"):
        out.append(Warning_("skf_constants_to_verify", "the SKF catalogue model beside kegel uses constants marked "
                            "verify (kegel.correlations.skf.VERIFY)"))
    hyd = point.get("hydraulic")
    if hyd and hyd.get("source") == "cfd":
        if hyd.get("steady") is False:
            out.append(Warning_("cfd_not_steady", f"the CFD result {hyd.get('file')} did not reach a steady loss "
                                "torque"))
        bal = hyd.get("angular_momentum_balance")
        if is_unbalanced(bal):
            out.append(Warning_("cfd_unbalanced", f"the CFD result {hyd.get('file')}: {unbalanced_reason(bal)}"))
    elif hyd and scene.lubrication.oil_level_m > 0 and scene.fidelity.hydraulic == "correlation":
        w = liebrecht_warning(scene.bearing.designation,
                              scene.lubrication.oil_level_m >= scene.bearing.outer_diameter_m)
        if w:
            out.append(w)
    estimated = getattr(scene.bearing, "estimated", ())
    if estimated:
        out.append(Warning_("geometry_estimated", f"bearing {scene.bearing.designation}: internal geometry estimated "
                            f"from its boundary dimensions ({', '.join(e.replace('_', ' ') for e in estimated)}), "
                            "not measured (kegel.estimate; docs/bearings_and_oils.md)"))
    if getattr(scene.lubricant, "estimated", ()):
        out.append(Warning_("lubricant_estimated", f"lubricant {scene.lubricant.name}: Vogel law and pressure-viscosity "
                            "coefficient estimated from its viscosities at 40 and 100 degC (ASTM D341, So-Klaus), "
                            "its other properties those of FVA 3 (kegel.estimate; docs/bearings_and_oils.md)"))
    for row in point.get("study") or ():
        for w in row.get("warnings", ()):
            if all(w["code"] != o.code for o in out):
                out.append(Warning_(w["code"], w["message"]))
    return out


# the (code, message) pairs already printed by this command (None: outside a command, each run
# prints its own): a command that runs several scenes (`kegel validate`) prints each warning once
_PRINTED: ContextVar[set[tuple[str, str]] | None] = ContextVar("kegel_printed_warnings", default=None)


@contextmanager
def warnings_once_per_command() -> Iterator[None]:
    """Within this block every :class:`WarningLog` prints a warning (code and message) at most
    once, however many runs the block makes; each run still counts its own points."""
    token = _PRINTED.set(set())
    try:
        yield
    finally:
        _PRINTED.reset(token)


@dataclass
class WarningLog:
    """Prints each warning code once per run (the first message with that code; within
    :func:`warnings_once_per_command`, once per command) and counts the points that carry it;
    :meth:`summary` gives the counts."""

    stream: TextIO | None = None
    counts: dict[str, int] = field(default_factory=dict)

    def add(self, index: int, warnings: list[Warning_]) -> None:
        """Record the warnings of point ``index``; print codes not seen before."""
        for w in warnings:
            if w.code not in self.counts:
                self.counts[w.code] = 0
                printed = _PRINTED.get()
                if printed is None or (w.code, w.message) not in printed:
                    print(f"kegel: warning [{w.code}] (point {index}): {w.message}", file=self.stream or sys.stderr)
                if printed is not None:
                    printed.add((w.code, w.message))
            self.counts[w.code] += 1

    def summary(self) -> dict[str, int]:
        """Points per warning code."""
        return dict(self.counts)
