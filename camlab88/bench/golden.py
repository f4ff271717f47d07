"""Compare a screen with a golden PNG, exactly; write it only when asked to."""

from __future__ import annotations

from pathlib import Path

import numpy as np


def golden_path(directory: Path, name: str) -> Path:
    """``directory/name.png``, refused (ValueError) unless it stays inside ``directory``:
    ``name`` is one plain file name (no ``/``, ``\\``, ``..``, no absolute or drive name),
    and the file, if it is a symbolic link, does not lead out of the directory — so that
    ``--camlab88-regen`` never writes (or replaces through a link) a file elsewhere."""
    bad = (not name or name in (".", "..") or "/" in name or "\\" in name or "\0" in name
           or ":" in name or Path(name).is_absolute())
    if bad:
        raise ValueError(f"camlab88_golden: {name!r} is not a plain file name; a golden "
                         f"image is named inside its directory {directory}")
    path = Path(directory) / f"{name}.png"
    base = Path(directory).resolve()
    if path.resolve().parent != base:
        raise ValueError(f"camlab88_golden: {path} leads out of the golden directory {base} "
                         f"(to {path.resolve()}): a golden image is a file of that directory")
    return path


def compare_golden(screen: np.ndarray, path: Path, regen: bool) -> None:
    """AssertionError naming the first differing pixel (or the missing file)."""
    from PIL import Image

    from camlab88.base.png import write_png

    frame = np.ascontiguousarray(screen, dtype=np.uint8)
    if regen:  # the golden directory (checked by golden_path) is made, nothing else
        path.parent.mkdir(parents=True, exist_ok=True)
        write_png(frame, path)
        return
    if not path.exists():
        raise AssertionError(f"golden image {path} is missing: run pytest --camlab88-regen, "
                             "look at the image, and commit it")
    with Image.open(path) as im:
        want = np.asarray(im.convert("RGB"))
    if want.shape != frame.shape:
        raise AssertionError(f"{path.name}: screen {frame.shape} != golden {want.shape}")
    diff = np.argwhere(np.any(want != frame, axis=-1))
    if len(diff):
        y, x = diff[0]
        raise AssertionError(f"{path.name}: {len(diff)} pixels differ from the golden image; "
                             f"first at row {y} col {x}: got {frame[y, x].tolist()} want "
                             f"{want[y, x].tolist()}")
