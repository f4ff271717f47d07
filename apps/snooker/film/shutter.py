"""Motion blur (thesis 6.4, after Korein & Badler and Potmesil & Chakravarty, 1983): "the
shutter is open for an appreciable amount of time (approximately 1/50 second) each time it
records the scene", so a frame shows every position a ball passes through meanwhile.

The motion is known exactly between frame boundaries: a ball moves at constant velocity
from one frame's position to the next (reconstructed: the checkpoint holds positions only,
so an event inside a frame interval is cut as a chord). The shutter is centred on the
frame's instant, so a frame's ball still lands where the visualiser puts it; the picture is
the mean, in linear light, of ``samples`` renders spread evenly over the open shutter, the
first at the opening and the last at the closing, so a streak's length is speed x shutter.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from camlab88.apps.snooker.render.scene import Scene
from camlab88.apps.snooker.render.specks import rolling_rotations

RATE = 25.0  # the motion program's frames a second, and the film camera's (thesis 6.4)
SHUTTER_S = 1.0 / 50.0


@dataclass(frozen=True, eq=False)
class ShutterScene(Scene):
    """Rows are instants inside one frame's shutter; orientations given, not integrated
    from row 0 (they continue the shot's rolling)."""

    given: np.ndarray = field(default_factory=lambda: np.zeros((0, 22, 3, 3)))

    @property
    def orientations(self) -> np.ndarray:
        return self.given


def sample_offsets(samples: int, shutter_s: float = SHUTTER_S) -> np.ndarray:
    """Times (s) of the samples relative to the frame's instant: opening .. closing."""
    if samples < 2:
        return np.zeros(1)
    return np.linspace(-shutter_s / 2.0, shutter_s / 2.0, samples)


def at_times(scene: Scene, frame: int, offsets_s: np.ndarray) -> ShutterScene:
    """The scene at the instants ``frame``'s time + offsets_s (constant velocity between
    frame boundaries; clamped at the shot's first and last frames)."""
    row = scene.index(frame)
    last = scene.n_frames - 1
    u = np.clip(row + np.asarray(offsets_s) * RATE, 0.0, float(last))
    a = np.minimum(np.floor(u).astype(np.int64), max(last - 1, 0))
    b = np.minimum(a + 1, last)
    w = (u - a)[:, None, None]
    ca, cb = scene.centres[a], scene.centres[b]
    near = np.where(w[:, :, 0] < 0.5, a[:, None], b[:, None])  # (n, 1) nearer row
    on = scene.on_table[near[:, 0]]
    # a ball potted or re-spotted between the rows jumps: no streak across the table
    both = scene.on_table[a] & scene.on_table[b]
    centres = np.where(both[:, :, None], ca + w * (cb - ca), scene.centres[near[:, 0]])
    rot = _orientations(scene, a, centres, both)
    return ShutterScene(scene.table, np.ascontiguousarray(centres), on, scene.lights, rot)


def _orientations(scene: Scene, a: np.ndarray, centres: np.ndarray,
                  both: np.ndarray) -> np.ndarray:
    """Row a's orientation turned on by the roll from row a's position to each sample's."""
    out = np.empty((len(a), centres.shape[1], 3, 3))
    base = scene.orientations
    for k in range(len(a)):
        step = centres[k, :, :2] - scene.centres[a[k], :, :2]
        step[~both[k]] = 0.0
        out[k] = rolling_rotations(step, scene.table.radius) @ base[a[k]]
    return out
