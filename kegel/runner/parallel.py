"""Independent operating points on every core, and on a Dask cluster.

The operating points of a scene (a sweep, a study) do not depend on each other, except that a
quasi-static point is warm-started from the solution of the point before it. kegel therefore
cuts the points into fixed *chains* (:func:`point_blocks`): :data:`QUASI_STATIC_CHAIN`
consecutive points for the quasi-static solution (each chain starts from a fresh state, the
others follow the one before them), one point for the dynamic solution. The chains do not
depend on the number of processes, and a run in one process uses the same chains, so a run
with any ``--jobs`` or on any cluster gives the same figures, to the last digit, in the same
order, as a run in one process.

Two engines run the chains:

- **Local processes** (``kegel run --jobs N``, ``run_scene(..., jobs=N)``): a
  :class:`concurrent.futures.ProcessPoolExecutor` whose workers are started by a fork server
  (``forkserver`` on Linux, ``spawn`` elsewhere) and load their own copy of the C++ core: no
  solver object is ever shared between processes. Each worker is replaced after
  :data:`MAX_TASKS_PER_CHILD` chains and at most two chains per worker are queued, so memory
  per worker stays bounded whatever the number of points. Workers ignore Ctrl-C; the parent
  stops them (SIGTERM) on any interrupt or error, after the finished points have been streamed
  to the run's ``points.jsonl``, so an interrupted parallel run resumes as a serial one does.
- **Dask** (``kegel run --scheduler ADDRESS``, ``run_scene(..., client=client)``): one task per
  chain on a ``dask.distributed`` cluster; dask-jobqueue's SLURM and PBS clusters give a
  ``Client`` the same way. The scene is sent once (scattered); the workers need kegel installed
  and, for dynamic points, the output folder's filesystem (the point files are written there).

:func:`map_tasks` runs any list of independent calls the same way (``kegel cfd sweep``: one task
per CFD case, which keeps its own MPI decomposition ``--np``).
"""

from __future__ import annotations

import copyreg
import dataclasses
import itertools
import os
import pickle
import signal
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Iterator, Sequence

from .. import _core

__all__ = ["MAX_TASKS_PER_CHILD", "QUASI_STATIC_CHAIN", "connect", "default_jobs", "effective_jobs", "map_tasks",
           "point_blocks", "solve_blocks", "task_resources"]

#: consecutive quasi-static points solved as one chain (warm-started from each other): the
#: cold start of a chain costs about 15 ms (32216, default preset), spread over its points
QUASI_STATIC_CHAIN = 16
#: chains a worker process solves before it is replaced by a fresh one (bounded memory)
MAX_TASKS_PER_CHILD = 64


# -- the C++ lubricant parameters travel by value ---------------------------------------------
def _lubricant_parameters(values: dict[str, float]) -> Any:
    """A new ``_core.LubricantParameters`` with ``values`` (the pickle reducer's constructor)."""
    p = _core.LubricantParameters()
    for k, v in values.items():
        setattr(p, k, v)
    return p


def _reduce_lubricant_parameters(p: Any) -> tuple[Callable[..., Any], tuple[dict[str, float]]]:
    names = [n for n in dir(p) if not n.startswith("_") and not callable(getattr(p, n))]
    return _lubricant_parameters, ({n: getattr(p, n) for n in names},)


# a scene holds the lubricant's core parameters: plain numbers, copied into each worker's own core
copyreg.pickle(_core.LubricantParameters, _reduce_lubricant_parameters)


def default_jobs() -> int:
    """The cores this process may use (``--jobs``' default)."""
    if hasattr(os, "sched_getaffinity"):
        return max(1, len(os.sched_getaffinity(0)))
    return max(1, os.cpu_count() or 1)


def point_blocks(scene: Any, fid: Any = None) -> list[list[int]]:
    """The chains of a scene's operating points (indices in the scene's order): a quasi-static
    chain is solved in one process, each point warm-started from the one before it."""
    fid = fid if fid is not None else scene.fidelity
    n = len(scene.operating_points)
    size = 1 if fid.solution == "dynamic" else QUASI_STATIC_CHAIN
    return [list(range(i, min(i + size, n))) for i in range(0, n, size)]


def effective_jobs(jobs: int | None, n_tasks: int, client: Any = None) -> int:
    """The processes worth starting: ``jobs`` (None: every core) but no more than the tasks.

    Raises
    ------
    KegelInputError
        ``jobs`` is not a whole number >= 1, or is given with a Dask client.
    """
    from ..base.errors import KegelInputError

    if jobs is not None and (isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1):
        raise KegelInputError("<argument>", "jobs", jobs, "a whole number of processes, at least 1 (None: every core)")
    if client is not None:
        return 1
    return max(1, min(jobs if jobs is not None else default_jobs(), n_tasks))


