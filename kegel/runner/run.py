"""Running a scene: every operating point's load distribution, friction and hydraulic loss.

:func:`run_scene` solves each operating point of a scene with the quasi-static model
(``kegel.quasi_static``), adds the hydraulic loss of an oil bath from the chosen correlation
(``kegel.correlations``) and writes, atomically and next to each other: ``results.json`` (every
figure, the resolved scene, the fidelity, the provenance), ``results.csv`` (one row per
operating point) and plots (torque against the swept variable, the breakdown by contact and
mechanism, the roller loads around the circumference, the cage slip).
"""

from __future__ import annotations

import contextlib
import csv
import dataclasses
import json
import io
import math
import os
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable

import numpy as np

from ..correlations import hydraulic_torques
from ..solutions import dynamics as _dynamics  # its POWER_BALANCE_TOLERANCE read at use
from ..solutions.dynamics import CONTACTS, MECHANISMS
from ..base.io import Terminated, atomic_write_json, atomic_write_json_records, atomic_write_text, provenance, signals_interrupt
from ..model.lubricant import lubricant_state
from .parallel import effective_jobs, point_blocks, solve_blocks
from ..base.errors import KegelInputError, KegelSolverError
from ..solutions.dynamics import SimulationDiverged, power_balanced
from ..outputs.point_warnings import Warning_, WarningLog, point_warnings
from ..solutions.quasi_static import bearing_friction, bearing_model, load_distribution
from ..outputs.study import STUDY_FILES, read_study_cfd, study_csv, study_plot, study_rows
from ..model.scene import Fidelity, Scene, static_equivalent_load_N
from ..physics.tribology import cage_speed_rad_s, load_friction
from .. import _core

if TYPE_CHECKING:  # pragma: no cover
    from .uncertainty import UncertaintyOptions

__all__ = ["RunResult", "choose_fidelity", "preflight", "run_scene"]

CONTACTS_WITH_CAGE = CONTACTS + ("cage",)


@dataclass
class RunResult:
    """Results of a scene run: one dictionary per operating point and the files written."""

    points: list[dict[str, Any]]
    files: dict[str, str]
    runtime_s: float


class _Progress:
    """A progress line on stderr (time per point, ETA) for runs longer than a second: redrawn at
    most ten times a second on a terminal, one line every 10 s into a log (a 10^6-point run once
    wrote 96 MB of progress text)."""

    def __init__(self, total: int, enabled: bool) -> None:
        self.total, self.enabled, self.t0, self.shown = total, enabled, time.perf_counter(), False
        self.tty = sys.stderr.isatty()
        self.every = 0.1 if self.tty else 10.0
        self.last = -math.inf

    def update(self, done: int, label: str) -> None:
        if not self.enabled:
            return
        now = time.perf_counter()
        elapsed = now - self.t0
        if elapsed < 1.0 and not self.shown:
            return
        if now - self.last < self.every and done < self.total:
            return
        self.shown, self.last = True, now
        eta = elapsed / done * (self.total - done) if done else float("nan")
        bar = "#" * int(30 * done / self.total)
        text = f"[{bar:<30}] {done}/{self.total} {label}  {elapsed:5.1f} s, ETA {eta:5.1f} s "
        sys.stderr.write(f"\r{text}" if self.tty else f"{text}\n")
        sys.stderr.flush()

    def close(self) -> None:
        if self.shown and self.tty:
            sys.stderr.write("\n")


def run_scene(scene: Scene, output_dir: str | Path | None = None, *, progress: bool = True,
              on_point: Callable[[dict[str, Any]], None] | None = None, write: bool = True,
              force: bool = False, uncertainty: "bool | UncertaintyOptions" = False, jobs: int | None = 1,
              client: Any = None) -> RunResult:
    """Solve every operating point of a scene and write the results (see the module docstring);
    ``write=False`` keeps them in memory only (no files, ``files`` empty).

    ``uncertainty`` (True or a :class:`kegel.uncertainty.UncertaintyOptions`) adds to every
    quasi-static point its friction torque at the perturbed crown data and the other slice model
    (three extra solves per point): ``point["uncertainty"]`` with the low/high band, the band
    columns of results.csv and a band in torque.png (:mod:`kegel.uncertainty`).

    The results are computed in a staging folder beside the output folder and replace the
    previous results only when the run has finished (:class:`kegel.io.RunFolder`); an output
    folder holding files kegel did not write is refused unless ``force``. An interrupted run
    (Ctrl-C, SIGTERM, a full disk) resumes when run again with the same scene.

    ``jobs`` processes solve independent points at once (None: every core; 1: this process
    alone), or ``client``, a ``dask.distributed.Client``, sends them to its cluster
    (:mod:`kegel.parallel`). The points, their order and the files are those of a run in one
    process, to the last digit for the quasi-static solution."""
    with signals_interrupt() if write else contextlib.nullcontext():
        return _run_scene(scene, output_dir, progress=progress, on_point=on_point, write=write, force=force,
                          uncertainty=_uncertainty_options(uncertainty), jobs=jobs, client=client)


def _uncertainty_options(uncertainty: "bool | UncertaintyOptions | None") -> "UncertaintyOptions | None":
    """The uncertainty options of a run (None: no band)."""
    from ..base.errors import KegelInputError
    from .uncertainty import UncertaintyOptions

    if uncertainty is None or uncertainty is False:
        return None
    if uncertainty is True:
        return UncertaintyOptions()
    if isinstance(uncertainty, UncertaintyOptions):
        return uncertainty
    raise KegelInputError("<argument>", "uncertainty", uncertainty, "true, false or a kegel.uncertainty.UncertaintyOptions")


