"""Running OpenFOAM v1912 (Debian) from Python: environment, solvers, logs, divergence.

The solvers are the ones ``make setup`` rebuilt without tree vectorisation
(``cfd_cases/solvers/build_solvers.sh``); the Debian utilities (blockMesh, gmshToFoam, checkMesh,
decomposePar, ...) are used as shipped. Every run writes its log into the case
(``log.<application>``); a failing or diverging run raises an error that carries the reason and the
log excerpt that shows it.
"""

from __future__ import annotations

import contextlib
import math
import os
import re
import shutil
import signal
import subprocess
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

__all__ = [
    "FoamError",
    "FoamSetupError",
    "FoamRunError",
    "FoamDivergenceError",
    "FoamInterrupted",
    "LogState",
    "RunSummary",
    "SOLVERS",
    "solver_dir",
    "solver_executable",
    "foam_environment",
    "run_utility",
    "run_solver",
    "read_field",
    "read_boundary_vectors",
    "read_boundary_geometry",
    "write_field_values",
    "rotation_matrix",
    "time_dirs",
    "cut_write",
    "set_aside_cut_writes",
    "controldict_value",
    "set_controldict_value",
]

#: Solvers kegel rebuilds (``make setup``); the Debian binaries of these are not used.
SOLVERS = ("interFoam", "pimpleFoam", "simpleFoam")

_DEFAULT_SOLVER_DIR = Path.home() / ".local" / "share" / "kegel" / "openfoam-v1912" / "bin"


class FoamError(RuntimeError):
    """Base class of OpenFOAM failures."""


class FoamSetupError(FoamError):
    """OpenFOAM or the rebuilt solvers are missing."""


class FoamRunError(FoamError):
    """An OpenFOAM application exited with an error.

    Attributes
    ----------
    case, application, log_path, excerpt
        Where it ran, what ran, the full log and the lines that show the failure.
    """

    def __init__(self, message: str, case: Path, application: str, log_path: Path, excerpt: str):
        self.case = case
        self.application = application
        self.log_path = log_path
        self.excerpt = excerpt
        super().__init__(f"{message}\n  case: {case}\n  log: {log_path}\n--- log excerpt ---\n{excerpt}")


class FoamDivergenceError(FoamRunError):
    """A solver diverged (NaN, Courant number explosion, floating point exception)."""


class FoamInterrupted(FoamRunError):
    """The run was interrupted (Ctrl-C); the case resumes from its latest written time."""


def solver_dir() -> Path:
    """Directory of the rebuilt solvers (``$KEGEL_OPENFOAM_BIN`` or the ``make setup`` default)."""
    env = os.environ.get("KEGEL_OPENFOAM_BIN")
    return Path(env) if env else _DEFAULT_SOLVER_DIR


def solver_executable(name: str, *, stock: bool = False) -> Path:
    """Path of a solver binary.

    Parameters
    ----------
    name
        One of :data:`SOLVERS`.
    stock
        Return Debian's binary from /usr/bin instead (only for the tests that show it is broken).

    Raises
    ------
    FoamSetupError
        When the rebuilt binary is missing (``make setup`` builds it).
    """
    if name not in SOLVERS:
        raise FoamSetupError(f"solver '{name}': expected one of {', '.join(SOLVERS)}")
    if stock:
        path = Path("/usr/bin") / name
    else:
        path = solver_dir() / name
    if not os.access(path, os.X_OK):
        raise FoamSetupError(
            f"OpenFOAM solver {path} not found: run `make setup` (it rebuilds {name} without tree "
            "vectorisation; see cfd_cases/solvers/build_solvers.sh) or set KEGEL_OPENFOAM_BIN"
        )
    return path


def foam_environment() -> dict[str, str]:
    """Environment for Debian's OpenFOAM v1912 binaries and Open MPI as root."""
    env = dict(os.environ)
    env.setdefault("WM_PROJECT_DIR", "/usr/share/openfoam")
    env.setdefault("WM_PROJECT_VERSION", "v1912")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_btl_vader_single_copy_mechanism", "none")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    # One OpenMP/BLAS thread per rank: the ranks already use every core.
    env.setdefault("OMP_NUM_THREADS", "1")
    return env


