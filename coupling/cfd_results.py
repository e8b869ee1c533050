"""Find the CFD result (``results.json`` of ``kegel cfd run`` or ``kegel cfd sweep``) that belongs
to an operating point.

A scene with ``[model] hydraulic = "cfd"`` names a results file or a folder of them
(``cfd_results``); each operating point takes the result computed for it: the same bearing and
lubricant, the speed within 0.5 %, the temperature within 0.5 K and the same oil level (flooded,
or the level within 0.1 mm). A CFD result is one frozen-rotor solution at one point, so kegel does
not scale it to other speeds or temperatures: a point without its result is an error that lists
the points available.
"""

from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass, replace
from pathlib import Path
from typing import Any

from ..base.errors import KegelInputError

__all__ = ["BALANCE_LIMIT", "balance_of", "is_unbalanced", "unbalanced_reason", "cfd_loss_at", "find_cfd_result",
           "cfd_result_files", "read_cfd_results"]

SPEED_TOLERANCE = 0.005       # relative
TEMPERATURE_TOLERANCE_K = 0.5
OIL_LEVEL_TOLERANCE_M = 1e-4
#: The CFD geometry's default gap ratio g / D_w (``kegel.cfd_cases.geometry.GAP_RATIO``, chosen by
#: the gap study, docs/cfd.md); stated here so that reading results does not import the mesher.
DEFAULT_GAP_RATIO = 0.08

#: Largest |angular-momentum balance| of a CFD result read as settled: (sum of the torques the
#: walls take from the oil - the moment of the fluid's weight) / |drive torque|. In a steady
#: state it vanishes; the discretisation leaves -14 % (flooded, tiny mesh) to -4 % (fine). An oil
#: bath on the tiny mesh, stopped by the present rule (five cage revolutions and a hold), misses
#: by +18 to +25 % at 2000-4000 rpm, and run on to 10.5 revolutions by +15 to +30 % while its
#: loss holds (docs/cfd.md, "Oil bath: how steady"): there most of it comes with the frozen
#: rotor's MRF term, not with a transient. Beyond 25 % a result is flagged as unconfirmed: either
#: the oil is still gaining or losing angular momentum as a whole, or the mesh misses the balance
#: by more than the shipped cases do.
BALANCE_LIMIT = 0.25


def is_unbalanced(balance: float | None) -> bool:
    """Whether a CFD result's angular-momentum balance (:func:`balance_of`; None: not stated)
    misses by more than :data:`BALANCE_LIMIT` of the drive torque, on either side."""
    return balance is not None and abs(balance) > BALANCE_LIMIT


def unbalanced_reason(balance: float) -> str:
    """The one reading of an unbalanced CFD result, shared by every place that flags it
    (``kegel run``'s and a study's ``cfd_unbalanced`` warnings, ``kegel losses --cfd``)."""
    return (f"its wall torques miss the angular-momentum balance by {100 * balance:+.0f} % of the drive torque "
            f"(accepted: within {100 * BALANCE_LIMIT:.0f} %): either the oil is still gaining or losing angular "
            "momentum as a whole, or the mesh and the frozen rotor's MRF term miss the balance by more than the "
            "shipped cases do; read its loss as unconfirmed")


def balance_of(data: dict[str, Any]) -> float | None:
    """The angular-momentum balance of a CFD ``results.json`` (sum of the wall torques less the
    moment of the fluid's weight, relative to the drive torque), or None when the result does not
    state it (an oil-bath result that does not count the weight's moment)."""
    bal = data.get("angular_momentum_balance") or {}
    oil_bath = (data.get("point") or {}).get("oil_level_m") is not None
    if oil_bath and "weight_moment_on_fluid_Nm" not in bal:
        return None  # an oil-bath result from before the weight's moment was counted: no balance stated
    b = bal.get("relative_to_drive_torque")
    return None if b is None or not math.isfinite(float(b)) else float(b)


