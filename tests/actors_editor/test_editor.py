"""The actor editor on an in-process Rainbow: a profile drawn by scripted clicks becomes the
expected lathe Part, a loaded file saves back unchanged, edits keep the parts the editor does
not draw, bad files are reported on the message pad as file:line:col while the editor keeps
running, and quitting over unsaved work asks y / n / Esc."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np

from camlab88.apps.actors.editor import layout as L
from camlab88.apps.actors.model import Part, format_actors, read_actors
from tests.actors_editor.driver import MAZE, Driver, screen

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "ca"
PAWN = [(0.0, 0.0), (0.35, 0.0), (0.35, 0.0625), (0.2, 0.25), (0.1, 0.5), (0.0, 0.5)]


def test_a_profile_drawn_by_clicks_is_saved_as_the_expected_lathe_part(tmp_path: Path) -> None:
    path = tmp_path / "life.actors"
    d = Driver(path)
    d.click_points(PAWN)
    x, y = screen(0.2, 0.25)
    d.run(f"drag left {x} {y} {x + 16} {y} 4\nwait 1\n")  # radius 0.2 -> 0.25
    x, y = screen(0.35, 0.0625)
    d.run(f"click right {x} {y}\nwait 1\n")  # deleted
    d.key("s")
    got = read_actors(path)
    assert got.rules == "life"
    actor = got.actors[1]
    assert actor.parts == (Part("lathe", ((0.0, 0.0), (0.35, 0.0), (0.25, 0.25), (0.1, 0.5),
                                          (0.0, 0.5))),)
    assert actor.colour == (0, 255, 0) and actor.name == "form_1"
    assert not d.editor.unsaved() and not d.editor.finished


def test_a_loaded_file_saves_back_unchanged(tmp_path: Path) -> None:
    path = tmp_path / "chess.actors"
    shutil.copy(EXAMPLES / "chess.actors", path)
    before = read_actors(path)
    d = Driver(path, MAZE)
    d.key("tab", "tab", "tab")  # through every cell type and back: nothing changes
    assert not d.editor.unsaved()
    d.run("press middle 600 200\nwait 1\n")  # the menu's Save
    item = d.editor.menus.main
    y = item.y + item.scroll + item.items.index("Save") * 18 + 9
    d.run(f"move {item.x + 10} {y}\nwait 1\nrelease middle {item.x + 10} {y}\nwait 1\n")
    assert "saved 4 actors" in d.editor.said[-1]
    after = read_actors(path)
    assert after == before
    assert format_actors(after) == format_actors(before)


def test_editing_the_lathe_keeps_the_other_parts_and_the_cycles(tmp_path: Path) -> None:
    path = tmp_path / "chess.actors"
    shutil.copy(EXAMPLES / "chess.actors", path)
    d = Driver(path, MAZE)
    pawn = d.editor.actor()
    assert pawn is not None and pawn.name == "pawn"
    x, y = screen(*pawn.parts[0].profile[-1])
    d.run(f"drag left {x} {y} {x + 8} {y} 2\nwait 1\nkey s\nwait 1\n")
    saved = read_actors(path).actors[1]
    assert pawn.parts[0].profile[-1] == (0.09, 0.58)
    assert saved.parts[0].profile[-1] == (0.1125, 0.575)  # moved, so snapped to 1/80
    assert saved.parts[0].profile[:-1] == pawn.parts[0].profile[:-1]
    assert saved.parts[1:] == pawn.parts[1:] and saved.cycles == pawn.cycles


def test_a_bad_file_is_reported_on_the_message_pad_and_the_editor_keeps_running(
        tmp_path: Path) -> None:
    path = tmp_path / "bad.actors"
    text = "rules life\nactor 1 pawn\n  colour 1 2\nend\n"
    path.write_text(text, encoding="utf-8")
    d = Driver(path)
    assert d.editor.said[0].startswith(f"{path}:3:")
    assert d.editor.display.message.text.startswith(f"{path}:3:")
    d.click_points(PAWN[:2])  # the editor works on
    assert len(d.editor.profile.points) == 2
    d.key("s")  # the first save over a file that did not load only asks
    assert path.read_text(encoding="utf-8") == text
    assert "save again" in d.editor.said[-1]
    d.key("s")
    assert read_actors(path).actors[1].parts[0].profile == tuple(PAWN[:2])


def test_quitting_with_unsaved_work_asks_y_n_or_esc(tmp_path: Path) -> None:
    path = tmp_path / "q.actors"
    d = Driver(path)
    d.click_points(PAWN[:2])
    d.key("q")
    assert d.editor.asking and not d.editor.finished
    d.key("escape")  # stays
    assert not d.editor.asking and not d.editor.finished
    assert not d.editor.may_close()  # the window's close button asks too
    d.key("n")
    assert d.editor.finished and d.editor.discarded and not path.exists()

    d = Driver(path)
    d.click_points(PAWN[:2])
    d.key("escape", "y")
    assert d.editor.finished and read_actors(path).actors[1].parts[0].profile == tuple(PAWN[:2])


def test_nothing_unsaved_quits_at_once(tmp_path: Path) -> None:
    d = Driver(tmp_path / "new.actors")
    d.key("q")
    assert d.editor.finished and not d.editor.asking


def test_the_sliders_set_colour_and_material(tmp_path: Path) -> None:
    path = tmp_path / "c.actors"
    d = Driver(path)
    d.click_points(PAWN[:2])
    x0, y0 = L.SLIDERS[0], L.SLIDERS[1]
    red = y0 + 2 + 10  # row 0
    spec = y0 + 2 + 5 * 20 + 10  # row 5
    d.run(f"click left {x0 + 72 + 199} {red}\nwait 1\nclick left {x0 + 72} {spec}\nwait 1\n"
          "key s\nwait 1\n")
    a = read_actors(path).actors[1]
    assert a.colour == (255, 255, 0) and a.material.specular == 0.0


def test_the_cell_type_menu_chooses_the_state_edited(tmp_path: Path) -> None:
    d = Driver(tmp_path / "m.actors", MAZE)
    d.run("press middle 600 200\nwait 1\n")
    m = d.editor.menus.main
    y = m.y + m.scroll + m.items.index("Cell type") * 18 + 9
    d.run(f"move {m.x + 10} {y}\nwait 1\nrelease middle {m.x + 10} {y}\nwait 1\n")
    t = d.editor.menus.types
    assert t is not None
    y = t.y + t.scroll + 2 * 18 + 9  # the third: state 3
    d.run(f"move {t.x + 10} {y}\nwait 1\nclick right {t.x + 10} {y}\nwait 1\n")
    assert d.editor.cell_type.state == 3 and d.editor.menus.types is None


def test_a_tablet_pen_draws_points(tmp_path: Path) -> None:
    from camlab88.protocols.rainbow.events import TabletEvent

    d = Driver(tmp_path / "t.actors")
    d.editor.pen.extent = (1000, 1000)
    for x, y, pressure in [(100, 900, 0), (100, 900, 500), (100, 900, 0), (300, 700, 500),
                           (300, 700, 0)]:
        d.machine.post(TabletEvent(0, x, y, pressure, 0))
        d.editor.frame()
    pts = d.editor.profile.points
    assert len(pts) == 2 and pts[0][1] < pts[1][1]


def test_the_preview_turns_in_its_pad(tmp_path: Path) -> None:
    d = Driver(tmp_path / "p.actors")
    d.click_points(PAWN)
    x, y, w, h = L.PREVIEW
    a = d.screen()[y:y + h, x:x + w].copy()
    d.run("wait 10\n")
    b = d.screen()[y:y + h, x:x + w]
    assert len(np.unique(a.reshape(-1, 3), axis=0)) > 8  # a lit solid, not a flat colour
    assert not np.array_equal(a, b)


def _menu(d: Driver, item: str) -> None:
    d.run("press middle 600 200\nwait 1\n")
    m = d.editor.menus.main
    y = m.y + m.scroll + m.items.index(item) * 18 + 9
    d.run(f"move {m.x + 10} {y}\nwait 1\nrelease middle {m.x + 10} {y}\nwait 1\n")


def test_the_actor_is_named_by_typing_on_the_message_pad(tmp_path: Path) -> None:
    path = tmp_path / "n.actors"
    d = Driver(path)
    d.click_points(PAWN[:2])
    _menu(d, "Name")
    assert d.editor.naming is not None and "form_1_" in d.editor.display.message.text
    d.run("type my pawn\nwait 1\nkey return\nwait 1\n")  # a space: not a name character
    assert d.editor.naming is None and d.editor.actor().name == "mypawn"
    _menu(d, "Name")
    d.run("key backspace\nkey backspace\nkey backspace\nkey backspace\nkey backspace\n"
          "key backspace\nkey return\nwait 1\n")  # nothing left: refused, still asked
    assert d.editor.naming is not None and "a name:" in d.editor.said[-1]
    d.run("key escape\nwait 1\nkey s\nwait 1\n")
    assert read_actors(path).actors[1].name == "mypawn"
