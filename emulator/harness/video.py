"""``--video FILE.mp4|.webm|.gif``: the frames shown, at the program's frame rate, streamed to
ffmpeg (imageio-ffmpeg, as the film pipeline uses it) so memory stays flat however long
the run.  A frame that stood for several frame periods of virtual time is written that many
times, so the video keeps the program's timing.  The file appears whole at the end (a
temporary file beside it is renamed in) or not at all."""

from __future__ import annotations

import sys
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from camlab88.emulator.harness.loop import Plugin
from camlab88.emulator.harness.written import tell_written

if TYPE_CHECKING:
    from camlab88.emulator.harness.loop import Harness

FORMATS = (".mp4", ".webm", ".gif")


def video_params(path: Path) -> dict[str, Any]:
    """imageio_ffmpeg.write_frames arguments for the file's kind (.webm: VP9)."""
    suffix = path.suffix.lower()
    if suffix == ".gif":  # one palette for the whole film, made by ffmpeg
        return {"codec": "gif", "pix_fmt_out": "pal8", "quality": None, "output_params": [
            "-f", "gif", "-filter_complex", "split[a][b];[a]palettegen[p];[b][p]paletteuse"]}
    if suffix == ".webm":
        return {"codec": "libvpx-vp9", "pix_fmt_out": "yuv420p", "quality": None,
                "output_params": ["-f", "webm", "-b:v", "0", "-crf", "33",
                                  "-deadline", "realtime", "-cpu-used", "8", "-row-mt", "1"]}
    return {"codec": "libx264", "pix_fmt_out": "yuv420p",
            "output_params": ["-f", "mp4", "-movflags", "+faststart"]}


class VideoWriter(Plugin):
    """Every frame shown into ``path``; ``count`` frames written.  ``params`` replaces the
    file kind's write_frames arguments (a web page's smaller encoding); ``quiet``: the
    caller names the file itself."""

    def __init__(self, path: Path, params: dict[str, Any] | None = None,
                 quiet: bool = False) -> None:
        if path.suffix.lower() not in FORMATS:
            raise ValueError(f"--video makes .mp4, .webm or .gif, not "
                             f"{path.suffix or path.name!r}")
        self.path = Path(path)
        self.params = params or video_params(self.path)
        self.quiet = quiet
        self.count = 0
        self._writer: Any = None
        self._tmp: Path | None = None
        self._stack: Any = None
        self._last: Fraction | None = None

    def _open(self, harness: Harness, frame: np.ndarray) -> None:
        import contextlib

        import imageio_ffmpeg

        from camlab88.base.atomicfile import atomic_path

        self._stack = contextlib.ExitStack()
        self._tmp = self._stack.enter_context(atomic_path(self.path))
        h, w = frame.shape[:2]
        self.size = (w - w % 2, h - h % 2)  # even sides for yuv420p
        self._writer = imageio_ffmpeg.write_frames(
            str(self._tmp), self.size, fps=float(harness.target.fps), macro_block_size=1,
            ffmpeg_log_level="error", **self.params)
        self._writer.send(None)  # start ffmpeg

    def on_frame(self, harness: Harness, frame: np.ndarray) -> None:
        if self._writer is None:
            self._open(harness, frame)
        now, fps = harness.target.time(), Fraction(harness.target.fps)
        n = 1 if self._last is None else max(1, round((now - self._last) * fps))
        self._last = now
        w, h = self.size
        data = np.ascontiguousarray(frame[:h, :w], dtype=np.uint8).tobytes()
        for _ in range(n):
            self._writer.send(data)
            self.count += 1

    def finish(self, harness: Harness) -> None:
        if self._writer is None:
            return
        failed = sys.exc_info()[0] is not None
        try:
            self._writer.close()
        except (OSError, RuntimeError) as exc:
            self._stack.__exit__(type(exc), exc, None)
            raise SystemExit(f"{harness.options.command}: cannot write {self.path}: "
                             f"{exc}") from None
        self._stack.close()
        if not failed and not self.quiet:
            tell_written(harness, f"video {self.path} ({self.count} frames at "
                         f"{float(harness.target.fps):g} fps)")
