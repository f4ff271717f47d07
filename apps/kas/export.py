"""PNG, GIF and MP4 export of sequences (imageio; MP4 through imageio-ffmpeg).

Pictures come from the emulated Sigma (camlab88/commands/kas.py) or ``camlab88.apps.kas.raster``.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator
from pathlib import Path

import numpy as np

from camlab88.apps.kas.model import AnimSequence, Drawing
from camlab88.apps.kas.raster import render
from camlab88.base.atomicfile import AtomicBatch, atomic_path, write_atomic
from camlab88.base.png import png_bytes

Progress = Callable[[int, int], None]


def export(seq: AnimSequence, out: str | os.PathLike[str], width: int = 768,
           background: str = "black", progress: Progress | None = None,
           render_frame: Callable[[Drawing], np.ndarray] | None = None) -> Path:
    """Write ``out`` (.gif, .mp4, or .png = one PNG per frame named out_NNNN.png).

    ``render_frame`` turns one frame into an (h, w, 3) picture; by default the rasteriser
    here, while the command line passes one that draws on the emulated Sigma."""
    if render_frame is None:
        def render_frame(f: Drawing) -> np.ndarray:
            return render(f, width, background)
    import imageio.v3 as iio

    out = Path(out)
    ext = out.suffix.lower()
    if ext not in (".gif", ".mp4", ".png"):
        raise ValueError(f"export to .gif, .mp4 or .png, not {out.suffix!r}")
    if not seq.frames:
        raise ValueError("the sequence has no frames")
    n = len(seq)

    def frames():
        for i, f in enumerate(seq.frames):
            img = render_frame(f)
            if progress:
                progress(i + 1, n)
            yield img

    if ext == ".png":
        _png_sequence(out, frames())
        return out.with_name(f"{out.stem}_0001.png")
    if ext == ".gif":  # made in memory, so a full disk cannot strand a half-open writer
        data = iio.imwrite("<bytes>", np.stack(list(frames())), extension=".gif",
                           duration=1000 / seq.fps, loop=0)
        write_atomic(out, data)
        return out
    with atomic_path(out) as tmp:
        _mp4(tmp, out, seq.fps, frames())
    return out


def _mp4(tmp: Path, out: Path, fps: float, frames: Iterator[np.ndarray]) -> None:
    """The frames as H.264 through ffmpeg; its failure is one OSError naming ``out``
    (ffmpeg says only "broken pipe" when the disk fills)."""
    import errno
    import shutil

    import imageio.v2 as iio2

    try:  # even dimensions for yuv420p; macro_block_size=1 keeps the exact size
        with iio2.get_writer(tmp, format="FFMPEG", mode="I", fps=fps, codec="libx264",
                             macro_block_size=1, ffmpeg_log_level="quiet",
                             output_params=["-pix_fmt", "yuv420p"]) as wr:
            for img in frames:
                h, w = img.shape[:2]
                wr.append_data(img[: h - h % 2, : w - w % 2])
    except (OSError, RuntimeError) as exc:
        if isinstance(exc, OSError) and exc.errno not in (errno.EPIPE, None):
            raise
        full = shutil.disk_usage(tmp.parent).free == 0
        code = errno.ENOSPC if full else errno.EIO
        why = os.strerror(code) if full else "ffmpeg could not write the video"
        raise OSError(code, why, os.fspath(out)) from None


def _png_sequence(out: Path, frames: Iterator[np.ndarray]) -> None:
    """out_0001.png ... as one whole: every frame is staged first and renamed in only when
    all are written, then frames left from a longer earlier export are removed — so a
    killed export never leaves old and new frames mixed."""
    with AtomicBatch() as batch:
        for i, img in enumerate(frames, start=1):
            batch.add(out.with_name(f"{out.stem}_{i:04d}.png"),
                      png_bytes(img))
    k = len(batch.staged) + 1
    while (old := out.with_name(f"{out.stem}_{k:04d}.png")).exists():
        old.unlink()
        k += 1