def _excerpt(lines: Sequence[str], n: int = 40) -> str:
    return "".join(lines[-n:]).rstrip()


def run_utility(
    case: str | Path,
    application: str,
    *args: str,
    log_name: str | None = None,
    timeout_s: float = 3600.0,
) -> str:
    """Run an OpenFOAM utility in ``case`` and return its output.

    The output is written to ``case/log.<log_name or application>``.

    Raises
    ------
    FoamRunError
        On a non-zero exit or a ``FOAM FATAL`` message, with the log excerpt.
    """
    case = Path(case)
    exe = shutil.which(application, path="/usr/bin:" + os.environ.get("PATH", ""))
    if exe is None:
        raise FoamSetupError(f"OpenFOAM utility '{application}' not found: run `make setup`")
    log = case / f"log.{log_name or application}"
    proc = subprocess.run(
        [exe, "-case", str(case), *args],
        env=foam_environment(),
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        timeout=timeout_s,
    )
    log.write_text(proc.stdout)
    if proc.returncode != 0 or "FOAM FATAL" in proc.stdout:
        lines = proc.stdout.splitlines(keepends=True)
        start = next((i for i, l in enumerate(lines) if "FOAM FATAL" in l), max(len(lines) - 30, 0))
        raise FoamRunError(
            f"{application} {' '.join(args)} failed (exit {proc.returncode})",
            case, application, log, _excerpt(lines[max(start - 5, 0):start + 25], 30),
        )
    return proc.stdout


_RE_TIME = re.compile(r"^Time = (\S+)")
_RE_CO = re.compile(r"^Courant Number mean: (\S+) max: (\S+)")
_RE_ACO = re.compile(r"^Interface Courant Number mean: (\S+) max: (\S+)")
_RE_DT = re.compile(r"^deltaT = (\S+)")
_RE_RES = re.compile(r"Solving for (\w+), Initial residual = (\S+), Final residual = (\S+)")
_RE_EXEC = re.compile(r"^ExecutionTime = (\S+) s\s+ClockTime = (\S+) s")
_RE_NAN = re.compile(r"(?<![A-Za-z])(nan|-nan|inf)(?![A-Za-z])", re.IGNORECASE)


@dataclass
class LogState:
    """What the solver log has said so far."""

    time: float = 0.0
    delta_t: float = math.nan
    courant_max: float = 0.0
    alpha_courant_max: float = 0.0
    residuals: dict[str, float] = field(default_factory=dict)
    steps: int = 0
    execution_time_s: float = 0.0
    ended: bool = False

    def feed(self, line: str) -> str | None:
        """Update from one log line; return a divergence reason or ``None``."""
        s = line.strip()
        if m := _RE_TIME.match(s):
            self.time = float(m.group(1))
            self.steps += 1
            return None
        if m := _RE_CO.match(s):
            self.courant_max = _num(m.group(2))
        elif m := _RE_ACO.match(s):
            self.alpha_courant_max = _num(m.group(2))
        elif m := _RE_DT.match(s):
            self.delta_t = _num(m.group(1))
        elif m := _RE_RES.search(s):
            self.residuals[m.group(1)] = _num(m.group(2))
            if not math.isfinite(_num(m.group(3))):
                return f"non-finite residual of {m.group(1)}"
        elif m := _RE_EXEC.match(s):
            self.execution_time_s = _num(m.group(1))
        elif s == "End":
            self.ended = True
        if "FOAM FATAL" in s:
            return "FOAM FATAL ERROR"
        if s.startswith("#0") and "sigFpe" in s or s.startswith("Floating point exception"):
            return "floating point exception (stack trace in the log)"
        if (_RE_CO.match(s) or _RE_RES.search(s) or _RE_DT.match(s)) and _RE_NAN.search(s):
            return "NaN or Inf in the solution"
        return None


def _num(text: str) -> float:
    try:
        return float(text.rstrip(","))
    except ValueError:
        return math.nan


@dataclass
class RunSummary:
    """Outcome of :func:`run_solver`."""

    application: str
    case: Path
    log_path: Path
    n_procs: int
    wall_time_s: float
    state: LogState
    stopped_early: bool


