"""Atomic file writes: a file on disk is either its old self or wholly the new one.

Every saved session, checkpoint, recording, keyframe and picture goes through here, so a
crash, a full disk or a bad path mid-save never loses what was saved before. It lives in
protocols/ because every layer (apps, emulator, the command line) may import protocols.
"""

from __future__ import annotations

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


@contextmanager
def atomic_output(path: str | os.PathLike[str], mode: str = "wb",
                  encoding: str | None = None, newline: str | None = None) -> Iterator[IO]:
    """Open a temporary file beside ``path`` for writing; on success fsync it and rename it
    over ``path``; on any error remove it and leave ``path`` untouched."""
    target = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp",
                               dir=str(target.parent) or ".")
    try:
        with os.fdopen(fd, mode, encoding=encoding, newline=newline) as fh:
            yield fh
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, _shared_mode())
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def write_atomic(path: str | os.PathLike[str], data: bytes | str,
                 encoding: str = "utf-8") -> None:
    """Write ``data`` (text is encoded) so that ``path`` is the old file or the whole new one."""
    raw = data.encode(encoding) if isinstance(data, str) else data
    with atomic_output(path, "wb") as fh:
        fh.write(raw)