def _run_scene(scene: Scene, output_dir: str | Path | None, *, progress: bool,
               on_point: Callable[[dict[str, Any]], None] | None, write: bool, force: bool,
               uncertainty: "UncertaintyOptions | None" = None, jobs: int | None = 1,
               client: Any = None) -> RunResult:
    t_start = time.perf_counter()
    out = Path(output_dir) if output_dir is not None else scene.output_directory
    g, b, m = scene.geometry, scene.bearing, scene.material
    choice = None
    if scene.fidelity.tolerance is not None:
        chosen, choice = choose_fidelity(scene)
        scene = dataclasses.replace(scene, fidelity=chosen)
    fid = scene.fidelity
    friction = _friction(fid)
    model = bearing_model(g, b, m, slices=fid.slices, method=fid.slice_model)
    data = _core.quasi_static.BearingData(model)
    cfd_runs = preflight(scene)
    study_cfd = read_study_cfd(scene)
    warn_log = WarningLog()
    folder, done = _open_folder(scene, fid, out, force, uncertainty) if write else (None, {})
    # written here, moved to out when finished; without writing (None), a dynamic point's own files
    # (its series, checkpoint, pictures) go to a temporary folder of its own, in the process that
    # solves it, removed when the point is done: never into the output folder, over a previous run's
    work = folder.staging if folder is not None else None
    try:
        bar = _Progress(len(scene.operating_points), progress)
        points: list[dict[str, Any]] = []

        def finish_point(point: dict[str, Any]) -> dict[str, Any]:
            # the parent's share of a point (paths, study rows, warnings, the stream), in the
            # order the points finish; the caller keeps the scene's order
            if folder is not None:
                point = folder.final(point)  # paths into the staging folder: where they will be
            if scene.study is not None and point.get("solved", True):
                point["study"] = study_rows(scene, point, study_cfd)
            warns = point_warnings(scene, point, friction)
            point["warnings"] = [w.as_dict() for w in warns]
            warn_log.add(point["index"], warns)
            if folder is not None:
                folder.add(point)
            return point

        # the points in fixed chains (kegel.parallel.point_blocks): a quasi-static point is
        # warm-started from the one before it within its chain only, so that any number of
        # processes gives the same figures, to the last digit, as this process alone
        blocks = point_blocks(scene, fid)
        pending = [[i for i in blk if i not in done] for blk in blocks]
        pending = [blk for blk in pending if blk]
        n_proc = effective_jobs(jobs, len(pending), client)
        if n_proc > 1 or client is not None:
            finished: dict[int, dict[str, Any]] = {}
            # the workers are stopped on any exception here (contextlib.closing)

            def release() -> None:  # the points finished so far, in the scene's order (on_point too)
                while len(points) < len(scene.operating_points):
                    op = scene.operating_points[len(points)]
                    label = f"n = {op.speed_rpm:.0f} rpm, T = {op.temperature_degC:.0f} degC"
                    if op.index in done:
                        points.append(done[op.index])
                        warn_log.add(op.index, [Warning_(**w) for w in done[op.index].get("warnings", ())])
                        bar.update(len(points), label + " (resumed)")
                        continue
                    if op.index not in finished:
                        break
                    points.append(finished.pop(op.index))
                    if on_point:
                        on_point(points[-1])
                    bar.update(len(points), label)

            release()
            with contextlib.closing(solve_blocks(scene, fid, pending, work, uncertainty, jobs=n_proc,
                                                 client=client)) as solved:
                for idx, point in solved:
                    finished[idx] = finish_point(point)
                    release()
        starts = {blk[0] for blk in blocks}
        for op in scene.operating_points[len(points):]:
            label = f"n = {op.speed_rpm:.0f} rpm, T = {op.temperature_degC:.0f} degC"
            if op.index in done:
                # finished by an interrupted run of the same scene, fidelity and version (a point's
                # answer does not depend on the points solved before it)
                points.append(done[op.index])
                warn_log.add(op.index, [Warning_(**w) for w in done[op.index].get("warnings", ())])
                bar.update(len(points), label + " (resumed)")
                continue
            if op.index in starts:
                data = _core.quasi_static.BearingData(model)  # a chain starts from a fresh state
            point, data = _solve_point(scene, fid, op, friction, model, data, work, progress, cfd_runs, uncertainty,
                                       study_cfd)
            points.append(finish_point(point))
            if on_point:
                on_point(points[-1])
            bar.update(len(points), label)
        bar.close()
        if warn_log.counts and progress:
            print("kegel: each warning is printed once; points with it: "
                  + ", ".join(f"{k} {v}" for k, v in warn_log.counts.items())
                  + f" of {len(points)} (every point's warnings: results.json, results.csv)", file=sys.stderr)
        runtime = time.perf_counter() - t_start
        if folder is None:
            return RunResult(points=points, files={}, runtime_s=runtime)
        try:
            files = _write_summary(scene, friction, choice, points, runtime, work, warn_log.summary(),
                                   folder.run_id)
        except OSError as exc:
            if exc.filename is None:
                exc.filename = str(work)
            raise
        folder.finish()
        return RunResult(points=points, files=folder.final(files), runtime_s=runtime)
    except BaseException as exc:
        if folder is not None:  # say what is kept: the previous results, the finished points
            why = (f"interrupted ({exc})" if isinstance(exc, Terminated) else "interrupted"
                   if isinstance(exc, KeyboardInterrupt) else f"stopped ({type(exc).__name__})")
            print(f"kegel: {why}: {folder.kept()}", file=sys.stderr)
        raise
    finally:
        if folder is not None:
            folder.close()


def _solve_point(scene: Scene, fid: Fidelity, op, friction, model, data, work: Path | None, progress: bool,
                 cfd_runs, uncertainty: "UncertaintyOptions | None",
                 study_cfd: list[tuple[Path, dict[str, Any]]] | None = None):
    """One operating point's record (a failed record when its solver raised) and the state to
    warm-start the next point of its chain from; :mod:`kegel.parallel` calls it in the workers.
    ``cfd_runs`` and ``study_cfd`` are the CFD results a run reads once (:func:`_read_cfd_runs`,
    :func:`kegel.outputs.study.read_study_cfd`)."""
    try:
        # the raceway contacts' inlet supply at this point (kegel.supply); a study's own
        # point has flooded contacts, each of its lubrications is solved with its supply
        op_friction, supply = _point_friction(scene, friction, op)
        cfd = _cfd_point(scene, op, cfd_runs) if cfd_runs is not None else None
        if cfd is not None:
            # the contact model owns the oil within the CFD's gap g: its rolling force is cut there
            op_friction = dataclasses.replace(op_friction, contact_film_limit_m=cfd[2].contact_film_limit_m)
        if fid.solution == "dynamic" and work is None:  # nothing is written: files in a removed folder
            with tempfile.TemporaryDirectory(prefix="kegel-point-") as tmp:
                point = _dynamic_point(scene, op, op_friction, Path(tmp), progress, cfd_runs, cfd)
            point["dynamic"]["files"] = {}
        elif fid.solution == "dynamic":
            point = _dynamic_point(scene, op, op_friction, work, progress, cfd_runs, cfd)
        else:
            point, data = _quasi_static_record(scene, fid, op, op_friction, model, data, cfd)
        if uncertainty is not None:
            point["uncertainty"] = _point_band(scene, fid, op, op_friction, point, uncertainty)
        point["lubricant_supply"] = supply.as_dict()
        if scene.study is not None and point.get("solved", True):
            point["study_friction"] = _study_case_friction(scene, fid, op, friction, point, model, study_cfd or [])
    except (KegelSolverError, SimulationDiverged) as exc:
        # the run keeps the points that finished and goes on: this one is recorded as
        # failed with the solver's message (and never warm-starts the next point)
        point = _failed_record(op, exc)
        data = _core.quasi_static.BearingData(model)
    return point, data


def preflight(scene: Scene) -> list[tuple[Path, dict[str, Any]]] | None:
    """Everything a run would reject, checked for every point before anything runs (``kegel
    check`` calls it too): with ``hydraulic = "cfd"``, each operating point's CFD result.
    Returns the CFD results read (None without them).

    Raises
    ------
    KegelInputError
        The first point without its CFD result (the message lists those found).
    """
    runs = _read_cfd_runs(scene)
    if runs is not None:
        for op in scene.operating_points:
            _cfd_point(scene, op, runs)
    return runs


def power_loss_W(total_torque_Nm: float, speed_rad_s: float) -> float:
    """Power lost in the bearing [W]: the total torque (friction and hydraulic loss) times the
    shaft speed, ``|M_total omega|`` (the ``P_loss`` column of ``kegel run``'s table, beside the
    torque in results.json and results.csv)."""
    return abs(float(total_torque_Nm) * float(speed_rad_s))


def _failed_record(op, exc: Exception) -> dict[str, Any]:
    """The record of a point whose solver raised: the operating point, ``converged`` false, the
    message as ``failure``, no figures (None, empty in the CSV)."""
    msg = str(exc).strip() or type(exc).__name__  # whole: a divergence report shows the state that explains it
    print(f"kegel: point {op.index} failed: {msg.splitlines()[0]}", file=sys.stderr)
    return {**op.as_dict(), "friction_torque_Nm": None, "hydraulic_torque_Nm": None, "total_torque_Nm": None,
            "power_loss_W": None, "converged": False, "failure": f"{type(exc).__name__}: {msg}", "solved": False,
            "torque_by_contact_Nm": {}, "torque_by_mechanism_Nm": {}}


