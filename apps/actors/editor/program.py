"""The actor editor's event loop on the Rainbow: one ``frame()`` reads the mouse, keyboard
and tablet, edits the current cell type's actor, uploads a new turntable picture and lets
the device show a frame.

The working actors are a dict; what was last read or saved is kept beside it, so "unsaved"
is simply "differs from the file". Quitting (q, Esc with nothing to cancel, the menu's
Finish or the window's close button) with unsaved work asks on the message pad as the KAS
editor does: y saves and quits, n quits without saving, Esc stays (a second close while
asked also quits without saving). A file that does not load is reported there as
``file:line:col: what`` and the editor starts with no actors; the first save over such a
file asks to be repeated, so a typing error in the file is not lost by accident.
"""

from __future__ import annotations

import os
from dataclasses import replace

from camlab88.apps.actors.editor import layout as L
from camlab88.apps.actors.editor import sliders as S
from camlab88.apps.actors.editor.cell_types import (
    CellType,
    first_lathe,
    new_actor,
    offered,
    tile,
    with_profile,
)
from camlab88.apps.actors.editor.display import Display
from camlab88.apps.actors.editor.menus import Menus
from camlab88.apps.actors.editor.naming import NameEntry
from camlab88.apps.actors.editor.profile import Profile
from camlab88.apps.actors.editor.tablet import TabletPen
from camlab88.apps.actors.model import (
    Actor,
    ActorFileError,
    ActorSet,
    Material,
    parse_actors,
    read_actor_text,
    write_actors,
)
from camlab88.apps.actors.preview import turntable
from camlab88.apps.quitting import QUIT_QUESTION, AsksBeforeQuitting
from camlab88.protocols.rainbow.client import RainbowClient
from camlab88.protocols.rainbow.events import KeyEvent, MouseEvent, TabletEvent

ERROR, INFO, PROMPT = "#ffb0b0", "#c8e8ff", "#fff0a0"
# A new turntable picture every PREVIEW_EVERY frames (12.5 a second), turned 6 degrees
# further: one picture costs about 0.15 s at the preview's size, so rendering one every frame
# would leave the mouse answered 6 times a second; this way three frames in four are quick.
PREVIEW_EVERY = 4
DEGREES_PER_PICTURE = 6  # once round in 60 pictures (4.8 s)
POLL_LIMIT = 256


