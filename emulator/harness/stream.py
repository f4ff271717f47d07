"""Targets and plugins for a program that hands the harness finished frames (the demo's
acts): a frame stream shown at ``fps``, and the headless writer of its PNGs and GIF."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Any

from camlab88.emulator.harness.loop import Plugin
from camlab88.emulator.host_input import HostEvent, KeyDown

if TYPE_CHECKING:
    import numpy as np

GIF_EVERY = 3  # every 3rd frame in the GIF keeps it small


class FrameStream:
    """Frames from ``frames``, ``fps`` a second; Space ends the stream (``skip``), Esc asks
    to stop everything (``quit``).  With ``hold`` the last frame stays up until a key."""

    def __init__(self, frames: Iterator[Any], size: tuple[int, int], fps: int, title: str,
                 keys: str, hold: bool = False) -> None:
        self.frames, self.size, self.fps = frames, size, fps
        self.title, self.keys, self.hold = title, keys, hold
        self.k = 0
        self.last: Any = None
        self.quit = self.skip = False

    def handle_events(self, events: list[HostEvent]) -> None:
        for ev in events:
            if isinstance(ev, KeyDown):
                self.quit |= ev.key == "escape"
                self.skip |= ev.key != "escape"

    def tick(self) -> bool:
        if self.quit or self.skip:
            return False
        nxt = next(self.frames, None)
        if nxt is None:
            self.k += self.hold  # holding: time goes on (paced), the picture stays
            return self.hold
        self.last, self.k = nxt, self.k + 1
        return True

    def frame(self) -> np.ndarray:
        import numpy as np

        return self.last if self.last is not None else np.zeros((*self.size[::-1], 3), np.uint8)

    def time(self) -> Fraction:
        return Fraction(self.k, self.fps)


class PngGifWriter(Plugin):
    """Every frame shown as ``OUT/NAME_NNNN.png`` and every 3rd in ``OUT/NAME_demo.gif``."""

    def __init__(self, out: Path, name: str, label: str, fps: int, command: str) -> None:
        self.out, self.name, self.label, self.fps = out, name, label, fps
        self.command = command
        self.gif: list[np.ndarray] = []
        self.count = 0

    def on_frame(self, harness: Any, frame: np.ndarray) -> None:
        from camlab88.base.png import write_png

        write_png(frame, self.out / f"{self.name}_{self.count:04d}.png")
        if self.count % GIF_EVERY == 0:
            self.gif.append(frame)
        self.count += 1

    def finish(self, harness: Any) -> None:
        if harness.last_frame is not None:
            self.gif.append(harness.last_frame)
        gif = self.out / f"{self.name}_demo.gif"
        write_gif(self.gif, gif, self.fps)
        print(f"{self.command}: {self.label}: {self.count} frames written to "
              f"{self.out}/{self.name}_*.png and {gif}")
        sys.stdout.flush()


def write_gif(frames: list[np.ndarray], path: Path, fps: int) -> None:
    """An animated GIF of every GIF_EVERY-th frame (64 colours), written atomically."""
    from camlab88.base.atomicfile import atomic_output
    from PIL import Image

    images = [Image.fromarray(f).convert("P", palette=Image.Palette.ADAPTIVE, colors=64)
              for f in frames]
    with atomic_output(path) as fh:
        images[0].save(fh, format="GIF", save_all=True, append_images=images[1:],
                       duration=int(1000 * GIF_EVERY / fps), loop=0)
