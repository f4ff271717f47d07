"""Shared helpers: run a front against an emulated T5684 from a script."""

from __future__ import annotations

from pathlib import Path

from camlab88.apps.kas.editor import Editor
from camlab88.apps.kas.events import Key, Pointer
from camlab88.apps.kas.program import EditorFront, Session, parse_timed_script
from camlab88.emulator.harness.sigma import SigmaSessionRun
from camlab88.emulator.machine import SigmaMachine

DATA = Path(__file__).parent.parent / "data" / "kas_front"
GOLDEN = DATA / "golden"


def drive(front) -> SigmaSessionRun:
    """``front`` on an emulated T5684 over a 9600-baud line, run as the harness runs it."""
    machine = SigmaMachine("t5684")
    return SigmaSessionRun(machine, Session(front, machine.host))


def script(name: str):
    return parse_timed_script((DATA / name).read_text(encoding="utf-8"), name)


def run_editor(name: str, seed: int = 1, background: str = "black", editor=None):
    saved = []
    front = EditorFront(editor or Editor(seed=seed), background,
                        on_save=lambda d: saved.append(d.copy()))
    session = drive(front)
    term = session.terminal
    session.run_script(script(name))
    return front, term, session, saved


def model_only(name: str, seed: int = 1) -> Editor:
    """The same events straight into the model, no device in between."""
    ed = Editor(seed=seed)
    for e in script(name):
        if e.kind == "pointer":
            ed.feed(Pointer(e.x, e.y, e.down))
        elif e.kind == "key":
            ed.feed(Key(e.key))
    return ed
