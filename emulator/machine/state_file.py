"""The whole-machine state file: a magic line, a JSON header (format version, device, each
component's JSON state) and the binary parts some components give (named, length-prefixed,
each deflated).

Reading is bounded before anything is allocated (a state is data from anyone): the file is
at most ``MAX_FILE`` bytes, its header at most ``MAX_HEADER`` bytes and nested at most
``MAX_DEPTH`` deep; each part declares its inflated length, which may be at most
``MAX_RATIO`` times its deflated length (deflate cannot do better) and, with the others, at
most ``MAX_INFLATED`` bytes; it is inflated in a stream that stops one byte past what it
declared. Every refusal is one line (MachineStateError).

Format 2 adds each part's inflated length; format 1 (parts without it) is still read, under
the same caps. A file of another format version is refused with a message naming both.
"""

from __future__ import annotations

import json
import zlib
from typing import Any

from camlab88.base.plainstate import depth

MAGIC = b"CAMLAB88-MACHINE-STATE\n"
VERSION = 2
READS = (1, 2)
MAX_FILE = 64 << 20      # bytes of a whole state file
MAX_HEADER = 8 << 20     # bytes of its JSON header
MAX_DEPTH = 64           # nesting of the header's lists and mappings
MAX_INFLATED = 256 << 20  # bytes of all the parts, inflated
MAX_RATIO = 1032         # deflate's best: a part claiming more is not deflate's output
_CHUNK = 1 << 20


class MachineStateError(ValueError):
    """A state that cannot be loaded: damaged, another device, or another version."""


def pack(device: str, header: dict[str, Any], blobs: dict[str, bytes]) -> bytes:
    packed = {name: zlib.compress(data, 1) for name, data in blobs.items()}
    head = dict(header, format_version=VERSION, device=device,
                blobs=[[name, len(packed[name]), len(blobs[name])] for name in blobs])
    text = json.dumps(head, sort_keys=True).encode("utf-8")
    return MAGIC + len(text).to_bytes(4, "big") + text + b"".join(packed.values())


def unpack(data: bytes, device: str) -> tuple[dict[str, Any], dict[str, bytes]]:
    """(header, blobs) of a state for ``device``; MachineStateError naming what is wrong."""
    if not isinstance(data, bytes | bytearray) or not data.startswith(MAGIC):
        raise MachineStateError("not a camlab88 machine state (bad magic at byte 0)")
    if len(data) > MAX_FILE:
        raise MachineStateError(f"the state is {len(data)} bytes; at most {MAX_FILE} are read")
    off = len(MAGIC)
    n = int.from_bytes(data[off:off + 4], "big")
    if n > MAX_HEADER or off + 4 + n > len(data):
        raise MachineStateError(f"machine state header length {n} (byte {off}) does not fit "
                                f"the file ({len(data)} bytes; headers at most {MAX_HEADER})")
    text = bytes(data[off + 4:off + 4 + n])
    if depth(text) > MAX_DEPTH:
        raise MachineStateError(f"machine state header (byte {off + 4}) is nested deeper "
                                f"than {MAX_DEPTH}")
    try:
        head = json.loads(text.decode("utf-8"))
    except (UnicodeDecodeError, ValueError, RecursionError) as exc:
        raise MachineStateError(f"machine state header is corrupt (byte {off + 4}): "
                                f"{_one_line(exc)}") from None
    if not isinstance(head, dict):
        raise MachineStateError("machine state header is not a mapping")
    if head.get("format_version") not in READS:
        raise MachineStateError(f"machine state is format version "
                                f"{_short(head.get('format_version'))}; this camlab88 reads "
                                f"version {VERSION}")
    if head.get("device") != device:
        raise MachineStateError(f"machine state is for a {_short(head.get('device'))}, not a "
                                f"{device!r}")
    return head, _blobs(data, head, off + 4 + n)


def _blobs(data: bytes, head: dict[str, Any], k: int) -> dict[str, bytes]:
    entries = head.get("blobs", [])
    if not isinstance(entries, list):
        raise MachineStateError("machine state blob list is corrupt")
    blobs: dict[str, bytes] = {}
    budget = MAX_INFLATED
    for entry in entries:
        if not (isinstance(entry, list) and len(entry) in (2, 3) and isinstance(entry[0], str)
                and all(type(v) is int and v >= 0 for v in entry[1:])):
            raise MachineStateError(f"machine state blob entry {_short(entry)} is corrupt")
        name, size = entry[0], entry[1]
        if k + size > len(data):
            raise MachineStateError(f"machine state blob {_short(name)} (byte {k}) runs past "
                                    f"the end of the file")
        declared = entry[2] if len(entry) == 3 else min(budget, size * MAX_RATIO)
        if declared > size * MAX_RATIO + 64 or declared > budget:
            raise MachineStateError(f"machine state blob {_short(name)} (byte {k}) claims "
                                    f"{declared} bytes from {size}: more than deflate gives "
                                    f"or than {MAX_INFLATED} in all")
        blobs[name] = _inflate(bytes(data[k:k + size]), declared, len(entry) == 3, name, k)
        budget -= len(blobs[name])
        k += size
    if k != len(data):
        raise MachineStateError(f"machine state is {len(data)} bytes, its header says {k}")
    return blobs


def _inflate(packed: bytes, declared: int, exact: bool, name: str, at: int) -> bytes:
    """``packed`` inflated in a stream that stops one byte past ``declared``."""
    d = zlib.decompressobj()
    out = bytearray()
    try:
        out += d.decompress(packed, declared + 1)
        while d.unconsumed_tail and len(out) <= declared:
            out += d.decompress(d.unconsumed_tail, declared + 1 - len(out))
        if not d.eof:
            raise zlib.error("incomplete or truncated stream" if len(out) <= declared
                             else "longer than it says")
    except zlib.error as exc:
        raise MachineStateError(f"machine state blob {_short(name)} (byte {at}) is corrupt: "
                                f"{exc}") from None
    if len(out) > declared or (exact and len(out) != declared):
        raise MachineStateError(f"machine state blob {_short(name)} (byte {at}) inflates to "
                                f"{'more than' if len(out) > declared else len(out)} bytes, "
                                f"not the {declared} it says")
    return bytes(out)


def _short(value: Any) -> str:
    """A value from a file, quoted for a message: one line, at most 60 characters."""
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _one_line(exc: BaseException) -> str:
    return _short(str(exc).splitlines()[0] if str(exc) else type(exc).__name__)[1:-1]