_MISSING = object()
#: figures every solved point's record carries (finite numbers): the table, the CSV and the plots read them
_RECORD_NUMBERS = ("friction_torque_Nm", "hydraulic_torque_Nm", "total_torque_Nm", "cage_slip", "cage_speed_rpm",
                   "power_input_W", "power_balance_error", "axial_force_N")
#: per-roller lists of a solved point (the roller-load plot)
_RECORD_ROLLERS = ("roller_azimuth_rad", "roller_outer_N", "roller_inner_N", "roller_rib_N")


def _check_record(scene: Scene, p: dict[str, Any], staging: Path | None = None) -> tuple[str, Any, str] | None:
    """Why a point record read back from ``points.jsonl`` on resume cannot be used, as (key, value,
    expected), or None when it is whole: its operating point must be the scene's at its index (the
    same numbers), and a solved point must carry every figure the table, the CSV and the plots
    read (finite numbers, the breakdowns by contact and mechanism, the roller lists, warnings; a
    dynamic point its files). A failed point carries ``converged`` false and its ``failure``."""
    def finite(v: Any) -> bool:
        return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)

    ops = scene.operating_points
    idx = p.get("index")
    if not isinstance(idx, int) or isinstance(idx, bool) or not 0 <= idx < len(ops):
        return "index", idx, f"an operating point index from 0 to {len(ops) - 1}"
    for k, v in json.loads(json.dumps(ops[idx].as_dict())).items():
        if p.get(k, _MISSING) != v:
            got = p.get(k, None)
            return k, got, f"{v!r}, the value of the scene's operating point {idx}"
    if not isinstance(p.get("converged"), bool):
        return "converged", p.get("converged"), "true or false"
    warns = p.get("warnings", [])
    if not isinstance(warns, list) or not all(isinstance(w, dict) and set(w) == {"code", "message"}
                                              and all(isinstance(x, str) for x in w.values()) for w in warns):
        return "warnings", warns, 'a list of {"code": ..., "message": ...}'
    if p.get("solved", True) is not True:
        if p.get("converged") is not False or not isinstance(p.get("failure"), str) or not p["failure"]:
            return "failure", p.get("failure"), "the solver's message of a failed point (converged false)"
        return None
    for k in _RECORD_NUMBERS:
        if not finite(p.get(k)):
            return k, p.get(k, None), "a finite number (every solved point has it)"
    for k, names in (("torque_by_contact_Nm", CONTACTS_WITH_CAGE), ("torque_by_mechanism_Nm", MECHANISMS),
                     ("Lambda_min", CONTACTS)):
        d = p.get(k)
        if not isinstance(d, dict) or any(not finite(d.get(n)) for n in names):
            return k, d, f"finite numbers for {', '.join(names)}"
    z = len(p.get("roller_azimuth_rad") or ())
    for k in _RECORD_ROLLERS:
        v = p.get(k)
        if not isinstance(v, list) or not v or len(v) != z or not all(finite(x) for x in v):
            return k, v, "a list of finite numbers, one per roller"
    if scene.study is not None and not isinstance(p.get("study"), list):
        return "study", p.get("study"), "the study's rows of the point (a list)"
    if scene.fidelity.solution == "dynamic":
        d = p.get("dynamic")
        if not isinstance(d, dict) or not finite(d.get("revolutions")) or not isinstance(d.get("files"), dict):
            return "dynamic", d, "the dynamic run's summary (revolutions, files)"
        for k in ("outer_ring_torque_Nm", "outer_ring_torque_std_Nm"):
            if not finite(p.get(k)):
                return k, p.get(k, None), "a finite number (every solved dynamic point has it)"
        err = p.get("power_balance_error")
        if p["converged"] and not (finite(err) and power_balanced(err)):
            # a record of a kegel before the power-balance gate: solve the point again
            return "power_balance_error", err, (f"within +-{_dynamics.POWER_BALANCE_TOLERANCE:g} for a converged dynamic "
                                                "point (kegel.dynamics.POWER_BALANCE_TOLERANCE)")
        if staging is not None and not (staging / "dynamic" / f"point_{idx:03d}" / "dynamic.json").is_file():
            return "dynamic.files", d["files"].get("json"), (f"the point's files in {staging / 'dynamic'} "
                                                             f"(point_{idx:03d}/dynamic.json is missing)")
    return None


def _point_band(scene: Scene, fid: Fidelity, op, friction, point: dict[str, Any], options) -> dict[str, Any]:
    """The uncertainty band of a solved point (:func:`kegel.uncertainty.point_uncertainty`);
    quasi-static points only (a dynamic or not converged point says why it has none)."""
    from .uncertainty import point_uncertainty

    if fid.solution == "dynamic":
        return {"inputs": options.as_dict(), "note": "not computed: the band is computed for quasi-static points"}
    if not point.get("converged"):
        return {"inputs": options.as_dict(), "note": "not computed: the nominal point did not converge"}
    inner = point.get("roller_inner_N") or []
    return point_uncertainty(scene, fid, op, friction, nominal_friction_Nm=point["friction_torque_Nm"],
                             hydraulic_Nm=point.get("hydraulic_torque_Nm") or 0.0,
                             inner_load_N=max(inner) if inner and max(inner) > 0 else None, options=options)


def _open_folder(scene: Scene, fid: Fidelity, out: Path, force: bool = False, uncertainty=None):
    """Take the output folder (lock, staging folder, stream of finished points); an interrupted
    run of the same scene, fidelity and kegel version resumes from the points it finished, each
    record checked (:func:`_check_record`)."""
    from ..base.version import __version__
    from ..base.io import OutputLocked, OutputRefused, RunFolder

    # the scene as written, less what does not change a result (the thread count)
    written = json.loads(json.dumps(scene.resolved))
    if isinstance(written.get("dynamic"), dict):
        written["dynamic"].pop("threads", None)
    key = {"scene": written, "fidelity": fid.as_dict(), "kegel_version": __version__,
           "core_version": _core.core_version()}
    if uncertainty is not None:  # a run with the band resumes only from points that have it
        key["uncertainty"] = uncertainty.as_dict()
    folder = RunFolder(out, key, SUMMARY_FILES, ("dynamic",), force=force,
                       validate=lambda p: _check_record(scene, p, folder.staging))
    try:
        done = folder.open()
    except OutputRefused as exc:
        hint = "" if exc.forceable else " (--force does not change this)"
        raise KegelInputError(str(out), "output", str(out), f"a folder kegel may write its results into: it "
                                                            f"{exc.reason}{hint}") from None
    except OutputLocked as exc:
        raise KegelInputError(str(out), "output", str(out), f"a folder no other kegel run is writing to ({exc})") from None
    except OSError as exc:
        folder.close()
        raise KegelInputError(str(out), "output", str(out),
                              f"a folder kegel can create and write ({exc.strerror or exc})") from None
    if done:
        print(f"kegel: resuming the run in {out}: {len(done)} of {len(scene.operating_points)} point(s) already "
              f"solved", file=sys.stderr)
    return folder, done