ProgressFn = Callable[[LogState, float], None]
StopFn = Callable[[LogState], bool]


def run_solver(
    case: str | Path,
    application: str,
    *,
    n_procs: int = 1,
    end_time: float | None = None,
    progress: ProgressFn | None = None,
    stop_when: StopFn | None = None,
    max_courant: float = 25.0,
    stock: bool = False,
    timeout_s: float = 6 * 3600.0,
) -> RunSummary:
    """Run a solver in ``case`` (in parallel with MPI when ``n_procs > 1``), following its log.

    Parameters
    ----------
    case
        Case directory (decomposed already when ``n_procs > 1``).
    application
        Solver name, one of :data:`SOLVERS`.
    n_procs
        MPI ranks.
    end_time
        The case's endTime, for the progress display's ETA.
    progress
        Called after every time step with the log state and the ETA in seconds (NaN if unknown).
    stop_when
        Called after every time step; when it returns True the run is stopped (``stopAt
        writeNow`` through controlDict) and :attr:`RunSummary.stopped_early` is set.
    max_courant
        A Courant number above this is treated as divergence.
    stock
        Use Debian's binary (tests only).

    Raises
    ------
    FoamDivergenceError
        On NaN, Courant explosion or a floating point exception; the solver is stopped and the
        error carries the log excerpt.
    FoamRunError
        On any other failure (non-zero exit, FOAM FATAL ERROR).
    """
    case = Path(case)
    exe = solver_executable(application, stock=stock)
    cmd = [str(exe), "-case", str(case)]
    if n_procs > 1:
        mpirun = shutil.which("mpirun")
        if mpirun is None:
            raise FoamSetupError("mpirun not found: run `make setup` (Debian package openmpi-bin)")
        cmd = [mpirun, "-np", str(n_procs), *cmd, "-parallel"]
    log_path = case / f"log.{application}"
    state = LogState()
    tail: list[str] = []
    t0 = time.monotonic()
    last_step = (t0, 0.0)
    first_step: tuple[float, float] | None = None
    slowest_step_s = 0.0
    reason: str | None = None
    fatal_at: int | None = None
    stopped = False
    stop_requested = 0.0
    interrupted: str | None = None
    # SIGTERM (kill, a batch system's stop) is handled as Ctrl-C: the solver runs in its own
    # session, so without this it ran on, orphaned, after its Python parent died
    with _sigterm_as_interrupt(), open(log_path, "a") as log, subprocess.Popen(
        cmd, env=foam_environment(), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
        bufsize=1, start_new_session=True,
    ) as proc:
        assert proc.stdout is not None
        try:
            for line in proc.stdout:
                log.write(line)
                tail.append(line)
                if len(tail) > 400:
                    del tail[:200]
                if fatal_at is not None:
                    continue  # let the solver finish printing its fatal error and exit
                step_before = state.steps
                reason = state.feed(line)
                if reason == "FOAM FATAL ERROR":
                    fatal_at, reason = len(tail) - 1, None
                    continue
                if reason is None and state.courant_max > max_courant:
                    reason = f"Courant number {state.courant_max:g} above {max_courant:g}"
                if reason is not None:
                    break
                if state.steps != step_before and first_step is None:
                    first_step = (time.monotonic(), state.time)  # a resumed run starts at its latest time
                    last_step = first_step
                elif state.steps != step_before:
                    now = time.monotonic()
                    slowest_step_s = max(slowest_step_s, now - last_step[0])
                    eta = math.nan
                    if end_time is not None and state.time > last_step[1]:
                        rate = (state.time - first_step[1]) / max(now - first_step[0], 1e-9)
                        eta = (end_time - state.time) / rate if rate > 0 else math.nan
                    last_step = (now, state.time)
                    if progress is not None:
                        progress(state, eta)
                    if stop_when is not None and not stopped and stop_when(state):
                        stopped = True
                        stop_requested = now
                        _request_write_now(case)
                    elif stopped and now - stop_requested > 15.0:
                        # OpenFOAM ignores a controlDict change within fileModificationSkew
                        # (10 s) of the previous one: ask again until the solver stops
                        stop_requested = now
                        _request_write_now(case)
                if time.monotonic() - t0 > timeout_s:
                    reason = f"timeout after {timeout_s:.0f} s"
                    break
        except KeyboardInterrupt:
            # The solver runs in its own session and does not see the terminal's Ctrl-C.
            interrupted = _stop_on_interrupt(proc, case, log,
                                             grace_s=max(STOP_GRACE_S, STOP_GRACE_STEPS * slowest_step_s))
        finally:
            if reason is not None or interrupted not in (None, "written"):
                _kill(proc)
            proc.wait()
    wall = time.monotonic() - t0
    if interrupted is not None:
        how = ("it wrote its state at the time above" if interrupted == "written"
               else f"it was killed ({interrupted}); its latest write may be cut short, and a resumed run "
                    "then goes on from the one before")
        raise FoamInterrupted(
            f"{application} interrupted at t = {state.time:g} s (step {state.steps}): {how}; "
            "the same command resumes the run", case, application, log_path, _excerpt(tail, 10))
    if reason is not None:
        raise FoamDivergenceError(
            f"{application} diverged at t = {state.time:g} s (step {state.steps}): {reason}",
            case, application, log_path, _excerpt(tail, 40),
        )
    if fatal_at is not None:
        raise FoamRunError(
            f"{application} stopped with a FOAM FATAL ERROR at t = {state.time:g} s",
            case, application, log_path, "".join(tail[max(fatal_at - 10, 0):fatal_at + 30]).rstrip(),
        )
    if proc.returncode != 0 and not stopped:
        raise FoamRunError(
            f"{application} failed (exit {proc.returncode})", case, application, log_path,
            _excerpt(tail, 40),
        )
    return RunSummary(application, case, log_path, n_procs, wall, state, stopped)


