"""Rendering a run of frames (thesis 6.4: "the production of high quality versions of the
frames in the sequence"): which views, which palette, and each frame in turn.

The Sigma modes need a terminal on a line; the caller hands a link to a machine it runs
(protocols.link.port.BatchLink; apps never import the emulator).  With
``palette="adaptive"`` every frame is first rendered in true colour so the 256 colours can
be chosen for the whole sequence (palette.adaptive_palette).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass

import numpy as np

from camlab88.apps.snooker.render.palette import Palette, adaptive_palette, fixed_palette
from camlab88.apps.snooker.render.scene import Scene
from camlab88.apps.snooker.render.sigma_host import SCREEN_H, SCREEN_W, SigmaHost
from camlab88.apps.snooker.render.sigma_session import SigmaSession
from camlab88.apps.snooker.render.truecolour import RenderOptions, render_frame, render_linear
from camlab88.protocols.link.port import BatchLink

MODES = ("period", "fixed", "adapted", "truecolour")
PALETTES = ("fixed", "adaptive")


class SequenceError(ValueError):
    pass


@dataclass(frozen=True)
class RenderedFrame:
    frame: int
    image: np.ndarray  # (H, W, 3) uint8, row 0 = top
    line_seconds: float | None = None  # Sigma modes: this frame's time on the 9600-baud line
    leaks: int | None = None
    gaps: int | None = None


def select_views(views: Sequence[object], scene: Scene, first: int | None, last: int | None,
                 where: str) -> list[object]:
    """The views of frames first..last (default: every view); each must exist in the scene."""
    by_frame = {int(v.frame): v for v in views}
    if not by_frame:
        raise SequenceError(f"{where}: no views")
    lo = min(by_frame) if first is None else first
    hi = max(by_frame) if last is None else last
    if lo > hi:
        raise SequenceError(f"--first {lo} is after --last {hi}")
    missing = [f for f in range(lo, hi + 1) if f not in by_frame]
    if missing:
        raise SequenceError(f"{where}: no view for frame {missing[0]} (views cover "
                            f"{min(by_frame)}-{max(by_frame)})")
    if hi > scene.n_frames:
        raise SequenceError(f"{where}: frame {hi} is past the shot's last frame "
                            f"{scene.n_frames}")
    return [by_frame[f] for f in range(lo, hi + 1)]


def choose_palette(scene: Scene, views: Sequence[object], kind: str,
                   progress: Callable[[int, int], None] | None = None) -> Palette:
    if kind == "fixed":
        return fixed_palette(scene)
    if kind != "adaptive":
        raise SequenceError(f"unknown palette {kind!r}; choose from {', '.join(PALETTES)}")
    opts = RenderOptions(SCREEN_W, SCREEN_H, wood=False)  # what the Sigma modes draw
    frames = []
    for k, v in enumerate(views, start=1):
        frames.append(render_linear(scene, v, opts))
        if progress is not None:
            progress(k, len(views))
    return adaptive_palette(frames)


def render_sequence(scene: Scene, views: Sequence[object], mode: str, size: tuple[int, int],
                    palette: Palette | None = None,
                    link_factory: Callable[[], BatchLink] | None = None,
                    specks: bool = True, wood: bool = True) -> Iterator[RenderedFrame]:
    """Each view's frame in turn. ``truecolour`` at ``size``; the Sigma modes at 768 x 512
    through one terminal for the whole sequence (its LUT loaded once)."""
    if mode == "truecolour":
        opts = RenderOptions(size[0], size[1], specks, wood=wood)
        for v in views:
            yield RenderedFrame(int(v.frame), render_frame(scene, v, opts))
        return
    if mode not in MODES:
        raise SequenceError(f"unknown mode {mode!r}; choose from {', '.join(MODES)}")
    if link_factory is None or palette is None:
        raise SequenceError(f"--mode {mode} needs a terminal and a palette")
    link = link_factory()
    session = SigmaSession(SigmaHost(scene, palette, mode, specks), link)
    for v in views:
        sent = session.show(v)
        yield RenderedFrame(int(v.frame), link.frame(), sent.line_seconds, sent.leaks,
                            sent.gaps)