def _quasi_static_record(scene: Scene, fid: Fidelity, op, friction, model, data, cfd=None):
    """One quasi-static operating point as its results record, and the state to warm-start the
    next point from (a fresh one after a failed point). ``cfd``: with ``hydraulic = "cfd"``, the
    point's CFD result, its file and its boundary (:func:`_cfd_point`)."""
    g = scene.geometry
    dist, fr = _quasi_static_point(scene, fid, op, friction, model=model, data=data)
    if not fr.converged:
        # never warm-start the next point from a failed one
        data = _core.quasi_static.BearingData(model)  # (reported through its not_converged warning)
    state = lubricant_state(scene.lubricant, op.temperature_K, source=scene.source, key="operating.temperature")
    hyd = None
    if fid.hydraulic == "correlation" and scene.lubrication.oil_level_m > 0:
        hyd = hydraulic_torques("liebrecht", g, state, shaft_speed_rad_s=op.speed_rad_s,
                                oil_level_m=scene.lubrication.oil_level_m,
                                cage_speed_rad_s=fr.cage_speed_rad_s)
    hyd_torque = hyd.total_Nm if hyd else 0.0
    hyd_out = hyd.as_dict() if hyd else None
    if fid.hydraulic == "cfd":
        # the CFD loss torque of this point (hydraulic power / shaft speed), as computed, and the
        # thin films the CFD leaves to analytic terms (the contact was cut at the CFD's gap)
        cfd, cfd_file, bnd = cfd
        bnd = _with_unloaded_line_wedge(scene, op, bnd, dist.loaded_length_m, cfd)
        hyd_torque = math.copysign(bnd.hydraulic_Nm, op.speed_rad_s)
        hyd_out = {"source": "cfd", "file": str(cfd_file), "loss_torque_at_shaft_Nm": cfd["loss_torque_at_shaft_Nm"],
                   "boundary": bnd.as_dict(),
                   "torques_Nm": cfd["torques_Nm"], "cfd_point": cfd["point"], "steady": cfd.get("steady"),
                   "angular_momentum_balance": _balance_of(cfd)}
    w = op.speed_rad_s
    skf = _skf_point(scene, op, state, dist.axial_force_N)
    converged, failure = fr.converged, fr.failure
    if op.axial_load_N is None and converged:
        # a displacement-controlled point: its axial force is known only now, so its static
        # equivalent load is checked here (a force-controlled one was checked with the scene)
        p0 = static_equivalent_load_N(g, dist.axial_force_N, op.radial_load_N)
        if p0 > scene.bearing.C0r_N:
            converged = False
            failure = (f"the static equivalent load P0 = {p0 / 1e3:.4g} kN (ISO 76; Fa = {dist.axial_force_N / 1e3:.4g} kN "
                       f"at the axial offset, Fr = {op.radial_load_N / 1e3:.4g} kN) exceeds C0r = "
                       f"{scene.bearing.C0r_N / 1e3:g} kN of bearing {scene.bearing.designation}: the raceways deform "
                       "permanently and the elastic contact models do not hold")
    point = {
        **op.as_dict(),
        "friction_torque_Nm": fr.drive_torque_Nm,
        "hydraulic_torque_Nm": hyd_torque,
        "total_torque_Nm": fr.drive_torque_Nm + hyd_torque,
        "power_loss_W": power_loss_W(fr.drive_torque_Nm + hyd_torque, op.speed_rad_s),
        "outer_ring_torque_Nm": fr.outer_ring_torque_Nm,
        "power_input_W": fr.power_input_W,
        "power_dissipated_W": fr.power_dissipated_W,
        "power_balance_error": fr.power_balance_error,
        "cage_speed_rpm": fr.cage_speed_rad_s * 30 / math.pi,
        "cage_slip": fr.cage_slip,
        "cage_model": fr.cage_model,
        "pocket_fraction": fr.pocket_fraction,
        "roller_drift_m": fr.roller_drift_m,
        "rib_edge_rollers": fr.rib_edge_rollers,
        "torque_by_contact_Nm": fr.torque_by_contact_Nm(w),
        "torque_by_mechanism_Nm": fr.torque_by_mechanism_Nm(w),
        "power_W": fr.power_W,
        "Lambda_min": fr.Lambda_min,
        "phi_max": fr.phi_max,
        "hydraulic": hyd_out,
        "skf_catalogue_model": skf,
        "roller_azimuth_rad": dist.azimuth_rad.tolist(),
        "roller_outer_N": dist.outer_N.tolist(),
        "roller_inner_N": dist.inner_N.tolist(),
        "roller_rib_N": dist.rib_N.tolist(),
        "axial_force_N": dist.axial_force_N,
        "ring_displacement_m": dist.ring_displacement_m.tolist(),
        "load_residual": dist.residual,
        "converged": converged,
        "failure": failure,
        "start": fr.start,
        "runtime_s": fr.runtime_s,
        "lubricant_state": state.as_dict(),
    }
    return point, data


def _write_summary(scene: Scene, friction, choice, points: list[dict[str, Any]], runtime: float,
                   out: Path, warnings: dict[str, int] | None = None, run_id: str | None = None) -> dict[str, str]:
    """results.json, results.csv and the plots of a finished run (and a study's table and plot);
    returns the files written."""
    fid = scene.fidelity
    rib_cells = _rib_cells(fid)
    files = {
        "json": str(atomic_write_json_records(out / "results.json", {
            "scene": {"name": scene.name, "title": scene.title, "description": scene.description,
                      "description_note": ("as written in the scene file; --set changed "
                                           + ", ".join(scene.overridden)) if scene.overridden else None,
                      "file": scene.source, "overridden": list(scene.overridden), "resolved": scene.resolved},
            "run_id": run_id,
            "bearing": scene.bearing.designation, "lubricant": scene.lubricant.name,
            "material": scene.material.name,
            "friction_parameters": friction.name,
            "rolling_resistance": friction.model_options(),
            "lubrication": {"mode": scene.lubrication.mode, "oil_level_m": scene.lubrication.oil_level_m,
                            "label": scene.lubrication_label},
            **({"study": scene.study.as_dict()} if scene.study is not None else {}),
            "fidelity": {**fid.as_dict(), "solution_used": fid.solution,
                         **({"dynamic": scene.dynamic.as_dict()} if fid.solution == "dynamic" else {}),
                         "rib_load_model": "hertz (load distribution); friction: "
                                           + (f"cell model {rib_cells} x {rib_cells}" if rib_cells else "one ellipse")},
            **({"fidelity_choice": choice} if choice else {}),
            "swept": list(scene.swept), "provenance": provenance(), "runtime_s": runtime,
            "warnings": {"points_per_code": warnings or {},
                         "note": "each point's warnings are in its record and in results.csv; codes: "
                                 "kegel.point_warnings"},
            "points": None,
        }, "points", iter(points))),
        "csv": str(atomic_write_text(out / "results.csv", _csv(points))),
    }
    solved = [p for p in points if p.get("solved", True)]  # points whose solver raised have no figures
    if solved:
        files.update(_plots(scene, solved, out))
    if scene.study is not None:
        files["study_csv"] = str(atomic_write_text(out / "study.csv", study_csv(points)))
        if solved:
            files["study_plot"] = study_plot(solved, _study_plot_meta(scene), out / "study.png")
    return files


def _study_plot_meta(scene: Scene) -> dict[str, Any]:
    """The study plot's metadata: title, the swept quantities (x axis first, as the run plots
    choose it: see :mod:`kegel.plots`) and the lubrication cases in the scene's order."""
    return {"title": f"{scene.title} ({scene.bearing.designation}, {scene.lubricant.name}, fidelity "
                     f"{scene.fidelity.name})", "swept": list(reversed(scene.swept)),
            "cases": ["minimum_quantity" if c.mode == "minimum_quantity" else c.oil_level_as_written
                      for c in scene.study.cases]}


AUTO_LEVELS = ("fast", "default", "fine")  # cheapest first; fine is the reference


