"""Golden-image comparison. Set CAMLAB88_REGEN_GOLDEN=1 to (re)write the references deliberately."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
from PIL import Image


def assert_matches_golden(frame: np.ndarray, path: Path) -> None:
    """Compare an HxWx3 uint8 frame with a reference PNG, exactly."""
    frame = np.ascontiguousarray(frame, dtype=np.uint8)
    if os.environ.get("CAMLAB88_REGEN_GOLDEN") == "1" or not path.exists():
        if os.environ.get("CAMLAB88_REGEN_GOLDEN") != "1" and os.environ.get("CI"):
            raise AssertionError(f"golden image {path} is missing (regenerate deliberately)")
        path.parent.mkdir(parents=True, exist_ok=True)
        Image.fromarray(frame).save(path)
        return
    want = np.asarray(Image.open(path).convert("RGB"))
    assert want.shape == frame.shape, f"{path.name}: shape {frame.shape} != golden {want.shape}"
    diff = np.argwhere(np.any(want != frame, axis=-1))
    if len(diff):
        y, x = diff[0]
        raise AssertionError(
            f"{path.name}: {len(diff)} pixels differ from the golden image; first at "
            f"row {y} col {x}: got {frame[y, x].tolist()} want {want[y, x].tolist()}"
        )