@dataclass(frozen=True)
class CfdBoundary:
    """Where a CFD result's oil ends and the contact model's begins, and the hydraulic loss that
    goes with it (docs/cfd.md, "The contact / CFD split").

    A result of the real-roller geometry (its ``point`` states ``gap_ratio``) opens a slab of
    height ``g = gap_ratio * D_w`` at each raceway line contact: the contact model owns the oil
    within g (its rolling force cut off there, ``contact_film_limit_m``), and the films thinner
    than the CFD's clearance (roller end / rib, pocket faces) are analytic terms
    (``thin_films_Nm``, :mod:`kegel.cfd_cases.thin_films`). A result of the old geometry (rollers
    shrunk by 0.08 D_w, no ``gap_ratio``) has no defined boundary: ``contact_film_limit_m`` 0 (the
    contact uncut) and no thin films, and ``geometry`` says so.

    Attributes
    ----------
    geometry
        ``"real rollers"`` or ``"shrunk rollers (old geometry, no contact / CFD boundary)"``.
    gap_ratio
        g / D_w of the result (None for the old geometry).
    contact_film_limit_m
        g [m]: the film height at which the contact model's rolling force is cut off (0: uncut).
    cfd_Nm
        The CFD's loss torque at the shaft (beyond g).
    thin_films_Nm
        The analytic thin-film terms (0 for the old geometry).
    unloaded_line_wedge_Nm
        The CFD's far field beyond g on the unloaded stretch of the raceway lines, which the
        contact model's convention (no rolling resistance off the loaded stretch) does not count
        (:func:`kegel.coupling.split.unloaded_line_wedge`; it needs the point's load
        distribution, so it is 0 until :meth:`with_unloaded_line_wedge` sets it).
    """

    geometry: str
    gap_ratio: float | None
    contact_film_limit_m: float
    cfd_Nm: float
    thin_films_Nm: float
    unloaded_line_wedge_Nm: float = 0.0

    @property
    def hydraulic_Nm(self) -> float:
        """The hydraulic loss at the shaft that goes with a contact cut at g: CFD + thin films,
        less the CFD's share on the unloaded stretch of the lines."""
        return self.cfd_Nm + self.thin_films_Nm - self.unloaded_line_wedge_Nm

    def with_unloaded_line_wedge(self, torque_Nm: float) -> "CfdBoundary":
        """The same boundary with its unloaded-stretch share (a finite torque >= 0)."""
        if not (math.isfinite(torque_Nm) and torque_Nm >= 0.0):
            raise KegelInputError("<argument>", "unloaded_line_wedge_Nm", torque_Nm, "a finite torque >= 0")
        return replace(self, unloaded_line_wedge_Nm=float(torque_Nm))

    def as_dict(self) -> dict[str, Any]:
        return {**asdict(self), "hydraulic_Nm": self.hydraulic_Nm}


def cfd_boundary(data: dict[str, Any], roller_mean_diameter_m: float, *, source: str = "<dict>") -> CfdBoundary:
    """The contact / CFD boundary of one CFD result (:class:`CfdBoundary`).

    Raises
    ------
    KegelInputError
        A real-roller result without its thin-film loss (``thin_film_loss_Nm``), or a gap ratio
        that is not a positive finite number.
    """
    pt = data.get("point") or {}
    cfd = float(data["loss_torque_at_shaft_Nm"])
    r = pt.get("gap_ratio")
    if r is None:
        return CfdBoundary("shrunk rollers (old geometry, no contact / CFD boundary)", None, 0.0, cfd, 0.0)
    if isinstance(r, bool) or not isinstance(r, (int, float)) or not (math.isfinite(r) and r > 0):
        raise KegelInputError(source, "point.gap_ratio", r, "a positive fraction of the roller diameter")
    thin = data.get("thin_film_loss_Nm")
    if isinstance(thin, bool) or not isinstance(thin, (int, float)) or not math.isfinite(thin) or thin < 0:
        raise KegelInputError(source, "thin_film_loss_Nm", thin,
                              "the analytic thin-film loss of a real-roller CFD result (a finite number >= 0; "
                              "kegel cfd run writes it)")
    return CfdBoundary("real rollers", float(r), float(r) * roller_mean_diameter_m, cfd, float(thin))


def cfd_result_files(path: str | Path) -> list[Path]:
    """``path`` itself when it is a file, else every ``results.json`` below it (sorted)."""
    p = Path(path)
    if p.is_file():
        return [p]
    return sorted(p.rglob("results.json")) if p.is_dir() else []


