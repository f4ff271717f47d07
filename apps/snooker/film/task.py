"""One frame of a film as a pure task: picklable inputs (the scene, the view, the options)
-> PNG bytes, byte-identical in whichever process renders it (thesis 6.4: "the production
of high quality versions of the frames in the sequence")."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, fields

import numpy as np

from camlab88.apps.snooker.film.shutter import SHUTTER_S, at_times, sample_offsets
from camlab88.apps.snooker.render.gamma import encode_image
from camlab88.apps.snooker.render.scene import Scene
from camlab88.apps.snooker.render.truecolour import RenderOptions, render_linear
from camlab88.base.png import png_bytes


@dataclass(frozen=True)
class FrameTask:
    """Frame ``frame`` (the checkpoint's numbering, from 1) seen through ``view``."""

    frame: int
    view: object  # the camera's (apps/snooker/camera) View (observer, viewpoint, focal_mm, frame)
    width: int = 768
    height: int = 512
    specks: bool = True
    shadows: bool = True
    blur_samples: int = 1  # 1: an instantaneous frame; more: motion blur over the shutter
    shutter_s: float = SHUTTER_S
    wood: bool = True  # Phong + grain on the surround; False: constant, as the Sigma draws it


def render_image(scene: Scene, task: FrameTask) -> np.ndarray:
    """(H, W, 3) uint8, row 0 = top."""
    from camlab88.apps.snooker.film.titles import TitleScene

    if isinstance(scene, TitleScene):  # §6.5: the table invisible, letters on the balls
        from camlab88.apps.snooker.film.letterballs import render_title

        return render_title(scene, task.view, task.frame, task.width, task.height)
    opts = RenderOptions(task.width, task.height, task.specks, task.shadows, task.wood)
    if task.blur_samples < 2:
        return encode_image(render_linear(scene, task.view, opts, task.frame))
    sub = at_times(scene, task.frame, sample_offsets(task.blur_samples, task.shutter_s))
    acc = np.zeros((task.height, task.width, 3), dtype=np.float64)
    for k in range(sub.n_frames):
        acc += render_linear(sub, task.view, opts, k + 1)
    return encode_image(acc / sub.n_frames)


def render_png(scene: Scene, task: FrameTask) -> bytes:
    """The frame encoded by the project's one PNG encoder (base/png.py)."""
    return png_bytes(render_image(scene, task))


def scene_digest(scene: Scene) -> str:
    """What the frames were rendered from (the motion, table, lights), as a hash."""
    h = hashlib.sha256()
    for a in (scene.centres, scene.on_table):
        h.update(np.ascontiguousarray(a).tobytes())
    for f in fields(scene.lights):
        h.update(np.ascontiguousarray(getattr(scene.lights, f.name), dtype=np.float64).tobytes())
    h.update(repr(scene.table).encode())
    return h.hexdigest()


def task_key(digest: str, task: FrameTask) -> str:
    """A frame's identity for resuming: same scene, view and look -> same key."""
    return hashlib.sha256(f"{digest}\n{task!r}".encode()).hexdigest()[:32]
