"""What a frame is rendered from: the table, every frame's ball centres, the lights.

A pure, picklable description (thesis 6.4: the motion program's positions and the camera
program's views in, frames out), so any process can render any frame byte-identically;
ball centres stay an input array so sub-frame positions (motion blur) can be fed later.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from camlab88.apps.snooker import checkpoint as ckpt
from camlab88.apps.snooker.camera import motion
from camlab88.apps.snooker.camera.space import checkpoint_centres
from camlab88.apps.snooker.render.lights import Lights, canopy
from camlab88.apps.snooker.render.specks import orientations
from camlab88.apps.snooker.table import Table


@dataclass(frozen=True, eq=False)
class Scene:
    """centres (frames, 22, 3) table-frame metres, on_table (frames, 22); index 0 is the
    checkpoint's frame 1."""

    table: Table
    centres: np.ndarray
    on_table: np.ndarray
    lights: Lights = field(default_factory=canopy)

    @cached_property
    def orientations(self) -> np.ndarray:
        """(frames, 22, 3, 3): each ball's rolling orientation (for the dust specks)."""
        return orientations(self.centres, self.on_table, self.table.radius)

    @property
    def n_frames(self) -> int:
        return int(self.centres.shape[0])

    def index(self, frame: int) -> int:
        """Checkpoint frame number (from 1) -> row of ``centres``."""
        if not 1 <= frame <= self.n_frames:
            raise ValueError(f"frame {frame} is not in 1..{self.n_frames}")
        return frame - 1

    @classmethod
    def from_checkpoint(cls, checkpoint: ckpt.Checkpoint, table: Table | None = None,
                        lights: Lights | None = None) -> Scene:
        t = table or Table()
        centres, on = checkpoint_centres(checkpoint, t)
        return cls(t, centres, on, lights or canopy())


def load_scene(path: str | os.PathLike[str], lights: Lights | None = None) -> Scene:
    """A checkpoint (§6.2.2) or a saved session (JSON) -> Scene, read as the camera
    reads it (so frame numbers agree with the view file); errors name file:line."""
    m = motion.load(path)
    return Scene(m.table, m.centres, m.on_table, lights or canopy())
