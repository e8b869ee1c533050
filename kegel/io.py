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
from typing import Any

from . import _core

__all__ = ["atomic_write_text", "atomic_write_json", "atomic_write_json_records", "atomic_save", "file_mode", "provenance", "RunFolder",
           "OutputLocked", "temp_beside"]


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
    from . import __version__

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


class RunFolder:
    """The output folder of one ``kegel run``: owned through a lock file, with each finished
    operating point streamed to ``points.jsonl`` so that an interrupted run resumes.

    - Lock: ``.kegel-run.lock`` created exclusively (``O_EXCL``) with the owner's PID and run
      id; a lock whose process is gone is taken over. A live owner makes :meth:`open` raise
      :class:`OutputLocked` naming it.
    - Stream: ``points.jsonl``, one JSON line per finished point after a header line with the
      run's ``key`` (scene, fidelity, kegel version). A run whose key matches the header resumes:
      :meth:`open` returns the finished points by index and the run skips them. Another key
      starts afresh: the previous run's summary files (results.json, results.csv, plots) are
      removed first, so no file of an older run stays beside the new ones.
    - :meth:`finish` removes the stream once the summary files are written; :meth:`close` the
      lock (always, also on an error or an interrupt).
    """

    LOCK = ".kegel-run.lock"
    STREAM = "points.jsonl"

    def __init__(self, path: str | Path, key: dict[str, Any], summary_files: tuple[str, ...],
                 summary_dirs: tuple[str, ...] = ()) -> None:
        self.path = Path(path)
        self.key = key
        self.summary_files = summary_files
        self.summary_dirs = summary_dirs  # folders of per-point files (a dynamic run's dynamic/)
        self.run_id = os.urandom(8).hex()
        self._lock_fd: int | None = None
        self._stream = None
        #: the run whose results this run replaces (None: an empty folder or a resumed run)
        self.replaced: str | None = None

    def open(self) -> dict[int, dict[str, Any]]:
        """Take the folder; returns the finished points of an interrupted run with the same key.

        Raises
        ------
        OutputLocked
            A live run owns the folder.
        OSError
            The folder cannot be created or written (a file, read-only, full).
        """
        self.path.mkdir(parents=True, exist_ok=True)
        lock = self.path / self.LOCK
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
        os.write(self._lock_fd, json.dumps({"pid": os.getpid(), "run_id": self.run_id}).encode())
        os.fsync(self._lock_fd)
        stream = self.path / self.STREAM
        done = _read_stream(stream, self.key) if stream.is_file() else None
        if done is None:  # no interrupted run of this key: a new run
            self.replaced = _previous_run(self.path / "results.json")
            if self.replaced:
                # an explicit policy, never a silent overwrite: say whose results are replaced
                print(f"kegel: {self.path} holds the results of another run ({self.replaced}): they are replaced "
                      "(choose another --output to keep them)", file=sys.stderr)
            for name in (*self.summary_files, self.STREAM):
                (self.path / name).unlink(missing_ok=True)
            for name in self.summary_dirs:
                if (self.path / name).is_dir() and not (self.path / name).is_symlink():
                    shutil.rmtree(self.path / name)
            for pattern in (".*.tmp", ".*.png"):  # temporary files of an interrupted write
                for tmp in self.path.glob(pattern):
                    tmp.unlink(missing_ok=True)
            self._stream = open(stream, "w", encoding="utf-8")
            self._write_line({"kegel_run": self.key, "run_id": self.run_id})
            return {}
        # an interrupted run of this key (perhaps before its first point finished: its dynamic
        # checkpoint is kept): resume, after the last whole line (a line cut by the interrupt
        # would otherwise swallow the next point's)
        with open(stream, "rb+") as fh:
            text = fh.read()
            fh.truncate(text.rfind(b"\n") + 1)
        self._stream = open(stream, "a", encoding="utf-8")
        return done

    def _write_line(self, obj: dict[str, Any]) -> None:
        try:
            self._stream.write(json.dumps(obj, allow_nan=False) + "\n")
            self._stream.flush()
            os.fsync(self._stream.fileno())
        except OSError as exc:
            if exc.filename is None:
                exc.filename = str(self.path / self.STREAM)
            raise

    def add(self, point: dict[str, Any]) -> None:
        """Stream one finished point."""
        self._write_line({"point": point})

    def finish(self) -> None:
        """The summary files are written: the stream is no longer needed."""
        if self._stream is not None:
            self._stream.close()
            self._stream = None
        (self.path / self.STREAM).unlink(missing_ok=True)

    def close(self) -> None:
        """Release the folder: close the stream (a full disk may refuse its last buffered line:
        that line is dropped, as a line cut by an interrupt is on resume) and remove the lock."""
        if self._stream is not None:
            stream, self._stream = self._stream, None
            try:
                stream.close()
            except OSError:
                pass
        if self._lock_fd is not None:
            os.close(self._lock_fd)
            self._lock_fd = None
            (self.path / self.LOCK).unlink(missing_ok=True)

    def __enter__(self) -> "RunFolder":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()


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


def _read_stream(stream: Path, key: dict[str, Any]) -> dict[int, dict[str, Any]] | None:
    """Finished points of a stream written with the same key (an unreadable last line, cut by
    an interrupt, is dropped; empty when none finished); None for another key or an unreadable
    header."""
    done: dict[int, dict[str, Any]] = {}
    try:
        lines = stream.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError):
        return None
    try:
        header = json.loads(lines[0]) if lines else {}
    except json.JSONDecodeError:
        return None
    if header.get("kegel_run") != json.loads(json.dumps(key)):
        return None
    for line in lines[1:]:
        try:
            p = json.loads(line)["point"]
            done[int(p["index"])] = p
        except (json.JSONDecodeError, KeyError, TypeError, ValueError):
            continue
    return done