def _describe(point: dict[str, Any]) -> str:
    level = point.get("oil_level_m")
    lvl = "flooded" if level is None else f"oil level {1e3 * level:.1f} mm"
    r = point.get("gap_ratio", "")
    geo = (", shrunk rollers" if r is None else f", gap {r:g} D_w" if isinstance(r, (int, float)) and
           not isinstance(r, bool) else "" if r == "" else f", gap {r!r}")
    return (f"{point.get('bearing')} {point.get('lubricant')} at {point.get('speed_rad_s', 0.0) * 30 / math.pi:.0f} rpm, "
            f"{point.get('temperature_K', 0.0) - 273.15:.1f} degC, {lvl}{geo}")


def read_cfd_results(path: str | Path, *, source: str = "<argument>",
                     key: str = "model.cfd_results") -> list[tuple[Path, dict[str, Any]]]:
    """Every ``kegel cfd run`` result at ``path`` (a ``results.json`` or a folder searched
    recursively), as (file, contents); other programs' ``results.json`` files are skipped.

    Raises
    ------
    KegelInputError
        No file at ``path``, or a file that is not readable JSON.
    """
    files = cfd_result_files(path)
    if not files:
        raise KegelInputError(source, key, str(path), "a kegel cfd results.json or a folder holding them")
    out = []
    for f in files:
        try:
            data = json.loads(f.read_text())
        except (OSError, json.JSONDecodeError) as exc:
            raise KegelInputError(str(f), "(file)", "", f"a readable CFD results.json ({exc})") from None
        if isinstance(data.get("point"), dict) and "kinematics" in data and "loss_torque_at_shaft_Nm" in data:
            out.append((f, data))
    return out


def find_cfd_result(path: str | Path, *, bearing: str, lubricant: str, speed_rad_s: float, temperature_K: float,
                    oil_level_m: float, flooded: bool, source: str = "<argument>", key: str = "model.cfd_results",
                    results: list[tuple[Path, dict[str, Any]]] | None = None) -> tuple[dict[str, Any], Path]:
    """The CFD result for one operating point, and its file.

    Parameters
    ----------
    path
        A ``results.json`` or a folder searched recursively for them.
    bearing, lubricant, speed_rad_s, temperature_K
        The operating point.
    oil_level_m, flooded
        The oil level above the lowest point of the outer diameter; ``flooded`` for a full bearing
        (the CFD's single-phase case).
    source, key
        Where ``path`` was written, for the error message.
    results
        What :func:`read_cfd_results` read from ``path`` already (a sweep reads the files once).

    Raises
    ------
    KegelInputError
        No readable result matches; the message lists the points that were found.
    """
    if results is None:
        results = read_cfd_results(path, source=source, key=key)
    # among the results of this bearing, lubricant, temperature and level, those of one geometry
    # (the real rollers at the default gap first) and per speed the finest mesh
    rows = _matching(results, bearing, lubricant, temperature_K, oil_level_m, flooded)
    for _, f, data in rows:
        # the signed speed: a result computed at +w is not one for -w
        if abs(float(data["point"].get("speed_rad_s", 0.0)) / speed_rad_s - 1.0) <= SPEED_TOLERANCE:
            return data, f
    found = [_describe(data["point"]) for _, data in results]
    wanted: dict[str, Any] = {"bearing": bearing, "lubricant": lubricant, "speed_rad_s": speed_rad_s,
                              "temperature_K": temperature_K, "oil_level_m": None if flooded else oil_level_m}
    if rows:  # the geometry these results use
        wanted["gap_ratio"] = rows[0][2]["point"].get("gap_ratio")
    want = _describe(wanted)
    have = "; ".join(found) if found else "no kegel cfd results"
    other = (" (results of another CFD geometry are not mixed with the one these results use)"
             if rows and len({cfd_geometry_key(d["point"]) for _, d in results}) > 1 else "")
    raise KegelInputError(source, key, str(path),
                          f"a CFD result for {want} (found: {have}){other}; run `kegel cfd run` for this point")


def cfd_geometry_key(point: dict[str, Any]) -> tuple:
    """What makes two CFD results the same model beside their speed: the flow-force sweep's
    :func:`kegel.coupling.flow_forces.cfd_model_key` (gap, pocket clearance, housing, frame,
    cage, bearing, lubricant, ...), so a lookup or an interpolation never joins results of
    different geometries."""
    from .flow_forces import cfd_model_key

    return cfd_model_key(point)


