"""The keyframe editor driven headless over the real byte path: script -> input layer and
terminal keyboard -> line -> program -> Encoder -> line -> emulated Sigma."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.kas.editor import Editor
from camlab88.apps.kas.files import KasFileError
from camlab88.apps.kas.program import EditorFront, parse_timed_script
from camlab88.emulator.sigma import Terminal
from camlab88.protocols.sigma.keyboard import bytes_to_keys
from tests.kas_front.helpers import DATA, GOLDEN, drive, model_only, run_editor
from tests.support.golden import assert_matches_golden


@pytest.fixture(scope="module")
def edit_all():
    return run_editor("edit_all.txt")


def test_every_command_through_the_front_matches_the_model(edit_all) -> None:
    front, term, session, saved = edit_all
    want = model_only("edit_all.txt")
    got = front.editor.drawing
    assert len(got.chains) == len(want.drawing.chains) == 5
    for a, b in zip(got.chains, want.drawing.chains, strict=True):
        np.testing.assert_allclose(a.points, b.points, atol=1e-9)
        assert a.colours.tolist() == b.colours.tolist()
        assert a.section == b.section
    # F2 at the end saved exactly that drawing
    assert len(saved) == 1 and saved[0].n_points == got.n_points
    # keys really went up the line, drawing orders down it, all understood
    assert session.machine.line.stats["device_to_host_bytes"] >= 60
    assert term.stats["unknown"] == term.stats["malformed"] == term.stats["errors"] == 0


def test_edit_session_screen_golden(edit_all) -> None:
    _front, term, _s, _saved = edit_all
    assert_matches_golden(term.frame(), GOLDEN / "edit_all.png")


def test_incremental_redraw_equals_a_full_redraw(edit_all) -> None:
    front, term, _s, _saved = edit_all
    fresh = Terminal("t5684")
    fresh.feed(EditorFront(front.editor).start())
    assert np.array_equal(fresh.indices(), term.indices())
    # and it really was incremental: many partial updates, one full draw
    assert front.painter.stats["full"] == 1
    assert front.painter.stats["erased"] > 10


def test_freehand_sends_only_new_segments() -> None:
    front = EditorFront(Editor())
    s = drive(front)
    # after the start-up screen has arrived, one new point every 0.1 s
    s.run_script(parse_timed_script("5.0 move 0 0\ndown 0 0\n" + "".join(
        f"+0.1 down {0.1 * i} {0.05 * (i % 3)}\n" for i in range(1, 30))))
    sizes = [len(d) for _, d in s.session.sent[1:]]
    assert len(sizes) >= 25
    assert len(front.editor.drawing.chains[0]) == 30
    assert max(sizes[1:]) < 40  # a few AGS bytes per new point, never the whole chain again
    assert front.painter.stats["grown"] >= 10


def test_white_background_golden() -> None:
    front, term, _s, _saved = run_editor("white.txt", background="white")
    assert len(front.editor.drawing.chains) == 2
    frame = term.frame()
    assert (frame[200, 300] == 255).all()  # the background is white
    assert_matches_golden(frame, GOLDEN / "white.png")


def test_stylus_cursor_follows_without_touching_the_planes() -> None:
    front = EditorFront(Editor())
    s = drive(front)
    term = s.terminal
    s.run_script(parse_timed_script("move 0 0\n0.5 move 2 1\n1.0 wait"))
    before = term.indices().copy()
    s.run_script(parse_timed_script("move -3 -2\n+0.5 wait"))
    assert np.array_equal(before, term.indices())
    assert (term.reg.cursor_x, term.reg.cursor_y) == (296 - 144, 218 - 96)
    assert front.editor.drawing.chains == []


@pytest.mark.parametrize("text, where", [
    ("move 0 0\nmove 1\n", ":2:"),
    ("1.0 move 0 0\n0.5 move 1 1\n", ":2:"),
    ("menu nothing\n", ":1:"),
    ("key f13\n", ":1:"),
    ("2.0\n", ":1:"),
    ("move nan 0\n", ":1:"),
])
def test_bad_script_names_the_line(text: str, where: str) -> None:
    with pytest.raises(KasFileError) as exc:
        parse_timed_script(text, "s.txt")
    assert f"s.txt{where}" in str(exc.value)


def test_script_times() -> None:
    ev = parse_timed_script("move 0 0\n+0.5 key a\n2 type bc\nmenu pen2\n")
    assert [float(e.t) for e in ev] == [0.0, 0.5, 2.0, 2.02, 2.04, 2.06]
    assert [e.key for e in ev if e.kind == "key"] == ["a", "b", "c"]


# Points of edit_all.txt (line numbers) where the Sigma's screen is checked, with what must be
# true of its colour indices there (10 = old positions, faint purple; 11 = unmoved, dim).
CHECKPOINTS = [
    (61, "drawn", {10: False, 11: False}),        # drawing mode, everything drawn
    (78, "moved", {10: True, 11: True}),          # background on; move, back, again
    (111, "stretched", {10: True, 11: True}),     # rotate, reflect x2, enlarge+back, stretch+back
    (135, "deregularised", {10: True}),           # move chain/section, colours, x twice
    (168, "background_off", {10: False, 11: False}),  # collapse, insert, delete; g off
]


@pytest.mark.parametrize("line, name, has", CHECKPOINTS)
def test_screen_at_points_of_the_edit_session(line: int, name: str, has: dict) -> None:
    text = "\n".join((DATA / "edit_all.txt").read_text(encoding="utf-8").splitlines()[:line])
    front = EditorFront(Editor(seed=1))
    run = drive(front)
    term = run.terminal
    run.run_script(parse_timed_script(text + "\n", "edit_all.txt"))
    idx = term.indices()
    for index, present in has.items():
        assert bool((idx == index).any()) == present, (name, index)
    # the incrementally updated screen is what a full redraw of the model gives
    fresh = Terminal("t5684")
    fresh.feed(EditorFront(front.editor).start())
    assert np.array_equal(fresh.indices(), idx)
    assert_matches_golden(term.frame(), GOLDEN / f"edit_all_{line:03d}_{name}.png")


# docs/fidelity/kas.md, "Key codes of cursor keys and F2 (^P ^N ^B ^F, ^W)": written out here,
# not read from the program's table, so a changed code fails.
LEDGER_KEY_CODES = {"up": 0x10, "down": 0x0E, "left": 0x02, "right": 0x06, "f2": 0x17}


@pytest.mark.parametrize(("key", "code"), LEDGER_KEY_CODES.items())
def test_the_terminal_sends_the_ledgers_key_codes(key: str, code: int) -> None:
    """The key struck on the emulated T5684's keyboard, as the kas commands wire it: the
    byte that arrives at the host's end of the line, and KAS hears that byte as the key."""
    from camlab88.emulator.harness.sigma import SigmaSessionRun
    from camlab88.emulator.machine import SigmaMachine

    class Tap:  # a host session that only listens
        got = b""

        def begin(self) -> None: ...

        def step(self, mouse: object) -> None:
            self.got += machine.host.read()

        def busy(self) -> bool:
            return False

    machine = SigmaMachine("t5684")
    tap = Tap()
    run = SigmaSessionRun(machine, tap)
    run.step(keys=[key])
    for _ in range(10):  # a byte is about a millisecond of line at 9600 baud
        run.step()
    assert tap.got == bytes([code])
    assert bytes_to_keys(tap.got) == [key]


