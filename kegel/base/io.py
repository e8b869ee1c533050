"""Result files: written atomically, with the scene, the kegel version and the fidelity."""

from __future__ import annotations

import contextlib
import json
import os
import platform
import shutil
import sys
import tempfile
from datetime import datetime, timezone
from pathlib import Path
from typing import Any, Callable

from .. import _core

__all__ = ["atomic_write_text", "atomic_write_json", "atomic_write_json_records", "atomic_save", "file_mode", "provenance", "RunFolder",
           "OutputLocked", "OutputRefused", "Terminated", "signals_interrupt", "staging_path", "temp_beside", "MANIFEST"]


def file_mode() -> int:
    """The mode a new file gets from ``open()``: 0o666 less the process's umask (mkstemp's
    temporary files are 0o600 whatever the umask; results must be readable as any file is)."""
    mask = os.umask(0o022)
    os.umask(mask)
    return 0o666 & ~mask


def temp_beside(path: str | Path, suffix: str = ".tmp") -> tuple[int, str]:
    """A hidden temporary file next to ``path`` (same folder, so the final rename is atomic),
    with the umask's mode (see :func:`file_mode`); returns the open descriptor and its name."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.stem}.", suffix=suffix, dir=path.parent)
    try:
        os.fchmod(fd, file_mode())
    except BaseException:
        os.close(fd)
        Path(tmp).unlink(missing_ok=True)
        raise
    return fd, tmp


def atomic_save(path: str | Path, write: Any, suffix: str | None = None) -> Path:
    """Write ``path`` atomically with ``write(tmp_name)`` (e.g. ``fig.savefig``, ``np.savez``):
    a temporary file beside it, then a rename; the temporary file is removed on any failure
    or interrupt, and the file gets the umask's mode."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = temp_beside(path, suffix if suffix is not None else path.suffix)
    os.close(fd)
    try:
        write(tmp)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def atomic_write_text(path: str | Path, text: str) -> Path:
    """Write ``text`` to ``path`` through a temporary file in the same folder and a rename,
    so that a reader never sees a half-written file (mode: see :func:`file_mode`)."""
    with _replacing(path) as fh:
        fh.write(text)
    return Path(path)