def _matching(results: list[tuple[Path, dict[str, Any]]], bearing: str, lubricant: str, temperature_K: float,
              oil_level_m: float, flooded: bool) -> list[tuple[float, Path, dict[str, Any]]]:
    """Results of one bearing, lubricant, temperature and oil level and of one CFD geometry: per
    speed (0.5 %) the one on the finest mesh, as (speed_rad_s, file, data) sorted by speed.

    Results of different geometries (gap ratios, or the old shrunk rollers) are never mixed: the
    CFD's loss depends on where the contact model stops. The geometry taken is the real rollers
    at the default gap (``GAP_RATIO`` of :mod:`kegel.cfd_cases.geometry`) when such results exist,
    else the real-roller model with the most results, else the old geometry; a model is
    :func:`cfd_geometry_key` (gap, pocket clearance, housing, frame, cage, ...)."""
    groups: dict[tuple, list[tuple[Path, dict[str, Any]]]] = {}
    gap: dict[tuple, float | None] = {}
    for f, data in results:
        pt = data["point"]
        level = pt.get("oil_level_m")
        if not (pt.get("bearing") == bearing and pt.get("lubricant") == lubricant
                and abs(pt.get("temperature_K", 0.0) - temperature_K) <= TEMPERATURE_TOLERANCE_K
                and (level is None) == flooded and (flooded or abs(level - oil_level_m) <= OIL_LEVEL_TOLERANCE_M)):
            continue
        r = pt.get("gap_ratio")
        if r is not None and (isinstance(r, bool) or not isinstance(r, (int, float)) or not (math.isfinite(r) and r > 0)):
            raise KegelInputError(str(f), "point.gap_ratio", r, "a positive fraction of the roller diameter")
        k = cfd_geometry_key(pt)
        groups.setdefault(k, []).append((f, data))
        gap[k] = None if r is None else float(r)
    if not groups:
        return []
    # the real rollers at the default gap, then the real-roller model with the most speeds, then
    # the old geometry
    pick = max(groups, key=lambda k: (gap[k] is not None and abs(gap[k] - DEFAULT_GAP_RATIO) < 1e-9,
                                      gap[k] is not None, len(groups[k])))
    by_speed: list[tuple[float, Path, dict[str, Any]]] = []
    for f, data in groups[pick]:
        pt = data["point"]
        w = abs(float(pt.get("speed_rad_s", 0.0)))
        cells = (data.get("fidelity") or {}).get("cells") or 0
        for i, (w2, _, d2) in enumerate(by_speed):
            if abs(w / w2 - 1.0) <= SPEED_TOLERANCE:
                if cells > ((d2.get("fidelity") or {}).get("cells") or 0):
                    by_speed[i] = (w, f, data)
                break
        else:
            by_speed.append((w, f, data))
    return sorted(by_speed, key=lambda r: r[0])


def _loglog(w: float, w1: float, t1: float, w2: float, t2: float) -> float:
    """Power-law interpolation T = t1 (w/w1)^k through two points (linear when a torque is <= 0)."""
    if t1 > 0 and t2 > 0:
        k = math.log(t2 / t1) / math.log(w2 / w1)
        return t1 * (w / w1) ** k
    return t1 + (t2 - t1) * (w - w1) / (w2 - w1)


