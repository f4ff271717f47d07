"""The real-time viewer's shown/dropped frames against calculations by hand (9600 8N1), timed
from the first transmitted character (the thesis's clock: tests/kas/test_viewer_clock.py)."""

from __future__ import annotations

import pytest

from camlab88.apps.kas import viewer_schedule as vs


def test_960_characters_a_second():
    assert vs.chars_per_second(9600, 10) == 960


def test_big_frames_hand_calculation():
    # 300 chars = 0.3125 s each at 960 chars/s; 25 fps -> a frame is due every 0.04 s.
    # f0 sent 0 -> 0.3125 (shown); due floor(0.3125 * 25) = 7 -> f7 sent 0.3125 -> 0.625;
    # due floor(15.625) = 15 >= 10 frames: stop.
    s = vs.realtime([300] * 10, clock="first-sent")
    assert s.shown_frames == [0, 7]
    assert s.dropped == [1, 2, 3, 4, 5, 6, 8, 9]
    assert s.shown[1].send_start == pytest.approx(0.3125)
    assert s.end == pytest.approx(0.625)


def test_mixed_frames_hand_calculation():
    # 48 chars = 0.05 s, 96 = 0.1 s, 10 = 0.0104 s.
    # f0 0 -> .05, due 1; f1 .05 -> .10, due 2; f2 .10 -> .20, due 5 -> drop 3, 4;
    # f5 .20 -> .2104, its due time .20 has passed: shown at once.
    s = vs.realtime([48, 48, 96, 10, 10, 10], clock="first-sent")
    assert s.shown_frames == [0, 1, 2, 5]
    assert s.dropped == [3, 4]
    assert s.end == pytest.approx(0.2 + 10 / 960)


def test_fast_frames_wait_for_their_time():
    # 10 chars each: drawn in 0.0104 s, then held until due (0.04 s apart): nothing dropped.
    s = vs.realtime([10] * 5, clock="first-sent")
    assert s.shown_frames == [0, 1, 2, 3, 4] and not s.dropped
    assert [round(x.shown, 6) for x in s.shown] == [round(10 / 960, 6), 0.04, 0.08, 0.12, 0.16]


def test_faster_line_shows_more_frames():
    sizes = [120] * 50
    slow = vs.realtime(sizes, baud=9600, clock="first-sent")
    fast = vs.realtime(sizes, baud=38400, clock="first-sent")
    assert len(fast.shown) > len(slow.shown)
    # 120 chars = 0.125 s at 9600: f0 drawn at .125 when frame 3 is due; f3 at .25 (6 due);
    # f6 at .375 (9 due) ...
    assert slow.shown_frames[:4] == [0, 3, 6, 9]


def test_every_frame_mode():
    s = vs.every_frame([96, 48])
    assert s.shown_frames == [0, 1] and s.end == pytest.approx(0.15)
