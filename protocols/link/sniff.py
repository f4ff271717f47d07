"""What a file given to the Sigma tools is: a link recording or a raw byte stream.

A recording is recognised by its first line. A file that is not one but looks like one — a
byte-order mark before the magic word, or a damaged first line above lines in the
recording's own syntax — is refused with a message, because taking it as raw Sigma bytes
would draw a different picture and exit 0.
"""

from __future__ import annotations

import os
import re
from fractions import Fraction
from pathlib import Path

from camlab88.base.textinput import read_bytes
from camlab88.protocols.link.recording import MAGIC, Recording, RecordingError, read_recording

# lines only a recording has: its header keys and "<time> <dir> <hex>" chunks
_RECORDING_LINE = re.compile(
    rb"(?:line [0-9]+ [5-8][NEOMS][12]|xonxoff (?:on|off)|end [0-9]+"
    rb"|[0-9]+(?:\.[0-9]+|/[0-9]+)? [<>] (?:[0-9a-fA-F]{2})+)\r?"
)
SNIFF_LINES = 8
# a render writes one PNG per frame period: more than this is refused unless asked for
MAX_RENDER_FRAMES = 100_000


def looks_like_recording(data: bytes) -> bool:
    """True when some of the first lines after the first are in a recording's syntax."""
    lines = data[:65536].split(b"\n")[1 : 1 + SNIFF_LINES]
    return any(_RECORDING_LINE.fullmatch(line.strip()) for line in lines)


def read_link_input(path: str | os.PathLike[str]) -> Recording | bytes:
    """A link recording (by its first line) or the file's raw bytes. A directory, an
    unreadable file, a bad recording, or a raw file that looks like a damaged recording
    raises RecordingError naming the file (and line)."""
    p = Path(path)
    data = read_bytes(p, error=RecordingError)
    if data.startswith(MAGIC.encode("ascii")):
        return read_recording(p)
    if data.startswith(b"\xef\xbb\xbf" + MAGIC.encode("ascii")):
        raise RecordingError(f"{p}:1:1: a link recording with a UTF-8 byte-order mark before "
                             f"'{MAGIC}'; save it without one")
    if looks_like_recording(data):
        raise RecordingError(f"{p}:1: looks like a link recording whose first line is damaged "
                             f"(expected '{MAGIC} 1'); not drawing it as raw Sigma bytes")
    return data


def frame_count(duration: Fraction, fps: int, limit: int | None = MAX_RENDER_FRAMES,
                name: str = "<input>") -> int:
    """Frame periods of 1/fps s needed to cover ``duration`` s; more than ``limit`` (None:
    no limit) raises ValueError saying how many, so a damaged time never means hours of PNGs."""
    n = int(duration * fps) + 1
    if limit is not None and n > limit:
        raise ValueError(f"{name}: {float(duration):.6g} s of line time at {fps} frames/s is "
                         f"{n} frames, more than {limit}; give a lower --fps or allow more")
    return n
