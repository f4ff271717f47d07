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
                 keys: str, hold: bool = False, stage: Any = None) -> None:
        self.frames, self.size, self.fps = frames, size, fps
        self.title, self.keys, self.hold = title, keys, hold
        self.stage = stage  # the device the frames come from, for the inspector (or None)
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


class ActSequence:
    """Frame streams (the demo's acts) one after another in one run, so one window: each
    frame is its act's, centred on the largest act's size; Space ends the act shown, Esc
    asks to stop everything (``quit``). ``on_act(i)`` is called as act ``i`` begins. The
    inspector follows the act's device (``inspected``)."""

    def __init__(self, streams: list[FrameStream], title: str, keys: str,
                 on_act: Any = None) -> None:
        self.streams, self.title, self.keys = streams, title, keys
        self.on_act = on_act or (lambda i: None)
        self.fps = streams[0].fps
        self.size = (max(s.size[0] for s in streams), max(s.size[1] for s in streams))
        self.i = 0
        self.before = 0  # frames of the acts already played
        self.quit = False
        self.on_act(0)

    @property
    def act(self) -> FrameStream:
        return self.streams[self.i]

    def handle_events(self, events: list[HostEvent]) -> None:
        self.act.handle_events(events)
        self.quit |= self.act.quit

    def tick(self) -> bool:
        while not self.quit:
            if self.act.tick():
                return True
            if self.act.quit or self.i + 1 == len(self.streams):
                self.quit |= self.act.quit
                return False
            self.before += self.act.k
            self.i += 1
            self.on_act(self.i)
        return False

    def frame(self) -> np.ndarray:
        import numpy as np

        f = self.act.frame()
        w, h = self.size
        if f.shape[:2] == (h, w):
            return f
        out = np.zeros((h, w, 3), np.uint8)
        top, left = (h - f.shape[0]) // 2, (w - f.shape[1]) // 2
        out[top:top + f.shape[0], left:left + f.shape[1]] = f
        return out

    def crop(self, frame: np.ndarray) -> np.ndarray:
        """The act's own picture out of a frame shown (without the centring band)."""
        w, h = self.act.size
        top, left = (self.size[1] - h) // 2, (self.size[0] - w) // 2
        return frame[top:top + h, left:left + w]

    def time(self) -> Fraction:
        return Fraction(self.before + self.act.k, self.fps)

    def inspected(self) -> Any:
        return self.act.stage


class ActWriters(Plugin):
    """Headless, each act's frames as ``OUT/NAME_NNNN.png`` and ``OUT/NAME_demo.gif``
    (PngGifWriter per act, the act's own size)."""

    def __init__(self, out: Path, names: list[tuple[str, str]], fps: int, command: str) -> None:
        self.writers = [PngGifWriter(out, name, label, fps, command) for name, label in names]
        self.at = 0

    def on_frame(self, harness: Any, frame: np.ndarray) -> None:
        seq = harness.target
        while self.at < seq.i:  # an act ended: its GIF now
            self.writers[self.at].finish(harness)
            self.at += 1
        self.writers[seq.i].on_frame(harness, seq.crop(frame))

    def finish(self, harness: Any) -> None:
        for w in self.writers[self.at:harness.target.i + 1]:
            w.finish(harness)


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
        self.last = frame

    def finish(self, harness: Any) -> None:
        if not self.count:
            return
        self.gif.append(self.last)
        gif = self.out / f"{self.name}_demo.gif"
        write_gif(self.gif, gif, self.fps)
        print(f"{self.command}: {self.label}: {self.count} frames written to "
              f"{self.out}/{self.name}_*.png and {gif}")
        sys.stdout.flush()


def write_gif(frames: list[np.ndarray], path: Path, fps: int) -> None:
    """An animated GIF of every GIF_EVERY-th frame (64 colours), written atomically."""
    from PIL import Image

    from camlab88.base.atomicfile import atomic_output

    images = [Image.fromarray(f).convert("P", palette=Image.Palette.ADAPTIVE, colors=64)
              for f in frames]
    with atomic_output(path) as fh:
        images[0].save(fh, format="GIF", save_all=True, append_images=images[1:],
                       duration=int(1000 * GIF_EVERY / fps), loop=0)