def connect(scheduler: str) -> Any:
    """A ``dask.distributed.Client`` of the scheduler at ``scheduler`` (``tcp://host:8786``, or
    a scheduler file ``*.json`` as dask-jobqueue and ``dask scheduler --scheduler-file`` write).

    Raises
    ------
    KegelInputError
        dask.distributed is not installed, or the scheduler cannot be reached.
    """
    from ..base.errors import KegelInputError

    try:
        from distributed import Client
    except ImportError:
        raise KegelInputError("command line", "--scheduler", scheduler,
                              "a Dask scheduler, with dask.distributed installed (pip install 'kegel[dask]')") from None
    try:
        if scheduler.endswith(".json") and Path(scheduler).is_file():
            return Client(scheduler_file=scheduler, timeout="30s")
        return Client(scheduler, timeout="30s")
    except (OSError, TimeoutError) as exc:
        raise KegelInputError("command line", "--scheduler", scheduler,
                              f"the address of a running Dask scheduler ({exc})") from None


def task_resources(client: Any, cores: int) -> dict[str, int] | None:
    """The Dask resource annotation of a task that uses ``cores`` cores (``{"cores": n}``) when
    the cluster's workers declare a ``cores`` resource (``dask worker ... --resources
    "cores=8"``), so that a worker runs only as many such tasks as it has cores; None otherwise
    (each worker then runs as many tasks as it has threads).

    Raises
    ------
    KegelInputError
        The workers declare ``cores`` but none has ``cores`` of them (the task would wait forever).
    """
    from ..base.errors import KegelInputError

    workers = client.scheduler_info().get("workers", {})
    have = [w.get("resources", {}).get("cores") for w in workers.values()]
    have = [h for h in have if h is not None]
    if not have:
        return None
    if max(have) < cores:
        raise KegelInputError("<dask cluster>", "resources.cores", max(have),
                              f"a worker with at least {cores} cores for a task that uses {cores}")
    return {"cores": cores}


# -- the operating points -------------------------------------------------------------------------
@dataclass(frozen=True)
class _Payload:
    """What every chain of a run needs (sent once to each worker)."""

    scene: Any
    fidelity: Any
    work: Path | None  # None: nothing is written (run_scene(write=False))
    uncertainty: Any


def _solve(payload: _Payload, indices: Sequence[int]) -> list[tuple[int, dict[str, Any]]]:
    """Solve one chain of points (in a worker): each point's record as ``run_scene`` makes it
    (kegel.run._solve_point), warm-started from the point before it in the chain."""
    from . import run as R
    from ..solutions.quasi_static import bearing_model

    scene, fid = payload.scene, payload.fidelity
    friction = R._friction(fid)
    model = bearing_model(scene.geometry, scene.bearing, scene.material, slices=fid.slices, method=fid.slice_model)
    data = _core.quasi_static.BearingData(model)
    cfd_runs = R._read_cfd_runs(scene)
    study_cfd = R.read_study_cfd(scene)
    out = []
    for i in indices:
        op = scene.operating_points[i]
        point, data = R._solve_point(scene, fid, op, friction, model, data, payload.work, False, cfd_runs,
                                     payload.uncertainty, study_cfd)
        out.append((i, point))
    return out


_WORKER: dict[str, Any] = {}