@contextlib.contextmanager
def _sigterm_as_interrupt() -> Iterator[None]:
    """Within the block, SIGTERM raises KeyboardInterrupt (the main thread only: signals cannot
    be handled elsewhere); the previous handler is restored after it."""
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def _raise(signum, frame):
        raise KeyboardInterrupt(f"signal {signum}")

    previous = signal.signal(signal.SIGTERM, _raise)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


#: After Ctrl-C (or SIGTERM) a solver gets this long to write its state and stop before it is
#: killed, or STOP_GRACE_STEPS times its slowest time step so far when that is longer: a 4.6 M-cell
#: sector took 50 s a step and was killed while writing after 60 s, its latest write cut short.
STOP_GRACE_S = 60.0
STOP_GRACE_STEPS = 3.0


def _stop_on_interrupt(proc: subprocess.Popen, case: Path, log, grace_s: float = STOP_GRACE_S) -> str:
    """Ctrl-C during a run: ask the solver to write its state and stop (``stopAt writeNow``),
    reading its output meanwhile (a full pipe would block it). Returns ``"written"`` when it
    stopped by itself, else why it has to be killed (no stop within ``grace_s``, a second Ctrl-C)."""
    asked = time.monotonic()
    deadline = asked + grace_s
    _request_write_now(case)
    try:
        assert proc.stdout is not None
        for line in proc.stdout:
            log.write(line)
            now = time.monotonic()
            if now > deadline:
                return f"no stop within {grace_s:.0f} s"
            if now - asked > 15.0:  # see the fileModificationSkew note in run_solver
                asked = now
                _request_write_now(case)
    except KeyboardInterrupt:
        return "a second Ctrl-C"
    return "written"


def _kill(proc: subprocess.Popen) -> None:
    try:
        os.killpg(proc.pid, signal.SIGTERM)
        proc.wait(timeout=10)
    except (ProcessLookupError, subprocess.TimeoutExpired):
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass


def time_dirs(case: str | Path) -> list[Path]:
    """The time folders of a case after the start (name a number > 0), in time order."""
    out = []
    for p in Path(case).iterdir():
        try:
            if p.is_dir() and float(p.name) > 0:
                out.append(p)
        except ValueError:
            continue
    return sorted(out, key=lambda p: float(p.name))


