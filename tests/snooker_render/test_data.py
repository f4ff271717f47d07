from __future__ import annotations

from tests.snooker_render import break_shot
from tests.snooker_render.helpers import BREAK, break_scene, break_views


def test_shipped_break_is_what_the_motion_program_makes() -> None:
    assert BREAK.read_text(encoding="ascii") == break_shot.make()


def test_break_has_all_balls_and_a_view_per_frame() -> None:
    s = break_scene()
    assert s.n_frames == break_shot.FRAMES
    assert s.on_table[0].all()
    assert [v.frame for v in break_views()] == list(range(1, s.n_frames + 1))
