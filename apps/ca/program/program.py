"""The ``ca`` program on the Rainbow (sections 7.3.1, 7.3.2): the event loop tying the
mouse and keyboard to the session model, the menus and the double-buffered display.

Initially in edit mode and single-step mode. The next generation is computed and drawn
into the off-screen buffer before it is wanted, and discarded after any intervention.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from camlab88.apps.ca import library, log
from camlab88.apps.ca.engine import Engine
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.program import commands, stepping
from camlab88.apps.ca.program import state as program_state
from camlab88.apps.ca.program.commands import ERROR, Ask, Dialogue
from camlab88.apps.ca.program.drawing import Display
from camlab88.apps.ca.program.edit import Editor
from camlab88.apps.ca.program.menus import EDIT_MODES, MainMenu, choice_menu, edit_menu
from camlab88.apps.ca.program.viewport import VIEW_H, VIEW_W, Viewport
from camlab88.apps.ca.session import Session
from camlab88.protocols.rainbow.client import RainbowClient
from camlab88.protocols.rainbow.events import LEFT, RIGHT, KeyEvent, MouseEvent

ZOOM_ITEMS = {"Zoom 16": 16, "Zoom 8": 8, "Zoom 4": 4, "Zoom 2": 2, "Zoom 1": 1}
PROMPT = "#fff0a0"
POLL_LIMIT = 256
INFO = "#c8e8ff"


@dataclass
class Options:
    """The command line of section 7.3.1 plus the starting rules and pattern."""

    rules: str = "life"
    pattern: str | None = None
    log: str | None = None  # Log/k
    record_pans: bool = False  # RecordPansAndZooms/s
    checkpoint: int = 0  # Checkpoint: every N generations
    script: str | None = None  # Script/k
    replay_pans: bool = False  # ReplayPansAndZooms/s
    start: int | None = None  # the generation to begin a script at (asked if None)
    edges: str | None = None  # None: the script's (its log header), else "wrap"
    seed: int | None = None  # None: the script's, else 0


class CAProgram:
    # its declared state (the harness's program_state): apps/ca/program/state.py
    STATE_VERSION = program_state.VERSION
    STATE_SCHEMA = program_state.SCHEMA

    def state_values(self) -> dict[str, Any]:
        return program_state.state_values(self)

    def check_state_values(self, values: dict[str, Any]) -> Callable[[], None]:
        return program_state.check_state_values(self, values)

    @staticmethod
    def migrate_state(version: int, values: Any) -> Any:
        return program_state.migrate(version, values)

    def __init__(self, client: RainbowClient, options: Options | None = None) -> None:
        self.client = client
        self.options = opts = options or Options()
        self.view = Viewport()
        self.display = Display(client, self.view)
        # A script is read before any log is opened: --log may name the same file (the
        # session then continues its own history, section 7.3.1).
        self.script_events: list[log.Event] = []
        recorded = log.LogSettings()
        if opts.script:
            self.script_events = log.read_log(opts.script)
            recorded = log.read_log_settings(opts.script)
        self.edges, self.seed, warnings = log.resolve_settings(recorded, opts.edges, opts.seed)
        writer = None
        if opts.log and not opts.script:  # with a script, opened once its start is known
            writer = log.LogWriter(opts.log, opts.record_pans, self.settings)
        self.session = Session(self.fresh_engine(), writer, opts.checkpoint)
        self.editor = Editor(self.session)
        self.main_menu = MainMenu(client, jumps=True)
        self.main_menu.mark("Step mode")
        self.cross = edit_menu(client)
        self.menu: str | None = None  # "main" or "edit" while the middle button is held
        self.choice = None  # a pop-up choice menu of a dialogue
        self.editing = True  # the program starts in edit mode (section 7.3.1)
        self.auto = False  # ... and in single-step mode
        self.frequency = 1
        self.fast_forward = False  # the display frequency doubles per shown frame
        self.frequency_before_fast_forward = 1
        self.pending: Engine | None = None
        self.pending_checkpoints: list[Engine] = []
        self.populations = 0
        self.finished = False
        self.mouse = (VIEW_W // 2, VIEW_H // 2)
        self.pan_from: tuple[int, int] | None = None
        self.dialogue: Dialogue | None = None
        self.asking: Ask | None = None
        # which dialogue runs (its name, its argument) and the answers it has been given:
        # what a save state rebuilds it from (apps/ca/program/state.py)
        self.dialogue_made: tuple[str, int] | None = None
        self.answers: list[Any] = []
        self.corner: tuple[int, int] | None = None
        self.text = ""
        self.text_fresh = False
        self.questioning = False
        self.said: list[str] = []  # every message shown (tests and the log of a session)
        # input read during a long jump (apps/ca/program/jump_bar.py), handled next frame
        self.held_events: list[object] = []
        self.clock = time.monotonic  # when a jump's progress bar shows (tests replace it)
        self.script = stepping.ScriptFeed()
        self.script_last = 0
        self.display.editing = True
        self.session.view.x, self.session.view.y = self.view.top_left_cell()
        for w in warnings:
            self.say(f"Warning: {w}", ERROR)
        if opts.script:
            last = max((e.generation for e in self.script_events), default=0)
            self.script_last = last
            if opts.start is None:
                self._start(commands.start_generation(self, last), ("Start generation", last))
            else:
                self.begin_script(opts.start)
        else:
            self._begin_fresh()

    # -- start-up -----------------------------------------------------------------------------
    @property
    def settings(self) -> log.LogSettings:
        return log.LogSettings(self.edges, self.seed)

    def fresh_engine(self) -> Engine:
        return Engine(edges=self.edges, seed=self.seed)

    def _begin_fresh(self) -> None:
        opts = self.options
        path = library.rules_path(opts.rules)
        with open(path, encoding="utf-8") as f:
            rules = self.session.change_rules(f.read(), os.path.basename(path))
        self.display.set_rules(rules)
        if opts.pattern:
            pat = read_pattern(library.pattern_path(opts.pattern))
            cx, cy = self.view.centre_cell()  # the pattern's box centred in the view
            x = cx - pat.width // 2 + pat.ref[0]
            y = cy - pat.height // 2 + pat.ref[1]
            self.session.load_pattern(os.path.basename(opts.pattern), pat, x, y)
        self.changed()

    def begin_script(self, target: int) -> None:
        """Section 7.3.1: read the latest checkpoint, apply the script up to ``target``
        before any graphics; later interventions are applied as their generations come."""
        opts = self.options
        assert opts.script is not None
        events = self.script_events
        on_view = self._view_event if opts.replay_pans else None
        engine = log.start_from_script(opts.script, target, self.fresh_engine, on_view)
        self.session.engine = engine
        if opts.log:  # the new log holds the whole history: the replayed part first
            self.session.writer = log.LogWriter(
                opts.log, opts.record_pans, self.settings,
                [ev for ev in events if ev.generation <= target], start=target)
        self.script = stepping.ScriptFeed([e for e in events if e.generation > target])
        if engine.rules is None:
            path = library.rules_path(opts.rules)
            with open(path, encoding="utf-8") as f:
                self.session.change_rules(f.read(), os.path.basename(path))
        self.display.set_rules(self.session.engine.rules)
        self.changed()

    def _view_event(self, ev: log.Event) -> None:
        self.session.apply_view_event(ev)
        v = self.session.view
        if ev.kind == "zoom":
            self.view.set_zoom(0 if v.zoom == "subpixel" else int(v.zoom),
                               v.cells_per_pixel if v.zoom == "subpixel" else 1)
            self.display.load_luts()
        self.view.set_top_left(v.x, v.y)
        self.display.redraw_front(self.session.engine)

    # -- the frame loop -------------------------------------------------------------------------
    def frame(self) -> None:
        """One frame: input, then the simulation's work, then let the device show it."""
        held, self.held_events = self.held_events, []
        for e in held:
            self.handle(e)
        for e in self.client.drain_events(POLL_LIMIT):  # however much arrived this frame
            self.handle(e)
        if not self.finished:
            self._idle()
        self.client.wait_frame()

    def run(self, max_frames: int | None = None) -> None:
        n = 0
        while not self.finished and (max_frames is None or n < max_frames):
            self.frame()
            n += 1

    def _simulating(self) -> bool:
        return (not self.editing and self.dialogue is None and self.menu is None
                and self.session.engine.rules is not None)

    def _idle(self) -> None:
        if not self._simulating():
            return
        if self.auto:
            self.commit()
        if self.pending is None:
            self._compute_pending()

    def _compute_pending(self) -> None:
        """The next generation to be shown, computed and drawn off screen (section 7.3.2)."""
        self.pending, self.pending_checkpoints = stepping.ahead(
            self.session, self.frequency, self.script.next_generation)
        self.display.draw_back(self.pending)

    def commit(self) -> None:
        """Show the next generation: swap buffers (nothing is drawn now)."""
        if self.pending is None:
            self._compute_pending()
        assert self.pending is not None
        if self.display.buffers.back.stale:
            self.display.draw_back(self.pending)
        self.display.buffers.swap()
        self.display.buffers.back.stale = True
        self.session.engine = self.pending
        self.frequency = stepping.next_frequency(self.frequency, self.fast_forward)
        self.pending = None
        stepping.write_checkpoints(self.session, self.pending_checkpoints)
        self.pending_checkpoints = []
        self._apply_script()

    def _apply_script(self) -> None:
        due = self.script.due(self.session.generation)
        for ev in due:
            if ev.kind in log.VIEW_EVENTS:
                if self.options.replay_pans:
                    self._view_event(ev)
                continue
            log.apply_event(self.session.engine, ev)
            if self.session.writer is not None:
                self.session.writer.add(ev)
            if ev.kind == "rules":
                self.display.set_rules(self.session.engine.rules)
        if due:
            self.changed()

    def changed(self) -> None:
        """The shown state was altered: redraw it, discard the unseen next generation."""
        self.pending = None
        self.display.redraw_front(self.session.engine)
        area = self.session.engine.advance_area
        if area is None:
            self.display.area.hide()
        else:
            self.display.show_rectangle(self.display.area, (area.x0, area.y0),
                                        (area.x1, area.y1))

    # -- messages -----------------------------------------------------------------------------
    def say(self, text: str, colour: str = INFO, question: bool = False) -> None:
        self.said.append(text)
        self.questioning = question  # a question is taken down when its dialogue ends
        lines = text.split("\n")[:2]
        self.display.prompt.show("\n".join(s[:120] for s in lines), colour)

    def show_statistics(self, text: str) -> None:
        self.said.append(text)
        self.display.stats.show(text, "#e0ffe0")

    # -- dialogues ----------------------------------------------------------------------------
    def _start(self, dialogue: Dialogue, made: tuple[str, int] = ("", 0)) -> None:
        self.dialogue, self.dialogue_made, self.answers = dialogue, made, []
        self._answer(None, first=True)

    def _answer(self, value, first: bool = False) -> None:
        assert self.dialogue is not None
        self._close_choice()
        self.corner = None
        self.display.rubber.hide()
        if not first:
            self.answers.append(value)
        try:
            ask = next(self.dialogue) if first else self.dialogue.send(value)
        except StopIteration:
            self._end_dialogue()
            return
        self.asking = ask
        if ask.kind == "menu":
            self.choice = choice_menu(self.client, list(ask.items))
            self.choice.open(*self.mouse)
            self.say(ask.prompt + ": move to a choice, right button to select", PROMPT, True)
        elif ask.kind == "text":
            self.text = ask.default
            self.text_fresh = True  # typing replaces the offered default
            self._show_text()
        else:
            self.say(ask.prompt, PROMPT, True)
            self._update_cursor()

    def _show_text(self) -> None:
        assert self.asking is not None
        self.questioning = True
        self.display.prompt.show(f"{self.asking.prompt}\n{self.text}_", PROMPT)

    def _end_dialogue(self) -> None:
        self.dialogue = None
        self.asking = None
        self.dialogue_made, self.answers = None, []
        self.corner = None
        self._close_choice()
        self.display.rubber.hide()
        if not self.editing:
            self.display.cursor.hide()
        if self.questioning:
            self.display.prompt.hide()
            self.questioning = False

    def cancel(self) -> None:
        if self.dialogue is not None:
            self.dialogue.close()
            self._end_dialogue()
            self.display.prompt.hide()
            if self.options.script and self.session.engine.rules is None:
                self.begin_script(self.script_last)  # the start question was not answered

    def _close_choice(self) -> None:
        if self.choice is not None:
            self.choice.dispose()
            self.choice = None

    # -- input --------------------------------------------------------------------------------
    def handle(self, e: object) -> None:
        if isinstance(e, KeyEvent):
            self._key(e)
        elif isinstance(e, MouseEvent):
            self._mouse(e)

    def _key(self, e: KeyEvent) -> None:
        if not e.pressed:
            return
        if e.key == "escape":
            if self.dialogue is None and self.choice is None:
                self.finished = True  # nothing to close: Esc leaves, as the window's close
            else:
                self.cancel()
        elif self.asking is not None and self.asking.kind == "text":
            if e.key in ("return", "enter", "kp_enter"):
                self._answer(self.text.strip())
            elif e.key == "backspace":
                self.text = self.text[:-1]
                self.text_fresh = False
                self._show_text()
            elif e.char and e.char.isprintable():
                self.text = ("" if self.text_fresh else self.text) + e.char
                self.text_fresh = False
                self._show_text()

    def _cell_under_mouse(self) -> tuple[int, int]:
        x = min(max(self.mouse[0], 0), VIEW_W - 1)  # the cursor stays in the visible area
        y = min(max(self.mouse[1], 0), VIEW_H - 1)
        return self.view.cell_at(x, y)

    def _wants_cursor(self) -> bool:
        if self.asking is not None:
            return self.asking.kind in ("point", "rect")
        return self.editing and self.view.zoom != 0

    def _update_cursor(self) -> None:
        if self._wants_cursor():
            cell = self._cell_under_mouse()
            self.display.show_cursor(*cell)
            if self.corner is not None:
                self.display.show_rectangle(self.display.rubber, self.corner, cell)
        else:
            self.display.cursor.hide()

    def _mouse(self, e: MouseEvent) -> None:
        old = self.mouse
        self.mouse = (e.x, e.y)
        if e.button == 0:
            self._moved(e, old)
        elif e.button == 1:
            self.pan_from = (e.x, e.y) if e.pressed else None
            if not e.pressed:
                self.session.pan_to(*self.view.top_left_cell())
        elif e.button == 2:
            self._middle(e.pressed)
        elif e.button == 3:
            if e.pressed:
                self._right()
            else:
                self.editor.release()

    def _moved(self, e: MouseEvent, old: tuple[int, int]) -> None:
        if self.menu == "main":
            self.main_menu.track(e.x, e.y)
            return
        if self.menu == "edit":
            self.cross.track(e.x, e.y)
            return
        if self.choice is not None:
            self.choice.track(e.x, e.y)
            return
        if e.buttons & LEFT and self.pan_from is not None:
            dx, dy = e.x - self.pan_from[0], e.y - self.pan_from[1]
            self.pan_from = (e.x, e.y)
            if dx or dy:
                self.view.pan(dx, dy)
                self.display.pan()
                area = self.session.engine.advance_area
                if area is not None:
                    self.display.show_rectangle(self.display.area, (area.x0, area.y0),
                                                (area.x1, area.y1))
        if e.buttons & RIGHT and self.editing and self.dialogue is None and self.view.zoom:
            for cell in self.editor.drag(self._cell_under_mouse()):
                self._edited(cell)
        self._update_cursor()

    def _middle(self, pressed: bool) -> None:
        if pressed:
            self.cancel()
            self.display.stats.hide()
            if self.editing:
                self.menu = "edit"
                self.cross.open(*self.mouse)
            else:
                self.menu = "main"
                self.main_menu.open(*self.mouse)
            return
        if self.menu == "edit":
            self.menu = None
            self._edit_choice(self.cross.close())
        elif self.menu == "main":
            self.menu = None
            self._main_choice(self.main_menu.close())

    def _right(self) -> None:
        if self.display.stats.text and self.asking is None:
            self.display.stats.hide()  # the click only dismisses the statistics
            return
        a = self.asking
        if a is not None and a.kind == "menu":
            assert self.choice is not None
            i = self.choice.highlighted
            self._answer(None if i is None else self.choice.items[i])
        elif a is not None and a.kind == "point":
            self._answer(self._cell_under_mouse())
        elif a is not None and a.kind == "rect":
            cell = self._cell_under_mouse()
            if self.corner is None:
                self.corner = cell
                self.display.show_rectangle(self.display.rubber, cell, cell)
            else:
                self._answer(commands.rect_from(self.corner, cell))
        elif a is not None:
            return
        elif self.editing:
            if self.view.zoom == 0:
                self.say("Cells cannot be edited at the subpixel zoom", ERROR)
                return
            for cell in self.editor.press(self._cell_under_mouse()):
                self._edited(cell)
            self.display.set_marker(self.editor.value or self.session.current)
        elif not self.auto and self.session.engine.rules is not None:
            self.commit()  # single-step mode: the next generation, already drawn

    def _edited(self, cell: tuple[int, int]) -> None:
        self.pending = None
        self.display.cell_changed(*cell)

    # -- menu choices -------------------------------------------------------------------------
    def _edit_choice(self, item: str) -> None:
        if item == "Leave editing":
            self.editing = False
            self.display.editing = False
            self.display.apply_page()
            self.display.cursor.hide()
        elif item == "Set to value":
            self._start(commands.set_value(self), (item, 0))
        elif item in EDIT_MODES:
            self.session.set_edit_mode(EDIT_MODES[item])

    def _main_choice(self, item: str | None) -> None:
        if item is None or item == "Do nothing":
            return
        if item == "Edit cells":
            self.editing = True
            self.display.editing = True
            self.display.apply_page()
            self._update_cursor()
        elif item == "Finish":
            self.finished = True
        elif item in ("Step mode", "Auto mode"):
            self.auto = item == "Auto mode"
            stepping.end_fast_forward(self)
            self.main_menu.mark(item)
        elif item == "Centralise viewport":
            w, h = self.view.cells_across()
            self.session.centralise(w, h)
            self.view.set_top_left(self.session.view.x, self.session.view.y)
            self.changed()
        elif item == "Go to generation":
            self._start(stepping.go_to_generation(self), (item, 0))
        elif item == "Fast forward":
            self._start(stepping.fast_forward(self), (item, 0))
        elif item in ZOOM_ITEMS:
            self.set_zoom(ZOOM_ITEMS[item])
        elif item in commands.MAIN:
            self._start(commands.MAIN[item](self), (item, 0))

    def set_zoom(self, zoom: int, cells_per_pixel: int = 1) -> None:
        self.view.set_zoom(zoom, cells_per_pixel)
        self.session.set_zoom(self.view.name, cells_per_pixel)
        self.session.pan_to(*self.view.top_left_cell())
        self.display.load_luts()
        self.changed()
        self._update_cursor()
