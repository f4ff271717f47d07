"""A Sigma stream file: raw host-to-terminal bytes, or a link recording (by its first line)."""

from __future__ import annotations

import os
from typing import Any


class StreamFileError(ValueError):
    """An unreadable stream file or a bad recording, naming the file (and line)."""


def read_stream_file(path: str | os.PathLike[str]) -> Any:
    """The raw bytes, or a protocols.link Recording if the file is one. A directory, an
    unreadable file, a bad recording, a recording behind a byte-order mark or one whose first
    line is damaged raises StreamFileError naming the file (never drawn as raw bytes)."""
    from camlab88.protocols.link.recording import RecordingError
    from camlab88.protocols.link.sniff import read_link_input

    try:
        return read_link_input(path)
    except RecordingError as exc:
        raise StreamFileError(str(exc)) from None


def host_bytes(got: Any) -> bytes:
    """Host-to-terminal bytes of what read_stream_file gave."""
    return got if isinstance(got, bytes) else got.stream(">")
