"""Title animation (thesis 6.5): "change the rendering procedures so that the table became
invisible and the (larger than usual) balls had letters of the alphabet on them. It then
became possible to use the tools provided (particularly the 'arrange to set up next shot'
command) to arrange that the letters lined up to form words at opportune moments."

The shot is made with the motion program itself: a table of giant balls (table.py allows
them), one ball per letter, each aimed with the orange menu's "aim to set up next shot"
(aiming.aim_next_shot, speed 0 at the target) at its slot in the word, then simulated by
the program's physics. Balls start alternately below and above the word's line, every one
the same distance from its slot, so they all stop together: the word forms at the moment
chosen by that distance (on the speed curve). Each letter is painted on its ball where it
will face the camera, upright, once the ball has stopped (reconstructed: the thesis does not
say how the letters were placed).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from camlab88.apps.snooker.camera.views import View
from camlab88.apps.snooker.render.scene import Scene
from camlab88.apps.snooker.session import Session
from camlab88.apps.snooker.table import Table

WORD = "CAMLAB88"
BALL_DIAMETER_M = 0.30  # "larger than usual": about six times a snooker ball
SPACING_M = 0.40
TRAVEL_M = 0.62  # each ball's distance to its slot: sets when the word forms
HOLD_S = 1.6  # the finished word stays on the screen this long
TITLE_VIEW = ((0.0, -2.2, 3.4), (0.0, 0.0, 0.0), 36.0)  # observer, viewpoint, focal mm


@dataclass(frozen=True, eq=False)
class TitleScene(Scene):
    """A scene drawn as titles: no table, letter ``letters[b]`` painted on ball b; the
    letter's centre direction, right and up in the ball's own frame are ``faces[b]``."""

    letters: str = ""
    faces: np.ndarray = field(default_factory=lambda: np.zeros((0, 3, 3)))


def title_table() -> Table:
    return Table(ball_diameter_m=BALL_DIAMETER_M)


def slots(table: Table, word: str) -> list[tuple[float, float]]:
    """Each letter's place in the word: a line along the table's middle (table metres)."""
    mid_x, mid_y = table.length_m / 2.0, table.width_m / 2.0
    n = len(word)
    return [(mid_x + (k - (n - 1) / 2.0) * SPACING_M, mid_y) for k in range(n)]


def title_session(word: str = WORD) -> Session:
    """The shot: letters scattered, each struck towards its slot with the aiming tool."""
    table = title_table()
    pos = np.full((22, 2), -1.0)  # balls beyond the word are off the table (potted)
    targets = slots(table, word)
    for k, (x, y) in enumerate(targets):
        pos[k] = (x, y - TRAVEL_M if k % 2 == 0 else y + TRAVEL_M)
    s = Session.from_positions(table, pos)
    for k, target in enumerate(targets):
        s.accept_aim(s.aim_next_shot(k, target, 0.0))
    return s


def title_scene(word: str = WORD, view: View | None = None) -> tuple[TitleScene, View]:
    """Simulate the shot to rest plus HOLD_S, and paint the letters for ``view``."""
    s = title_session(word)
    rate = s.table.frame_rate
    s.simulate_to_rest()
    end = s.frame_number
    hold = int(round(HOLD_S * rate))
    cp = s.checkpoint(0, end)
    base = Scene.from_checkpoint(cp, s.table)
    centres = np.concatenate([base.centres, np.repeat(base.centres[-1:], hold, axis=0)])
    on = np.concatenate([base.on_table, np.repeat(base.on_table[-1:], hold, axis=0)])
    v = view or View(1, *TITLE_VIEW)
    rolled = Scene(base.table, centres, on, base.lights)
    faces = _faces(rolled, v)
    return TitleScene(base.table, centres, on, base.lights, word, faces), v


def _faces(scene: Scene, view: View) -> np.ndarray:
    """Letters placed so that, in the last frame, each faces the observer upright."""
    from camlab88.apps.snooker.render.pinhole import Pinhole

    pin = Pinhole.of(np.asarray(view.observer), np.asarray(view.viewpoint), view.focal_mm,
                     640, 480)
    last = scene.orientations[-1]
    out = np.zeros((22, 3, 3))
    for b in range(22):
        to_eye = pin.observer - scene.centres[-1, b]
        e = to_eye / np.linalg.norm(to_eye)
        right = pin.right - (pin.right @ e) * e
        right /= np.linalg.norm(right)
        up = np.cross(e, right)
        out[b] = last[b].T @ np.stack([e, right, up], axis=1)  # world -> ball frame
    return np.transpose(out, (0, 2, 1))  # rows: centre, right, up (ball frame)


def title_views(scene: Scene, view: View) -> list[View]:
    return [View(f, view.observer, view.viewpoint, view.focal_mm)
            for f in range(1, scene.n_frames + 1)]
