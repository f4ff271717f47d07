"""Makes tests/data/snooker_render/break.checkpoint: the opening break of a new game, made
with the motion program's own model (all 22 balls on the table; the cue ball struck from
the D into the pack). Run ``.venv/bin/python -m tests.snooker_render.break_shot``;
test_data.py checks the shipped file is what this makes."""

from __future__ import annotations

import math
from pathlib import Path

from camlab88.apps.snooker.session import Session
from camlab88.apps.snooker.table import CUE

OUT = Path(__file__).resolve().parents[1] / "data" / "snooker_render" / "break.checkpoint"
FRAMES = 40


def make() -> str:
    s = Session.new_game()
    red = s.balls.pos[7]
    cue = s.balls.pos[CUE]
    angle = math.degrees(math.atan2(red[1] - cue[1], red[0] - cue[0]))
    s.strike(CUE, 6.0, angle)
    for _ in range(FRAMES - 1):
        s.simulate_frame()
    return s.checkpoint(0, FRAMES - 1).to_text()


if __name__ == "__main__":
    from camlab88.base.atomicfile import write_atomic

    write_atomic(OUT, make(), encoding="ascii")
    print(f"wrote {OUT}")
