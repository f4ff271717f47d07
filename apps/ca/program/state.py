"""``ca program``'s declared state (the harness's program_state): plain values the
program is rebuilt from through its own code.

The automaton (the shown generation, the one computed ahead and the checkpoints waiting to
be written) is kept as the thesis's checkpoint text (log.format_checkpoint) and read back by
log.parse_checkpoint, the reader a user's checkpoint files go through, with the rules'
source name and the engine's algorithm beside it. The rest is the program's values, the
session's, the viewport's, the display's (buffers, outlines, message areas) and the menus'.

Not saved, and so refused while they are there: a dialogue in progress (a generator: made
again only by running it, which would read files its answers name) and input held during a
long jump. What the command line gave (the rules file, the pattern, the script, the Log
being written) is the fresh build's.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from camlab88.apps.ca import algorithms, log
from camlab88.apps.ca.engine import Engine
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
from camlab88.protocols.rainbow.ui import MessageArea, PopupMenu
from camlab88.protocols.rainbow.ui.menu import CrossMenu

if TYPE_CHECKING:
    from camlab88.apps.ca.program.program import CAProgram

VERSION = 1
_PAIR = Tuple((Int(), Int()))
ENGINE = Record(checkpoint=Blob(256 << 20), rules_source=Str(4096),
                algorithm=Choice(algorithms.CHOICES), hashlife_memory=Int(1))
_BUFFER = Record(engine=Choice(("none", "shown", "pending")), stale=Bool(), vx=Int(), vy=Int(),
                 drawn_pixels=Int(0))
_OUTLINE = Record(shape=Opt(Tuple((Int(),) * 4)), visible=Bool())
SCHEMA = Record(
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


def state_values(p: CAProgram) -> dict[str, Any]:
    if p.dialogue is not None or p.asking is not None or p.choice is not None:
        raise ValueError("a dialogue is in progress (it is saved once it has ended)")
    if p.held_events:
        raise ValueError("input read during a jump is waiting")
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
    sv, pv, dv = values["session"], values["program"], values["display"]
    if sv["edit_mode"] not in _edit_modes():
        raise ValueError(f"edit mode {sv['edit_mode'][:40]!r} is not one of the program's")
    if pv["script_left"] > len(p.script.queue):
        raise ValueError(f"{pv['script_left']} script events left; this run's script has "
                         f"{len(p.script.queue)}")
    if values["main_menu"]["marked"] not in ("", *p.main_menu.items):
        raise ValueError("the marked main-menu item is not one of the menu's")
    refs = {"none": None, "shown": engine, "pending": pending}
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
        p.dialogue = p.asking = p.corner = None
        for part in puts:
            part()
    return put


def _edit_modes() -> set[str]:
    from camlab88.apps.ca.program.menus import EDIT_MODES

    return set(EDIT_MODES.values()) | {"step_up"}
