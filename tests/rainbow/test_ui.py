"""The thesis's Rainbow techniques, through the client API: double buffering, a scrolling
pop-up menu, a cross-shaped menu, message areas and the four-times-mapped panning pad."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.emulator.machine import RainbowMachine
from camlab88.protocols.rainbow import SCREEN
from camlab88.protocols.rainbow.ui import CrossMenu, DoubleBuffer, MessageArea, PopupMenu, SuperPad
from camlab88.protocols.rainbow.ui.menu import ROW_H


def _rgb(hexs: str) -> list[int]:
    return [int(hexs[i: i + 2], 16) for i in (1, 3, 5)]


def test_double_buffered_animation_shows_only_whole_frames() -> None:
    s = RainbowMachine()
    c = s.client
    c.set_lut(0, ["#000000", "#ffffff"])
    db = DoubleBuffer(c, SCREEN, 200, 100, 1, x=50, y=50)
    shown = []
    for step in range(6):
        c.clear(db.back, 0)
        c.rect(db.back, step * 20, 10, 20, 20, 1)
        # half-way through drawing the next picture the screen still shows the old one
        c.wait_frame()
        half = s.shown()[60:80, 50:250, 0] > 0
        if step:
            assert half.any() and not half[:, step * 20: step * 20 + 20].all()
        db.swap()
        c.wait_frame()
        lit = np.flatnonzero(s.shown()[70, 50:250, 0] > 0)
        shown.append((int(lit.min()), int(lit.max())))
        assert np.array_equal(s.executor.last_frame, s.device.reference())
    assert shown == [(i * 20, i * 20 + 19) for i in range(6)]
    assert db.swaps == 6


def test_scrolling_menu_moves_pad_inside_smaller_cluster() -> None:
    s = RainbowMachine()
    c = s.client
    items = [f"Item {i}" for i in range(12)] + ["Do nothing"]
    menu = PopupMenu(c, items, visible_rows=5)
    words_before = None
    menu.open(300, 300)
    c.wait_frame()
    assert menu.highlighted == items.index("Do nothing")  # highlighted first
    frame = s.executor.last_frame
    assert (frame == _rgb(menu.highlights[12])).all(axis=-1).any()
    words_before = s.device.memory.words.copy()
    # move the invisible cursor up to the top of the window: the menu scrolls down
    seen = []
    for _ in range(200):
        seen.append(menu.track(300, menu.y + 2))
        c.wait_frame()
    assert menu.scroll == 0
    # the items under the cursor run smoothly back to Item 0 as the menu scrolls down
    assert seen[-1] == 0 and seen[0] > 5
    assert all(b in (a, a - 1) for a, b in zip(seen, seen[1:]))
    # the window (cluster) stayed 5 rows high: nothing of the menu below it
    lit = np.flatnonzero(np.any(s.shown()[:, 300] != 0, axis=-1))
    assert lit.max() - lit.min() + 1 == 5 * ROW_H
    # and back down
    for _ in range(200):
        menu.track(300, menu.y + 5 * ROW_H - 2)
    assert menu.scroll == 5 * ROW_H - 13 * ROW_H
    assert menu.close() == "Do nothing"
    c.wait_frame()
    assert not np.any(s.executor.last_frame)  # gone, nothing beneath
    # highlighting and scrolling never redrew a pixel: all done by LUT writes and arc moves
    assert np.array_equal(s.device.memory.words, words_before)


def test_a_scrolled_menu_reattached_from_a_loaded_rainbow_goes_on_alike() -> None:
    """A scrolling menu, open and scrolled, kept as the Rainbow's session state and the
    menu's plain values: re-attached on a fresh Rainbow loaded from them (nothing sent), it
    tracks, lights, scrolls and closes with the frames of the menu that never stopped."""
    items = [f"Item {i}" for i in range(12)] + ["Do nothing"]
    a = RainbowMachine()
    menu = PopupMenu(a.client, items, visible_rows=5)
    menu.open(300, 300)
    for _ in range(40):
        menu.track(300, menu.y + 2)
    assert menu.scroll < 0 and menu.is_made_last()
    b = RainbowMachine()
    b.check_session_state(a.session_state())()
    calls = b.client.calls
    again = PopupMenu.reattached(b.client, items, menu.state_values(), visible_rows=5)
    assert b.client.calls == calls  # nothing drawn or sent
    assert (again.pad, again.cluster, again.inner, again.arc) == (
        menu.pad, menu.cluster, menu.inner, menu.arc)
    for y in [menu.y + 2] * 30 + [menu.y + 40] + [menu.y + 5 * ROW_H - 2] * 60:
        assert again.track(300, y) == menu.track(300, y)
        a.client.wait_frame()
        b.client.wait_frame()
        assert np.array_equal(a.shown(), b.shown())
    assert again.close() == menu.close()
    a.client.create_pad(8, 8, 1)
    assert not menu.is_made_last()  # something was made after it


def test_menu_values_outside_where_the_menu_can_be_are_refused() -> None:
    c = RainbowMachine().client
    items = [f"Item {i}" for i in range(12)]
    menu = PopupMenu(c, items, visible_rows=5)
    good = menu.state_values()
    for name, value in (("scroll", 1), ("scroll", -8 * ROW_H - 1), ("x", -1), ("y", 10**6),
                        ("highlighted", 12)):
        with pytest.raises(ValueError, match=f"menu {'item' if name == 'highlighted' else name}"):
            PopupMenu.reattached(c, items, dict(good, **{name: value}), visible_rows=5)


def test_cross_menu_chooses_by_direction() -> None:
    s = RainbowMachine()
    c = s.client
    items = {"centre": "Finish editing", "up": "Step up", "down": "Step down",
             "left": "Set to value", "right": "Pick up colour"}
    m = CrossMenu(c, items)
    for (dx, dy), want in (((0, 3), "Finish editing"), ((0, -40), "Step up"),
                           ((3, 200), "Step down"), ((-90, 10), "Set to value"),
                           ((50, -20), "Pick up colour")):
        m.open(400, 300)
        c.wait_frame()
        m.track(400 + dx, 300 + dy)
        c.wait_frame()
        assert m.close() == want
    # corners of the cross are transparent: the cluster has nothing mapped there
    m.open(400, 300)
    c.wait_frame()
    f = s.executor.last_frame
    assert not f[300 - 30, 400 - 150].any() and f[300, 400].any()


def test_message_area_colour_and_text() -> None:
    s = RainbowMachine()
    c = s.client
    msg = MessageArea(c, 10, 10, 200, 30, lut_page=3)
    msg.show("Move ball", "#ffc0cb")
    c.wait_frame()
    f = s.shown()[10:40, 10:210]
    assert (f == _rgb("#ffc0cb")).all(axis=-1).sum() > 3000  # pink paper
    assert (f == 0).all(axis=-1).sum() > 20  # black writing
    msg.hide()
    c.wait_frame()
    assert not s.executor.last_frame.any()


def world(wx: np.ndarray, wy: np.ndarray) -> np.ndarray:
    """An endless checked plane with diagonal stripes: every position is distinguishable."""
    return ((wx // 16 + wy // 16) % 2 + 2 * ((wx + 2 * wy) % 7 == 0)).astype(np.uint8)


def test_four_times_mapped_panning() -> None:
    s = RainbowMachine()
    c = s.client
    c.set_lut(0, ["#202020", "#e0e0e0", "#ff0000", "#ff8080"])
    view = c.create_cluster(752, 576)
    c.map(SCREEN, view, 0, 0)

    def draw(wx, wy, w, h, px, py):
        yy, xx = np.mgrid[wy: wy + h, wx: wx + w]
        c.put_pixels(sp.pad, px, py, world(xx, yy))

    sp = SuperPad.__new__(SuperPad)  # so draw() can see sp.pad during construction
    SuperPad.__init__(sp, c, view, 752, 576, 768, 592, 2, draw)
    assert len(sp.arcs) == 4
    lut = np.array([[0x20] * 3, [0xe0] * 3, [255, 0, 0], [255, 128, 128]], np.uint8)
    pans = [(5, 0), (0, 7), (-13, -3), (300, 0), (400, 350), (-1000, 20), (17, -600), (1, 1)]
    for dx, dy in pans:
        drawn = sp.drawn_pixels
        sp.pan(dx, dy)
        c.wait_frame()
        yy, xx = np.mgrid[sp.vy: sp.vy + 576, sp.vx: sp.vx + 752]
        want = lut[world(xx, yy)]
        got = s.shown()[:, :752]
        assert np.array_equal(got, want), (dx, dy)
        # only the newly exposed strips were drawn
        if abs(dx) < 752 and abs(dy) < 576:
            exposed = 752 * 576 - (752 - abs(dx)) * (576 - abs(dy))
            assert sp.drawn_pixels - drawn == exposed
    assert np.array_equal(s.executor.last_frame, s.device.reference())


def test_a_pop_up_menu_is_pastel_with_a_white_border_and_black_writing() -> None:
    """§6.2.1: "pastel colours", a white border, black writing; the item under the
    invisible cursor turns to its own pastel colour."""
    s = RainbowMachine()
    c = s.client
    items = ["Pot", "Place", "Do nothing"]
    menu = PopupMenu(c, items)
    menu.open(300, 300)
    c.wait_frame()
    box = s.shown()[menu.y: menu.y + menu.window_h, menu.x: menu.x + menu.width]
    colours = {tuple(int(v) for v in px) for px in box.reshape(-1, 3)}
    item = _rgb(menu.colour)
    lit = _rgb(menu.highlights[2])  # 'Do nothing', highlighted first
    assert colours == {(255, 255, 255), (0, 0, 0), tuple(item), tuple(lit)}
    assert (box[0] == 255).all() and (box[:, 0] == 255).all()  # the white border
    assert (box[ROW_H * 2 + 9, 2: menu.width - 2] == lit).all(axis=-1).sum() > 10
    for rgb in [item] + [_rgb(h) for h in menu.highlights]:
        value, chroma = max(rgb), max(rgb) - min(rgb)
        assert value >= 230 and 0.15 <= chroma / value <= 0.45  # pastel: bright, pale hue
    menu.track(menu.x + 20, menu.y + 5)  # the cursor passes over 'Pot'
    c.wait_frame()
    box = s.shown()[menu.y: menu.y + menu.window_h, menu.x: menu.x + menu.width]
    assert (box[9] == _rgb(menu.highlights[0])).all(axis=-1).sum() > 10
    assert (box[ROW_H * 2 + 9] == lit).all(axis=-1).sum() == 0  # back to the menu colour
