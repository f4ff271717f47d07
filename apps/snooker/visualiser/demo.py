"""The demo: the thesis's example camera script (§6.3.1), as printed, over the shot it was
written for, in the visualiser -- "the cueball being struck and hitting the pink ball (which
was on its spot at the time).  The pink ball then goes into the top left pocket."

The shot is made with the motion program's own tools: the end-game position (cue ball, the
pink on its spot, the black: the pink is on, so potting it is legal and it stays down), then
"arrange to set up next shot" (aiming.aim_next_shot) sends the cue ball off the right cushion
to the ghost-ball position that cuts the pink towards the top left pocket, arriving at
1.5 m/s; then the shot is simulated until every ball is at rest (75 frames).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from camlab88.apps.snooker.camera import ccl
from camlab88.apps.snooker.camera.motion import from_session
from camlab88.apps.snooker.session import Session
from camlab88.apps.snooker.table import BLACK, CUE, N_BALLS, PINK, Table
from camlab88.apps.snooker.visualiser.program import Visualiser
from camlab88.protocols.rainbow.client import RainbowClient

EXAMPLE_SCRIPT = """\
:
from frame 1 until frame 33;
observer at camera 1;
viewpoint at (0,0,0);
focal length of 50
:
camera 3 at (7.3, -4.5, 1.2);
from frame 34 until cueball strikes;
observer moving from camera 3 - (0,1,0) to camera 3;
focal length from 30 to 135;
viewpoint at pink spot
:
until pink ball stops - 10;
viewpoint following pink ball
:
until pink ball stops;
observer following pink ball + (0.1, -0.1, 0.05);
viewpoint at top left pocket;
focal length of 28
:
"""
CUE_START = (0.5, 1.4)  # table coordinates (m): the baulk end, near the left cushion
ARRIVAL_SPEED = 1.5  # m/s at the ghost-ball position


def example_shot() -> Session:
    t = Table()
    pos = np.zeros((N_BALLS, 2))
    for i in range(N_BALLS):  # every other ball potted: parked beyond the top left pocket
        pos[i] = (t.length_m + 0.1 + 0.06 * i, t.width_m + 0.1)
    pos[CUE] = CUE_START
    pos[PINK] = t.spots[PINK]
    pos[BLACK] = t.spots[BLACK]
    s = Session.from_positions(t, pos)
    pocket = t.pockets[t.pocket_index("top-left")]
    u = np.subtract(pocket.centre, pos[PINK])
    ghost = pos[PINK] - 2.0 * t.radius * u / np.linalg.norm(u)
    s.accept_aim(s.aim_next_shot(CUE, (float(ghost[0]), float(ghost[1])), ARRIVAL_SPEED,
                                 ("right",)))
    s.simulate_to_rest()
    return s


def play_example(client: RainbowClient, on_shown: Callable[[int], None] | None = None) -> int:
    """The example over its shot, every frame once at 25 frames/s; `on_shown(frame)` is
    called when each frame is first on the screen.  Returns the number of frames."""
    shot = from_session(example_shot())
    views = ccl.compile_script(EXAMPLE_SCRIPT, shot, "<thesis example>").views()
    return Visualiser(client, shot, views).play_through(on_shown)
