"""Playing the demo's acts on the harness: a window per act, or headless into PNGs + GIFs."""

from __future__ import annotations

import argparse
import sys
from fractions import Fraction
from pathlib import Path
from typing import Any

import numpy as np

from camlab88.commands.demo.acts import FPS, Act
from emulator.harness import Plugin, RunOptions, choose_headless, run
from emulator.host_input import HostEvent, KeyDown

COMMAND = "camlab88 demo"
GIF_EVERY = 3  # every 3rd frame in the GIF (8.3 fps) keeps it small
KEYS = "Space: next act; Esc or close: quit"


class ActTarget:
    """One act's frames, 25 a second; Space ends the act, Esc the demo.  With ``hold`` the
    last frame stays up until a key is pressed."""

    fps = FPS
    keys = KEYS

    def __init__(self, act: Act, hold: bool) -> None:
        self.title, self.size = f"{COMMAND} - {act.title}", act.size
        self.frames = act.play()
        self.hold = hold
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
        return self.last if self.last is not None else np.zeros((*self.size[::-1], 3), np.uint8)

    def time(self) -> Fraction:
        return Fraction(self.k, FPS)


class ActWriter(Plugin):
    """Headless: every frame as OUT/ACT_NNNN.png and every 3rd in OUT/ACT_demo.gif."""

    def __init__(self, out: Path, act: Act) -> None:
        self.out, self.act = out, act
        self.gif: list[np.ndarray] = []
        self.count = 0

    def on_frame(self, harness: Any, frame: np.ndarray) -> None:
        from emulator.png import write_png

        write_png(frame, self.out / f"{self.act.name}_{self.count:04d}.png")
        if self.count % GIF_EVERY == 0:
            self.gif.append(frame)
        self.count += 1

    def finish(self, harness: Any) -> None:
        if harness.last_frame is not None:
            self.gif.append(harness.last_frame)
        gif = self.out / f"{self.act.name}_demo.gif"
        _write_gif(self.gif, gif)
        print(f"{COMMAND}: {self.act.title}: {self.count} frames written to "
              f"{self.out}/{self.act.name}_*.png and {gif}")


def _write_gif(frames: list[np.ndarray], path: Path) -> None:
    from PIL import Image

    from protocols.atomicfile import atomic_output

    images = [Image.fromarray(f).convert("P", palette=Image.Palette.ADAPTIVE, colors=64)
              for f in frames]
    with atomic_output(path) as fh:
        images[0].save(fh, format="GIF", save_all=True, append_images=images[1:],
                       duration=int(1000 * GIF_EVERY / FPS), loop=0)


def play_acts(acts: list[Act], args: argparse.Namespace) -> int:
    headless = choose_headless(COMMAND, args.headless,
                               f"writing every frame as PNG and a GIF per act into {args.out}")
    for i, act in enumerate(acts, 1):
        print(f"{COMMAND}: act {i}/{len(acts)}: {act.title}", file=sys.stderr, flush=True)
        last = i == len(acts)
        target = ActTarget(act, hold=not headless and last and args.screenshot is None)
        opts = RunOptions(headless=headless, paced=not args.fast, scale=args.scale,
                          screenshot=args.screenshot if last else None, command=COMMAND)
        plugins: list[Plugin] = [ActWriter(args.out, act)] if headless else []
        if headless:
            args.out.mkdir(parents=True, exist_ok=True)
        h = run(target, opts, plugins)
        if target.quit or h.quit:
            return 0
    return 0