# the line OpenFOAM ends every file it writes with (regIOobject::writeEndDivider)
_END_DIVIDER = "// " + "*" * 73 + " //"


def _cut_file(path: Path) -> bool:
    """Whether OpenFOAM's file ``path`` was cut while being written: it does not end with the
    divider OpenFOAM writes last (compressed files are not checked)."""
    if path.suffix == ".gz":
        return False
    with path.open("rb") as f:
        f.seek(0, os.SEEK_END)
        f.seek(max(0, f.tell() - 200))
        tail = f.read().decode("ascii", "replace").rstrip()
    return not tail.endswith(_END_DIVIDER)


def cut_write(time_dir: Path, fields: Sequence[str]) -> str | None:
    """Why the time folder ``time_dir`` cannot be restarted from (a field of ``fields``
    missing, or a file that does not end as OpenFOAM ends what it writes: the solver was
    killed while writing it), or None when it is whole."""
    missing = [f for f in fields if not (time_dir / f).is_file() and not (time_dir / f"{f}.gz").is_file()]
    if missing:
        return f"{time_dir} lacks {', '.join(missing)}"
    for f in sorted(time_dir.rglob("*")):
        if f.is_file() and _cut_file(f):
            return f"{f} is cut short (it does not end with OpenFOAM's closing line)"
    return None


#: Files of a ``0`` folder that no restart needs: post-processing output (cell volumes and
#: centres, written there for a moment) and setFields' originals.
_NOT_RESTART_FIELDS = frozenset({"V", "C", "Cx", "Cy", "Cz"})


def _fields_of(folder: Path) -> list[str]:
    """The fields a restart of ``folder`` (a case or processor folder) needs: those of its ``0``
    (less post-processing output and ``*.orig`` copies)."""
    zero = folder / "0"
    if not zero.is_dir():
        return []
    return sorted(f.name for f in zero.iterdir()
                  if f.is_file() and f.name not in _NOT_RESTART_FIELDS and not f.name.endswith(".orig"))


def set_aside_cut_writes(case: str | Path, log: Callable[[str], None] = print) -> list[Path]:
    """Before a resumed run: move every time folder that cannot be restarted from aside as
    ``<time>.cut`` (``<time>.cut-2``, ...), so that the solver's latest time, reconstructPar
    and kegel all go on from the last whole write. Nothing is deleted.

    A time is set aside in every processor folder and in the case when any processor folder
    lacks it or holds it cut (a file that does not end as OpenFOAM ends what it writes, or a
    field of the folder's ``0`` missing: the solver was killed while writing); a reconstructed
    time of the case that is cut (reconstructPar killed) is set aside in the case only, and
    reconstructed again. Returns the folders moved."""
    case = Path(case)
    procs = sorted(p for p in case.glob("processor[0-9]*") if p.is_dir())
    bad: dict[str, tuple[str, list[Path]]] = {}
    names = sorted({t.name for r in procs for t in time_dirs(r)}, key=float)
    fields_of = {r: _fields_of(r) for r in procs}
    for name in names:
        lacking = [r.name for r in procs if not (r / name).is_dir()]
        why = (f"{', '.join(lacking)} lack{'s' if len(lacking) == 1 else ''} it" if lacking else
               next((w for r in procs if (w := cut_write(r / name, fields_of[r])) is not None), None))
        if why is not None:
            bad[name] = (why, [r / name for r in procs if (r / name).is_dir()] +
                         ([case / name] if (case / name).is_dir() else []))
    fields = _fields_of(case)
    for t in time_dirs(case):
        if t.name not in bad and (why := cut_write(t, fields)) is not None:
            bad[t.name] = (why, [t])
    moved = []
    for name, (why, folders) in sorted(bad.items(), key=lambda kv: float(kv[0])):
        for src in folders:
            dst, k = src.with_name(f"{name}.cut"), 1
            while dst.exists():
                k += 1
                dst = src.with_name(f"{name}.cut-{k}")
            src.rename(dst)
            moved.append(dst)
        log(f"cfd: the write of time {name} cannot be restarted from ({why}); set aside as "
            f"{name}.cut, the run goes on from the last whole write")
    return moved


