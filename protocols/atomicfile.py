"""Atomic file writes: a file on disk is either its old self or wholly the new one.

Every saved session, checkpoint, recording, keyframe and picture goes through here, so a
crash, a full disk or a bad path mid-save never loses what was saved before. It lives in
protocols/ because every layer (apps, emulator, the command line) may import protocols.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
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


@contextmanager
def atomic_output(path: str | os.PathLike[str], mode: str = "wb",
                  encoding: str | None = None, newline: str | None = None) -> Iterator[IO]:
    """Open a temporary file beside ``path`` for writing; on success fsync it and rename it
    over ``path``; on any error remove it and leave ``path`` untouched. The temporary name
    is ``.<name>.<pid>.<random>.tmp``, so a later write sweeps up one a killed writer left."""
    target = Path(path)
    sweep_stale(target)
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.{os.getpid()}.", suffix=".tmp",
                               dir=str(target.parent) or ".")
    try:
        with os.fdopen(fd, mode, encoding=encoding, newline=newline) as fh:
            yield fh
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, _shared_mode())
        os.replace(tmp, target)
        fsync_dir(target.parent)
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
    target = Path(path)
    sweep_stale(target)
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.{os.getpid()}.",
                               suffix=f".tmp{target.suffix}", dir=str(target.parent) or ".")
    os.close(fd)
    try:
        yield Path(tmp)
        with open(tmp, "rb+") as fh:
            os.fsync(fh.fileno())
        os.chmod(tmp, _shared_mode())
        os.replace(tmp, target)
        fsync_dir(target.parent)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


class AtomicBatch:
    """Several files that appear together: ``add`` stages each in a temporary file beside
    its target (written and fsynced at once, so memory stays flat); leaving the ``with``
    block renames them all into place, one after another, only when every one was written.
    An error or a kill before then leaves every old file as it was (a kill leaves staged
    temporaries that the next write sweeps up). Used for a PNG sequence."""

    def __init__(self) -> None:
        self.staged: list[tuple[Path, Path]] = []

    def add(self, path: str | os.PathLike[str], data: bytes) -> None:
        target = Path(path)
        sweep_stale(target)
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.{os.getpid()}.", suffix=".tmp",
                                   dir=str(target.parent) or ".")
        self.staged.append((Path(tmp), target))
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, _shared_mode())

    def __enter__(self) -> AtomicBatch:
        return self

    def __exit__(self, kind: object, exc: object, tb: object) -> None:
        if kind is not None:
            for tmp, _ in self.staged:
                tmp.unlink(missing_ok=True)
            return
        for tmp, target in self.staged:
            os.replace(tmp, target)
        for folder in {target.parent for _, target in self.staged}:
            fsync_dir(folder)