def _skf_point(scene: Scene, op, state, axial_N: float) -> dict[str, Any] | None:
    """The SKF catalogue model's frictional moment at a point (an independent engineering model
    beside kegel's: its rolling + sliding moment against kegel's contact friction, its drag
    against the hydraulic loss), or None for a bearing series without SKF constants."""
    from ..correlations.skf import SERIES_CONSTANTS, skf_bearing, skf_friction

    b = scene.bearing
    if str(b.designation)[:3] not in SERIES_CONSTANTS:
        return None
    lub = scene.lubrication
    oil = lub.oil_level_m if lub.mode == "oil_bath" and lub.oil_level_m > 0 else None
    f = skf_friction(skf_bearing(b), speed_rad_s=abs(op.speed_rad_s),
                     kinematic_viscosity_m2_s=state.kinematic_viscosity_m2_s,
                     axial_load_N=abs(axial_N), radial_load_N=op.radial_load_N, oil_level_m=oil,
                     lubrication="oil_bath" if lub.mode == "oil_bath" else "oil_air")
    return {"rolling_sliding_Nm": f.rolling_sliding_Nm, "drag_Nm": f.drag_Nm, "total_Nm": f.total_Nm,
            "phi_ish": f.phi_ish, "phi_rs": f.phi_rs, "verify": f.verify}


def _friction(fid: "Fidelity"):
    """The friction parameters with the scene's rolling-resistance options (``model.rolling_thermal``,
    ``model.inlet_gap_ratio``, ``model.contact_film_limit``)."""
    return dataclasses.replace(load_friction(), rolling_thermal=fid.rolling_thermal,
                               inlet_gap_ratio=fid.inlet_gap_ratio, contact_film_limit_m=fid.contact_film_limit_m)


def _point_friction(scene: Scene, friction, op, lubrication=None):
    """The friction parameters of one operating point with the inlet supply of its raceway
    contacts (:func:`kegel.supply.lubricant_supply`) for ``lubrication`` (default: the scene's;
    a study's own point: flooded contacts), and that supply."""
    from ..coupling.supply import lubricant_supply

    lub = lubrication
    supply_model = scene.fidelity.lubricant_supply
    if lub is None:
        lub = scene.lubrication
        if scene.study is not None:
            supply_model = "flooded"  # the study's lubrications are solved in _study_case_friction
    state = lubricant_state(scene.lubricant, op.temperature_K, source=scene.source, key="operating.temperature")
    supply = lubricant_supply(scene.geometry, scene.bearing, mode=lub.mode, oil_level_m=lub.oil_level_m,
                              speed_rad_s=op.speed_rad_s, kinematic_viscosity_m2_s=state.kinematic_viscosity_m2_s,
                              model=supply_model)
    return dataclasses.replace(friction, inlet_gap_ratio_inner=supply.inlet_gap_ratio_inner,
                               inlet_gap_ratio_outer=supply.inlet_gap_ratio_outer), supply


def _study_case_friction(scene: Scene, fid: "Fidelity", op, friction, point: dict[str, Any], model,
                         study_cfd: list[tuple[Path, dict[str, Any]]]) -> dict[str, Any]:
    """A study point's contact friction per lubrication, each with its raceway contacts' inlet
    supply: a lubrication whose contacts are flooded reuses the point's solution (flooded
    contacts), any other is solved again (quasi-static; a dynamic study keeps the point's
    friction and says so in ``note``). With CFD results of the real rollers (``study_cfd``, read
    once per run), also the contact cut at their gap for the CFD rows."""
    from ..coupling import cfd_loss_at
    from ..outputs.study import case_name

    out: dict[str, Any] = {}
    for lub in scene.study.cases:
        f_case, supply = _point_friction(scene, friction, op, lub)
        rec: dict[str, Any] = {"lubricant_supply": supply.as_dict()}
        same = (f_case.inlet_gap_ratio_inner, f_case.inlet_gap_ratio_outer) == (0.0, 0.0)
        if same or fid.solution == "dynamic":
            rec.update(friction_torque_Nm=point["friction_torque_Nm"], converged=point["converged"],
                       torque_by_mechanism_Nm=point.get("torque_by_mechanism_Nm"),
                       note="" if same else "dynamic study: the friction of flooded contacts (supply not applied)")
        else:
            _, fr = _quasi_static_point(scene, fid, op, f_case, model=model)
            rec.update(friction_torque_Nm=fr.drive_torque_Nm, converged=fr.converged,
                       torque_by_mechanism_Nm=fr.torque_by_mechanism_Nm(op.speed_rad_s), note="")
        if study_cfd and lub.mode == "oil_bath":
            # the CFD row's contact: cut where the CFD results' oil begins (their gap g)
            flooded = lub.oil_level_m >= scene.bearing.outer_diameter_m
            c = cfd_loss_at(study_cfd, bearing=scene.bearing.designation, lubricant=scene.lubricant.name,
                            speed_rad_s=op.speed_rad_s, temperature_K=op.temperature_K,
                            oil_level_m=lub.oil_level_m, flooded=flooded)
            if c["gap_ratio"] is not None and c["status"] != "missing" and fid.solution != "dynamic":
                g_cut = float(c["gap_ratio"]) * scene.geometry.roller_mean_diameter_m
                dist, fr = _quasi_static_point(scene, fid, op, dataclasses.replace(f_case, contact_film_limit_m=g_cut),
                                               model=model)
                # the CFD's far field on the unloaded stretch of the lines (flooded results only: the
                # lookup above took a flooded result exactly when the lubrication is flooded)
                wedge = _unloaded_line_wedge_Nm(scene, op, g_cut, dist.loaded_length_m, flooded=flooded)
                rec.update(contact_film_limit_m=g_cut, friction_cut_at_g_Nm=fr.drive_torque_Nm,
                           friction_cut_at_g_converged=fr.converged, unloaded_line_wedge_Nm=wedge)
        out[case_name(lub)] = rec
    return out


def _rib_cells(fid: "Fidelity") -> int:
    """Cells per side of the rib's cell model, 0 for the closed-form ellipse."""
    return fid.rib_cells if fid.rib_model == "cell" else 0


def _quasi_static_point(scene: Scene, fid: "Fidelity", op, friction, *, model=None, data=None):
    """Load distribution and friction of one operating point at the fidelity ``fid`` (a new
    model unless ``model`` and ``data`` are passed to warm-start a sweep)."""
    return bearing_friction(
        scene.geometry, scene.bearing, scene.material, scene.lubricant, friction, temperature_K=op.temperature_K,
        inner_speed_rad_s=op.speed_rad_s, axial_N=op.axial_load_N, axial_offset_m=op.axial_offset_m,
        radial_N=op.radial_load_N, misalignment_rad=op.misalignment_rad, tilt_moment_Nm=op.tilt_moment_Nm,
        slices=fid.slices, method=fid.slice_model,
        rib_cells=_rib_cells(fid), cage=fid.cage, model=model, data=data,
        inner_ring_temperature_K=op.inner_ring_temperature_K, outer_ring_temperature_K=op.outer_ring_temperature_K)