@contextlib.contextmanager
def _replacing(path: str | Path):
    """A text file opened beside ``path`` that replaces it, synced, when the block ends; removed
    on any failure or interrupt (the old ``path`` stays as it was)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = temp_beside(path, ".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            yield fh
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def atomic_write_json(path: str | Path, data: Any) -> Path:
    """Atomically write ``data`` as indented JSON (NaN is refused: results must be finite)."""
    return atomic_write_text(path, json.dumps(data, indent=2, allow_nan=False) + "\n")


def atomic_write_json_records(path: str | Path, header: dict[str, Any], key: str, records: Any) -> Path:
    """Atomically write ``header`` as a JSON object whose ``key`` holds the list ``records``,
    one record at a time: a 10^5-point sweep never builds its whole results text in memory
    (``json.dumps`` of it made a string of about 1 GB). Readers see the same JSON as
    :func:`atomic_write_json` would write (indented, NaN refused)."""
    sentinel = f"@@kegel-records-{os.urandom(6).hex()}@@"
    head = json.dumps({**header, key: sentinel}, indent=2, allow_nan=False)
    marker = f'"{key}": "{sentinel}"'
    cut = head.index(marker)
    with _replacing(path) as fh:
        fh.write(head[:cut] + f'"{key}": [')
        first = True
        for rec in records:
            text = json.dumps(rec, indent=2, allow_nan=False).replace("\n", "\n    ")
            fh.write(("\n    " if first else ",\n    ") + text)
            first = False
        fh.write(("\n  ]" if not first else "]") + head[cut + len(marker):] + "\n")
    return Path(path)


def provenance() -> dict[str, str]:
    """Versions and host facts written next to every result."""
    from .version import __version__

    return {
        "kegel_version": __version__,
        "core_version": _core.core_version(),
        "eigen_version": _core.eigen_version(),
        "sundials_version": _core.sundials_version(),
        "python_version": platform.python_version(),
        "created_utc": datetime.now(timezone.utc).isoformat(timespec="seconds"),
    }


class OutputLocked(RuntimeError):
    """Another live kegel run owns the output folder."""


class OutputRefused(ValueError):
    """The output folder holds what kegel did not write (or cannot be a kegel output folder).

    Attributes
    ----------
    path
        The output folder as given.
    reason
        What was found, in words (the files kegel did not write, a symlink's target, ...).
    forceable
        True when ``--force`` would let the run go ahead (the foreign files are then kept beside
        the results, or moved aside to ``kegel-replaced-<run id>/`` if kegel writes the same name).
    """

    def __init__(self, path: str | Path, reason: str, forceable: bool = True) -> None:
        self.path, self.reason, self.forceable = str(path), reason, forceable
        super().__init__(f"{path}: {reason}")


class Terminated(KeyboardInterrupt):
    """A termination signal (SIGTERM, SIGHUP) received while a run computes: raised like Ctrl-C's
    KeyboardInterrupt so that every temporary file is removed on the way out; ``signum`` is the
    signal (the ``kegel`` command exits with 128 + signum)."""

    def __init__(self, signum: int) -> None:
        import signal

        self.signum = signum
        super().__init__(signal.Signals(signum).name)


@contextlib.contextmanager
def signals_interrupt():
    """Within the block, SIGTERM and SIGHUP raise :class:`Terminated` (Python's default lets them
    end the process at once, leaving half-written temporary files); the previous handlers are
    restored afterwards. A no-op outside the main thread."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def handler(signum: int, frame: Any) -> None:
        raise Terminated(signum)

    old = {}
    for sig in (signal.SIGTERM, getattr(signal, "SIGHUP", None)):
        if sig is not None:
            old[sig] = signal.signal(sig, handler)
    try:
        yield
    finally:
        for sig, h in old.items():
            signal.signal(sig, h)


@contextlib.contextmanager
def _signals_deferred():
    """Hold SIGINT, SIGTERM and SIGHUP back while the block runs and act on the first one received
    after it: the few renames that replace the previous results are not cut in the middle by an
    interrupt (a kill or a power cut is handled by rolling the replacement forward on the next
    run). Python-level handlers, so a signal that the OS delivers to another thread is held too."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    received: list[int] = []

    def hold(signum: int, frame: Any) -> None:
        received.append(signum)

    sigs = [signal.SIGINT, signal.SIGTERM] + ([signal.SIGHUP] if hasattr(signal, "SIGHUP") else [])
    old = {sig: signal.signal(sig, hold) for sig in sigs}
    try:
        yield
    finally:
        for sig, h in old.items():
            signal.signal(sig, h)
        if received:
            sig, h = received[0], old[received[0]]
            if callable(h):
                h(sig, None)
            elif h == signal.SIG_DFL:
                os.kill(os.getpid(), sig)


MANIFEST = ".kegel-manifest.json"
_LOCK = ".kegel-run.lock"
_STAGING_IN_MOUNT = ".kegel-staging"
_MANIFEST_TMP = f".{Path(MANIFEST).stem}."  # the manifest's temporary files (see temp_beside)


def staging_path(output: str | Path) -> Path:
    """The staging folder of an output folder: ``.<name>.kegel-staging`` beside it (same parent,
    so the same filesystem and the results are moved into place by renames), or
    ``<output>/.kegel-staging`` when the output folder is a mount point (a container volume: its
    parent is another filesystem) or its parent is not writable."""
    out = Path(os.path.abspath(output))
    if out.is_dir() and not out.is_symlink() and (
            os.path.ismount(out) or (not os.access(out.parent, os.W_OK | os.X_OK) and os.access(out, os.W_OK | os.X_OK))):
        return out / _STAGING_IN_MOUNT  # a mount point, or a folder the user may write in a parent they may not
    return out.parent / f".{out.name}.kegel-staging"


def _stat_entry(path: Path) -> dict[str, int]:
    st = path.lstat()
    return {"size": st.st_size, "mtime_ns": st.st_mtime_ns}


def _read_manifest(folder: Path) -> dict[str, Any] | None:
    """A folder's kegel manifest (None without one, or an unreadable one)."""
    f = folder / MANIFEST
    try:
        data = json.loads(f.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if not isinstance(data, dict) or not isinstance(data.get("files"), dict):
        return None
    return data


def _describe_results(results: Path) -> str:
    """What a results.json that kegel's manifest does not list is (for the refusal message)."""
    try:
        data = json.loads(results.read_text(encoding="utf-8"))
    except (OSError, ValueError, UnicodeDecodeError):
        return "a results.json kegel cannot read"
    if not isinstance(data, dict):
        return "a results.json kegel did not write"
    if "loss_torque_at_shaft_Nm" in data or "kinematics" in data:
        return "the results.json of a CFD case (kegel cfd run)"
    if "run_id" in data and "scene" in data:
        return (f"a kegel run's results.json without kegel's manifest (an older kegel version, or copied: "
                f"{_previous_run(results)})")
    return "a results.json kegel did not write"


def _foreign(out: Path, manifest: dict[str, Any] | None, skip: tuple[str, ...] = ()) -> dict[str, str]:
    """The top-level entries of ``out`` that kegel's ``manifest`` does not account for, with the
    reason for each: a file it does not list, one changed since kegel wrote it (size or time), a
    symlink, a folder holding such files. kegel's own bookkeeping (manifest, lock, staging and
    trash folders) is left out, and so are the names in ``skip``."""
    listed = (manifest or {}).get("files", {})
    found: dict[str, str] = {}
    try:
        entries = sorted(os.scandir(out), key=lambda e: e.name)
    except FileNotFoundError:
        return found
    for e in entries:
        name = e.name
        if (name in (MANIFEST, _LOCK, _STAGING_IN_MOUNT, *skip) or name.startswith(".kegel-trash-")
                or name.startswith(_MANIFEST_TMP)):
            continue
        why = _foreign_reason(Path(e.path), name, listed)
        if why:
            found[name] = why
    return found


def _foreign_reason(path: Path, rel: str, listed: dict[str, Any]) -> str | None:
    if path.is_symlink():
        return f"a symlink to {os.readlink(path)}"
    if path.is_dir():
        if not any(k.startswith(rel + "/") for k in listed):
            return "a folder kegel did not write"
        for root, dirs, files in os.walk(path):
            dirs.sort()
            for f in sorted(files) + [d for d in dirs if (Path(root) / d).is_symlink()]:
                sub = Path(root) / f
                why = _foreign_reason(sub, sub.relative_to(path.parent).as_posix(), listed) if sub.is_symlink() \
                    else _file_reason(sub, sub.relative_to(path.parent).as_posix(), listed)
                if why:
                    return f"a folder holding {sub.relative_to(path.parent).as_posix()} ({why})"
        return None
    return _file_reason(path, rel, listed)


def _file_reason(path: Path, rel: str, listed: dict[str, Any]) -> str | None:
    entry = listed.get(rel)
    if not isinstance(entry, dict):
        return _describe_results(path) if rel == "results.json" else "not written by kegel"
    if entry.get("size") != path.lstat().st_size or entry.get("mtime_ns") != path.lstat().st_mtime_ns:
        return "changed since kegel wrote it"
    return None


def _scan(root: Path, skip: tuple[str, ...] = ()) -> dict[str, dict[str, int]]:
    """Every file under ``root`` (relative POSIX paths) with its size and time."""
    files = {}
    for dirpath, dirs, names in os.walk(root):
        dirs.sort()
        for n in sorted(names):
            p = Path(dirpath) / n
            rel = p.relative_to(root).as_posix()
            if rel in skip:
                continue
            files[rel] = _stat_entry(p)
    return files


def _prune_empty(folder: Path, stop: Path) -> None:
    """Remove ``folder`` and its parents up to (not including) ``stop`` while they are empty."""
    while folder != stop and stop in folder.parents:
        try:
            folder.rmdir()
        except OSError:
            return
        folder = folder.parent


class RunFolder:
    """The output folder of one ``kegel run``: results computed in a staging folder and moved into
    place when the run has finished; only files kegel's own manifest lists are ever replaced.

    - **Staging.** Everything a run writes (the stream of finished points, a dynamic run's
      ``dynamic/`` files and checkpoints, the summary files) goes into :func:`staging_path`, a
      hidden folder beside the output (same filesystem). The output folder is not touched until
      the run has finished, so the previous results survive any failure, interrupt or kill.
    - **Lock.** ``.kegel-run.lock`` in the staging folder, created exclusively (``O_EXCL``) with
      the owner's PID and run id; a lock whose process is gone is taken over. A live owner makes
      :meth:`open` raise :class:`OutputLocked` naming it.
    - **Ownership.** The output folder must be empty, missing, or hold only files listed (with
      their size and time) in its ``.kegel-manifest.json``. Anything else (the user's files, a
      CFD case's results.json, a symlink) makes :meth:`open` raise :class:`OutputRefused` naming
      it, unless ``force``: then foreign files stay where they are, and one that has a name kegel
      writes is moved to ``kegel-replaced-<run id>/`` in the output folder, never deleted.
    - **Resume.** ``points.jsonl`` in the staging folder: a header line with the run's ``key``
      (scene, fidelity, kegel version), then one JSON line per finished point. A run whose key
      matches resumes: :meth:`open` returns the finished points by index, each checked by
      ``validate`` (a bad record is refused with the file, line and reason). A staging folder of
      another key is discarded, with a notice.
    - **Finish.** :meth:`finish` removes the stream, stray temporary files and checkpoints from
      the staging folder, writes its manifest (the commit point), then moves each entry into the
      output folder (file by file with ``os.replace``; a folder of the older run is first moved to
      a hidden trash folder), removes the older run's files that the new run does not have (only
      those its manifest lists) and writes the output's manifest. A replacement cut by a kill or a
      power cut is rolled forward by the next run into the folder.
    """

    LOCK = _LOCK
    STREAM = "points.jsonl"
    MANIFEST = MANIFEST

    def __init__(self, path: str | Path, key: dict[str, Any], summary_files: tuple[str, ...] = (),
                 summary_dirs: tuple[str, ...] = (), *, force: bool = False,
                 validate: Callable[[dict[str, Any]], tuple[str, Any, str] | None] | None = None) -> None:
        self.given = Path(path)
        self.path = Path(os.path.abspath(path))
        self.key = key
        self.summary_files = summary_files  # (kept for callers; the manifest says what kegel wrote)
        self.summary_dirs = summary_dirs
        self.force = force
        self.validate = validate
        self.run_id = os.urandom(8).hex()
        self.staging = staging_path(self.path)
        self._lock_fd: int | None = None
        self._lock_path: Path | None = None
        self._stream = None
        self._finished = False
        #: the run whose results this run replaces (None: an empty folder or none of kegel's)
        self.replaced: str | None = None
        #: foreign entries found when the folder was opened (only with ``force``)
        self.foreign: dict[str, str] = {}
        #: after :meth:`finish`: the folder where foreign files with a name kegel writes were moved
        self.moved_aside: Path | None = None

    @property
    def stream_path(self) -> Path:
        """The stream of finished points (in the staging folder)."""
        return self.staging / self.STREAM

    # -- opening -----------------------------------------------------------------------------
    def open(self) -> dict[int, dict[str, Any]]:
        """Take the folder; returns the finished points of an interrupted run with the same key.

        Raises
        ------
        OutputLocked
            A live run owns the folder.
        OutputRefused
            The folder holds files kegel did not write, is a symlink (both unless ``force``), is
            a file, or holds the current directory.
        KegelInputError
            A record of the stream to resume from is bad (file, line, reason).
        OSError
            The folder cannot be created or written (read-only, full).
        """
        self._check_target()
        self.staging = staging_path(self.path)
        self.staging.mkdir(parents=True, exist_ok=True)
        self._take_lock()
        try:
            return self._open_locked()
        except BaseException:
            self.close()
            raise

    def _check_target(self) -> None:
        p = self.path
        if p.is_symlink():
            target = Path(os.path.realpath(p))
            what = ("kegel run output" if (target / MANIFEST).is_file()
                    else "CFD case" if (target / "system" / "controlDict").is_file() or (
                        (target / "results.json").is_file() and "CFD" in _describe_results(target / "results.json"))
                    else "folder")
            if not self.force:
                raise OutputRefused(self.given, f"is a symlink to {target} (a {what}); kegel writes its results only "
                                                f"into a real folder: give that folder as --output, or --force to write "
                                                f"into {target}")
            self.path = target
            p = target
        if p.exists() and not p.is_dir():
            raise OutputRefused(self.given, "is a file, not a folder", forceable=False)
        if p.parent == p:
            raise OutputRefused(self.given, "is the root folder", forceable=False)
        cwd = Path(os.getcwd())
        if cwd == p or p in cwd.parents:
            raise OutputRefused(self.given, f"holds the current directory ({cwd}); choose a folder of its own",
                                forceable=False)
        if p.is_dir():  # the results are moved in at the end: found now, with the system's reason
            fd, probe = tempfile.mkstemp(prefix=".kegel-probe.", dir=p)
            os.close(fd)
            os.unlink(probe)

    def _take_lock(self) -> None:
        # the lock of a run of an earlier kegel version (in the output folder itself)
        legacy = self.path / self.LOCK
        legacy_owner = _lock_owner(legacy) if legacy.is_file() else None
        if legacy_owner is not None and _alive(legacy_owner):
            raise OutputLocked(f"{self.path} is the output folder of a running kegel run (PID {legacy_owner}, lock "
                               f"{legacy}); choose another --output or wait for it")
        lock = self.staging / self.LOCK
        for _ in range(2):
            try:
                self._lock_fd = os.open(lock, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644)
                break
            except FileExistsError:
                owner = _lock_owner(lock)
                if owner is not None and _alive(owner):
                    raise OutputLocked(f"{self.path} is the output folder of a running kegel run (PID {owner}, "
                                       f"lock {lock}); choose another --output or wait for it") from None
                lock.unlink(missing_ok=True)  # stale: its process is gone
        else:
            raise OutputLocked(f"{self.path}: could not take the lock {lock}")
        self._lock_path = lock
        os.write(self._lock_fd, json.dumps({"pid": os.getpid(), "run_id": self.run_id}).encode())
        os.fsync(self._lock_fd)
        if legacy.is_file():  # a stale lock of a dead run in the output folder: kegel's own
            legacy.unlink(missing_ok=True)

    def _open_locked(self) -> dict[int, dict[str, Any]]:
        staged = _read_manifest(self.staging)
        if staged is not None and staged.get("state") == "complete":
            # a finished run whose replacement of the results was cut (a kill, a power cut): finish it
            print(f"kegel: completing the replacement of the results in {self.path} by the finished run "
                  f"{staged.get('run_id', '?')} (it was cut short)", file=sys.stderr)
            self._commit(staged)
        old = _read_manifest(self.path)
        if self.path.is_dir() and (self.path / MANIFEST).exists() and old is None:
            raise OutputRefused(self.given, f"its kegel manifest {self.path / MANIFEST} cannot be read")
        foreign = _foreign(self.path, old)
        if foreign:
            listing = "; ".join(f"{k} ({v})" for k, v in list(foreign.items())[:6])
            more = f"; and {len(foreign) - 6} more" if len(foreign) > 6 else ""
            if not self.force:
                raise OutputRefused(self.given, f"holds files kegel did not write: {listing}{more}. kegel writes only "
                                                f"into a new or empty folder or one it wrote ({MANIFEST}); choose "
                                                "another --output, or --force to write beside them (a file with a "
                                                "name kegel writes is then moved to kegel-replaced-<run id>/, "
                                                "never deleted)")
            self.foreign = foreign
            print(f"kegel: --force: {self.path} holds files kegel did not write ({listing}{more}); they are kept",
                  file=sys.stderr)
        if old is not None and (self.path / "results.json").is_file() and "results.json" not in foreign:
            self.replaced = _previous_run(self.path / "results.json")
        done = self._resume()
        if done is None:  # no interrupted run of this key: a new run
            self._clear_staging()
            if self.replaced:
                # an explicit policy, never a silent overwrite: say whose results are replaced
                print(f"kegel: {self.path} holds the results of another run ({self.replaced}): they are replaced "
                      "when this run has finished (choose another --output to keep them)", file=sys.stderr)
            self._stream = open(self.stream_path, "w", encoding="utf-8")
            self._write_line({"kegel_run": self.key, "run_id": self.run_id})
            return {}
        # an interrupted run of this key (perhaps before its first point finished: its dynamic
        # checkpoint is kept): resume, after the last whole line (a line cut by the interrupt
        # would otherwise swallow the next point's); summary files it may have written are
        # written again at the end
        for e in os.scandir(self.staging):
            if e.name not in (self.STREAM, self.LOCK) and (e.is_file(follow_symlinks=False) or e.is_symlink()):
                os.unlink(e.path)
        with open(self.stream_path, "rb+") as fh:
            text = fh.read()
            fh.truncate(text.rfind(b"\n") + 1)
        self._stream = open(self.stream_path, "a", encoding="utf-8")
        return done

    def _resume(self) -> dict[int, dict[str, Any]] | None:
        """The finished points of an interrupted run of this key in the staging folder (None: no
        such run). Every record is checked; a bad one raises KegelInputError with its line."""
        from .errors import KegelInputError

        stream = self.stream_path
        if not stream.is_file():
            return None
        try:
            raw = stream.read_bytes()
            lines = raw.decode("utf-8").split("\n")
        except (OSError, UnicodeDecodeError):
            return None
        try:
            header = json.loads(lines[0]) if lines and raw.find(b"\n") >= 0 else {}
        except json.JSONDecodeError:
            header = {}
        if not isinstance(header, dict) or header.get("kegel_run") != json.loads(json.dumps(self.key)):
            n = max(0, sum(1 for x in lines[1:] if x.strip()))
            print(f"kegel: {self.staging} holds {n} finished point(s) of an interrupted run of another scene, fidelity "
                  "or kegel version: discarded, this run starts afresh", file=sys.stderr)
            return None
        done: dict[int, dict[str, Any]] = {}
        last = len(lines) - 1  # the text after the last newline: a line cut by the interrupt (or "")
        for n, line in enumerate(lines[1:last], start=2):

            def bad(key: str, value: Any, expected: str) -> KegelInputError:
                return KegelInputError(stream, key, value, f"{expected} (a record of the interrupted run kegel "
                                                           f"resumes; delete {self.staging} to start afresh)", line=n)

            try:
                rec = json.loads(line)
            except json.JSONDecodeError as exc:
                raise bad("", line[:60], f"a JSON line ({exc.msg})") from None
            if not isinstance(rec, dict) or not isinstance(rec.get("point"), dict):
                raise bad("point", line[:60], 'a line {"point": {...}}')
            p = rec["point"]
            idx = p.get("index")
            if not isinstance(idx, int) or isinstance(idx, bool):
                raise bad("point.index", idx, "an operating point index (an integer)")
            if idx in done:
                raise bad("point.index", idx, "each point once (this index is on an earlier line too)")
            if self.validate is not None:
                problem = self.validate(p)
                if problem is not None:
                    key, value, expected = problem
                    raise bad(f"point.{key}", value, expected)
            done[idx] = p
        return done

    def _clear_staging(self) -> None:
        """Remove what an earlier run of another key left in the staging folder: only what kegel
        writes there (the stream, summary files, dynamic/, temporary files)."""
        for e in sorted(os.scandir(self.staging), key=lambda e: e.name):
            if e.name == self.LOCK:
                continue
            if e.name == "dynamic" and e.is_dir(follow_symlinks=False):
                shutil.rmtree(e.path)
            elif e.is_file(follow_symlinks=False) or e.is_symlink():
                os.unlink(e.path)
            else:
                raise OutputRefused(self.staging, f"kegel's staging folder holds a folder kegel did not write: {e.name}",
                                    forceable=False)

    # -- running -----------------------------------------------------------------------------
    def _write_line(self, obj: dict[str, Any]) -> None:
        try:
            self._stream.write(json.dumps(obj, allow_nan=False) + "\n")
            self._stream.flush()
            os.fsync(self._stream.fileno())
        except OSError as exc:
            if exc.filename is None:
                exc.filename = str(self.stream_path)
            raise

    def add(self, point: dict[str, Any]) -> None:
        """Stream one finished point."""
        self._write_line({"point": point})

    def final(self, obj: Any) -> Any:
        """``obj`` (a path, or a record holding paths) with every path into the staging folder
        replaced by the same path in the output folder, where it is once the run has finished."""
        if isinstance(obj, dict):
            return {k: self.final(v) for k, v in obj.items()}
        if isinstance(obj, list):
            return [self.final(v) for v in obj]
        if isinstance(obj, (str, Path)):
            s, prefix = str(obj), str(self.staging) + os.sep
            if s.startswith(prefix):
                return type(obj)(str(self.path / s[len(prefix):]))
        return obj

    # -- finishing ---------------------------------------------------------------------------
    def finish(self) -> None:
        """The summary files are written in the staging folder: remove the stream, temporary
        files and checkpoints there, write its manifest and move the results into the output
        folder (see the class docstring). Interrupts are held back until it is done."""
        if self._stream is not None:
            self._stream.close()
            self._stream = None
        self.stream_path.unlink(missing_ok=True)
        _sweep(self.staging, keep=(self.LOCK,), checkpoints=True)
        manifest = {"kegel_manifest": 1, "run_id": self.run_id, "state": "complete",
                    "created_utc": datetime.now(timezone.utc).isoformat(timespec="seconds"),
                    "files": _scan(self.staging, skip=(self.LOCK, MANIFEST))}
        with _signals_deferred():
            atomic_write_json(self.staging / MANIFEST, manifest)  # the commit point
            self._commit(manifest)
            self._finished = True

    def _commit(self, new: dict[str, Any]) -> None:
        """Move the staged results listed in ``new`` into the output folder (idempotent: a second
        call after a cut one finishes the job)."""
        out, stage = self.path, self.staging
        out.mkdir(parents=True, exist_ok=True)
        old = _read_manifest(out) or {"files": {}}
        new_files: dict[str, Any] = new["files"]
        new_top = sorted({rel.split("/")[0] for rel in new_files})
        trash = out / f".kegel-trash-{new.get('run_id', self.run_id)}"
        aside = out / f"kegel-replaced-{new.get('run_id', self.run_id)}"
        foreign = _foreign(out, old, skip=(aside.name,))
        for name in new_top:
            src, dst = stage / name, out / name
            if not os.path.lexists(src):
                continue  # moved by the cut replacement this call finishes
            if os.path.lexists(dst):
                if name in foreign:  # only with --force (or put there while this run computed)
                    aside.mkdir(exist_ok=True)
                    os.replace(dst, aside / name)
                    self.moved_aside = aside
                elif dst.is_dir() and not dst.is_symlink():
                    trash.mkdir(exist_ok=True)
                    os.replace(dst, trash / name)
            os.replace(src, dst)
        # the older run's files that this run does not have (only those its manifest lists)
        for rel in old["files"]:
            top = rel.split("/")[0]
            if top in new_files or top in new_top or top in foreign:
                continue
            f = out / rel
            if f.is_file() and not f.is_symlink() and _file_reason(f, rel, old["files"]) is None:
                f.unlink()
                _prune_empty(f.parent, out)
        if trash.is_dir():  # folders of the older run, moved out of the way: its listed files
            for rel in old["files"]:
                f = trash / rel
                if f.is_file() and not f.is_symlink():
                    f.unlink()
                    _prune_empty(f.parent, out)
            if trash.exists():  # something the manifest does not list: kept, moved aside
                aside.mkdir(exist_ok=True)
                for e in os.listdir(trash):
                    os.replace(trash / e, aside / e)
                trash.rmdir()
                self.moved_aside = aside
        atomic_write_json(out / MANIFEST, {**new, "state": "written"})
        for e in os.listdir(out):
            if e.startswith(_MANIFEST_TMP):  # left by a kill while the manifest was written
                (out / e).unlink(missing_ok=True)
        (stage / MANIFEST).unlink(missing_ok=True)
        if self.moved_aside is not None:
            print(f"kegel: files kegel did not write that had the names of its results were moved to "
                  f"{self.moved_aside} (nothing was deleted)", file=sys.stderr)

    def kept(self) -> str:
        """What an unfinished run leaves, in words: the output folder unchanged, the finished
        points in the staging folder for a resume."""
        n = 0
        try:
            with open(self.stream_path, encoding="utf-8") as fh:
                n = max(0, sum(1 for line in fh if line.endswith("\n")) - 1)
        except OSError:
            pass
        if self._finished:
            return f"the results are complete in {self.path}"
        before = f"the results in {self.path} are as they were" if self.path.is_dir() else f"{self.path} was not created"
        dyn = " and the dynamic checkpoints" if (self.staging / "dynamic").is_dir() else ""
        return (f"{before}; {n} finished point(s){dyn} kept in {self.staging}: rerun the same command to resume")

    def close(self) -> None:
        """Release the folder: close the stream (a full disk may refuse its last buffered line:
        that line is dropped, as a line cut by an interrupt is on resume), remove temporary files
        from the staging folder, remove the lock, and the staging folder once it is empty."""
        if self._stream is not None:
            stream, self._stream = self._stream, None
            try:
                stream.close()
            except OSError:
                pass
        if self._lock_fd is not None:
            os.close(self._lock_fd)
            self._lock_fd = None
            try:
                _sweep(self.staging, keep=(self.LOCK, MANIFEST))
            except OSError:
                pass
            if self._lock_path is not None:
                self._lock_path.unlink(missing_ok=True)
            try:
                self.staging.rmdir()  # empty once the results have moved (or nothing was done)
            except OSError:
                pass

    def __enter__(self) -> "RunFolder":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()


def _sweep(folder: Path, keep: tuple[str, ...] = (), checkpoints: bool = False) -> None:
    """Remove temporary files (hidden files: kegel's writes go through ``.<name>.*`` temporary
    files) and, with ``checkpoints``, dynamic checkpoints from a staging folder, whose every file
    kegel wrote."""
    if not folder.is_dir():
        return
    for dirpath, _, names in os.walk(folder):
        for n in names:
            p = Path(dirpath) / n
            if p.parent == folder and n in keep:
                continue
            if n.startswith(".") or (checkpoints and n == "checkpoint.npz" and p.parent.parent.name == "dynamic"):
                p.unlink(missing_ok=True)


def _previous_run(results: Path) -> str | None:
    """A short description of the run whose ``results.json`` is in a folder (None without one)."""
    if not results.is_file():
        return None
    try:
        data = json.loads(results.read_text())
        scene = data.get("scene") or {}
        title = scene.get("title") or scene.get("name") or "?"
        created = (data.get("provenance") or {}).get("created_utc", "?")
        return f"scene '{title}', run id {data.get('run_id') or '?'}, created {created}"
    except (OSError, ValueError, AttributeError):
        return "an unreadable results.json"


def _lock_owner(lock: Path) -> int | None:
    try:
        return int(json.loads(lock.read_text() or "{}").get("pid"))
    except (OSError, ValueError, TypeError):
        return None


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True
