"""Scripted mouse and keyboard input for the CA program: the one Rainbow script format,
protocols.rainbow.script (see there for the language and its bounds).

``parse`` gives the old list of steps (a Rainbow input event, or an int: frames to run);
``play`` runs such a list against a program.
"""

from __future__ import annotations

from collections.abc import Callable

from camlab88.protocols.rainbow.events import KeyEvent, MouseEvent
from camlab88.protocols.rainbow.script import MouseState, ScriptError, load
from camlab88.protocols.rainbow.script import parse as parse_script

Step = MouseEvent | KeyEvent | int
__all__ = ["MouseState", "ScriptError", "Step", "parse", "play", "read"]


def parse(text: str, source: str = "<events>", mouse: MouseState | None = None) -> list[Step]:
    """Events and frame counts in order; errors name ``source:line:col``."""
    return parse_script(text, source, mouse=mouse).flat()


def read(path: str) -> list[Step]:
    return load(path).flat()


def play(steps: list[Step], inject: Callable[[MouseEvent | KeyEvent], None],
         frame: Callable[[], None], finished: Callable[[], bool] = lambda: False) -> int:
    """Inject the events, running ``frame`` where the script says; returns frames run."""
    frames = 0
    unread = False
    for s in steps:
        if finished():
            break
        if isinstance(s, int):
            for _ in range(s):
                if finished():
                    break
                frame()
                frames += 1
            unread = False
        else:
            inject(s)
            unread = True
    if unread and not finished():
        frame()
        frames += 1
    return frames
