"""A Sigma stream file: raw host-to-terminal bytes, or a link recording (by its first line)."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any


class StreamFileError(ValueError):
    """An unreadable stream file or a bad recording, naming the file (and line)."""


def read_stream_file(path: str | os.PathLike[str]) -> Any:
    """The raw bytes, or a protocols.link Recording if the file is one."""
    from protocols.link import recording

    try:
        data = Path(path).read_bytes()
    except OSError as exc:
        raise StreamFileError(f"cannot read {path}: {exc.strerror or exc}") from None
    if data.startswith(recording.MAGIC.encode("ascii")):
        try:
            return recording.read_recording(path)
        except ValueError as exc:
            raise StreamFileError(str(exc)) from None
    return data


def host_bytes(got: Any) -> bytes:
    """Host-to-terminal bytes of what read_stream_file gave."""
    return got if isinstance(got, bytes) else got.stream(">")