def controldict_value(case: str | Path, key: str) -> str:
    """The value of ``key`` in ``case/system/controlDict`` (as written)."""
    path = Path(case) / "system" / "controlDict"
    m = re.search(rf"^{key}\s+([^;]+);", path.read_text(), re.M)
    if m is None:
        raise FoamError(f"{path}: no {key} entry")
    return m.group(1).strip()


def set_controldict_value(case: str | Path, key: str, value: str) -> None:
    """Replace the value of ``key`` in ``case/system/controlDict`` (write, then rename)."""
    path = Path(case) / "system" / "controlDict"
    text, n = re.subn(rf"^{key}\s+[^;]+;", f"{key:<16}{value};", path.read_text(), count=1, flags=re.M)
    if n != 1:
        raise FoamError(f"{path}: no {key} entry")
    tmp = path.with_suffix(".tmp")
    tmp.write_text(text)
    tmp.replace(path)


def _request_write_now(case: Path) -> None:
    """Ask a running solver to write and stop (runTimeModifiable re-reads controlDict)."""
    set_controldict_value(case, "stopAt", "writeNow")


_RE_FIELD = re.compile(
    r"internalField\s+(uniform\s+(\([^)]*\)|\S+)|nonuniform\s+List<(\w+)>\s*(\d+)\s*\()", re.S
)


def read_field(path: str | Path) -> np.ndarray:
    """Internal field values of an ASCII OpenFOAM field file.

    Returns
    -------
    numpy.ndarray
        Shape (n,) for scalars or (n, 3) for vectors; a uniform field gives one row.
    """
    path = Path(path)
    text = path.read_text()
    m = _RE_FIELD.search(text)
    if m is None:
        raise FoamError(f"{path}: no ASCII internalField found")
    if m.group(1).startswith("uniform"):
        token = m.group(2)
        vals = np.array(token.strip("()").split(), dtype=float)
        return vals if vals.size > 1 else vals.reshape(1)
    kind, n = m.group(3), int(m.group(4))
    body = text[m.end():]
    end = body.find("\n)")
    numbers = np.array(body[:end].replace("(", " ").replace(")", " ").split(), dtype=float)
    if kind == "scalar":
        out = numbers
    elif kind == "vector":
        out = numbers.reshape(-1, 3)
    else:
        raise FoamError(f"{path}: field type List<{kind}> not supported")
    if out.shape[0] != n:
        raise FoamError(f"{path}: expected {n} values, read {out.shape[0]}")
    return out


def read_boundary_vectors(path: str | Path) -> dict[str, np.ndarray]:
    """Boundary values of an ASCII vector field file (e.g. the face centres in ``0/C``),
    patch name -> (n, 3) array; patches with uniform or no values are left out."""
    path = Path(path)
    text = path.read_text()
    start = text.find("boundaryField")
    if start < 0:
        raise FoamError(f"{path}: no boundaryField")
    out: dict[str, np.ndarray] = {}
    for m in re.finditer(r"\n\s{4}(\w+)\s*\n\s{4}\{.*?value\s+nonuniform\s+List<vector>\s*(\d+)\s*\(",
                         text[start:], re.S):
        name, n = m.group(1), int(m.group(2))
        body = text[start + m.end():]
        end = body.find("\n)")
        vals = np.array(body[:end].replace("(", " ").replace(")", " ").split(), dtype=float).reshape(-1, 3)
        if vals.shape[0] != n:
            raise FoamError(f"{path}: patch {name}: expected {n} vectors, read {vals.shape[0]}")
        out[name] = vals
    return out


def _foam_list_body(path: Path) -> str:
    """The text of an ASCII OpenFOAM list file after its header (from the element count on)."""
    text = path.read_text()
    end_header = text.find("}", text.find("FoamFile"))
    return text[end_header + 1:] if end_header >= 0 else text


