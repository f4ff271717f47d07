"""Atomic file writes (temp file in the same directory, fsync, rename)."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np

from protocols.atomicfile import write_atomic


def save_png(path: str | Path, frame: np.ndarray) -> None:
    from PIL import Image

    buf = io.BytesIO()
    Image.fromarray(np.ascontiguousarray(frame, np.uint8)).save(buf, format="PNG")
    write_atomic(path, buf.getvalue())
