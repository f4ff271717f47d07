"""The one PNG writer: an (h, w, 3) uint8 frame to a file, atomically.

Every command, the harness (``--screenshot``, ``--frames DIR``) and the window's screenshot
write PNGs through :func:`write_png` (programs in apps/ may too: it is in protocols/), so
every picture camlab88 writes is encoded the same way (Pillow, no metadata) and a crash never
leaves half a file; :func:`png_bytes` gives the encoded bytes for callers that bundle them.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np


def png_bytes(frame: np.ndarray) -> bytes:
    """``frame`` (an (h, w, 3) uint8 array, row 0 = top) encoded as PNG."""
    import io

    from PIL import Image

    arr = np.ascontiguousarray(frame, dtype=np.uint8)
    if arr.ndim != 3 or arr.shape[2] != 3:
        raise ValueError(f"a frame is (h, w, 3) uint8, not shape {arr.shape}")
    buf = io.BytesIO()
    Image.fromarray(arr).save(buf, format="PNG")
    return buf.getvalue()


def write_png(frame: np.ndarray, path: str | os.PathLike[str]) -> Path:
    """Write ``frame`` (row 0 = top) as PNG at ``path``, atomically. Its directory is never
    created (the one output rule, docs/exit_status.md): a missing one is an OSError whose
    words are the rule's (``no such directory D``, ``F is a file in the way ...``)."""
    from camlab88.base.atomicfile import write_atomic

    data = png_bytes(frame)
    target = Path(path)
    write_atomic(target, data)
    return target


def write_frame(frame: np.ndarray, directory: str | os.PathLike[str], k: int) -> Path:
    """``frame`` as ``DIR/frame_NNNNN.png`` (``--frames DIR``): DIR is made if it is new,
    one level only — its parent must exist, as the command checked before the work."""
    folder = Path(directory)
    folder.mkdir(exist_ok=True)
    return write_png(frame, frame_path(folder, k))


def frame_path(directory: str | os.PathLike[str], k: int) -> Path:
    """``DIR/frame_NNNNN.png``: what ``--frames DIR`` means in every command."""
    return Path(directory) / f"frame_{k:05d}.png"