def choose_fidelity(scene: Scene) -> tuple["Fidelity", dict[str, Any]]:
    """``fidelity = "auto"``: the cheapest quasi-static preset whose friction torque at the scene's
    first and last operating points lies within ``scene.fidelity.tolerance`` of the ``fine``
    level.

    Each level is solved cold at those points (model built, load distribution, friction), so the
    choice costs about the runtime of the ``fine`` level at two points. Returns the chosen
    :class:`kegel.scene.Fidelity` (named ``auto:<preset>``, hydraulic options kept) and a record of
    the comparison: per level the torques, the largest deviation from ``fine`` and the runtime.
    """
    from ..model.scene import FIDELITY_PRESETS

    friction = _friction(scene.fidelity)
    ops = scene.operating_points
    checks = [ops[0]] if len(ops) == 1 else [ops[0], ops[-1]]
    rows: dict[str, dict[str, Any]] = {}
    for level in AUTO_LEVELS:
        fid = dataclasses.replace(scene.fidelity, **FIDELITY_PRESETS[level])
        t0 = time.perf_counter()
        torques = [_quasi_static_point(scene, fid, op, _point_friction(scene, friction, op)[0])[1].drive_torque_Nm
                   for op in checks]
        rows[level] = {"torques_Nm": torques, "runtime_s": time.perf_counter() - t0}
    ref = rows["fine"]["torques_Nm"]
    for r in rows.values():
        r["deviation_from_fine"] = max(abs(t / tf - 1.0) for t, tf in zip(r["torques_Nm"], ref))
    tol = scene.fidelity.tolerance
    chosen = next(level for level in AUTO_LEVELS if rows[level]["deviation_from_fine"] <= tol)
    fid = dataclasses.replace(scene.fidelity, name=f"auto:{chosen}", **FIDELITY_PRESETS[chosen])
    record = {"tolerance": tol, "chosen": chosen, "checked_points": [op.index for op in checks], "levels": rows}
    return fid, record


