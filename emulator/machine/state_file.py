"""The whole-machine state file: a magic line, a JSON header (format version, device, each
component's JSON state) and the binary parts some components give (named, length-prefixed,
each deflated).

A file from another format version is refused with a message naming both versions.
"""

from __future__ import annotations

import json
import zlib
from typing import Any

MAGIC = b"CAMLAB88-MACHINE-STATE\n"
VERSION = 1


class MachineStateError(ValueError):
    """A state that cannot be loaded: damaged, another device, or another version."""


def pack(device: str, header: dict[str, Any], blobs: dict[str, bytes]) -> bytes:
    blobs = {name: zlib.compress(data, 1) for name, data in blobs.items()}
    head = dict(header, format_version=VERSION, device=device,
                blobs=[[name, len(data)] for name, data in blobs.items()])
    text = json.dumps(head, sort_keys=True).encode("utf-8")
    return MAGIC + len(text).to_bytes(4, "big") + text + b"".join(blobs.values())


def unpack(data: bytes, device: str) -> tuple[dict[str, Any], dict[str, bytes]]:
    """(header, blobs) of a state for ``device``; MachineStateError naming what is wrong."""
    if not isinstance(data, bytes | bytearray) or not data.startswith(MAGIC):
        raise MachineStateError("not a camlab88 machine state (bad magic at byte 0)")
    off = len(MAGIC)
    n = int.from_bytes(data[off:off + 4], "big")
    try:
        head = json.loads(bytes(data[off + 4:off + 4 + n]).decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise MachineStateError(f"machine state header is corrupt (byte {off + 4}): "
                                f"{exc}") from None
    if not isinstance(head, dict):
        raise MachineStateError("machine state header is not a mapping")
    if head.get("format_version") != VERSION:
        raise MachineStateError(f"machine state is format version "
                                f"{head.get('format_version')!r}; this camlab88 reads "
                                f"version {VERSION}")
    if head.get("device") != device:
        raise MachineStateError(f"machine state is for a {head.get('device')!r}, not a "
                                f"{device!r}")
    blobs, k = {}, off + 4 + n
    for entry in head.get("blobs", []):
        if not (isinstance(entry, list) and len(entry) == 2 and isinstance(entry[0], str)
                and type(entry[1]) is int and entry[1] >= 0):
            raise MachineStateError(f"machine state blob entry {entry!r} is corrupt")
        try:
            blobs[entry[0]] = zlib.decompress(bytes(data[k:k + entry[1]]))
        except zlib.error as exc:
            raise MachineStateError(f"machine state blob {entry[0]!r} (byte {k}) is corrupt: "
                                    f"{exc}") from None
        k += entry[1]
    if k != len(data):
        raise MachineStateError(f"machine state is {len(data)} bytes, its header says {k}")
    return head, blobs
