"""Scripted mouse and keyboard input for headless runs and tests.

One command a line; ``#`` starts a comment:

    move X Y                 the pointer moves to (X, Y) in device pixels
    glide X Y N              ... in N equal steps (N movement reports, as a real mouse sends)
    press left|middle|right  a button goes down (at the pointer)
    release left|middle|right
    key NAME                 a key is pressed and released (return, escape, y, ...)
    type TEXT                each character typed (a space is the "space" key)
    wait N                   let N display frames (1/50 s each) pass

Events between two waits reach the program before its next frame.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

from protocols.rainbow.events import LEFT, MIDDLE, RIGHT, Event, KeyEvent, MouseEvent

BUTTONS = {"left": (1, LEFT), "middle": (2, MIDDLE), "right": (3, RIGHT)}
MAX_WAIT = 1_000_000


class ScriptError(ValueError):
    pass


@dataclass
class Script:
    """Batches of events, each followed by a number of frames to wait."""

    steps: list[tuple[list[Event], int]] = field(default_factory=list)

    @property
    def frames(self) -> int:
        return sum(n for _, n in self.steps)


def parse(text: str, where: str = "<script>", start: tuple[int, int] = (0, 0)) -> Script:
    """`start`: where the pointer is when the script begins."""
    script = Script()
    batch: list[Event] = []
    (x, y), buttons = start, 0
    for n, raw in enumerate(text.splitlines(), 1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        word, _, rest = line.partition(" ")
        rest = rest.strip()

        def bad(msg: str, n: int = n) -> ScriptError:
            return ScriptError(f"{where}:{n}: {msg}")

        if word == "move":
            try:
                x, y = (int(v) for v in rest.split())
            except ValueError:
                raise bad(f"move wants two integers X Y, got {rest!r}") from None
            batch.append(MouseEvent(0, x, y, buttons))
        elif word == "glide":
            try:
                tx, ty, steps = (int(v) for v in rest.split())
            except ValueError:
                raise bad(f"glide wants three integers X Y N, got {rest!r}") from None
            if not 1 <= steps <= 10_000:
                raise bad(f"glide steps {steps} outside 1..10000")
            x0, y0 = x, y
            for k in range(1, steps + 1):
                x, y = x0 + (tx - x0) * k // steps, y0 + (ty - y0) * k // steps
                batch.append(MouseEvent(0, x, y, buttons))
        elif word in ("press", "release"):
            if rest not in BUTTONS:
                raise bad(f"unknown button {rest!r} (left, middle, right)")
            number, bit = BUTTONS[rest]
            pressed = word == "press"
            buttons = buttons | bit if pressed else buttons & ~bit
            batch.append(MouseEvent(0, x, y, buttons, number, pressed))
        elif word == "key":
            if not rest or " " in rest:
                raise bad(f"key wants one key name, got {rest!r}")
            char = rest if len(rest) == 1 else ""
            batch += [KeyEvent(0, rest, char, True), KeyEvent(0, rest, "", False)]
        elif word == "type":
            for ch in rest:
                name = "space" if ch == " " else ch
                batch += [KeyEvent(0, name, ch, True), KeyEvent(0, name, "", False)]
        elif word == "wait":
            try:
                k = int(rest)
            except ValueError:
                raise bad(f"wait wants a frame count, got {rest!r}") from None
            if not 0 <= k <= MAX_WAIT:
                raise bad(f"wait {k} is outside 0..{MAX_WAIT}")
            script.steps.append((batch, k))
            batch = []
        else:
            raise bad(f"unknown command {word!r} (move, glide, press, release, key, type, wait)")
    if batch:
        script.steps.append((batch, 1))
    return script


def load(path: str | os.PathLike[str]) -> Script:
    try:
        raw = Path(path).read_bytes()
    except OSError as exc:
        raise ScriptError(f"{path}: cannot read: {exc.strerror}") from None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise ScriptError(f"{path}: byte offset {exc.start}: not UTF-8") from None
    return parse(text, str(path))


class Player:
    """Feeds a script to a device frame by frame: ``due()`` before each display frame gives
    the events to inject then."""

    def __init__(self, script: Script) -> None:
        self.steps = list(script.steps)
        self.wait = 0

    @property
    def finished(self) -> bool:
        return not self.steps and self.wait == 0

    def due(self) -> list[Event]:
        out: list[Event] = []
        while self.wait == 0 and self.steps:
            batch, n = self.steps.pop(0)
            out += batch
            self.wait = n
        if self.wait:
            self.wait -= 1
        return out