def cfd_loss_at(results: list[tuple[Path, dict[str, Any]]], *, bearing: str, lubricant: str, speed_rad_s: float,
                temperature_K: float, oil_level_m: float, flooded: bool) -> dict[str, Any]:
    """The CFD loss torque at the shaft for a point: computed, interpolated between computed
    speeds, or missing.

    Between two computed speeds the loss is interpolated as a power of the speed (a straight line
    in log-log axes, the form of every drag law). Its error is estimated by leaving out a computed
    neighbour: each of the two bracketing results that has computed speeds on both sides is
    predicted from those two, and the larger relative miss is stated (the left-out spacing is wider
    than the interpolation's, so this over-estimates). With only two computed speeds no estimate
    exists and the result says so. A speed outside the computed ones is not extrapolated.

    Returns
    -------
    dict
        ``status`` ("computed", "interpolated", "missing"), ``loss_torque_at_shaft_Nm`` (None when
        missing), ``files``, ``meshes``, ``steady`` (all results used steady), ``balance`` (the
        largest |angular-momentum balance| of the results used; None when none states it),
        ``error_rel`` (the
        stated interpolation error; None when computed or unknown), ``note``, ``wall_time_s``
        (runtime of the CFD results used), ``computed_speeds_rpm``; the contact / CFD boundary
        (:class:`CfdBoundary`): ``gap_ratio`` (g / D_w of the results used, None for the old
        shrunk-roller geometry), ``thin_films_Nm`` (their analytic thin-film terms, interpolated
        in the same way; 0 for the old geometry) and ``hydraulic_Nm`` (CFD + thin films: the
        hydraulic loss that goes with a contact cut at g).
    """
    rows = _matching(results, bearing, lubricant, temperature_K, oil_level_m, flooded)
    w = abs(speed_rad_s)
    speeds = [r[0] for r in rows]
    ratio = rows[0][2]["point"].get("gap_ratio") if rows else None
    base = {"computed_speeds_rpm": [s * 30 / math.pi for s in speeds], "gap_ratio": ratio}
    # D_w does not matter here: only the loss parts are read
    parts = [cfd_boundary(d, 1.0, source=str(f)) for _, f, d in rows]

    def with_thin(out: dict[str, Any], thin: float | None) -> dict[str, Any]:
        c = out["loss_torque_at_shaft_Nm"]
        return {**out, "thin_films_Nm": thin, "hydraulic_Nm": None if c is None else c + (thin or 0.0)}

    def used(idx: list[int]) -> dict[str, Any]:
        ds = [rows[i][2] for i in idx]
        bals = [abs(b) for b in map(balance_of, ds) if b is not None]
        return {"files": [str(rows[i][1]) for i in idx], "balance": max(bals) if bals else None,
                "meshes": [(d.get("fidelity") or {}).get("mesh") for d in ds],
                "steady": all(d.get("steady") is not False for d in ds),
                "wall_time_s": sum(float(d.get("chain_wall_time_s") or d.get("runtime_s") or 0.0) for d in ds)}

    def loss(i: int) -> float:
        return float(rows[i][2]["loss_torque_at_shaft_Nm"])

    for i, s in enumerate(speeds):
        if abs(w / s - 1.0) <= SPEED_TOLERANCE:
            return with_thin({**base, "status": "computed", "loss_torque_at_shaft_Nm": loss(i), "error_rel": None,
                              "note": "computed at this speed", **used([i])}, parts[i].thin_films_Nm)
    j = next((i for i in range(1, len(speeds)) if speeds[i - 1] < w < speeds[i]), None)
    if j is None:
        return with_thin({**base, "status": "missing", "loss_torque_at_shaft_Nm": None, "error_rel": None,
                          "files": [], "meshes": [], "steady": None, "balance": None, "wall_time_s": 0.0,
                          "note": "no CFD result at this speed and none on both sides to interpolate from"}, None)
    value = _loglog(w, speeds[j - 1], loss(j - 1), speeds[j], loss(j))
    misses = []
    for k in (j - 1, j):
        if 0 < k < len(speeds) - 1:
            pred = _loglog(speeds[k], speeds[k - 1], loss(k - 1), speeds[k + 1], loss(k + 1))
            misses.append(abs(pred / loss(k) - 1.0))
    meshes = {m for m in used([j - 1, j])["meshes"]}
    note = (f"interpolated (power law) between {speeds[j - 1] * 30 / math.pi:.0f} and "
            f"{speeds[j] * 30 / math.pi:.0f} rpm")
    if misses:
        note += f"; error estimated by leaving out a computed neighbour: {100 * max(misses):.1f} %"
    else:
        note += "; two computed speeds only: no estimate of the interpolation error"
    if len(meshes) > 1:
        note += f"; mixed mesh levels {sorted(str(m) for m in meshes)}"
    a, b = parts[j - 1].thin_films_Nm, parts[j].thin_films_Nm
    thin = _loglog(w, speeds[j - 1], a, speeds[j], b)  # linear where an end is 0
    return with_thin({**base, "status": "interpolated", "loss_torque_at_shaft_Nm": value,
                      "error_rel": max(misses) if misses else None, "note": note, **used([j - 1, j])}, thin)
