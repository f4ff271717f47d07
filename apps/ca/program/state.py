"""``ca program``'s declared state (the harness's program_state): plain values the
program is rebuilt from through its own code.

The automaton (the shown generation, the one computed ahead and the checkpoints waiting to
be written) is kept as the thesis's checkpoint text (log.format_checkpoint) and read back by
log.parse_checkpoint, the reader a user's checkpoint files go through, with the rules'
source name and the engine's algorithm beside it. The rest is the program's values, the
session's, the viewport's, the display's (buffers, outlines, message areas) and the menus'.

A dialogue in progress is a generator: it is kept as which dialogue it is and the answers
it has been given, and made again by starting it through the program's own code and giving
it those answers (``REBUILT``; their steps before the last only ask; a state whose answers
would end one is refused, and what ending it would do is an action a user could take
anyway). A dialogue waiting on a choice (Advance area, Alter display, Clear area, Set to
value) has its pop-up menu open: a PopupMenu, whose pad, cluster and arcs are on the
Rainbow. The loaded Rainbow state already holds them, drawn, placed and lit, so the menu is
not opened again (that would name new ones and draw over them): the made-again dialogue's
question gives the items, the state gives the menu's plain values (the lit item, its place,
its scroll: ``DIALOGUE.menu``, each checked against where opening and tracking the menu can
put it) and the menu is re-attached to the pad, cluster and two arcs the client named last.
Those are derived from the client's ids, never read from the state: nothing is made on the
Rainbow while a choice menu is open, and a save checks that this menu is still the last
made. Save pattern, Load pattern and Change rules name a file in one answer
(``FILE_ANSWER``): they are saved, and made again, only up to the question for it (a state
never names a file a program reads or writes).

Input read during a long jump and held for the next frame (apps/ca/program/jump_bar.py:
mouse, key and tablet events of the Rainbow) is kept in ``held_events`` as the events'
own binary form (protocols.rainbow.events.encode_event, concatenated), read back by
``decode_events``, the checking decoder the Rainbow's replies and recordings go through,
and put back in ``held_events`` for the next frame to handle first. They are input a user
could have given (the loaded Rainbow's own input queue holds the same kind); nothing else
about them chooses anything. At most ``jump_bar.HOLD_LIMIT`` events (a jump holds no more)
in at most ``HELD_BYTES`` bytes.

What is not saved (``--save-state`` fails in one line, status 1; F2 and F4 say so and try
again at the next snapshot), because the state would have to name a file or hold what
runs: a file dialogue once given its file name (Save pattern asking for the reference
point; Load pattern asking where a copy goes or, in its menu, the orientation; Change
rules ends with its answer). What the command line gave (the rules file, the pattern,
the script, the Log being written) is the fresh build's.

Version 2 added ``dialogue``, version 3 the file dialogues to its names, version 4 the open
choice menu (``dialogue.menu``), version 5 the input held during a jump (``held_events``);
``migrate`` reads versions 1 to 4.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from camlab88.apps.ca import algorithms, log
from camlab88.apps.ca.engine import Engine, Rect
from camlab88.apps.ca.program import commands, stepping
from camlab88.apps.ca.program.jump_bar import HOLD_LIMIT
from camlab88.apps.ca.program.menus import choice_menu_reattached
from camlab88.apps.ca.rules import parse_rules
from camlab88.base.plainstate import (
    Blob,
    Bool,
    Choice,
    Int,
    ListOf,
    Opt,
    Record,
    Str,
    Tuple,
)
from camlab88.protocols.rainbow.events import decode_events, encode_event
from camlab88.protocols.rainbow.ui import MessageArea, PopupMenu
from camlab88.protocols.rainbow.ui.menu import CrossMenu

if TYPE_CHECKING:
    from camlab88.apps.ca.program.program import CAProgram

VERSION = 5
# the held input's bytes: HOLD_LIMIT events of up to 64 bytes each, 256 KiB (a mouse event
# is 20, a tablet's 21, a key's 14 and its name and text: a window's key, at most 32 and 4
# characters as the input log keeps them, fits); a save holding more is refused in one line
HELD_BYTES = HOLD_LIMIT * 64
_PAIR = Tuple((Int(), Int()))
ENGINE = Record(checkpoint=Blob(256 << 20), rules_source=Str(4096),
                algorithm=Choice(algorithms.CHOICES), hashlife_memory=Int(1))
_BUFFER = Record(engine=Choice(("none", "shown", "pending")), stale=Bool(), vx=Int(), vy=Int(),
                 drawn_pixels=Int(0))
_OUTLINE = Record(shape=Opt(Tuple((Int(),) * 4)), visible=Bool())
# the dialogues made again from their answers (no file read or written in any of them):
# name -> (the program, its argument) -> the dialogue, as the menus start it
REBUILT: dict[str, Callable[[Any, int], Any]] = {
    "Advance area": lambda p, _: commands.advance_area(p),
    "Alter display": lambda p, _: commands.alter_display(p),
    "Clear area": lambda p, _: commands.clear_area(p),
    "Randomly populate": lambda p, _: commands.randomly_populate(p),
    "Zoom subpixel": lambda p, _: commands.zoom_subpixel(p),
    "Set to value": lambda p, _: commands.set_value(p),
    "Go to generation": lambda p, _: stepping.go_to_generation(p),
    "Start generation": commands.start_generation,
    "Change rules": lambda p, _: commands.change_rules(p),
    "Load pattern": lambda p, _: commands.load_pattern(p),
    "Save pattern": lambda p, _: commands.save_pattern(p),
}
# the dialogues that name a file: the answer that names it (they are saved and made again
# only before it is given)
FILE_ANSWER: dict[str, int] = {"Change rules": 0, "Load pattern": 0, "Save pattern": 1}
# an answer: none (cancelled), a text or menu item, a cell, a rectangle
ANSWER = Record(kind=Choice(("none", "text", "point", "rect")), text=Str(4096),
                ints=ListOf(Int(), 4))
# menu: the open choice menu's plain state (which item is lit, where it is, its scroll)
DIALOGUE = Record(name=Choice(tuple(REBUILT)), arg=Int(0, 1 << 62),
                  answers=ListOf(ANSWER, 64), corner=Opt(_PAIR),
                  menu=Opt(PopupMenu.STATE_SCHEMA))
SCHEMA = Record(
    dialogue=Opt(DIALOGUE), held_events=Opt(Blob(HELD_BYTES)),
    engine=ENGINE, pending=Opt(ENGINE), pending_checkpoints=ListOf(ENGINE, 4096),
    session=Record(edit_mode=Str(64), current=Int(0, 255), view=Record(
        x=Int(), y=Int(), zoom=Str(16), cells_per_pixel=Int(1)),
        loaded=ListOf(Tuple((Str(4096), Int(), Int(), Str(32))), 1 << 16)),
    viewport=Record(zoom=Int(0, 64), cells_per_pixel=Int(1), px=Int(), py=Int(), grid=Bool()),
    display=Record(mode=Choice(("colour", "mono")), editing=Bool(), shown=Int(0, 1),
                   swaps=Int(0), buffers=ListOf(_BUFFER, 2), cursor=_OUTLINE,
                   rubber=_OUTLINE, area=_OUTLINE, prompt=MessageArea.STATE_SCHEMA,
                   stats=MessageArea.STATE_SCHEMA),
    editor=Record(value=Opt(Int(0, 255)), last=Opt(_PAIR)),
    main_menu=Record(marked=Str(64), menu=PopupMenu.STATE_SCHEMA),
    cross=CrossMenu.STATE_SCHEMA,
    program=Record(menu=Opt(Choice(("main", "edit"))), editing=Bool(), auto=Bool(),
                   frequency=Int(1), fast_forward=Bool(), frequency_before_fast_forward=Int(1),
                   populations=Int(0), finished=Bool(), mouse=_PAIR, pan_from=Opt(_PAIR),
                   text=Str(4096), text_fresh=Bool(), questioning=Bool(),
                   said=ListOf(Str(65536), 1 << 16), script_left=Int(0), script_last=Int(0)))


def engine_values(engine: Engine) -> dict[str, Any]:
    return {"checkpoint": log.format_checkpoint(engine).encode("utf-8"),
            "rules_source": engine.rules.source if engine.rules is not None else "",
            "algorithm": engine.algorithm, "hashlife_memory": engine.hashlife_memory}


def engine_from(values: dict[str, Any]) -> Engine:
    """The engine a state's values describe, through the checkpoint reader (LogError,
    RuleError: ValueErrors naming what is wrong)."""
    try:
        text = values["checkpoint"].decode("utf-8")
    except UnicodeDecodeError:
        raise ValueError("the checkpoint is not UTF-8 text") from None
    engine = log.parse_checkpoint(text, "the state's checkpoint")
    if engine.rules is not None:
        engine.set_rules(parse_rules(engine.rules.text, values["rules_source"]))
    engine.algorithm = values["algorithm"]
    engine.hashlife_memory = values["hashlife_memory"]
    return engine


def migrate(version: int, values: Any) -> Any:
    """An older state (JSON, unchecked) as this version's. Version 1 as 2: no dialogue was
    in progress (a version-1 state could not be saved in one). Version 2 as 3: the same
    values (3 only adds the file dialogues, up to their file's question, to the names).
    Version 3 as 4: a dialogue in progress has no open choice menu (a version-3 state could
    not be saved with one). Version 4 as 5: no input is held (a version-4 state could not
    be saved with any)."""
    if version not in (1, 2, 3, 4):
        raise ValueError(f"no migration from version {version}")
    if not isinstance(values, dict) or ("dialogue" in values) != (version > 1) or \
            "held_events" in values:
        raise ValueError(f"its program part is not a version-{version} mapping")
    dialogue = values.get("dialogue")
    if version < 4 and isinstance(dialogue, dict):
        if "menu" in dialogue:
            raise ValueError(f"its dialogue is not a version-{version} mapping")
        dialogue = dict(dialogue, menu=None)
    return dict(values, dialogue=dialogue, held_events=None)


def held_values(p: CAProgram) -> bytes | None:
    """The input held during a jump as its events' binary form (None: none is held)."""
    if not p.held_events:
        return None
    data = b"".join(encode_event(e) for e in p.held_events)
    if len(p.held_events) > HOLD_LIMIT or len(data) > HELD_BYTES:
        raise ValueError(f"the input held during a jump ({len(p.held_events)} events, "
                         f"{len(data)} bytes) is more than a state holds ({HOLD_LIMIT} "
                         f"events, {HELD_BYTES} bytes)")
    return data


def held_from(data: bytes | None) -> list[Any]:
    """The held events a state's bytes describe, through the events' checking decoder
    (EventFormatError, a ValueError naming the byte, if they are not events)."""
    events = decode_events(data or b"", "state.program.held_events")
    if len(events) > HOLD_LIMIT:
        raise ValueError(f"state.program.held_events: {len(events)} events; a jump holds at "
                         f"most {HOLD_LIMIT}")
    return events


def _answer_values(a: Any) -> dict[str, Any]:
    if a is None:
        return {"kind": "none", "text": "", "ints": []}
    if isinstance(a, str):
        return {"kind": "text", "text": a, "ints": []}
    if isinstance(a, Rect):
        return {"kind": "rect", "text": "", "ints": [a.x0, a.y0, a.x1, a.y1]}
    return {"kind": "point", "text": "", "ints": [int(a[0]), int(a[1])]}


def _answer(v: dict[str, Any]) -> Any:
    n = {"none": 0, "text": 0, "point": 2, "rect": 4}[v["kind"]]
    if len(v["ints"]) != n:
        raise ValueError(f"a {v['kind']} answer holds {n} numbers, not {len(v['ints'])}")
    if v["kind"] == "rect":
        return Rect(*v["ints"])
    return {"none": None, "text": v["text"], "point": tuple(v["ints"])}[v["kind"]]


def dialogue_values(p: CAProgram) -> dict[str, Any] | None:
    """The dialogue in progress as its name, argument and answers (None: none runs)."""
    if p.dialogue is None and p.asking is None and p.choice is None:
        return None
    name, arg = p.dialogue_made or ("", 0)
    if name not in REBUILT:
        raise ValueError("a dialogue is in progress (it is saved once it has ended)")
    if len(p.answers) > FILE_ANSWER.get(name, len(p.answers)):
        raise ValueError(f"the dialogue {name!r} has been given a file name (it is saved "
                         "once it has ended)")
    if p.choice is not None and not p.choice.is_made_last():
        raise ValueError(f"the dialogue {name!r}'s choice menu is not the last thing made "
                         "on the Rainbow (it is saved once it has ended)")
    return {"name": name, "arg": arg, "answers": [_answer_values(a) for a in p.answers],
            "corner": p.corner,
            "menu": None if p.choice is None else p.choice.state_values()}


def rebuild_dialogue(p: CAProgram, v: dict[str, Any]) -> None:
    """Start the saved dialogue through the program's own code and give it its answers
    (its steps before the last only ask); a question it asks as a choice menu takes the
    menu the loaded Rainbow holds, with the state's plain menu values. ValueError if the
    answers end it, or a menu is asked for and the state holds none (or the reverse)."""
    answers = [_answer(a) for a in v["answers"]]
    if len(answers) > FILE_ANSWER.get(v["name"], len(answers)):  # before any step runs
        raise ValueError(f"the dialogue {v['name']!r} would be given a file name by the state")
    dialogue = REBUILT[v["name"]](p, v["arg"])
    try:
        ask = next(dialogue)
        for a in answers:
            ask = dialogue.send(a)
    except StopIteration:
        raise ValueError(f"the answers given end the dialogue {v['name']!r}") from None
    if ask is None or (ask.kind == "menu") != (v["menu"] is not None):
        dialogue.close()
        raise ValueError(f"the dialogue {v['name']!r} would wait on a menu choice the "
                         "state does not hold" if v["menu"] is None else
                         f"the dialogue {v['name']!r} asks for no menu choice here")
    if v["menu"] is not None:
        try:
            if not v["menu"]["open"]:  # a dialogue's choice menu is open while it asks
                raise ValueError(f"the dialogue {v['name']!r}'s choice menu is not open")
            p.choice = choice_menu_reattached(p.client, list(ask.items), v["menu"])
        except ValueError:
            dialogue.close()
            raise
    p.dialogue, p.asking, p.corner = dialogue, ask, v["corner"]
    p.dialogue_made, p.answers = (v["name"], v["arg"]), answers


def state_values(p: CAProgram) -> dict[str, Any]:
    dialogue = dialogue_values(p)
    s, v, d = p.session, p.view, p.display
    engines = {id(s.engine): "shown", id(p.pending): "pending"}
    buffers = []
    for buf in d.buffers.items:
        ref = "none" if buf.engine is None else engines.get(id(buf.engine))
        if ref is None and not buf.stale:
            raise ValueError("a buffer shows a generation the program no longer holds")
        buffers.append({"engine": ref or "none", "stale": buf.stale, "vx": buf.vx,
                        "vy": buf.vy, "drawn_pixels": buf.drawn_pixels})
    return {
        "dialogue": dialogue, "held_events": held_values(p),
        "engine": engine_values(s.engine),
        "pending": None if p.pending is None else engine_values(p.pending),
        "pending_checkpoints": [engine_values(e) for e in p.pending_checkpoints],
        "session": {"edit_mode": s.edit_mode, "current": s.current,
                    "view": {"x": s.view.x, "y": s.view.y, "zoom": s.view.zoom,
                             "cells_per_pixel": s.view.cells_per_pixel},
                    "loaded": [(n, x, y, o) for (n, x, y), o in s._loaded.items()]},
        "viewport": {"zoom": v.zoom, "cells_per_pixel": v.cells_per_pixel, "px": v.px,
                     "py": v.py, "grid": v.grid},
        "display": {"mode": d.mode, "editing": d.editing, "shown": d.buffers.shown,
                    "swaps": d.buffers.swaps, "buffers": buffers,
                    "cursor": _outline(d.cursor), "rubber": _outline(d.rubber),
                    "area": _outline(d.area), "prompt": d.prompt.state_values(),
                    "stats": d.stats.state_values()},
        "editor": {"value": p.editor.value, "last": p.editor.last},
        "main_menu": {"marked": p.main_menu.marked, "menu": p.main_menu.state_values()},
        "cross": p.cross.state_values(),
        "program": {"menu": p.menu, "editing": p.editing, "auto": p.auto,
                    "frequency": p.frequency, "fast_forward": p.fast_forward,
                    "frequency_before_fast_forward": p.frequency_before_fast_forward,
                    "populations": p.populations, "finished": p.finished, "mouse": p.mouse,
                    "pan_from": p.pan_from, "text": p.text, "text_fresh": p.text_fresh,
                    "questioning": p.questioning, "said": list(p.said),
                    "script_left": len(p.script.queue), "script_last": p.script_last}}


def _outline(o: Any) -> dict[str, Any]:
    return {"shape": o.shape, "visible": o.visible}


def check_state_values(p: CAProgram, values: dict[str, Any]) -> Callable[[], None]:
    """Everything a state says checked and built first; returns what puts it in place."""
    engine = engine_from(values["engine"])
    pending = None if values["pending"] is None else engine_from(values["pending"])
    checkpoints = [engine_from(e) for e in values["pending_checkpoints"]]
    held = held_from(values["held_events"])
    sv, pv, dv = values["session"], values["program"], values["display"]
    if sv["edit_mode"] not in _edit_modes():
        raise ValueError(f"edit mode {sv['edit_mode'][:40]!r} is not one of the program's")
    if pv["script_left"] > len(p.script.queue):
        raise ValueError(f"{pv['script_left']} script events left; this run's script has "
                         f"{len(p.script.queue)}")
    if values["main_menu"]["marked"] not in ("", *p.main_menu.items):
        raise ValueError("the marked main-menu item is not one of the menu's")
    refs = {"none": None, "shown": engine, "pending": pending}
    dialogue = values["dialogue"]
    if dialogue is not None:  # its answers' shapes checked now; it is made once in place
        [_answer(a) for a in dialogue["answers"]]
    puts = [p.display.prompt.check_state_values(dv["prompt"]),
            p.display.stats.check_state_values(dv["stats"]),
            p.main_menu.check_state_values(values["main_menu"]["menu"]),
            p.cross.check_state_values(values["cross"])]

    def put() -> None:
        s, v, d = p.session, p.view, p.display
        s.engine, p.pending, p.pending_checkpoints = engine, pending, checkpoints
        s.edit_mode, s.current = sv["edit_mode"], sv["current"]
        for name, value in sv["view"].items():
            setattr(s.view, name, value)
        s._loaded = {(n, x, y): o for n, x, y, o in sv["loaded"]}
        for name, value in values["viewport"].items():
            setattr(v, name, value)
        d.mode, d.editing = dv["mode"], dv["editing"]
        d.buffers.shown, d.buffers.swaps = dv["shown"], dv["swaps"]
        for buf, bv in zip(d.buffers.items, dv["buffers"], strict=True):
            buf.engine = refs[bv["engine"]]
            buf.stale, buf.vx, buf.vy = bv["stale"], bv["vx"], bv["vy"]
            buf.drawn_pixels = bv["drawn_pixels"]
        for name in ("cursor", "rubber", "area"):
            outline = getattr(d, name)
            outline.shape, outline.visible = dv[name]["shape"], dv[name]["visible"]
        d.rules = engine.rules
        p.editor.value, p.editor.last = values["editor"]["value"], values["editor"]["last"]
        p.main_menu.marked = values["main_menu"]["marked"]
        for name in ("menu", "editing", "auto", "frequency", "fast_forward",
                     "frequency_before_fast_forward", "populations", "finished", "mouse",
                     "pan_from", "text", "text_fresh", "questioning", "script_last"):
            setattr(p, name, pv[name])
        p.said = list(pv["said"])
        left = pv["script_left"]
        p.script.queue = p.script.queue[len(p.script.queue) - left:] if left else []
        p.dialogue = p.asking = p.corner = p.choice = None
        p.dialogue_made, p.answers = None, []
        p.held_events = held  # handled first by the next frame, as after the jump
        for part in puts:
            part()
        if dialogue is not None:  # (its answers checked above; a refusal here ends a load)
            rebuild_dialogue(p, dialogue)
    return put


def _edit_modes() -> set[str]:
    from camlab88.apps.ca.program.menus import EDIT_MODES

    return set(EDIT_MODES.values()) | {"step_up"}