def _init_worker(payload: bytes | None, cwd: str) -> None:
    """A local worker: Ctrl-C is the parent's to handle (it stops the workers), the parent's
    working folder, and the run's payload (unpickled once per worker)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    os.chdir(cwd)
    if payload is not None:
        _WORKER["payload"] = pickle.loads(payload)


def _solve_local(indices: Sequence[int]) -> list[tuple[int, dict[str, Any]]]:
    return _solve(_WORKER["payload"], indices)


def _context():
    import multiprocessing as mp

    if "forkserver" in mp.get_all_start_methods():
        ctx = mp.get_context("forkserver")
        # the fork server imports kegel once; every worker is forked from it before it has made
        # any solver object, and builds its own
        ctx.set_forkserver_preload(["kegel.parallel", "kegel.run"])
        return ctx
    return mp.get_context("spawn")


def _stop(executor: ProcessPoolExecutor) -> None:
    """Stop a pool at once: queued tasks cancelled, running workers terminated (SIGTERM, then
    SIGKILL after 5 s); their finished points are already with the parent."""
    procs = list((getattr(executor, "_processes", None) or {}).values())
    executor.shutdown(wait=False, cancel_futures=True)
    for p in procs:
        if p.is_alive():
            p.terminate()
    for p in procs:
        p.join(timeout=5.0)
        if p.is_alive():
            p.kill()
            p.join(timeout=5.0)


def _local_map(task: Callable[[Any], Any], items: Sequence[Any], jobs: int, payload: bytes | None = None,
               ) -> Iterator[tuple[int, Any]]:
    """Run ``task(item)`` for every item in ``jobs`` local processes, at most two queued per
    worker; yield (item number, result) as each finishes."""
    executor = ProcessPoolExecutor(max_workers=jobs, mp_context=_context(), initializer=_init_worker,
                                   initargs=(payload, os.getcwd()), max_tasks_per_child=MAX_TASKS_PER_CHILD)
    try:
        todo = iter(enumerate(items))
        running = {executor.submit(task, item): n for n, item in itertools.islice(todo, 2 * jobs)}
        while running:
            finished, _ = wait(running, return_when=FIRST_COMPLETED)
            for f in sorted(finished, key=running.__getitem__):
                n = running.pop(f)
                result = f.result()
                for m, item in itertools.islice(todo, 1):
                    running[executor.submit(task, item)] = m
                yield n, result
    except BaseException:
        _stop(executor)
        raise
    executor.shutdown(wait=True)


def _dask_map(client: Any, fn: Callable[..., Any], arg_lists: Sequence[tuple[Any, ...]], *,
              resources: Sequence[dict[str, int] | None] | None = None, name: str = "kegel",
              ) -> Iterator[tuple[int, Any]]:
    """One Dask task per argument tuple; yield (task number, result) as each finishes."""
    from distributed import as_completed

    futures = {}
    try:
        for n, args in enumerate(arg_lists):
            res = resources[n] if resources is not None else None
            f = client.submit(fn, *args, pure=False, key=f"{name}-{n}-{os.urandom(4).hex()}",
                              **({"resources": res} if res else {}))
            futures[f] = n
        for f in as_completed(list(futures)):
            yield futures[f], f.result()
    except BaseException:
        client.cancel(list(futures), force=True)
        raise


def solve_blocks(scene: Any, fid: Any, blocks: Sequence[Sequence[int]], work: Path | None, uncertainty: Any, *,
                 jobs: int = 1, client: Any = None) -> Iterator[tuple[int, dict[str, Any]]]:
    """Solve the chains ``blocks`` of ``scene`` in ``jobs`` local processes or on the Dask
    ``client``'s cluster; yield (point index, record) as each chain finishes (any order: the
    caller keeps the scene's). A dynamic point gets ``dynamic.threads`` threads, or the cores
    shared out among the processes (one on a Dask worker): the threads do not change its result.

    Any exception of a worker (other than a point's solver failure, which is a failed record)
    is raised here, and the other workers are stopped.
    """
    if not blocks:
        return
    dyn = scene.dynamic
    if fid.solution == "dynamic" and not dyn.threads:
        threads = 1 if client is not None else max(1, default_jobs() // max(1, jobs))
        scene = dataclasses.replace(scene, dynamic=dataclasses.replace(dyn, threads=threads))
    payload = _Payload(scene=scene, fidelity=fid, work=None if work is None else Path(os.path.abspath(work)), uncertainty=uncertainty)
    if client is not None:
        shared = client.scatter(payload, hash=False)
        cores = scene.dynamic.threads if fid.solution == "dynamic" else 1
        res = task_resources(client, cores)
        runs = _dask_map(client, _solve, [(shared, list(b)) for b in blocks], resources=[res] * len(blocks),
                         name="kegel-points")
    else:
        runs = _local_map(_solve_local, [list(b) for b in blocks], jobs, pickle.dumps(payload))
    try:
        for _, records in runs:
            yield from records
    finally:
        runs.close()


def map_tasks(fn: Callable[..., Any], arg_lists: Sequence[tuple[Any, ...]], *, jobs: int = 1, client: Any = None,
              cores_per_task: int = 1, name: str = "kegel") -> Iterator[tuple[int, Any]]:
    """``fn(*args)`` for every tuple of ``arg_lists`` (independent tasks, ``fn`` a module-level
    function): in this process (``jobs`` 1), in ``jobs`` local processes, or one Dask task each
    on ``client``'s cluster, annotated with ``cores_per_task`` cores (:func:`task_resources`);
    yield (task number, result) as each finishes."""
    if client is not None:
        res = task_resources(client, cores_per_task)
        yield from _dask_map(client, fn, arg_lists, resources=[res] * len(arg_lists), name=name)
    elif jobs <= 1 or len(arg_lists) <= 1:
        for n, args in enumerate(arg_lists):
            yield n, fn(*args)
    else:
        runs = _local_map(_call_local_args, [(fn, tuple(a)) for a in arg_lists], min(jobs, len(arg_lists)))
        try:
            yield from runs
        finally:
            runs.close()


def _call_local_args(item: tuple[Callable[..., Any], tuple[Any, ...]]) -> Any:
    fn, args = item
    return fn(*args)
