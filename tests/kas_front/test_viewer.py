"""The line test over the line: counts equal the schedule; the double buffer hides drawing."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.kas import demo
from camlab88.apps.kas import viewer_schedule as vs
from camlab88.apps.kas.program.viewer import (
    LineTest,
    ViewerHost,
    draw_frame,
    four_colours,
    setup,
    swap,
)
from camlab88.emulator.harness.sigma_batch import host_periods
from camlab88.emulator.machine import SigmaMachine
from camlab88.emulator.sigma import Terminal
from camlab88.protocols.link import LineSettings


@pytest.fixture(scope="module")
def seq():
    return demo.build()


@pytest.mark.parametrize("how", ["lut", "mask"])
def test_realtime_counts_equal_the_schedule(seq, how: str) -> None:
    test = LineTest(seq, how)
    sizes = test.sizes()
    shown = {}
    for baud in (9600, 19200, 38400):
        rep = test.run("realtime", baud)
        want = vs.realtime(sizes, seq.fps, baud)
        assert rep.shown_frames == want.shown_frames
        assert rep.dropped == want.dropped
        assert len(rep.shown) + len(rep.dropped) == len(seq)
        # the bytes really sent per shown frame are the sizes the schedule was given
        sent = [len(d) for _, d in rep.sent[1:]]
        assert [a + b for a, b in zip(sent[0::2], sent[1::2], strict=True)] == \
            [sizes[j] for j in rep.shown_frames]
        shown[baud] = len(rep.shown)
    assert shown[9600] < shown[19200] < shown[38400]
    assert shown[9600] < len(seq)  # 9600 baud cannot carry this sequence in real time


def test_every_frame_mode_shows_all(seq) -> None:
    rep = LineTest(seq).run("every", 9600)
    assert rep.shown_frames == list(range(len(seq))) and rep.dropped == []
    sched = vs.every_frame(LineTest(seq).sizes())
    assert rep.end - rep.start == pytest.approx(sched.end)


def _reference(test: LineTest, j: int) -> np.ndarray:
    t = Terminal("t5684")
    t.feed(setup(test.enc, test.plan, test.how) + draw_frame(test.enc, test.seq.frames[j], 0,
                                                             test.plan)
           + swap(test.enc, 0, test.plan, test.how))
    return t.frame()


@pytest.mark.parametrize("how", ["lut", "mask"])
def test_double_buffer_never_shows_a_half_drawn_frame(seq, how: str) -> None:
    test = LineTest(seq, how)
    refs = [_reference(test, j) for j in range(len(seq))]
    blank = np.zeros_like(refs[0])
    rgb = np.array(test.plan.rgb, dtype=np.uint8) * 17
    seen: list[np.ndarray] = []
    hidden_partial = 0
    mixed = 0

    def is_complete(img: np.ndarray) -> bool:
        return any(np.array_equal(img, r) for r in refs) or np.array_equal(img, blank)

    def period(_k: int, t: Terminal) -> None:
        nonlocal hidden_partial
        seen.append(t.frame())
        # what each 2-bit buffer holds, as a picture: one of them is often caught half
        # drawn, so the check on the displayed frame below is not vacuous
        for shift in (0, 2):
            img = rgb[(t.planes[::-1] >> shift) & 3]
            if not is_complete(img):
                hidden_partial += 1

    machine = SigmaMachine("t5684")
    host = ViewerHost(test, "every", machine.host, LineSettings(baud=9600))
    for k in host_periods(machine, host, host.period):
        period(k, machine.terminal)
    assert len(seen) > 100
    assert hidden_partial > 20
    k = -1  # the last complete frame seen
    for f in seen:
        if k < 0 and np.array_equal(f, blank):
            continue
        match = [j for j in range(max(k, 0), len(seq)) if np.array_equal(f, refs[j])]
        if match:
            k = match[0]
            continue
        # only the LUT rewrite itself can mix, and then only the two whole frames it switches
        assert how == "lut", "the display-mask swap is a single order"
        a = refs[k] if k >= 0 else blank
        b = refs[k + 1]
        assert np.all((f == a) | (f == b), axis=-1).all(), "a part-drawn buffer was visible"
        # and while the swap's orders arrive one whole frame stays up: never a gap
        on = f.any(axis=-1)
        assert (on >= a.any(axis=-1)).all() or (on >= b.any(axis=-1)).all(), \
            "the swap showed neither the old frame nor the new one whole"
        mixed += 1
    assert np.array_equal(seen[-1], refs[-1])
    if how == "lut":
        assert mixed > 5  # periods caught mid-swap were really checked


def test_four_colours_keep_the_most_used_pens(seq) -> None:
    plan = four_colours(seq)
    assert sorted(plan.slot_of_pen.values())[:1] == [1]
    assert set(plan.slot_of_pen.values()) <= {1, 2, 3}
    assert len(plan.rgb) == 4 and plan.rgb[0] == (0, 0, 0)


def test_pens_beyond_the_three_most_used_borrow_the_nearest_colour(seq) -> None:
    import copy

    from camlab88.apps.kas.paint import outlines
    from camlab88.apps.kas.pens import pen_counts, pen_slots

    more = copy.deepcopy(seq)
    more.frames[0].chains[0].colours[:] = 7  # a fourth pen, used least
    counts = pen_counts(more)
    assert counts[7] == len(seq.frames[0].chains[0].colours)
    top = sorted(counts, key=lambda p: (-counts[p], p))[:3]
    assert 7 in counts and 7 not in top
    colours = {top[0]: (0, 0, 0), top[1]: (0, 0, 10), top[2]: (200, 0, 0), 7: (0, 0, 9)}
    got_top, slots = pen_slots(more, colours.__getitem__)
    assert got_top == top and [slots[p] for p in top] == [1, 2, 3]
    assert slots[7] == 2  # (0, 0, 9) is nearest (0, 0, 10)
    # on black the line test and the painting program put every pen in the same slot
    assert four_colours(more).slot_of_pen == outlines.plan(more).slot_of_pen
