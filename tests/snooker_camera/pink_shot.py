"""The shot of the thesis's example camera script (§6.3.1): "the cueball being struck and
hitting the pink ball (which was on its spot at the time).  The pink ball then goes into
the top left pocket."  Made with the motion program's own tools: the end-game position
(cue ball, pink on its spot, black: the pink is on, so potting it is legal and it stays
down), then "arrange to set up next shot" (aiming.aim_next_shot) sends the cue ball off the
right cushion to the ghost-ball position that cuts the pink towards the top left pocket,
arriving at 1.5 m/s; then simulate until every ball is at rest.

Regenerate the shipped files (tests check they are what this makes):
    .venv/bin/python -m tests.snooker_camera.pink_shot
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from apps.snooker.session import Session
from apps.snooker.table import BLACK, CUE, N_BALLS, PINK, Table

DATA = Path(__file__).resolve().parents[1] / "data" / "snooker_camera"
CHECKPOINT = DATA / "pink_shot.checkpoint"
SESSION = DATA / "pink_shot.session.json"
CUE_START = (0.5, 1.4)  # table coordinates (m): baulk end, near the left cushion
ARRIVAL_SPEED = 1.5  # m/s at the ghost-ball position


def make() -> Session:
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


def main() -> None:
    s = make()
    s.checkpoint().write(CHECKPOINT)
    s.save(SESSION)
    print(f"wrote {CHECKPOINT} ({s.checkpoint().n_frames} frames) and {SESSION}")


if __name__ == "__main__":
    main()
