"""Atomic file writes: a file on disk is either its old self or wholly the new one.

Every saved session, checkpoint, recording, keyframe and picture goes through here, so a
crash, a full disk or a bad path mid-save never loses what was saved before. It lives in
protocols/ because every layer (apps, emulator, the command line) may import protocols.

Only a regular file (or a new name) is replaced by renaming a temporary file over it. A
path that names a character device or a FIFO (``--out /dev/stdout``, a named pipe) is
written *into*, never replaced; a symbolic link is followed and its target written (the
link stays). A directory is refused. Every error names the user's path, never the
temporary file (``p.kas: No space left on device``, not ``.p.kas.3802.x1y2.tmp: ...``).
"""

from __future__ import annotations

import contextlib
import errno
import os
import stat
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import IO


def _shared_mode() -> int:
    # mkstemp makes files 0600; a saved file should get the ordinary mode the umask gives
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # someone else's process: alive
        return True
    return True


def output_target(path: str | os.PathLike[str]) -> tuple[Path, bool]:
    """The file to write for ``path`` (a symlink's target) and whether it is written into
    in place (a device or FIFO) rather than replaced; a directory raises IsADirectoryError."""
    target = Path(path)
    if target.is_symlink():
        target = Path(os.path.realpath(target))
    try:
        mode = os.stat(target).st_mode
    except OSError:
        return target, False  # a new file (a bad directory is reported when writing)
    if stat.S_ISDIR(mode):
        raise IsADirectoryError(errno.EISDIR, os.strerror(errno.EISDIR), os.fspath(path))
    return target, not stat.S_ISREG(mode)


@contextmanager
def naming_user_path(path: str | os.PathLike[str], tmp: str | None = None) -> Iterator[None]:
    """An OSError about the temporary file (or about no file: a write on a full disk)
    re-raised naming ``path``, the name the user gave."""
    try:
        yield
    except OSError as exc:
        if exc.filename is not None and (tmp is None or exc.filename != tmp):
            raise
        raise type(exc)(exc.errno, exc.strerror or str(exc), os.fspath(path)) from None


def place_fault(target: Path) -> str | None:
    """Why no file can be made at ``target``'s place (docs/exit_status.md, the one output
    rule): a file in the way of its directory, named as such, or a directory that does not
    exist (never created for an output); None when its directory is there."""
    for parent in reversed(target.parents):
        if parent.exists() and not parent.is_dir():
            return f"{parent} is a file in the way, not a directory"
    parent = target.parent if str(target.parent) else Path(".")
    return None if parent.is_dir() else f"no such directory {parent}"


def temp_beside(target: Path, suffix: str = "") -> tuple[int, str]:
    """A new temporary file beside ``target``, named ``.<name>.<pid>.<random>.tmp<suffix>``
    so that ``sweep_stale`` removes it if this writer is killed; errors name ``target``."""
    import tempfile  # here, not at the top: a program that only reads (``ca run``) is spared

    sweep_stale(target)
    with naming_user_path(target):
        try:
            return tempfile.mkstemp(prefix=f".{target.name}.{os.getpid()}.",
                                    suffix=f".tmp{suffix}", dir=str(target.parent) or ".")
        except OSError as exc:  # mkstemp names its random file: name the user's
            why = place_fault(target) if exc.errno in (errno.ENOENT, errno.ENOTDIR) else None
            raise type(exc)(exc.errno, why or exc.strerror, None) from None


def commit(tmp: str | os.PathLike[str], target: Path, sync_dir: bool = True) -> None:
    """Make the fsynced temporary ``tmp`` the file ``target`` (mode as the umask gives)."""
    with naming_user_path(target, os.fspath(tmp)):
        os.chmod(tmp, _shared_mode())
        os.replace(tmp, target)
    if sync_dir:
        fsync_dir(target.parent)


def probe(path: str | os.PathLike[str]) -> None:
    """Check now, before a long run, that ``path`` can be written: a block written and
    synced to a temporary file beside it (then removed) fails on a full disk, a read-only
    mount or a directory in the way; the OSError names ``path``."""
    target, into = output_target(path)
    if into:
        return
    fd, tmp = temp_beside(target)
    try:
        with naming_user_path(path, tmp):
            os.write(fd, bytes(4096))
            os.fsync(fd)
    finally:
        os.close(fd)
        Path(tmp).unlink(missing_ok=True)


def sweep_stale(target: Path) -> list[Path]:
    """Remove temporary files left beside ``target`` by writers that were killed (SIGKILL
    gives no chance to clean up): their names carry the writer's pid, and a temporary file
    whose writer is gone can never be renamed into place. Returns what was removed."""
    gone = []
    prefix = f".{target.name}."
    try:
        names = os.listdir(target.parent if str(target.parent) else ".")
    except OSError:
        return gone
    for name in names:
        if not (name.startswith(prefix) and ".tmp" in name[len(prefix):]):
            continue
        pid = name[len(prefix):].split(".", 1)[0]
        if pid.isascii() and pid.isdigit() and int(pid) != os.getpid() and not _alive(int(pid)):
            stale = target.parent / name
            with contextlib.suppress(OSError):
                stale.unlink()
                gone.append(stale)
    return gone


