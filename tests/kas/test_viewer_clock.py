"""§3.1.4: the real-time viewer's clock starts when the first frame is displayed."""

from __future__ import annotations

import pytest

from camlab88.apps.kas import viewer_schedule as vs


@pytest.mark.claim("§3.1.4: the viewer keeps track of the elapsed time since the first frame "
                   "of the sequence was displayed", measured="frame k due at shown_0 + k/fps "
                   "(hand calculations at 9600 baud 8N1)", verdict="agrees")
def test_clock_starts_at_the_first_displayed_frame() -> None:
    # 300 chars = 0.3125 s each at 960 chars/s; 25 fps.  f0 shown at 0.3125 (time 0 of the
    # sequence); due floor(0) = 0 is on screen, so f1 is sent: 0.3125 -> 0.625; due
    # floor((0.625 - 0.3125) * 25) = 7 -> f7 0.625 -> 0.9375; due 15 >= 10: stop.
    s = vs.realtime([300] * 10)
    assert s.shown_frames == [0, 1, 7]
    assert s.dropped == [2, 3, 4, 5, 6, 8, 9]
    assert s.shown[1].shown == pytest.approx(0.625) and s.end == pytest.approx(0.9375)
    # timed from the first character instead, f1 counts as 7 frames late and is dropped
    assert vs.realtime([300] * 10, clock="first-sent").shown_frames == [0, 7]


def test_due_times_count_from_frame_0_on_the_screen() -> None:
    # 48 chars = 0.05 s, 96 = 0.1 s, 10 = 0.0104 s; f0 shown at 0.05, f_k due 0.05 + 0.04 k.
    # f1 .05 -> .10 (due .09); f2 .10 -> .20 (due .13); due floor(.15 * 25) = 3: f3 .20 ->
    # .2104 (due .17); f4 -> .2208 (due .21); f5 -> .2313, held until its due time .25.
    s = vs.realtime([48, 48, 96, 10, 10, 10])
    assert s.shown_frames == [0, 1, 2, 3, 4, 5] and not s.dropped
    assert [round(x.shown, 4) for x in s.shown] == [0.05, 0.1, 0.2, 0.2104, 0.2208, 0.25]


def test_fast_frames_keep_the_frame_rate_after_the_first() -> None:
    s = vs.realtime([10] * 5)
    first = 10 / 960
    assert [x.shown for x in s.shown] == pytest.approx([first + k * 0.04 for k in range(5)])


def test_unknown_clock_is_refused() -> None:
    with pytest.raises(ValueError, match="first-shown"):
        vs.realtime([10], clock="wall")