def _dynamic_point(scene: Scene, op, friction, out: Path, progress: bool,
                   cfd_runs: list[tuple[Path, dict[str, Any]]] | None = None, cfd_point=None) -> dict[str, Any]:
    """One operating point with the dynamic simulation: steady-state means as the point's
    figures, the time series and VTK bodies in ``dynamic/point_NNN`` (resumable from its
    checkpoint after an interrupt). With ``hydraulic = "cfd"``: ``cfd_runs`` (the speed sweep the
    flow-force laws are fitted over) and ``cfd_point`` (the point's result, file and boundary,
    :func:`_cfd_point`)."""
    from ..coupling import flow_forces_from_cfd, flow_forces_from_correlation
    from ..solutions.dynamics import simulate, write_result

    g, b, m, fid, dyn = scene.geometry, scene.bearing, scene.material, scene.fidelity, scene.dynamic
    if fid.rib_model == "cell":
        rib_note = "hertz (the dynamic model evaluates the rib as one ellipse)"
    else:
        rib_note = "hertz"
    profile = list(dyn.speed_profile) or [(0.0, op.speed_rad_s)]
    state = lubricant_state(scene.lubricant, op.temperature_K, source=scene.source, key="operating.temperature")
    # the oil acts on the bodies: the correlation's roller-set drag as a force element on every
    # roller (fitted at the point's pure-rolling cage speed); the ring churning acts on the rings,
    # whose speeds are prescribed, and is added to their torques
    elements, law, hyd0 = [], None, None
    if fid.hydraulic == "correlation" and scene.lubrication.oil_level_m > 0:
        wc0 = cage_speed_rad_s(g, op.speed_rad_s)
        hyd0 = hydraulic_torques("liebrecht", g, state, shaft_speed_rad_s=op.speed_rad_s,
                                 oil_level_m=scene.lubrication.oil_level_m, cage_speed_rad_s=wc0)
        law = flow_forces_from_correlation(hyd0, g, density_kg_m3=state.density_kg_m3, cage_speed_rad_s=wc0)
        elements.append(law.element())
    cfd = None
    if fid.hydraulic == "cfd":
        # the CFD result of this point: rollers and cage through the fitted force law, the oil's
        # torque on the inner ring and the shaft (turning with the prescribed speed) on top
        # (levels from this point's result, speed exponents fitted over the same CFD model's sweep)
        cfd, cfd_file, bnd = cfd_point
        # the CFD's far field on the unloaded stretch of the lines (the point's load distribution)
        # (the quasi-static load distribution of the point, as the dynamic run starts from it)
        dist0 = load_distribution(g, b, m, axial_N=op.axial_load_N, axial_offset_m=op.axial_offset_m,
                                  radial_N=op.radial_load_N, misalignment_rad=op.misalignment_rad,
                                  tilt_moment_Nm=op.tilt_moment_Nm, tilt_free=dyn.tilt_free or op.tilt_moment_Nm != 0.0,
                                  cage_speed_rad_s=cage_speed_rad_s(g, op.speed_rad_s),
                                  slices=fid.slices, method=fid.slice_model)
        bnd = _with_unloaded_line_wedge(scene, op, bnd, dist0.loaded_length_m, cfd)
        law = flow_forces_from_cfd(cfd, g, sweep=cfd_runs, source=str(cfd_file))
        elements.append(law.element())
    pdir = out / "dynamic" / f"point_{op.index:03d}"
    pdir.mkdir(parents=True, exist_ok=True)
    res = simulate(g, b, m, scene.lubricant, friction, temperature_K=op.temperature_K, speed_profile=profile,
                   duration_s=dyn.duration_s, max_duration_s=dyn.max_duration_s, axial_N=op.axial_load_N, axial_offset_m=op.axial_offset_m,
                   radial_N=op.radial_load_N, misalignment_rad=op.misalignment_rad, slices=fid.slices,
                   method=fid.slice_model, cage=fid.cage, output_interval_s=dyn.output_interval_s,
                   average_fraction=dyn.average_fraction, rtol=dyn.tolerance, hold_axial=dyn.hold_axial,
                   tilt_free=dyn.tilt_free, tilt_moment_Nm=op.tilt_moment_Nm,
                   checkpoint=pdir / "checkpoint.npz", checkpoint_interval_s=dyn.checkpoint_interval_s,
                   # the threads do not change the result (rollers in parallel, identical to one thread),
                   # so a run resumed with another thread count keeps its checkpoint
                   checkpoint_key=json.dumps([scene.bearing.designation, scene.lubricant.name, op.as_dict(),
                                              fid.as_dict(), {k: v for k, v in dyn.as_dict().items() if k != "threads"}],
                                             sort_keys=True),
                   progress=progress, elements=elements, load_profile=list(dyn.load_profile),
                   threads=dyn.threads or (len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else 1),
                   inner_ring_temperature_K=op.inner_ring_temperature_K,
                   outer_ring_temperature_K=op.outer_ring_temperature_K)
    st = res.steady
    w = st["inner_speed_rad_s"]
    hyd = None
    if hyd0 is not None:
        hyd = hydraulic_torques("liebrecht", g, state, shaft_speed_rad_s=w, oil_level_m=scene.lubrication.oil_level_m,
                                cage_speed_rad_s=st["cage_speed_rad_s"])
    # the drive torque pays for the roller drag through the contacts (the element's power);
    # friction is the rest; the rings' churning comes on top
    roller_drag = st["external_power_W"] / w if w else 0.0
    friction = st["drive_torque_Nm"] - roller_drag
    churning = (hyd.components["churning_inner_ring_Nm"] + hyd.components["churning_outer_ring_Nm"]) if hyd else 0.0
    hyd_out = ({**hyd.as_dict(), "roller_drag_on_the_bodies_Nm": roller_drag, "flow_force_law": law.as_dict()}
               if hyd else None)
    if cfd is not None:
        ring = -(cfd["torques_Nm"]["inner_ring"]["total"] + cfd["torques_Nm"]["shaft"]["total"])
        # the thin films (roller end / rib, pocket faces) are analytic terms at the CFD's
        # kinematics, added at the shaft like the rings' churning: they do not act on the bodies
        # and less the CFD's far field on the unloaded stretch of the lines, which the contact
        # convention does not count (taken off at the shaft: the CFD splits it between the
        # rollers and the rings, and the flow-force law still puts the rollers' part on them, so
        # the cage slip keeps that small drag)
        churning = ring + math.copysign(bnd.thin_films_Nm - bnd.unloaded_line_wedge_Nm, op.speed_rad_s)
        hyd_out = {"source": "cfd", "file": str(cfd_file), "loss_torque_at_shaft_Nm": cfd["loss_torque_at_shaft_Nm"],
                   "boundary": bnd.as_dict(), "thin_films_Nm": bnd.thin_films_Nm,
                   "unloaded_line_wedge_Nm": bnd.unloaded_line_wedge_Nm,
                   "inner_ring_and_shaft_Nm": ring, "roller_drag_on_the_bodies_Nm": roller_drag,
                   # the CFD's bodies' share at its own kinematics (pure rolling): what the
                   # flow-force laws take there; the dynamic run's share differs by its slip
                   "bodies_share_in_the_cfd_Nm": cfd["loss_torque_at_shaft_Nm"] - ring,
                   "flow_force_law": law.as_dict(), "cfd_point": cfd["point"], "steady": cfd.get("steady"),
                   "angular_momentum_balance": _balance_of(cfd)}
    power = {c: {k: st[f"power_{c}_{k}_W"] for k in MECHANISMS} for c in CONTACTS}
    by_contact = {c: sum(power[c].values()) / w for c in CONTACTS}
    by_contact["cage"] = st["cage_power_W"] / w
    by_mech = {k: sum(power[c][k] for c in CONTACTS) / w for k in MECHANISMS}
    by_mech["solid_sliding"] += st["cage_power_W"] / w
    # pure-rolling cage speed (the quasi-static kinematics' ratio) at the mean speed
    wc0 = res.stats["cage_to_inner_speed_pure_rolling"] * w
    last = {k: res.series[k][-1].tolist() for k in ("roller_outer_N", "roller_inner_N", "roller_rib_N")}
    Z = g.roller_count
    meta = {"scene": scene.source, "operating_point": op.as_dict(), "fidelity": fid.as_dict(),
            "dynamic": dyn.as_dict(), "rib_model": rib_note,
            "flow_forces": law.as_dict() if law else None}
    files = write_result(res, pdir, meta, g=g, vtk_every=max(1, len(res.time_s) // 100))
    failure = (_not_settled(st, dyn.duration_s, dyn.max_duration_s if res.stats.get("extended") else None)
               if not (res.finished and st["settled"]) else
               None if st["power_balanced"] else _unbalanced(st, dyn.tolerance))
    return {
        **op.as_dict(),
        "friction_torque_Nm": friction,
        "hydraulic_torque_Nm": roller_drag + churning,
        "total_torque_Nm": friction + roller_drag + churning,
        "power_loss_W": power_loss_W(friction + roller_drag + churning, w),
        "outer_ring_torque_Nm": st["outer_ring_torque_Nm"],
        "outer_ring_torque_std_Nm": st["outer_ring_torque_std"],
        "power_input_W": st["power_input_W"],
        "power_dissipated_W": st["power_dissipated_W"],
        "power_balance_error": st["power_balance_error"],
        "cage_speed_rpm": st["cage_speed_rad_s"] * 30 / math.pi,
        "cage_slip": 1.0 - st["cage_speed_rad_s"] / wc0 if wc0 else 0.0,
        "torque_by_contact_Nm": by_contact,
        "torque_by_mechanism_Nm": by_mech,
        "power_W": power,
        "Lambda_min": {c: float(res.series[f"Lambda_min_{c}"][-1]) for c in CONTACTS},
        "phi_max": {c: float(res.series[f"phi_max_{c}"][-1]) for c in CONTACTS},
        "hydraulic": hyd_out,
        "roller_azimuth_rad": (2 * np.pi * np.arange(Z) / Z).tolist(),
        **last,
        "axial_force_N": -float(res.series["ring_force_N"][-1][2]),
        "ring_displacement_m": res.states[-1][12 * Z + 13:12 * Z + 16].tolist(),
        "load_residual": None,
        # the means are an answer only where the torques and the cage speed have settled
        # (kegel.dynamics.settling); otherwise the figures are kept and the point says why
        "converged": failure is None,
        **({} if failure is None else {"failure": failure}),
        "steady_window_s": [st["window_start_s"], st["window_end_s"]],
        "steady_drift": st["drift_relative"],
        "runtime_s": res.runtime_s,
        "lubricant_state": state.as_dict(),
        "dynamic": {"steady": st, "stats": res.stats, "revolutions": res.revolutions,
                    "wall_time_per_revolution_s": res.runtime_s / res.revolutions if res.revolutions else None,
                    "files": files},
    }


def _unbalanced(steady: dict[str, Any], tolerance: float) -> str:
    """The failure text of a settled dynamic point whose power does not balance (see
    :data:`kegel.dynamics.POWER_BALANCE_TOLERANCE`): its figures are kept, but are not an answer."""
    return (f"the dynamic run's power does not balance: input {steady['power_input_W']:.6g} W, dissipated "
            f"{steady['power_dissipated_W']:.6g} W, kinetic-energy rate {steady['kinetic_energy_rate_W']:.3g} W over "
            f"{steady['window_start_s'] * 1e3:.4g}-{steady['window_end_s'] * 1e3:.4g} ms: off by "
            f"{100 * steady['power_balance_error']:+.3g} % of the input, more than "
            f"{100 * _dynamics.POWER_BALANCE_TOLERANCE:.2g} %. The balance is an identity of the equations of motion, so the "
            f"integration is not accurate enough (tighten dynamic.tolerance, now {tolerance:.3g}) or the model has "
            "a defect; the figures are kept, but are not an answer")


def _not_settled(steady: dict[str, Any], duration_s: float, max_duration_s: float | None = None) -> str:
    """The failure text of a dynamic point whose signals have not settled (its figures are the
    means over the last part of the run: not a steady answer)."""
    info = steady["settling"]
    need = max(3 * info["window_s"], 2 * info["window_s"] + info["hold_s"])  # kegel.steady.settled_window
    return (f"the dynamic run has not settled: {info['reason']}; the figures are the means over "
            f"{steady['window_start_s'] * 1e3:.4g}-{steady['window_end_s'] * 1e3:.4g} ms, not a steady answer. "
            f"The steady test needs {need * 1e3:.3g} ms of settled running after the transients of the last speed "
            f"or load change ({(need + info['window_s']) * 1e3:.3g} ms for a run steady from its start): "
            + (f"lengthen dynamic.duration (now {duration_s * 1e3:.4g} ms) or set dynamic.max_duration to let it run on"
               if max_duration_s is None else
               f"it ran on to dynamic.max_duration ({max_duration_s * 1e3:.4g} ms); raise that"))


def _read_cfd_runs(scene: Scene) -> list[tuple[Path, dict[str, Any]]] | None:
    """The CFD results of ``[model] cfd_results``, read once per run (None without them)."""
    from ..coupling import read_cfd_results

    if scene.fidelity.hydraulic != "cfd":
        return None
    return read_cfd_results(scene.fidelity.cfd_results, source=scene.source, key="model.cfd_results")


def _balance_of(cfd: dict[str, Any]) -> float | None:
    from ..coupling.cfd_results import balance_of

    return balance_of(cfd)


def _unloaded_line_wedge_Nm(scene: Scene, op, film_limit_m: float, loaded_length_m, *, flooded: bool) -> float:
    """The CFD's far field beyond the gap ``film_limit_m`` on the unloaded stretch of the raceway
    lines at this point's load distribution (:func:`kegel.coupling.split.unloaded_line_wedge`),
    for a flooded CFD result; 0 without a boundary (the old geometry) and for an oil bath, whose
    wedges hold 26-69 % oil: the term there, 0.4-0.6 % of the totals, is estimated in
    docs/cfd.md (benchmarks/cfd_wedge_oil_fraction.py) and left in."""
    from ..coupling.split import unloaded_line_wedge

    if not film_limit_m or not flooded or loaded_length_m is None or op.speed_rad_s == 0.0:
        return 0.0
    state = lubricant_state(scene.lubricant, op.temperature_K, source=scene.source, key="operating.temperature")
    return unloaded_line_wedge(scene.geometry, viscosity_Pas=state.dynamic_viscosity_Pas,
                               inner_speed_rad_s=abs(op.speed_rad_s), loaded_length_m=loaded_length_m,
                               film_limit_m=film_limit_m).torque_Nm


def _with_unloaded_line_wedge(scene: Scene, op, bnd, loaded_length_m, cfd: dict[str, Any]):
    """``bnd`` with its unloaded-stretch term (:func:`_unloaded_line_wedge_Nm`); a CFD result is
    flooded when its point has no oil level."""
    flooded = (cfd.get("point") or {}).get("oil_level_m") is None
    return bnd.with_unloaded_line_wedge(
        _unloaded_line_wedge_Nm(scene, op, bnd.contact_film_limit_m, loaded_length_m, flooded=flooded))


def _cfd_point(scene: Scene, op, runs: list[tuple[Path, dict[str, Any]]]):
    """The ``kegel cfd run`` result of an operating point, among ``runs`` (:func:`_read_cfd_runs`),
    its file and its contact / CFD boundary (:class:`kegel.coupling.cfd_results.CfdBoundary`).

    Raises
    ------
    KegelInputError
        No result for the point; or a scene whose ``model.contact_film_limit`` differs from the
        result's gap (the contact would then own oil the CFD owns too, or neither would own it).
    """
    from ..coupling import find_cfd_result
    from ..coupling.cfd_results import cfd_boundary

    lub = scene.lubrication
    data, f = find_cfd_result(scene.fidelity.cfd_results, bearing=scene.bearing.designation,
                              lubricant=scene.lubricant.name, speed_rad_s=op.speed_rad_s,
                              temperature_K=op.temperature_K, oil_level_m=lub.oil_level_m,
                              flooded=lub.oil_level_m >= scene.bearing.outer_diameter_m,
                              source=scene.source, key="model.cfd_results", results=runs)
    bnd = cfd_boundary(data, scene.geometry.roller_mean_diameter_m, source=str(f))
    g = scene.fidelity.contact_film_limit_m
    if g and abs(g - bnd.contact_film_limit_m) > 1e-3 * max(g, bnd.contact_film_limit_m):
        want = (f"{bnd.contact_film_limit_m * 1e3:.4g} mm (the gap g = {bnd.gap_ratio:g} D_w of the CFD result "
                f"{f}) or no value: with hydraulic = \"cfd\" the contact is cut where the CFD's oil begins"
                if bnd.gap_ratio is not None else
                f"no value: the CFD result {f} is of the old geometry (rollers shrunk, no contact / CFD boundary)")
        raise KegelInputError(scene.source, "model.contact_film_limit", f"{g * 1e3:.4g} mm", want)
    return data, f, bnd


#: results.csv: the point's own columns, then the derived ones (see _csv_row).
CSV_COLUMNS = ("index", "speed_rpm", "temperature_degC", "axial_load_N", "axial_offset_m", "radial_load_N",
               "tilt_moment_Nm", "misalignment_rad", "axial_force_N", "friction_torque_Nm", "hydraulic_torque_Nm",
               "total_torque_Nm", "power_loss_W", "converged", "failure", "cage_model", "pocket_fraction", "cage_speed_rpm",
               "cage_slip", "power_input_W", "power_balance_error", "start")
CSV_DERIVED = ("Lambda_min", "Lambda_min_contact", "hydraulic_source", "hydraulic_inner_ring_Nm",
               "hydraulic_outer_ring_Nm", "hydraulic_cage_Nm", "skf_rolling_sliding_Nm", "skf_drag_Nm",
               "skf_total_Nm", "supply_inlet_gap_ratio_inner", "supply_inlet_gap_ratio_outer",
               "supply_rolling_force_factor_inner", "supply_rolling_force_factor_outer", "warnings")


#: results.csv's band columns, present when the run computed the uncertainty (kegel.uncertainty)
CSV_UNCERTAINTY = ("friction_torque_low_Nm", "friction_torque_high_Nm", "total_torque_low_Nm",
                   "total_torque_high_Nm")


def _csv_row(p: dict[str, Any]) -> list[Any]:
    lam = p.get("Lambda_min") or {}
    worst = min(lam, key=lambda k: lam[k]) if isinstance(lam, dict) and lam else None
    hyd = p.get("hydraulic") or {}
    skf = p.get("skf_catalogue_model") or {}
    tq = hyd.get("torques_Nm") or {}
    src = hyd.get("source") or hyd.get("correlation")
    derived = [lam[worst] if worst else None, worst, src,
               hyd.get("inner_ring_Nm", (tq.get("inner_ring") or {}).get("total")),
               hyd.get("outer_ring_Nm", (tq.get("outer_ring") or {}).get("total")),
               hyd.get("cage_Nm", (tq.get("cage") or {}).get("total")),
               skf.get("rolling_sliding_Nm"), skf.get("drag_Nm"), skf.get("total_Nm"),
               *((p.get("lubricant_supply") or {}).get(k) for k in (
                   "inlet_gap_ratio_inner", "inlet_gap_ratio_outer", "rolling_force_factor_inner",
                   "rolling_force_factor_outer")),
               "; ".join(w["code"] for w in p.get("warnings", ()))]
    if p.get("power_loss_W") is None and p.get("total_torque_Nm") is not None and p.get("speed_rad_s") is not None:
        p = {**p, "power_loss_W": power_loss_W(p["total_torque_Nm"], p["speed_rad_s"])}  # a record of an older run
    row = [p.get(c) for c in CSV_COLUMNS] + derived
    row += [(p.get("torque_by_contact_Nm") or {}).get(c) for c in CONTACTS_WITH_CAGE]
    row += [(p.get("torque_by_mechanism_Nm") or {}).get(k) for k in MECHANISMS]
    return ["" if v is None else v for v in row]


def _csv(points: list[dict[str, Any]]) -> str:
    """results.csv: one row per operating point, every scalar of its record (the per-roller
    arrays are in results.json); the warnings column lists the point's warning codes."""
    cols = [*CSV_COLUMNS, *CSV_DERIVED]
    cols += [f"torque_{c}_Nm" for c in CONTACTS_WITH_CAGE] + [f"torque_{k}_Nm" for k in MECHANISMS]
    band = any("uncertainty" in p for p in points)
    if band:
        cols += list(CSV_UNCERTAINTY)
    buf = io.StringIO()
    w = csv.writer(buf)
    w.writerow(cols)
    for p in points:
        row = _csv_row(p)
        if band:
            u = p.get("uncertainty") or {}
            row += ["" if u.get(k) is None else u[k] for k in CSV_UNCERTAINTY]
        w.writerow(row)
    return buf.getvalue()


#: The summary files of a run (written at its end, all together).
SUMMARY_FILES = ("results.json", "results.csv", "torque.png", "breakdown.png", "roller_loads_and_slip.png",
                 *STUDY_FILES)


def _plots(scene: Scene, points: list[dict[str, Any]], out: Path) -> dict[str, str]:
    """torque.png, breakdown.png and roller_loads_and_slip.png (see :mod:`kegel.plots`)."""
    from ..outputs.plots import plot_meta_from_scene, run_plots

    return run_plots(points, plot_meta_from_scene(scene), out)
