"""Pure parts: scripted input, table <-> screen mapping, arrows, the menus' item lists."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.snooker.program import arrows, menus, script_events
from camlab88.apps.snooker.program.layout import TableView
from camlab88.apps.snooker.table import Table
from camlab88.protocols.rainbow.client import SCREEN_W
from camlab88.protocols.rainbow.events import LEFT, MIDDLE, KeyEvent, MouseEvent

VIEW = TableView.fit(Table())


def test_script_commands():
    s = script_events.parse("move 10 20\npress middle\nglide 20 40 2\nrelease middle\n"
                            "wait 3\ntype a b\nkey return\n")
    assert s.frames == 4
    (first, n1), (second, n2) = s.steps
    assert n1 == 3 and n2 == 1
    assert first == [MouseEvent(0, 10, 20, 0), MouseEvent(0, 10, 20, MIDDLE, 2, True),
                     MouseEvent(0, 15, 30, MIDDLE), MouseEvent(0, 20, 40, MIDDLE),
                     MouseEvent(0, 20, 40, 0, 2, False)]
    keys = [e.key for e in second if isinstance(e, KeyEvent) and e.pressed]
    assert keys == ["a", "space", "b", "return"]


def test_script_buttons_accumulate():
    s = script_events.parse("press left\npress middle\nmove 1 1\nrelease left\n")
    evs = s.steps[0][0]
    assert [e.buttons for e in evs] == [LEFT, LEFT | MIDDLE, LEFT | MIDDLE, MIDDLE]


@pytest.mark.parametrize("text, msg", [
    ("move 1", "s.txt:1:6: move wants 2 numbers"),
    ("\n\npress thumb", "s.txt:3:7: press needs a button: left, middle or right"),
    ("wait x", "s.txt:1:6: expected a whole number, found 'x'"),
    ("wait -1", "s.txt:1:6: value -1 is outside 0..1000000"),
    ("jump 3", "s.txt:1:1: unknown command 'jump'"),
    ("glide 1 2 0", "s.txt:1:11: number of steps 0 is outside 1..10000"),
    ("key", "s.txt:1:1: key wants one key name"),
    ("move 2147483648 0", "s.txt:1:6: coordinate 2147483648 is outside -32768..32767"),
    ("drag left 0 0 9 9 99999", "s.txt:1:19: number of steps 99999 is outside 1..10000"),
    ("wait 600000\nwait 600000", "s.txt:2:6: the script runs 1200000 frames, more than"),
])
def test_script_errors_name_file_and_line(text, msg):
    with pytest.raises(script_events.ScriptError, match=msg):
        script_events.parse(text, "s.txt")


def test_script_file_errors(tmp_path):
    p = tmp_path / "bad.events"
    p.write_bytes(b"move 1 2\n\xff\n")
    with pytest.raises(script_events.ScriptError, match="bad.events:2:1: not UTF-8"):
        script_events.load(p)
    with pytest.raises(script_events.ScriptError, match="cannot read"):
        script_events.load(tmp_path / "missing")


@settings(max_examples=60, deadline=None)
@given(st.text(alphabet="movepresswaitglidekytl 0123456789-\n#", max_size=80))
def test_script_parser_never_crashes(text):
    try:
        s = script_events.parse(text)
    except script_events.ScriptError as exc:
        assert str(exc).startswith("<script>:")
        return
    player = script_events.Player(s)
    for _ in range(s.frames + 2):
        player.due()
    assert player.finished


def test_player_spreads_batches_over_frames():
    p = script_events.Player(script_events.parse("move 1 1\nwait 2\nmove 2 2\nwait 1\n"))
    got = [p.due() for _ in range(4)]
    assert [len(g) for g in got] == [1, 0, 1, 0]
    assert p.finished


@settings(max_examples=50, deadline=None)
@given(st.floats(0, 3.6), st.floats(0, 1.86))
def test_table_screen_round_trip(x, y):
    sx, sy = VIEW.to_screen(x, y)
    assert VIEW.to_table(sx, sy) == pytest.approx((x, y), abs=1e-9)


def test_orientation_overhead_baulk_on_the_left():
    t = Table()
    bx, _ = VIEW.to_screen(0.0, t.width_m / 2)
    tx, _ = VIEW.to_screen(t.length_m, t.width_m / 2)
    assert bx < tx
    # +y is to the left of a player looking up the table: the screen's up
    _, y_left = VIEW.to_screen(1.0, t.width_m)
    _, y_right = VIEW.to_screen(1.0, 0.0)
    assert y_left < y_right
    x, y, w, h = VIEW.play_rect
    assert 0 < x and x + w < 768 and 60 < y and y + h < 540


def test_velocity_arrow_round_trip_and_scale():
    start = VIEW.to_screen(1.0, 0.9)
    end = arrows.arrow_end(VIEW, start, (2.0, -1.0))
    assert math.hypot(end[0] - start[0], end[1] - start[1]) == pytest.approx(
        math.sqrt(5) * arrows.PX_PER_M_S)
    assert arrows.velocity_from_arrow(VIEW, start, end) == pytest.approx((2.0, -1.0))


def test_spin_up_is_top_spin_and_lies_along_the_arrow():
    assert arrows.spin_from_drag(-60) == pytest.approx(1.0)
    assert arrows.spin_from_drag(30) == pytest.approx(-0.5)
    seg = arrows.spin_arrow((100, 100), (200, 100), -0.5)
    assert seg == (100, 100, 70, 100)  # back spin points backwards along the line
    assert arrows.spin_arrow((100, 100), (100, 100), 1.0) is None


def test_dotted_extension_and_path():
    dots = arrows.dotted_extension((0, 0), (10, 0), length=40)
    assert dots == [(10 + d, 0) for d in range(6, 40, 6)]
    path = arrows.dotted_path([(0, 0), (12, 0), (12, 12)])
    assert path[0] == (0, 0) and (12, 6) in path and (12, 12) in path
    assert all(abs(a[0] - b[0]) + abs(a[1] - b[1]) <= 6 for a, b in zip(path, path[1:]))


def test_menus_are_the_thesis_lists():
    # §6.2.2, item for item, copied from the thesis into tests/data/snooker_program/menus.txt
    green, orange = thesis_menus()
    assert menus.GREEN_ITEMS == green
    assert menus.ORANGE_ITEMS == orange
    assert menus.ORANGE_VISIBLE_ROWS < len(menus.ORANGE_ITEMS)  # it scrolls


def thesis_menus() -> tuple[list[str], list[str]]:
    text = (Path(__file__).parents[1] / "data" / "snooker_program" / "menus.txt").read_text()
    lists: dict[str, list[str]] = {}
    current = ""
    for line in text.splitlines():
        if line.startswith("Menu when"):
            current = "green" if "no ball" in line else "orange"
            lists[current] = []
        elif line.startswith("- "):
            lists[current].append(line[2:])
    return lists["green"], lists["orange"]


def test_menus_fit_on_the_screen_unabridged(rainbow):
    for menu in (menus.green_menu(rainbow.client), menus.orange_menu(rainbow.client)):
        assert menu.width <= SCREEN_W
        assert menu.width >= max(len(s) for s in menu.items) * 6


def _rgb(c: str) -> list[int]:
    return [int(c[k:k + 2], 16) for k in (1, 3, 5)]


def test_highlights_are_distinct_pastels_but_the_velocity_green():
    velocity = {menus.VELOCITY_MOUSE, menus.CUE_VELOCITY}  # the same command, two menus
    items = [i for i in dict.fromkeys(menus.GREEN_ITEMS + menus.ORANGE_ITEMS)
             if i not in velocity]
    cols = [menus.HIGHLIGHT[i] for i in items]
    assert len(set(cols)) == len(cols) and menus.DEEP_GREEN not in cols
    for c in cols + [menus.GREEN, menus.ORANGE]:
        rgb = [int(c[k:k + 2], 16) for k in (1, 3, 5)]
        assert min(rgb) >= 0x80  # pastel: light, little saturation


@pytest.mark.claim("§6.2.1: a mistaken position choice shows \"a pink message ... rather than "
                   "a deep green one\" (the velocity message)", measured="the message colours "
                   "of the mouse position and velocity items: pink (red highest, light) and a "
                   "deep green (green highest, red and blue under half of it, not pastel)",
                   verdict="agrees (the other highlights are pastel, as §6.2.1 says)")
def test_velocity_message_is_deep_green_position_pink():
    r, g, b = _rgb(menus.HIGHLIGHT[menus.VELOCITY_MOUSE])
    assert g > 0x80 and r < g // 2 and b < g // 2 and min(r, g, b) < 0x80
    assert menus.HIGHLIGHT[menus.CUE_VELOCITY] == menus.HIGHLIGHT[menus.VELOCITY_MOUSE]
    r, g, b = _rgb(menus.HIGHLIGHT[menus.POSITION_MOUSE])
    assert r > g and r > b and min(r, g, b) >= 0x80
