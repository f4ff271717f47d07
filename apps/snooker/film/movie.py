"""A film's frames as MP4 (H.264, yuv420p) or GIF at 25 frames a second — the film
camera's rate (thesis 6.4) — with no sound track, written atomically (imageio, as the
project's KAS export)."""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

from camlab88.base.atomicfile import atomic_path

FPS = 25


def write_movie(frames: Sequence[str | os.PathLike[str]], out: str | os.PathLike[str],
                fps: int = FPS) -> Path:
    """Frame PNG files (in order) -> ``out`` (.mp4 or .gif)."""
    import imageio.v3 as iio
    import numpy as np

    out = Path(out)
    ext = out.suffix.lower()
    if ext not in (".mp4", ".gif"):
        raise ValueError(f"{out}: a film is .mp4 or .gif, not {out.suffix!r}")
    if not frames:
        raise ValueError(f"{out}: no frames to film")
    with atomic_path(out) as tmp:
        if ext == ".gif":
            stack = np.stack([iio.imread(f) for f in frames])
            iio.imwrite(tmp, stack, extension=".gif", duration=1000 / fps, loop=0)
        else:
            _mp4(frames, tmp, fps, iio)
    return out


def _mp4(frames: Sequence[str | os.PathLike[str]], tmp: Path, fps: int, iio: object) -> None:
    import imageio.v2 as iio2

    # even sides for yuv420p; macro_block_size=1 keeps the exact size; no audio stream
    with iio2.get_writer(tmp, format="FFMPEG", mode="I", fps=fps, codec="libx264",
                         macro_block_size=1, ffmpeg_log_level="error",
                         output_params=["-pix_fmt", "yuv420p", "-an"]) as wr:
        for f in frames:
            img = iio.imread(f)
            h, w = img.shape[:2]
            wr.append_data(img[: h - h % 2, : w - w % 2])
