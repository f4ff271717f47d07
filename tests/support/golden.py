"""Golden-image comparison. Set CAMLAB88_REGEN_GOLDEN=1 to (re)write the references deliberately."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
from PIL import Image


def assert_matches_golden(frame: np.ndarray, path: Path) -> None:
    """Compare an HxWx3 uint8 frame with a reference PNG, exactly.

    A missing reference is a failure, never silently created: regenerate deliberately with
    ``CAMLAB88_REGEN_GOLDEN=1`` and look at the new image before committing it.
    """
    frame = np.ascontiguousarray(frame, dtype=np.uint8)
    if os.environ.get("CAMLAB88_REGEN_GOLDEN") == "1":
        path.parent.mkdir(parents=True, exist_ok=True)
        Image.fromarray(frame).save(path)
        return
    if not path.exists():
        raise AssertionError(
            f"golden image {path} is missing: run the test with CAMLAB88_REGEN_GOLDEN=1, "
            "look at the image, and commit it"
        )
    want = np.asarray(Image.open(path).convert("RGB"))
    assert want.shape == frame.shape, f"{path.name}: shape {frame.shape} != golden {want.shape}"
    diff = np.argwhere(np.any(want != frame, axis=-1))
    if len(diff):
        y, x = diff[0]
        raise AssertionError(
            f"{path.name}: {len(diff)} pixels differ from the golden image; first at "
            f"row {y} col {x}: got {frame[y, x].tolist()} want {want[y, x].tolist()}"
        )
