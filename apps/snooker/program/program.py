"""The interactive motion-development program (§6.2.1, §6.2.2) on the Rainbow.

One ``step()`` is one display frame (1/50 s of device time): read the mouse and keyboard,
advance whatever is running (the simulation and replays run at 25 frames/s: one time frame
every second display frame), redraw the back ball pad and swap, move the cursor pad,
update the message areas, ``wait_frame``.

Mouse buttons (§6.2.1): right = restart the simulation (and abandon the current action);
left = magnify mouse movement by four; middle = menus and everything else. In "alter a
different frame" left/right step back/forward (auto-repeat when held), moving the mouse up
or down switches between single frames and significant events, middle selects the frame.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import numpy as np

from camlab88.apps.snooker import aiming
from camlab88.apps.snooker.events import EventKind
from camlab88.apps.snooker.program import arrows, constants, layout, menus
from camlab88.apps.snooker.program.layout import TableView
from camlab88.apps.snooker.program.pads import (
    DOTS,
    MAGENTA,
    MOVING,
    SELECT,
    SPIN,
    Display,
    Overlay,
)
from camlab88.apps.snooker.rules import describe_on
from camlab88.apps.snooker.session import Session, SessionError
from camlab88.apps.snooker.state import effective_velocity
from camlab88.apps.snooker.table import BALL_NAMES, CUE, N_BALLS, cushion_sides
from camlab88.base.plainstate import (
    Bool,
    Choice,
    Float,
    Int,
    JsonText,
    ListOf,
    Opt,
    Record,
    Str,
    Tuple,
)
from camlab88.protocols.rainbow.client import RainbowClient
from camlab88.protocols.rainbow.events import LEFT, MIDDLE, Event, KeyEvent, MouseEvent
from camlab88.protocols.rainbow.ui import PopupMenu

MAGNIFY = 4  # left button: mouse movement x4 (§6.2.1)
REPEAT_DELAY, REPEAT_EVERY = 12, 2  # auto-repeat in display frames
UNIT_SWITCH_PX = 16  # mouse travel that switches frame <-> event stepping
MAX_TEXT = 60  # keyboard entry fits the help area
HELP_COLOUR = "#e8e8e8"
WARN_COLOUR = "#ffb0b0"
START_HELP = ("Middle button: menu of options (over a ball: the ball's menu).\n"
              "Right: restart simulation.  Left held: mouse moves x4.\n"
              "Key t: table constants (ball size, cushion restitution, friction).")


# Exit's questions after "y": the file's name (no --save), the frames to save; a state holds
# them as a mode, their question asked again by the program's own code (state_values)
EXIT_QUESTIONS = ("exit_file", "exit_range")
# what the program may be doing (``mode``): a state names one of these, nothing else
MODES = frozenset(["aim_confirm", "aim_pot", "aim_target", "alter", "escape", "exit", "idle",
                   "menu", "position", "replay", "running", "spin", "start", "velocity",
                   *(f"keys:{p}" for p in ("position", "velocity", "replay", "aim_speed",
                                           "aim_cushions", *EXIT_QUESTIONS)),
                   *(f"keys:table:{item}" for item in constants.ITEMS)])


class Program:
    def __init__(self, client: RainbowClient, session: Session | None = None,
                 restore: Session | None = None, save_to: str | os.PathLike[str] | None = None,
                 restore_name: str = "the saved session") -> None:
        self.client = client
        self.session = session or Session.new_game()
        self.restore = restore
        self.save_to = Path(save_to) if save_to is not None else None
        self.display = Display(client, TableView.fit(self.session.table))
        self.green = menus.green_menu(client)
        self.orange = menus.orange_menu(client)
        self.constants = constants.table_menu(client)
        self.cursor = (layout.SCREEN_W / 2, layout.SCREEN_H / 2)
        self.mouse: tuple[int, int] | None = None
        self.buttons = 0
        self.mode = "idle"
        self.ball: int | None = None  # the ball an action applies to
        self.menu = None  # the open PopupMenu
        self.menu_cursor = (0.0, 0.0)
        self.text = ""  # keyboard entry
        self.prompt = ""
        self.help_text, self.help_colour = START_HELP, HELP_COLOUR
        self.arrow_end = (0.0, 0.0)
        self.spin = 0.0
        self.spin_from = 0.0
        self.unit = "frame"
        self.unit_acc = 0.0
        self.repeat: tuple[int, int] | None = None  # (direction, frames held)
        self.aim: aiming.Aim | None = None
        self.aim_target = (0.0, 0.0)
        self.aim_speed = 0.0
        self.replay: list[int] = []
        self.replay_at = 0
        self.ticks = 0
        self.done = False
        self.saved: list[Path] = []
        self.exit_path: Path | None = None  # a file name typed on Exit, until it is written
        self._status_key: object = None
        if restore is not None:
            self.mode = "start"
            self.help_text = (f"New game (key n, or right button) or restore {restore_name}\n"
                              "(key r, or middle button)?")

    # ------------------------------------------------------------------ declared state
    # (the harness's program_state): the game as the session file holds it (read back by
    # Session.from_json), the program's own values, the menus and the display. What the
    # command line gave (the file to restore, where to save) stays the fresh build's.
    # Exit's dialogue (as the CA program's file dialogues, apps/ca/program/state.py) is
    # saved up to its file's question and asked again through the program's own code at a
    # load (its question's text is the program's, never the state's); the characters typed
    # into the name so far are kept, as plain text (nothing is read or written until the
    # user ends the name with Return and then the frames with Return, the name on screen).
    # Once a name has been given (asking for the frames) it is refused: a state never names
    # a file. Version 2 added the exit questions to the modes; migrate_state reads 1.
    STATE_VERSION = 2
    _POINT = Tuple((Float(), Float()))
    _MENUS = ("green", "orange", "constants")
    STATE_SCHEMA = Record(
        session=JsonText(), restore_pending=Bool(), cursor=_POINT,
        mouse=Opt(Tuple((Int(), Int()))), buttons=Int(0, 7), mode=Str(64),
        ball=Opt(Int(0, N_BALLS - 1)), menu=Opt(Choice(_MENUS)), menu_cursor=_POINT,
        text=Str(MAX_TEXT), prompt=Str(4096), help_text=Str(4096), help_colour=Str(64),
        arrow_end=_POINT, spin=Float(), spin_from=Float(), unit=Choice(("frame", "event")),
        unit_acc=Float(), repeat=Opt(Tuple((Int(-1, 1), Int(0)))),
        aim=Opt(Record(ball=Int(0, N_BALLS - 1), old_velocity=_POINT, velocity=_POINT,
                       path=ListOf(_POINT, 64), warning=Opt(Str(4096)))),
        aim_target=_POINT, aim_speed=Float(), replay=ListOf(Int(0), 1 << 20),
        replay_at=Int(0), ticks=Int(0), done=Bool(),
        menus=Record(**{m: PopupMenu.STATE_SCHEMA for m in _MENUS}),
        display=Display.STATE_SCHEMA)

    @staticmethod
    def migrate_state(version: int, values: Any) -> Any:
        """An older state (JSON, unchecked) as this version's: version 1's values are
        version 2's (2 only lets a state be in Exit's questions)."""
        if version != 1:
            raise ValueError(f"no migration from version {version}")
        return values

    def state_values(self) -> dict[str, Any]:
        if self.exit_path is not None:
            raise ValueError("Exit has been given a file name (a state never names a file; "
                             "it is saved once Exit's dialogue has ended)")
        menus_ = {m: getattr(self, m) for m in self._MENUS}
        menu = next((m for m, w in menus_.items() if w is self.menu), None)
        aim = None if self.aim is None else {
            "ball": self.aim.ball, "old_velocity": self.aim.old_velocity,
            "velocity": self.aim.velocity, "path": list(self.aim.path),
            "warning": self.aim.warning}
        return {"session": self.session.to_json(), "restore_pending": self.restore is not None,
                "cursor": self.cursor, "mouse": self.mouse, "buttons": self.buttons,
                "mode": self.mode, "ball": self.ball, "menu": menu,
                "menu_cursor": self.menu_cursor, "text": self.text, "prompt": self.prompt,
                "help_text": self.help_text, "help_colour": self.help_colour,
                "arrow_end": self.arrow_end, "spin": self.spin, "spin_from": self.spin_from,
                "unit": self.unit, "unit_acc": self.unit_acc, "repeat": self.repeat,
                "aim": aim, "aim_target": self.aim_target, "aim_speed": self.aim_speed,
                "replay": self.replay, "replay_at": self.replay_at, "ticks": self.ticks,
                "done": self.done,
                "menus": {m: w.state_values() for m, w in menus_.items()},
                "display": self.display.state_values()}

    def check_state_values(self, v: dict[str, Any]) -> Callable[[], None]:
        session = Session.from_json(v["session"])  # the session file's own checks
        if v["restore_pending"] and self.restore is None:
            raise ValueError("the state waits to restore a session this run was not given")
        if v["mode"] not in MODES:  # (never a file name: see state_values)
            raise ValueError(f"mode {v['mode'][:40]!r} is not one of the program's")
        if not v["text"].isprintable():  # (as typed: keys add printable characters only)
            raise ValueError("the text typed holds a character no key types")
        if v["mode"] == "keys:exit_range" and self.save_to is None:  # (a name was typed)
            raise ValueError("the state asks which frames to save to a file it would name")
        if v["replay"] and not v["replay_at"] < len(v["replay"]):
            raise ValueError(f"replay place {v['replay_at']} of {len(v['replay'])}")
        n = len(session.timeline.time_frames)
        if any(f >= n for f in v["replay"]):
            raise ValueError(f"a replayed frame past the session's {n}")
        puts = [getattr(self, m).check_state_values(v["menus"][m]) for m in self._MENUS]
        puts.append(self.display.check_state_values(v["display"]))
        a = v["aim"]
        aim = None if a is None else aiming.Aim(a["ball"], a["old_velocity"], a["velocity"],
                                                tuple(a["path"]), a["warning"])

        def put() -> None:
            self.session = session
            self.display.view = TableView.fit(session.table)
            if not v["restore_pending"]:
                self.restore = None
            for name in ("cursor", "mouse", "buttons", "mode", "ball", "menu_cursor", "text",
                         "prompt", "help_text", "help_colour", "arrow_end", "spin",
                         "spin_from", "unit", "unit_acc", "repeat", "aim_target",
                         "aim_speed", "replay", "replay_at", "ticks", "done"):
                setattr(self, name, v[name])
            self.menu = None if v["menu"] is None else getattr(self, v["menu"])
            self.aim, self.exit_path, self._status_key = aim, None, None
            for p in puts:
                p()
            if v["mode"][5:] in EXIT_QUESTIONS:
                self.ask_again(v["mode"][5:], v["text"], v["help_colour"])
        return put

    def ask_again(self, question: str, text: str, colour: str) -> None:
        """One of Exit's questions asked again (a load): its text the program's own, then
        what had been typed into it and the colour it was shown in (a warning after an
        empty name or frames out of range)."""
        if question == "exit_file":
            self.ask_exit_file()
        else:
            self.ask_save_range()
        self.text, self.help_colour = text, colour
        self.help_text = f"{self.prompt}\n> {self.text}_"

    # ------------------------------------------------------------------ the frame loop
    def step(self) -> tuple[int, int]:
        for e in self.client.poll_events():
            try:
                self.handle(e)
            except (SessionError, aiming.AimError, ValueError) as exc:
                # the model refused a change: say so and carry on (never crash the session)
                self.menu = None if self.menu is None else self._close_menu()
                self.mode = "idle"
                self.say(f"Not done: {exc}", WARN_COLOUR)
        self.tick()
        self.render()
        return self.client.wait_frame()

    def run(self, frames: int) -> None:
        for _ in range(frames):
            if self.done:
                return
            self.step()

    def tick(self) -> None:
        self.ticks += 1
        if self.mode == "running" and self.ticks % 2 == 0:
            added = self.session.simulate_frame()
            if not added or (added[-1].event is not None
                             and added[-1].event.kind == EventKind.SHOT_END):
                self.mode = "idle"
                self.say(f"All balls at rest. {self.session.frame.game.message}\n"
                         "Middle button: menu.", HELP_COLOUR)
        elif self.mode == "replay" and self.ticks % 2 == 0:
            if self.replay_at + 1 < len(self.replay):
                self.replay_at += 1
            else:
                self.mode = "idle"
                self.say("Replay finished. Middle button: menu.", HELP_COLOUR)
        elif self.mode == "alter" and self.repeat is not None:
            d, held = self.repeat
            held += 1
            self.repeat = (d, held)
            if held >= REPEAT_DELAY and (held - REPEAT_DELAY) % REPEAT_EVERY == 0:
                self.session.step(d, self.unit)

    # ------------------------------------------------------------------ input
    def handle(self, e: Event) -> None:
        if isinstance(e, KeyEvent):
            if e.pressed:
                self.key(e.key, e.char)
            return
        if not isinstance(e, MouseEvent):
            return
        if self.mouse is None:
            self.mouse = (e.x, e.y)
            if self.mode not in ("menu", "alter"):
                self.cursor = (float(e.x), float(e.y))
        dx, dy = e.x - self.mouse[0], e.y - self.mouse[1]
        self.mouse = (e.x, e.y)
        self.buttons = e.buttons
        if (dx or dy) and e.button == 0:
            self.moved(dx, dy)
        if e.button:
            self.button(e.button, e.pressed)

    def moved(self, dx: int, dy: int) -> None:
        k = MAGNIFY if self.buttons & LEFT and self.mode != "alter" else 1
        # The cursor follows the mouse in every mode (so it stays with a host pointer);
        # only the left button's magnification makes it run ahead.
        x = min(max(self.cursor[0] + dx * k, 0.0), layout.SCREEN_W - 1.0)
        y = min(max(self.cursor[1] + dy * k, 0.0), layout.SCREEN_H - 1.0)
        self.cursor = (x, y)
        if self.mode == "menu" and self.menu is not None:
            m = self.menu
            mx = min(max(self.menu_cursor[0] + dx * k, m.x), m.x + m.width - 1)
            my = min(max(self.menu_cursor[1] + dy * k, m.y), m.y + m.window_h - 1)
            self.menu_cursor = (mx, my)  # the invisible menu cursor stays on the menu
            m.track(int(mx), int(my))
        elif self.mode == "alter":
            self.unit_acc += dy
            if abs(self.unit_acc) >= UNIT_SWITCH_PX:
                self.unit = "frame" if self.unit_acc < 0 else "event"
                self.unit_acc = 0.0
        elif self.mode == "spin" and self.buttons & MIDDLE:
            self.spin = arrows.spin_from_drag(y - self.spin_from)
        elif self.mode == "velocity" and self.buttons & MIDDLE:
            self.arrow_end = self.cursor

    def button(self, b: int, pressed: bool) -> None:
        mode = self.mode
        if mode == "start":
            if pressed and b in (2, 3):
                self.start(restore=b == 2)
            return
        if mode == "alter":
            if b in (1, 3):
                d = -1 if b == 1 else 1
                if pressed:
                    self.session.step(d, self.unit)
                    self.repeat = (d, 0)
                else:
                    self.repeat = None
            elif b == 2 and pressed:
                self.repeat = None
                self.mode = "idle"
                f = self.session.frame
                self.say(f"Frame {f.index} selected. Change it from the menus, or the right\n"
                         "button restarts the simulation from here.", menus.HIGHLIGHT[
                             menus.ALTER_FRAME])
            return
        if b == 1:
            return  # left only magnifies
        if b == 3:
            if pressed:
                self.right_button()
            return
        # the middle button
        if mode == "menu":
            if not pressed:
                self.choose()
            return
        if not pressed:
            if mode == "velocity" and self.ball is not None:
                self.mode = "spin"
                self.spin_from = self.cursor[1]
                self.spin = 0.0
                self.say("Spin: hold the middle button and move up (top spin) or down\n"
                         "(back spin); or press the right button to start.", self._colour())
            elif mode == "spin":
                self.apply_velocity(start=False)
            elif mode == "position" and self.ball is not None:
                self.place_ball()
            return
        if mode in ("idle", "running", "replay"):
            self.open_menu()
        elif mode == "velocity":
            self.arrow_end = self.cursor
        elif mode == "spin":
            self.spin_from = self.cursor[1]
        elif mode == "aim_pot":
            self.aim_pot()
        elif mode == "aim_target":
            self.aim_target = self.view.to_table(*self.cursor)
            self.ask("aim_speed", "Speed the ball should have there (m/s, Return = stop "
                     "there):")
        elif mode == "aim_confirm":
            self.accept()

    def right_button(self) -> None:
        """Restart the simulation from the frame shown (abandoning any action)."""
        if self.mode == "spin":
            self.apply_velocity(start=True)
            return
        if self.mode == "menu" and self.menu is not None:
            self.menu.close()
            self.menu = None
        self.aim = None
        self.mode = "running"
        self.ticks = 0  # the first time frame follows two display frames from now
        self.say("Simulating. Middle button: interrupt (menu).", HELP_COLOUR)

    def key(self, name: str, char: str) -> None:
        if self.mode == "start":
            if name in ("n", "r"):
                self.start(restore=name == "r")
            return
        if self.mode == "exit":
            if name in ("y", "n"):
                if name == "n":
                    self.done = True
                elif self.save_to is None:
                    self.ask_exit_file()
                else:
                    self.ask_save_range()
            elif name == "escape":
                self.mode = "idle"
                self.say(START_HELP, HELP_COLOUR)
            return
        if self.mode == "aim_confirm":
            if name in ("y", "return"):
                self.accept()
            elif name in ("n", "escape"):
                self.reject()
            return
        if name == "escape" and self.mode in ("idle", "running", "replay"):
            self.ask_exit(menus.HIGHLIGHT[menus.EXIT])  # as the Exit menu item
            return
        if name == constants.KEY and self.mode in ("idle", "running", "replay"):
            self.open_menu(table_constants=True)
            return
        if not self.mode.startswith("keys:"):
            return
        if name == "return":
            self.entered(self.mode[5:], self.text.strip())
        elif name == "escape":
            self.mode = "idle"
            self.say("Cancelled.", HELP_COLOUR)
        elif name == "backspace":
            self.text = self.text[:-1]
        elif char and char.isprintable() and len(self.text) < MAX_TEXT:
            self.text += char
        if self.mode.startswith("keys:"):
            self.help_text = f"{self.prompt}\n> {self.text}_"

    # ------------------------------------------------------------------ menus
    def open_menu(self, table_constants: bool = False) -> None:
        if self.mode in ("running", "replay"):
            self.mode = "idle"  # the middle button (or the table key) interrupts
        cx, cy = int(self.cursor[0]), int(self.cursor[1])
        self.ball = None if table_constants else self.selected()
        if table_constants:
            m = self.constants
            m.open(cx + m.width // 2 + 12, cy)
            self.say("Table constants: move to an item and click the middle button\n"
                     "(they apply from this frame on).", constants.COLOUR)
        elif self.ball is None:
            m = self.green  # "just to the right of the cursor"
            m.open(cx + m.width // 2 + 12, cy)
        else:
            m = self.orange
            m.open(cx, cy)
        self.menu = m
        self.menu_cursor = (m.x + m.width / 2, float(cy))
        m.track(int(self.menu_cursor[0]), int(self.menu_cursor[1]))
        self.mode = "menu"

    def ask_exit(self, colour) -> None:
        """The exit question: y saves and leaves, n leaves, Escape stays."""
        self.mode = "exit"
        where = str(self.save_to) if self.save_to else "a file you name"
        self.say(f"Exit: y = save (all or some frames) to {where} and leave,\n"
                 "n = leave without saving, escape = stay.", colour)

    def choose(self) -> None:
        assert self.menu is not None
        item = self.menu.close()
        self.menu = None
        self.mode = "idle"
        if item is None or item == menus.DO_NOTHING:
            self.say(START_HELP, HELP_COLOUR)
            return
        if item in constants.CONSTANTS:
            self.ask("table:" + item, constants.prompt(item, self.session.table))
            return
        colour = menus.HIGHLIGHT[item]
        b = self.ball
        name = BALL_NAMES[b] if b is not None else ""
        if item == menus.ALTER_FRAME:
            self.mode = "alter"
            self.repeat = None
            self.unit_acc = 0.0
            self.say("Alter a different frame: left = back, right = forward (hold to\n"
                     "repeat); move the mouse up = frames, down = events; middle = select.",
                     colour)
        elif item == menus.EXIT:
            self.ask_exit(colour)
        elif item == menus.REPLAY:
            self.ask("replay", "Replay at 25 frames/s: first and last frame (Return = all):")
        elif item == menus.CUE_VELOCITY:
            self.begin_velocity(CUE, colour)
        elif item == menus.VELOCITY_MOUSE:
            self.begin_velocity(b, colour)
        elif item == menus.POSITION_MOUSE:
            self.mode = "position"
            self.say(f"Move the {name}: hold the middle button, drag, release.\n"
                     "Off the table = potted.", colour)
        elif item == menus.POSITION_KEYS:
            self.ask("position", f"New position of the {name}: x y in metres from the "
                     "baulk-right corner:")
        elif item == menus.VELOCITY_KEYS:
            self.ask("velocity", f"Velocity of the {name}: speed (m/s) angle (degrees\n"
                     "anticlockwise from up the table) [spin m/s]:")
        elif item == menus.STOP_ALL:
            self.session.stop_all()
            self.say("All balls stopped. Right button: restart simulation.", colour)
        elif item == menus.AIM_POT:
            self.mode = "aim_pot"
            self.say(f"Aim to pot the {name}: point at a pocket, middle button.", colour)
        elif item == menus.AIM_NEXT:
            self.mode = "aim_target"
            self.say(f"Aim the {name}: point at the position to reach, middle button.",
                     colour)

    def _close_menu(self) -> None:
        assert self.menu is not None
        self.menu.close()

    def ask(self, purpose: str, prompt: str) -> None:
        self.mode = "keys:" + purpose
        self.text = ""
        self.prompt = prompt
        self.help_text = f"{prompt}\n> _"
        self.help_colour = self.menu_item_colour(purpose) or self.help_colour

    @staticmethod
    def menu_item_colour(purpose: str) -> str | None:
        if purpose.startswith("table:"):
            return constants.HIGHLIGHT[purpose[6:]]
        return {"replay": menus.HIGHLIGHT[menus.REPLAY],
                "position": menus.HIGHLIGHT[menus.POSITION_KEYS],
                "velocity": menus.HIGHLIGHT[menus.VELOCITY_KEYS],
                "aim_speed": menus.HIGHLIGHT[menus.AIM_NEXT],
                "aim_cushions": menus.HIGHLIGHT[menus.AIM_NEXT],
                "exit_file": menus.HIGHLIGHT[menus.EXIT],
                "exit_range": menus.HIGHLIGHT[menus.EXIT]}.get(purpose)

    def entered(self, purpose: str, text: str) -> None:
        colour = self.help_colour
        try:
            nums = [float(v) for v in text.replace(",", " ").split()] \
                if purpose not in ("aim_cushions", "exit_file") else []
        except ValueError:
            self.say(f"Not numbers: {text!r}. Try again.", WARN_COLOUR)
            self.mode = "keys:" + purpose
            self.help_text = f"{self.prompt}\n> _"
            self.text = ""
            return
        self.mode = "idle"
        try:
            if purpose == "position" and self.ball is not None:
                if len(nums) != 2:
                    raise SessionError("type two numbers: x y")
                self.session.set_position(self.ball, nums[0], nums[1])
                self.say(f"{BALL_NAMES[self.ball]} moved. Right button: restart.", colour)
            elif purpose == "velocity" and self.ball is not None:
                if len(nums) not in (2, 3):
                    raise SessionError("type speed angle [spin]")
                self.session.strike(self.ball, nums[0], nums[1], nums[2] if len(nums) > 2
                                    else 0.0)
                self.say(f"{BALL_NAMES[self.ball]} velocity set. Right button: start.", colour)
            elif purpose == "replay":
                n = len(self.session.timeline.time_frames)
                first, last = (0, n - 1) if not nums else (int(nums[0]), int(nums[-1]))
                if len(nums) not in (0, 2) or not 0 <= first <= last < n:
                    raise SessionError(f"frames must be within 0..{n - 1}")
                self.replay = list(range(first, last + 1))
                self.replay_at = 0
                self.ticks = 0
                self.mode = "replay"
                self.say(f"Replaying frames {first}..{last} at 25 frames/s.\n"
                         "Middle button: stop.", colour)
            elif purpose.startswith("table:"):
                self.alter_table(purpose[6:], nums, colour)
            elif purpose == "aim_speed":
                self.aim_speed = nums[0] if nums else 0.0
                self.ask("aim_cushions", "Cushions to hit on the way, in order (left right "
                         "top baulk;\nReturn = none):")
            elif purpose == "aim_cushions":
                self.aim_next(tuple(text.lower().split()))
            elif purpose == "exit_file":
                if not text:
                    self.ask("exit_file", self.prompt)
                    self.help_colour = WARN_COLOUR
                    return
                self.exit_path = Path(text)
                self.ask_save_range()
            elif purpose == "exit_range":
                n = len(self.session.timeline.time_frames)
                first, last = (0, n - 1) if not nums else (int(nums[0]), int(nums[-1]))
                if len(nums) not in (0, 2) or not 0 <= first <= last < n:
                    self.ask("exit_range", self.prompt)
                    self.help_colour = WARN_COLOUR
                    return
                self.save(first, last)
                self.done = True
        except (SessionError, aiming.AimError, ValueError) as exc:
            self.mode = "idle"
            self.say(f"Not done: {exc}", WARN_COLOUR)
        except OSError as exc:  # saving on Exit: stay in the program, nothing is lost
            self.mode = "idle"
            self.exit_path = None
            self.say(f"Not saved: {exc.strerror}: {exc.filename}", WARN_COLOUR)

    def ask_exit_file(self) -> None:
        self.ask("exit_file", "Save to which file? (the session; the checkpoint is written "
                 "beside it\nas NAME.cp)  Escape = stay in the program:")

    def ask_save_range(self) -> None:
        """§6.2.2: the animator saves "either the complete sequence or a subset of frames"."""
        n = len(self.session.timeline.time_frames)
        self.ask("exit_range", f"Frames to save in the checkpoint: first last\n"
                 f"(Return = all, 0..{n - 1}):")

    # ------------------------------------------------------------------ actions
    def start(self, restore: bool) -> None:
        if restore and self.restore is not None:
            self.session = self.restore
            self.display.view = TableView.fit(self.session.table)
            self.display.draw_table()
        self.restore = None
        self.mode = "idle"
        self.say(START_HELP, HELP_COLOUR)

    def alter_table(self, item: str, nums: list[float], colour: str) -> None:
        """New table constants from the current frame on; the table view is redrawn."""
        if not nums:
            self.say(f"{item} kept.", colour)
            return
        table = self.session.change_table(**constants.changes(item, nums))
        self.display.view = TableView.fit(table)
        self.display.draw_table()
        self.display.last_scene = None  # the balls' size or place on the screen changed
        self.say(f"{item} changed from this frame on. Right button: restart simulation.",
                 colour)

    def begin_velocity(self, ball: int | None, colour: str) -> None:
        if ball is None or not self.session.balls.on_table[ball]:
            self.say("That ball is not on the table.", WARN_COLOUR)
            return
        self.ball = ball
        self.mode = "velocity"
        self.arrow_end = self.ball_screen(ball)
        self.say(f"Velocity of the {BALL_NAMES[ball]}: hold the middle button and move\n"
                 "to the end of the velocity arrow; release.", colour)

    def apply_velocity(self, start: bool) -> None:
        assert self.ball is not None
        v = arrows.velocity_from_arrow(self.view, self.ball_screen(self.ball), self.arrow_end)
        spin = 0.0 if start else self.spin
        try:
            self.session.set_velocity(self.ball, v[0], v[1], spin)
        except SessionError as exc:
            self.mode = "idle"
            self.say(f"Not done: {exc}", WARN_COLOUR)
            return
        self.mode = "idle"
        if start:
            self.right_button()
        else:
            self.mode = "idle"
            self.say(f"Velocity {math.hypot(*v):.2f} m/s, spin {spin:+.2f} m/s set.\n"
                     "Right button: start the simulation.", self._colour())

    def place_ball(self) -> None:
        assert self.ball is not None
        x, y = self.view.to_table(*self.cursor)
        self.session.set_position(self.ball, x, y)
        self.mode = "idle"
        self.say(f"{BALL_NAMES[self.ball]} placed at ({x:.3f}, {y:.3f}) m.\n"
                 "Right button: restart simulation.", menus.HIGHLIGHT[menus.POSITION_MOUSE])

    def aim_pot(self) -> None:
        assert self.ball is not None
        x, y = self.view.to_table(*self.cursor)
        colour = menus.HIGHLIGHT[menus.AIM_POT]
        self.mode = "idle"
        try:
            aim = self.session.aim_to_pot(self.ball, x, y)
        except (aiming.AimError, SessionError) as exc:
            self.say(f"Cannot aim: {exc}", WARN_COLOUR)
            return
        self.session.accept_aim(aim)
        self.aim = aim
        warn = f"\nWARNING: {aim.warning}" if aim.warning else ""
        self.say(f"{BALL_NAMES[aim.ball]} aimed at the pocket, speed kept.{warn}",
                 WARN_COLOUR if aim.warning else colour)

    def aim_next(self, cushions: tuple[str, ...]) -> None:
        assert self.ball is not None
        for c in cushions:
            if c not in cushion_sides():
                raise ValueError(f"unknown cushion {c!r} (left, right, top, baulk)")
        self.aim = self.session.aim_next_shot(self.ball, self.aim_target, self.aim_speed,
                                              cushions)
        o, n = self.aim.old_velocity, self.aim.velocity
        self.mode = "aim_confirm"
        self.say(f"old velocity ({o[0]:.3f}, {o[1]:.3f})  new ({n[0]:.3f}, {n[1]:.3f}) m/s\n"
                 "Use the new one? middle button or y = yes, n = no.",
                 menus.HIGHLIGHT[menus.AIM_NEXT])

    def accept(self) -> None:
        assert self.aim is not None
        self.session.accept_aim(self.aim)
        self.aim = None
        self.mode = "idle"
        self.say("New velocity in use. Right button: restart simulation.",
                 menus.HIGHLIGHT[menus.AIM_NEXT])

    def reject(self) -> None:
        self.aim = None
        self.mode = "idle"
        self.say("Old velocity kept.", HELP_COLOUR)

    def save(self, first: int = 0, last: int | None = None) -> None:
        """Write the session (all of it, to continue later) and time frames first..last of
        the checkpoint beside it; a name typed on Exit becomes the file from then on."""
        target = self.exit_path or self.save_to
        if target is None:
            return
        if target.suffix == ".cp":  # never let the checkpoint overwrite the session file
            target = target.with_suffix(".json")
        self.session.save(target)
        cp = target.with_suffix(".cp")
        self.session.checkpoint(first, last).write(cp)
        self.save_to, self.exit_path = target, None
        self.saved = [target, cp]

    # ------------------------------------------------------------------ display
    @property
    def view(self) -> TableView:
        return self.display.view

    def say(self, text: str, colour: str) -> None:
        self.help_text, self.help_colour = text, colour

    def _colour(self) -> str:
        return self.help_colour

    def ball_screen(self, ball: int) -> tuple[float, float]:
        return self.view.to_screen(*self.session.balls.pos[ball])

    def selected(self) -> int | None:
        x, y = self.view.to_table(*self.cursor)
        b = self.session.balls
        best, best_d = None, math.inf
        slack = max(self.session.table.radius, 3.0 / self.view.scale)  # a small ball is hard to hit
        for i in range(len(BALL_NAMES)):
            d = math.hypot(b.pos[i, 0] - x, b.pos[i, 1] - y)
            if b.on_table[i] and d <= slack and d < best_d:
                best, best_d = i, d
        return best

    def scene(self) -> tuple[np.ndarray, np.ndarray, Overlay]:
        s = self.session
        if self.mode == "replay":
            f = s.timeline.time_frames[self.replay[self.replay_at]]
            return f.balls.pos, f.balls.on_table, Overlay()
        balls = s.balls
        pos, on = np.array(balls.pos), np.array(balls.on_table)
        ov = Overlay()
        r = self.view.ball_radius_px
        if self.mode == "position" and self.ball is not None and self.buttons & MIDDLE:
            pos[self.ball] = self.view.to_table(*self.cursor)
            on[self.ball] = True
        if self.mode != "running":  # arrows on every moving ball (§6.2.2)
            vel = effective_velocity(np.asarray(balls.vel), np.asarray(balls.spin))
            for i in range(len(BALL_NAMES)):
                if on[i] and (vel[i, 0] or vel[i, 1]):
                    a = self.view.to_screen(*pos[i])
                    ov.lines += [(*seg, MOVING) for seg in
                                 arrows.arrow_segments(a, arrows.arrow_end(self.view, a,
                                                                           vel[i]))]
        sel = self.ball if self.mode not in ("idle", "running", "alter") \
            else self.selected()
        if sel is not None and on[sel]:
            px, py = self.view.to_pixel(*pos[sel])
            ov.rings.append((px, py, r + 2, SELECT))
        if self.mode in ("velocity", "spin") and self.ball is not None:
            a = self.ball_screen(self.ball)
            ov.lines += [(*seg, MAGENTA) for seg in arrows.arrow_segments(a, self.arrow_end)]
            ov.dots += [(x, y, MAGENTA) for x, y in arrows.dotted_extension(a, self.arrow_end)]
            if self.mode == "spin":
                seg = arrows.spin_arrow(a, self.arrow_end, self.spin)
                if seg is not None:
                    ov.lines += [(*s2, SPIN) for s2 in arrows.arrow_segments(seg[:2], seg[2:])]
        if self.aim is not None and self.mode in ("aim_confirm", "idle"):
            pts = [self.view.to_screen(*p) for p in self.aim.path]
            ov.dots += [(x, y, DOTS) for x, y in arrows.dotted_path(pts)]
            if self.mode == "aim_confirm":
                a = pts[0]
                for vel, val in ((self.aim.old_velocity, MOVING), (self.aim.velocity, MAGENTA)):
                    end = arrows.arrow_end(self.view, a, vel)
                    ov.lines += [(*seg, val) for seg in arrows.arrow_segments(a, end)]
        return pos, on, ov

    def render(self) -> None:
        d = self.display
        pos, on, ov = self.scene()
        d.draw_balls(pos, on, ov)
        d.move_cursor(int(self.cursor[0]), int(self.cursor[1]))
        d.help.show(self.help_text, self.help_colour)
        self.render_info()
        self.render_status()

    def render_info(self) -> None:
        d = self.display
        if self.mode == "replay":
            d.info.show(f"replay: frame {self.replay[self.replay_at]}\n"
                        f"({self.replay[0]}..{self.replay[-1]})", HELP_COLOUR)
        else:
            b = self.ball if self.mode not in ("idle", "running", "alter") \
                else self.selected()
            if b is None:
                d.info.show("no ball selected", HELP_COLOUR)
            else:
                bs = self.session.balls
                vx, vy = effective_velocity(np.asarray(bs.vel), np.asarray(bs.spin))[b] + 0.0
                d.info.show(f"{BALL_NAMES[b]}\nposition ({bs.pos[b, 0]:.3f}, "
                            f"{bs.pos[b, 1]:.3f}) m\nvelocity ({vx:.3f}, {vy:.3f}) m/s",
                            HELP_COLOUR)
        if self.mode == "alter":
            mark = (">", " ") if self.unit == "frame" else (" ", ">")
            d.step_box.show(f"{mark[0]} single frame\n{mark[1]} significant event",
                            menus.HIGHLIGHT[menus.ALTER_FRAME])
        else:
            d.step_box.hide()

    def render_status(self) -> None:
        d = self.display
        s = self.session
        if self.mode == "replay":
            n = self.replay[self.replay_at]
            d.frame_box.show(f"frame {n}", "#ffffff")
            return
        key = (s.cursor, len(s.timeline.time_frames), len(s.timeline.event_frames))
        if key != self._status_key:
            self._status_key = key
            f = s.frame
            st = s.status()
            sc = f.game.scores
            d.status.show(f"player {st['player']}  score {sc[0]}-{sc[1]}  break "
                          f"{st['break']}  on: {describe_on(f.game.on)}\n"
                          f"collision {st['collision']}  t = {f.balls.t:.2f} s"
                          + (f"  [{f.event.kind.name.lower()}]" if f.event else ""),
                          "#d8d8d8")
            d.frame_box.show(f"frame {f.index}" + ("+" if f.kind == "event" else ""),
                             "#ffffff")

    # ------------------------------------------------------------------ replaying a file
    def play_positions(self, frames: list[np.ndarray], on_table: list[np.ndarray]) -> None:
        """Show the given frames at 25 frames/s (used by ``snooker replay``)."""
        for _ in self.position_steps(frames, on_table):
            pass

    def position_steps(self, frames: list[np.ndarray], on_table: list[np.ndarray],
                       start: int = 0) -> Iterator[int]:
        """``play_positions`` one position at a time (two 50 Hz display frames each), for a
        run loop that ticks: yields the index of each position shown (from ``start``: a
        replay continued from a save state)."""
        d = self.display
        d.help.show(f"Replaying {len(frames)} frames at 25 frames/s.", HELP_COLOUR)
        d.info.show("checkpoint replay", HELP_COLOUR)
        for n, (pos, on) in enumerate(zip(frames, on_table)):
            if n < start:
                continue
            d.draw_balls(pos, on, Overlay())
            d.frame_box.show(f"frame {n}", "#ffffff")
            for _ in range(2):  # 25 frames/s on a 50 Hz display
                self.client.wait_frame()
            yield n


class PositionReplay:
    """``snooker replay``'s program: the checkpoint's positions shown one per tick
    (``position_steps``). Its declared state is how many have been shown and the display;
    a load makes the steps again from there (a generator is rebuilt, never saved)."""

    STATE_VERSION = 1
    STATE_SCHEMA = Record(shown=Int(0), display=Display.STATE_SCHEMA)

    def __init__(self, program: Program, frames: list[np.ndarray],
                 on_table: list[np.ndarray]) -> None:
        self.program, self.frames, self.on_table = program, frames, on_table
        self.shown = 0
        self._steps = program.position_steps(frames, on_table)

    def step(self) -> bool:
        if next(self._steps, None) is None:
            return False
        self.shown += 1
        return True

    def state_values(self) -> dict[str, Any]:
        return {"shown": self.shown, "display": self.program.display.state_values()}

    def check_state_values(self, values: dict[str, Any]) -> Callable[[], None]:
        if values["shown"] > len(self.frames):
            raise ValueError(f"{values['shown']} positions shown; the checkpoint has "
                             f"{len(self.frames)}")
        put_display = self.program.display.check_state_values(values["display"])

        def put() -> None:
            put_display()
            self.shown = values["shown"]
            self._steps = self.program.position_steps(self.frames, self.on_table, self.shown)
        return put