def fsync_dir(folder: Path) -> None:
    """Make a rename in ``folder`` durable (the new name survives a power cut)."""
    try:
        fd = os.open(str(folder) or ".", os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass  # some filesystems refuse fsync on a directory; the rename still happened
    finally:
        os.close(fd)


# How long a write waits for a FIFO's reader (a named pipe nobody reads blocked for ever):
# CAMLAB88_FIFO_WAIT seconds, default 10
FIFO_WAIT = 10.0
_POLL = 0.05


def fifo_wait() -> float:
    text = os.environ.get("CAMLAB88_FIFO_WAIT", "")
    try:
        wait = float(text) if text else FIFO_WAIT
    except ValueError:
        return FIFO_WAIT
    return wait if 0 <= wait <= 86400 else FIFO_WAIT


def open_into(target: Path, path: str | os.PathLike[str], mode: str = "wb",
              encoding: str | None = None, newline: str | None = None) -> IO:
    """``target`` (a device or FIFO) opened for writing in place. A FIFO is opened only
    once a reader has it open, waited for at most ``fifo_wait()`` seconds; then
    ``OSError(ENXIO, 'no reader opened this FIFO in N s', path)`` — one line, not a hang."""
    if not stat.S_ISFIFO(os.stat(target).st_mode):
        return open(target, mode, encoding=encoding, newline=newline)
    import time

    wait = fifo_wait()
    deadline = time.monotonic() + wait
    while True:
        try:
            fd = os.open(target, os.O_WRONLY | os.O_NONBLOCK)
            break
        except OSError as exc:
            if exc.errno != errno.ENXIO:  # ENXIO: no reader yet
                raise
            if time.monotonic() >= deadline:
                raise OSError(errno.ENXIO, f"no reader opened this FIFO in {wait:g} s "
                              "(CAMLAB88_FIFO_WAIT)", os.fspath(path)) from None
            time.sleep(_POLL)
    os.set_blocking(fd, True)  # a reader is there: writes wait for it as a pipe's do
    return os.fdopen(fd, mode, encoding=encoding, newline=newline)


@contextmanager
def atomic_output(path: str | os.PathLike[str], mode: str = "wb",
                  encoding: str | None = None, newline: str | None = None) -> Iterator[IO]:
    """Open a temporary file beside ``path`` for writing; on success fsync it and rename it
    over ``path``; on any error remove it and leave ``path`` untouched. The temporary name
    is ``.<name>.<pid>.<random>.tmp``, so a later write sweeps up one a killed writer left."""
    target, into = output_target(path)
    if into:  # a device or FIFO: written into, in place
        with naming_user_path(path), open_into(target, path, mode, encoding, newline) as fh:
            yield fh
        return
    fd, tmp = temp_beside(target)
    try:
        with naming_user_path(path, tmp), os.fdopen(fd, mode, encoding=encoding,
                                              newline=newline) as fh:
            yield fh
            fh.flush()
            os.fsync(fh.fileno())
        commit(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def write_atomic(path: str | os.PathLike[str], data: bytes | str,
                 encoding: str = "utf-8") -> None:
    """Write ``data`` (text is encoded) so that ``path`` is the old file or the whole new one."""
    raw = data.encode(encoding) if isinstance(data, str) else data
    with atomic_output(path, "wb") as fh:
        fh.write(raw)


@contextmanager
def atomic_path(path: str | os.PathLike[str]) -> Iterator[Path]:
    """For writers that need a file name (ffmpeg, imageio): a temporary path beside ``path``
    with the same suffix; when the block ends it is fsynced and renamed over ``path``, on
    any error removed. Killed writers' leftovers are swept as in ``atomic_output``."""
    target, into = output_target(path)
    if into:  # a device or FIFO: the writer opens it by name and writes into it (a FIFO
        # once a reader is there: held open meanwhile, so the writer's open does not wait)
        with naming_user_path(path), open_into(target, path):
            yield target
        return
    fd, tmp = temp_beside(target, target.suffix)
    os.close(fd)
    try:
        with naming_user_path(path, tmp):
            yield Path(tmp)
            with open(tmp, "rb+") as fh:
                os.fsync(fh.fileno())
        commit(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


class AtomicBatch:
    """Several files that appear together: ``add`` stages each in a temporary file beside
    its target (written and fsynced at once, so memory stays flat); leaving the ``with``
    block renames them all into place, one after another, only when every one was written.
    An error or a kill before then leaves every old file as it was (a kill leaves staged
    temporaries that the next write sweeps up). Used for a PNG sequence. A device or FIFO
    among the paths is written into at once (it has no old content to keep)."""

    def __init__(self) -> None:
        self.staged: list[tuple[Path, Path]] = []

    def add(self, path: str | os.PathLike[str], data: bytes) -> None:
        target, into = output_target(path)
        if into:
            with naming_user_path(path), open_into(target, path) as fh:
                fh.write(data)
            return
        fd, tmp = temp_beside(target)
        self.staged.append((Path(tmp), target))
        with naming_user_path(path, tmp), os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())

    def __enter__(self) -> AtomicBatch:
        return self

    def __exit__(self, kind: object, exc: object, tb: object) -> None:
        if kind is not None:
            for tmp, _ in self.staged:
                tmp.unlink(missing_ok=True)
            return
        for tmp, target in self.staged:  # back to back: the directories synced after
            commit(tmp, target, sync_dir=False)
        for folder in {target.parent for _, target in self.staged}:
            fsync_dir(folder)