def read_boundary_geometry(case: str | Path) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Face centres and area vectors (pointing out of the domain) of every boundary patch, from
    an ASCII ``constant/polyMesh``: patch name -> (Cf, Sf), each of shape (n, 3).

    Polygons are split into triangles about their vertex average; the centre is the area-weighted
    mean of the triangle centroids (OpenFOAM's own definition).
    """
    mesh = Path(case) / "constant" / "polyMesh"
    for f in ("points", "faces", "boundary"):
        if not (mesh / f).is_file():
            raise FoamError(f"{mesh / f}: missing (is the mesh converted?)")
    body = _foam_list_body(mesh / "points")
    start = body.find("(")
    n_pts = int(body[:start].split()[-1])
    nums = body[start + 1: body.rfind(")")].replace("(", " ").replace(")", " ").split()
    pts = np.array(nums, dtype=float).reshape(-1, 3)
    if pts.shape[0] != n_pts:
        raise FoamError(f"{mesh / 'points'}: expected {n_pts} points, read {pts.shape[0]} (binary format?)")
    btext = (mesh / "boundary").read_text()
    patches = [(m.group(1), int(m.group(3)), int(m.group(2)))
               for m in re.finditer(r"^\s{4}(\w+)\s*\n\s{4}\{[^}]*?nFaces\s+(\d+);[^}]*?startFace\s+(\d+);",
                                    btext, re.S | re.M)]
    first = min(start_face for _, start_face, _ in patches)
    body = _foam_list_body(mesh / "faces")
    start = body.find("(")
    tokens = body[start + 1:].replace("(", " ( ").replace(")", " ) ").split()
    # walk the face list: k ( a b c ... )
    faces: list[list[int]] = []
    i = 0
    index = 0
    while i < len(tokens) and tokens[i] != ")":
        k = int(tokens[i])
        if index >= first:
            faces.append([int(t) for t in tokens[i + 2: i + 2 + k]])
        index += 1
        i += k + 3
    out: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    for name, start_face, n in patches:
        cf = np.empty((n, 3))
        sf = np.empty((n, 3))
        for j in range(n):
            v = pts[faces[start_face - first + j]]
            if len(v) == 3:
                sf[j] = 0.5 * np.cross(v[1] - v[0], v[2] - v[0])
                cf[j] = v.mean(axis=0)
                continue
            c0 = v.mean(axis=0)
            tri_s = 0.5 * np.cross(v - c0, np.roll(v, -1, axis=0) - c0)
            tri_c = (v + np.roll(v, -1, axis=0) + c0) / 3.0
            s_vec = tri_s.sum(axis=0)
            n_hat = s_vec / np.linalg.norm(s_vec)
            w = tri_s @ n_hat
            sf[j] = s_vec
            cf[j] = (w[:, None] * tri_c).sum(axis=0) / w.sum()
        out[name] = (cf, sf)
    return out


def write_field_values(path: str | Path, values: np.ndarray) -> None:
    """Replace the internal field (uniform or a non-uniform list) of an ASCII field file by
    ``values``: shape (n,) for a scalar field, (n, 3) for a vector field. The boundary field is
    kept as it is."""
    path = Path(path)
    text = path.read_text()
    v = np.asarray(values, dtype=float)
    if v.ndim == 1:
        body = "\n".join(f"{x:.12g}" for x in v)
        kind = "scalar"
    else:
        body = "\n".join(f"({x:.12g} {y:.12g} {z:.12g})" for x, y, z in v)
        kind = "vector"
    new = f"internalField   nonuniform List<{kind}> {len(v)}\n(\n{body}\n)\n;"
    text, n = re.subn(r"internalField\s+(uniform\s+[^;]+;|nonuniform\s+List<\w+>\s*\d+\s*\(.*?\)\s*;)",
                      lambda m: new, text, count=1, flags=re.S)
    if n != 1:
        raise FoamError(f"{path}: expected an internalField to replace")
    tmp = path.with_suffix(".tmp")
    tmp.write_text(text)
    tmp.replace(path)


def rotation_matrix(axis: Sequence[float], angle_deg: float) -> np.ndarray:
    """Rotation matrix about ``axis`` by ``angle_deg`` (right hand), Rodrigues' formula."""
    a = np.asarray(axis, dtype=float)
    a = a / np.linalg.norm(a)
    t = math.radians(angle_deg)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(t) * k + (1 - math.cos(t)) * (k @ k)