def test_vectors_go_in_abbreviated_graphics_mode_about_half_the_characters() -> None:
    # §3.1.4: the programs send vectors in abbreviated graphics mode, saving about half
    from camlab88.apps.kas.program.draw import encode, poly
    from camlab88.protocols.sigma import Encoder

    enc = Encoder()
    pts = [(100 + 7 * i, 200 + 3 * (i % 5)) for i in range(40)]
    sent = encode(enc, poly(2, pts))
    colour = enc.colour(2)
    assert sent.startswith(colour + b"JH")
    full = len(colour + enc.polyline(pts))
    assert len(sent) < 0.6 * full


def test_screen_layout_menu_above_the_field_keys_to_its_right_cross_at_its_centre() -> None:
    # §3.1.1, figure 3.1's caption: the field with its centre cross, a menu row of coloured
    # boxes above the drawing area, the keyboard commands listed to the right
    from camlab88.apps.kas.program import layout as L
    from camlab88.apps.kas.program import screen

    boxes = [b for _item, b in screen.menu_boxes()]
    assert len(boxes) > 8 and all(y0 > L.FIELD_Y1 for _x0, y0, _x1, _y1 in boxes)
    lines = screen.key_lines("draw")
    shown = [p for p in screen.editor_prims(Editor()) if p.kind == "text" and p.text in lines]
    assert len(shown) == len(lines) and all(p.data[0] > L.FIELD_X1 for p in shown)
    cx, cy = round(L.CENTRE_X), round(L.CENTRE_Y)
    arms = [p.data for p in screen.field_marks() if len(p.data) == 4]
    assert (cx - 12, cy, cx + 12, cy) in arms and (cx, cy - 12, cx, cy + 12) in arms


def test_the_tablet_maps_to_the_whole_screen_menu_at_its_top() -> None:
    # §3.1.1: commands are picked by touching the menu "at the top of the tablet"
    from camlab88.apps.kas.editor import menu_hit
    from camlab88.apps.kas.program import layout as L

    w, h = L.TABLET_AREA.width, L.TABLET_AREA.height
    assert L.tablet_to_field(0, 0) == L.px_to_field(0, L.SCREEN_H)       # top left
    assert L.tablet_to_field(w, h) == L.px_to_field(L.SCREEN_W, 0)       # bottom right
    top_row = [menu_hit(*L.tablet_to_field(x / 10, 1.2)) for x in range(10, 110, 10)]
    assert all(top_row), top_row
    assert menu_hit(*L.tablet_to_field(w / 2, h - 1.2)) is None


def test_editing_cursors_are_a_cyan_square_and_a_magenta_triangle() -> None:
    from camlab88.apps.kas.model import PALETTE, Chain, Drawing
    from camlab88.apps.kas.program.screen import cursor_prims

    ed = Editor(Drawing([Chain.from_points([(0, 0), (1, 0), (2, 1)])]))
    ed.enter_edit()
    prims = cursor_prims(ed)
    squares = [p for p in prims if p.kind == "rect"]
    triangles = [p for p in prims if p.kind == "poly"]
    assert squares and {PALETTE[p.colour][0] for p in squares} == {"cyan"}
    assert triangles and {PALETTE[p.colour][0] for p in triangles} == {"magenta"}
    assert all(len(p.data) == 8 and p.data[:2] == p.data[-2:] for p in triangles)
