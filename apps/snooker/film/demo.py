"""The demo act "from motion development to rendered film" (thesis 6.2-6.4, kept short so
``camlab88 demo`` stays quick): a break simulated by the motion program, a camera script
interpreted over it, every frame rendered in true colour at the T5688's 768 x 512."""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np

from camlab88.apps.snooker.camera import ccl, motion
from camlab88.apps.snooker.film.task import FrameTask, render_image
from camlab88.apps.snooker.render.scene import Scene
from camlab88.apps.snooker.session import Session
from camlab88.apps.snooker.table import CUE

SCRIPT = """:
from frame 1 until cueball strikes;
observer at (-2.6, 0.45, 0.9);
viewpoint following cueball;
focal length of 30
:
until frame {last};
observer moving from (-2.6, 0.45, 0.9) to (-1.2, -0.9, 1.4);
viewpoint at pink spot;
focal length from 30 to 40
"""


def film_frames(frames: int = 36, size: tuple[int, int] = (768, 512)) -> Iterator[np.ndarray]:
    """The act's frames, one a 1/25 s of the break."""
    s = Session.new_game()
    red, cue = s.balls.pos[7], s.balls.pos[CUE]
    s.strike(CUE, 6.0, math.degrees(math.atan2(red[1] - cue[1], red[0] - cue[0])))
    for _ in range(frames - 1):
        s.simulate_frame()
    cp = s.checkpoint(0, frames - 1)
    shot = motion.from_checkpoint(cp)
    views = ccl.compile_script(SCRIPT.format(last=frames), shot, "<film demo>").views()
    scene = Scene.from_checkpoint(cp)
    for v in views:
        yield render_image(scene, FrameTask(int(v.frame), v, size[0], size[1]))
