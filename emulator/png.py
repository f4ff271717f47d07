"""The one PNG writer: an (h, w, 3) uint8 frame to a file, atomically.

Every command, the harness (``--screenshot``, ``--frames DIR``) and the window's screenshot
write PNGs through :func:`write_png`, so every picture camlab88 writes is encoded the same way
(Pillow, no metadata) and a crash never leaves half a file.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np


def write_png(frame: np.ndarray, path: str | os.PathLike[str]) -> Path:
    """Write ``frame`` (row 0 = top) as PNG at ``path``, creating its directory."""
    from PIL import Image

    from protocols.atomicfile import atomic_output

    arr = np.ascontiguousarray(frame, dtype=np.uint8)
    if arr.ndim != 3 or arr.shape[2] != 3:
        raise ValueError(f"a frame is (h, w, 3) uint8, not shape {arr.shape}")
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    with atomic_output(target) as fh:
        Image.fromarray(arr).save(fh, format="PNG")
    return target


def frame_path(directory: str | os.PathLike[str], k: int) -> Path:
    """``DIR/frame_NNNNN.png``: what ``--frames DIR`` means in every command."""
    return Path(directory) / f"frame_{k:05d}.png"