class ActorEditor(AsksBeforeQuitting):
    def __init__(self, client: RainbowClient, path: str, types: list[CellType],
                 rules: str, may_save: bool = True, start: dict | None = None) -> None:
        """``start``: what FILE held when a saved session began (``self.start``, kept in
        a save state: ``exists``, its ``text`` or the ``error`` reading it gave), in place
        of reading FILE now."""
        self.client = client
        self.may_save = may_save  # False: a --screenshot run, which writes no file
        self.writes = True  # False while a save state's load runs the session again
        self.start = start
        self.path = path
        self.rules = rules
        self.display = Display(client)
        self.said: list[str] = []  # every message shown (tests, and the command's exit)
        self.load_error: str | None = None
        self.saved = self._load()
        self.actors: dict[int, Actor] = dict(self.saved.actors)
        self.types = offered(types, self.actors)
        self.menus = Menus(client)
        self.pen = TabletPen()
        self.index = 0
        self.profile = Profile()
        self.picked: int | None = None   # the point the left button drags
        self.slider: int | None = None   # the slider row the left button drags
        self.mouse = (0, 0)
        self.asking = False   # the quit question is on the message pad
        self.confirm_overwrite = False
        self.naming: NameEntry | None = None  # the actor's name being typed
        self.finished = self.discarded = False
        self.frames = 0
        self.select(0)

    # -- the file ---------------------------------------------------------------------------
    def _load(self) -> ActorSet:
        if self.start is None:
            self.start = _read_start(self.path)
        if not self.start["exists"]:
            self.say(f"{self.path}: a new actors file for the rules {self.rules}", INFO)
            return ActorSet(self.rules, {})
        if self.start["error"] is not None:
            self.load_error = self.start["error"]
            self.say(self.load_error + "\nthe editor starts with no actors", ERROR)
            return ActorSet(self.rules, {})
        try:
            got = parse_actors(self.start["text"], self.path)
        except ActorFileError as exc:
            self.load_error = _one_line(exc, self.path)
            self.say(self.load_error + "\nthe editor starts with no actors", ERROR)
            return ActorSet(self.rules, {})
        if got.rules != self.rules:
            self.say(f"{self.path} was made for the rules {got.rules}; it is saved for "
                     f"{self.rules}", INFO)
        return ActorSet(self.rules, dict(got.actors))

    def savable(self) -> dict[int, Actor]:
        """The actors a save writes: those with a part (the file's rule; a state whose
        actor has none stays a tile)."""
        return {s: a for s, a in sorted(self.actors.items()) if a.parts}

    def unsaved(self) -> bool:
        return self.savable() != self.saved.actors

    def save(self) -> bool:
        if self.load_error is not None and not self.confirm_overwrite:
            self.confirm_overwrite = True
            self.say(f"{self.path} did not load (see above): save again to replace it", PROMPT)
            return False
        new = ActorSet(self.rules, self.savable())
        if not self.may_save:
            self.say(f"{self.path}: not saved (a --screenshot run writes no file)", INFO)
            return True
        try:
            if self.writes:
                write_actors(self.path, new)
        except OSError as exc:
            self.say(f"{self.path}: not saved: {exc.strerror or exc}", ERROR)
            return False
        self.saved, self.load_error = new, None
        self.say(f"saved {len(new.actors)} actors to {self.path}", INFO)
        self.show_status()
        return True

    # -- the cell type being edited -----------------------------------------------------------
    @property
    def cell_type(self) -> CellType:
        return self.types[self.index]

    def actor(self) -> Actor | None:
        return self.actors.get(self.cell_type.state)

    def select(self, index: int) -> None:
        self.index = index % len(self.types)
        a = self.actor()
        i = None if a is None else first_lathe(a)
        self.profile = Profile(() if i is None else a.parts[i].profile)
        self.picked = None
        self.display.draw_profile(self.profile.points, None)
        self.display.sliders.show(self._slider_values())
        self.show_status()

    def _slider_values(self) -> list[float]:
        a = self.actor()
        colour = self.cell_type.colour if a is None else a.colour
        m = a.material if a is not None else tile(self.cell_type).material
        return [float(v) for v in colour] + [m.ambient, m.diffuse, m.specular, m.shininess]

    def _editable(self) -> Actor:
        a = self.actor()
        if a is not None:
            return a
        return new_actor(self.cell_type)

    def _profile_changed(self) -> None:
        self.actors[self.cell_type.state] = with_profile(self._editable(),
                                                         self.profile.as_tuple())
        self.display.draw_profile(self.profile.points, self.picked)
        self.show_status()

    def _slider_set(self, row: int, value: float) -> None:
        values = self._slider_values()
        if values[row] == value:
            return
        values[row] = value
        a = self._editable()
        colour = (int(values[0]), int(values[1]), int(values[2]))
        self.actors[a.state] = replace(a, colour=colour, material=Material(*values[3:]))
        self.display.sliders.show(values)
        self.show_status()

    def remove_actor(self) -> None:
        self.actors.pop(self.cell_type.state, None)
        self.select(self.index)
        self.say(f"cell type {self.cell_type.state} is a coloured square tile again", INFO)

    # -- messages -----------------------------------------------------------------------------
    def say(self, text: str, colour: str = INFO) -> None:
        self.said.append(text)
        lines = text.split("\n")[:2]
        self.display.message.show("\n".join(s[:120] for s in lines), colour)

    def show_status(self) -> None:
        t = self.cell_type
        a = self.actor()
        what = "a square tile" if a is None else f"actor '{a.name}', {len(a.parts)} parts"
        mark = "  [unsaved]" if self.unsaved() else ""
        self.display.status.show(f"cell type {t.state} ({t.name}) of {self.rules}: {what}"
                                 f"   file {os.path.basename(self.path)}{mark}", "#d8f0d8")

    # -- the frame loop -----------------------------------------------------------------------
    def frame(self) -> None:
        for e in self.client.drain_events(POLL_LIMIT):
            self.handle(e)
        if not self.finished:
            self._turn()
        self.client.wait_frame()

    def _turn(self) -> None:
        if self.frames % PREVIEW_EVERY == 0:
            a = self.actor() or tile(self.cell_type)
            angle = (self.frames // PREVIEW_EVERY * DEGREES_PER_PICTURE) % 360
            self.display.show_preview(turntable(a, angle, (L.PREVIEW[2], L.PREVIEW[3])))
        self.frames += 1

    # -- quitting -----------------------------------------------------------------------------
    # (apps.quitting asks over unsaved work)
    def save_work(self) -> bool:
        return self.save()

    def ask_quit(self) -> None:
        self.say(QUIT_QUESTION, PROMPT)

    def stay(self) -> None:
        self.say("carrying on", INFO)

    def end(self) -> None:
        self.finished = True

    # -- input --------------------------------------------------------------------------------
    def handle(self, e: object) -> None:
        if self.finished:
            return
        if isinstance(e, KeyEvent):
            if e.pressed:
                self._key(e.key, e.char)
        elif isinstance(e, MouseEvent):
            self._mouse(e)
        elif isinstance(e, TabletEvent):
            for m in self.pen.mouse_events(e):
                self._mouse(m)

    def _key(self, key: str, char: str = "") -> None:
        if self.asking:
            self.answer_quit(key)
        elif self.naming is not None:
            self._name_key(key, char)
        elif key == "escape" and self.menus.is_open():
            self.menus.cancel()
            self.say("no cell type chosen", INFO)
        elif key in ("q", "escape"):
            self.request_quit()
        elif key == "s":
            self.save()
        elif key == "tab":
            self.select(self.index + 1)
        elif key in ("delete", "backspace"):
            self._delete_at(*self.mouse)

    def _mouse(self, e: MouseEvent) -> None:
        self.mouse = (e.x, e.y)
        self.display.move_cursor(e.x, e.y)
        if self.asking:
            return
        if e.button == 0:
            self._moved(e.x, e.y)
        elif e.button == 1 and e.pressed:
            self._left(e.x, e.y)
        elif e.button == 1:
            self._release()
        elif e.button == 2:
            self._middle(e.pressed, e.x, e.y)
        elif e.button == 3 and e.pressed:
            self._right(e.x, e.y)

    def _moved(self, x: int, y: int) -> None:
        if self.menus.is_open():
            self.menus.track(x, y)
        elif self.picked is not None:
            px, py = _in(L.PROFILE, x, y)
            if self.profile.move(self.picked, px, py):
                self._profile_changed()
        elif self.slider is not None:
            self._slider_set(self.slider, S.value_at(S.SLIDERS[self.slider], x - L.SLIDERS[0]))

    def _left(self, x: int, y: int) -> None:
        if self.menus.is_open():
            return
        if L.inside(L.PROFILE, x, y):
            px, py = _in(L.PROFILE, x, y)
            i = self.profile.hit(px, py)
            if i is None:
                i = self.profile.add(px, py)
                if i is None:
                    self.say(f"a profile has at most {L.MAX_POINTS} points", ERROR)
                    return
                self._profile_changed()
            self.picked = i
            self.display.draw_profile(self.profile.points, i)
        elif L.inside(L.SLIDERS, x, y):
            row = S.row_at(y - L.SLIDERS[1])
            if row is not None and x - L.SLIDERS[0] < S.SWATCH[0]:
                self.slider = row
                self._moved(x, y)

    def _release(self) -> None:
        if self.picked is not None:
            self.picked = None
            self.display.draw_profile(self.profile.points, None)
        self.slider = None

    def _right(self, x: int, y: int) -> None:
        if self.menus.choosing():
            index = self.menus.chosen_type()
            if index is not None:
                self.select(index)
            t = self.cell_type
            self.say(f"editing cell type {t.state} ({t.name})", INFO)
        elif L.inside(L.PROFILE, x, y) and self.picked is None:
            self._delete_at(x, y)

    def _delete_at(self, x: int, y: int) -> None:
        if not L.inside(L.PROFILE, x, y) or self.picked is not None:
            return
        i = self.profile.hit(*_in(L.PROFILE, x, y))
        if i is not None:
            self.profile.delete(i)
            self._profile_changed()

    def _show_name(self) -> None:
        assert self.naming is not None
        t = self.cell_type
        self.display.message.show(f"name of cell type {t.state}'s actor (Return sets it, Esc "
                                  f"leaves it):\n{self.naming.text}_", PROMPT)

    def _name_key(self, key: str, char: str) -> None:
        assert self.naming is not None
        done = self.naming.key(key, char)
        if done == "typing":
            self._show_name()
        elif done == "bad":
            self.say("a name: letters, digits, _ . + - (at most 64, starting with a letter, "
                     f"digit or _)\n{self.naming.text}_", ERROR)
        elif done == "cancel":
            self.naming = None
            self.say("the name is unchanged", INFO)
        else:
            a = self._editable()
            name, self.naming = self.naming.text, None
            self.actors[a.state] = replace(a, name=name)
            self.say(f"cell type {a.state}'s actor is called {name}", INFO)
            self.show_status()

    def _middle(self, pressed: bool, x: int, y: int) -> None:
        if pressed:
            self._release()
            self.menus.open_main(x, y)
            return
        item = self.menus.close_main()
        if item == "Cell type":
            self.menus.open_types(self.types, self.index, x, y)
            self.say("move to a cell type, right button to select (Esc: none)", PROMPT)
        elif item == "Name":
            self.naming = NameEntry(self._editable().name)
            self._show_name()
        elif item == "Clear profile":
            self.profile.clear()
            self._profile_changed()
        elif item == "Remove actor":
            self.remove_actor()
        elif item == "Save":
            self.save()
        elif item == "Finish":
            self.request_quit()


def _in(rect: tuple[int, int, int, int], x: int, y: int) -> tuple[int, int]:
    return x - rect[0], y - rect[1]


def _read_start(path: str) -> dict:
    """What FILE holds now: whether it exists, its text, or the one-line error reading it."""
    if not os.path.exists(path):
        return {"exists": False, "text": None, "error": None}
    try:
        return {"exists": True, "text": read_actor_text(path), "error": None}
    except (ActorFileError, OSError) as exc:
        return {"exists": True, "text": None, "error": _one_line(exc, path)}


def _one_line(exc: Exception, path: str) -> str:
    if isinstance(exc, OSError):
        return f"{path}: {exc.strerror or exc}"
    return str(exc).splitlines()[0]
