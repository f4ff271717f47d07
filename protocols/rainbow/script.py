"""The one scripted-input language for programs on the Rainbow (snooker, CA, and new ones).

A UTF-8 text file, one command a line, ``#`` starts a comment (except in ``type``)::

    move X Y                          the mouse moves (buttons held stay held)
    glide X Y [N]                     ... in N equal steps (default 8), N reports
    press left|middle|right [X Y]     a button goes down (at X Y, else where the mouse is)
    release left|middle|right [X Y]
    click left|middle|right [X Y]     press then release
    drag left|middle|right X0 Y0 X1 Y1 [N]   press, N moves (default 8), release
    key NAME                          a key pressed and released (return, escape, y, ...)
    type TEXT                         each character typed (rest of the line, spaces kept)
    wait N   (or: frames N)           let N display frames (1/50 s each) pass

The events written before a ``wait`` reach the program before the first of its N frames;
events after the last ``wait`` get one frame.  This merges the snooker program's language
(``wait``, ``glide``) and the CA program's (``frames``, ``click``, ``drag``, buttons at a
position): every old file of either reads the same.  Bounds, so a typing error is a clear
``file:line:col`` error and never a hang or a huge allocation: coordinates in
-32768..32767, at most 10000 steps in a glide or drag, at most 1000000 frames and 1000000
input events in a script.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

from camlab88.protocols.rainbow.events import KeyEvent, MouseEvent

Event = MouseEvent | KeyEvent
BUTTONS = {"left": (1, 1), "middle": (2, 2), "right": (3, 4)}  # name: (button, bit)
COORD = (-32768, 32767)
MAX_STEPS = 10_000
MAX_FRAMES = 1_000_000
MAX_EVENTS = 1_000_000
DEFAULT_STEPS = 8
VERBS = ("move", "glide", "press", "release", "click", "drag", "key", "type", "wait", "frames")


class ScriptError(ValueError):
    """A bad script line: ``file:line:col: what was wrong, what was expected``."""


@dataclass
class Script:
    """Batches of events, each followed by the number of frames to wait."""

    steps: list[tuple[list[Event], int]] = field(default_factory=list)

    @property
    def frames(self) -> int:
        return sum(n for _, n in self.steps)

    def flat(self) -> list[Event | int]:
        """Events and frame counts in order (the CA program's old ``Step`` list)."""
        out: list[Event | int] = []
        for batch, n in self.steps:
            out += batch
            out.append(n)
        return out


@dataclass
class MouseState:
    """Where the mouse is and which buttons are held; carried from line to line (and from
    one script to the next when a caller passes the same state)."""

    x: int = 0
    y: int = 0
    held: int = 0


class _Line:
    """One line's words with their columns, for error messages."""

    def __init__(self, where: str, no: int, raw: str) -> None:
        self.where, self.no, self.raw = where, no, raw
        self.words: list[tuple[str, int]] = []
        col = 0
        for word in raw.split():
            col = raw.index(word, col)
            self.words.append((word, col + 1))
            col += len(word)

    def error(self, message: str, index: int | None = None) -> ScriptError:
        col = self.words[index][1] if index is not None and index < len(self.words) else 1
        return ScriptError(f"{self.where}:{self.no}:{col}: {message}")

    def ints(self, start: int, counts: tuple[int, ...], what: str,
             bounds: tuple[int, int] = COORD) -> list[int]:
        words = self.words[start:]
        if len(words) not in counts:
            want = " or ".join(map(str, counts))
            raise self.error(f"{self.words[0][0]} wants {want} numbers ({what}), found "
                             f"{len(words)}", min(start + len(words), len(self.words) - 1))
        out = []
        for k, (w, _c) in enumerate(words, start):
            digits = w[1:] if w[:1] in "+-" else w
            if not (digits.isascii() and digits.isdigit()) or len(digits) > 12:
                raise self.error(f"expected a whole number, found {w!r}", k)
            v = int(w)
            if not bounds[0] <= v <= bounds[1]:
                kind = "coordinate" if bounds == COORD else "value"
                raise self.error(f"{kind} {v} is outside {bounds[0]}..{bounds[1]}", k)
            out.append(v)
        return out


class _Parser:
    def __init__(self, where: str, mouse: MouseState) -> None:
        self.where = where
        self.mouse = mouse
        self.script = Script()
        self.batch: list[Event] = []
        self.total = 0
        self.events = 0
        self.counted = 0  # events of the current batch already counted

    def move(self, x: int, y: int) -> None:
        m = self.mouse
        m.x, m.y = x, y
        self.batch.append(MouseEvent(0, x, y, m.held))

    def button(self, name: str, pressed: bool) -> None:
        b, bit = BUTTONS[name]
        m = self.mouse
        m.held = m.held | bit if pressed else m.held & ~bit
        self.batch.append(MouseEvent(0, m.x, m.y, m.held, b, pressed))

    def steps_to(self, x1: int, y1: int, n: int) -> None:
        x0, y0 = self.mouse.x, self.mouse.y
        for k in range(1, n + 1):
            self.move(x0 + (x1 - x0) * k // n, y0 + (y1 - y0) * k // n)

    def key(self, name: str, char: str) -> None:
        self.batch += [KeyEvent(0, name, char, True), KeyEvent(0, name, "", False)]

    def wait(self, line: _Line, n: int) -> None:
        self.total += n
        if self.total > MAX_FRAMES:
            raise line.error(f"the script runs {self.total} frames, more than {MAX_FRAMES} "
                             "(about 5.5 hours at 50 frames a second)", 1)
        self.script.steps.append((self.batch, n))
        self.batch = []
        self.counted = 0

    def line(self, line: _Line) -> None:
        verb = line.words[0][0]
        handler = getattr(self, f"_{verb}", None) if verb in VERBS else None
        if handler is None:
            raise line.error(f"unknown command {verb!r}; expected one of {', '.join(VERBS)}", 0)
        handler(line)
        self.events += len(self.batch) - self.counted
        self.counted = len(self.batch)
        if self.events > MAX_EVENTS:
            raise line.error(f"the script makes more than {MAX_EVENTS} input events", 0)

    def _move(self, line: _Line) -> None:
        self.move(*line.ints(1, (2,), "X Y"))

    def _glide(self, line: _Line) -> None:
        x, y, *n = self._coords_steps(line, 1, (2, 3), "X Y [STEPS]")
        self.steps_to(x, y, n[0] if n else DEFAULT_STEPS)

    def _coords_steps(self, line: _Line, start: int, counts: tuple[int, ...],
                      what: str) -> list[int]:
        """Coordinates then an optional step count (bounded on its own)."""
        values = line.ints(start, counts, what, (-2**31, 2**31 - 1))
        n_coords = min(counts)
        for k, v in enumerate(values):
            lo, hi = COORD if k < n_coords else (1, MAX_STEPS)
            if not lo <= v <= hi:
                what = "coordinate" if k < n_coords else "number of steps"
                raise line.error(f"{what} {v} is outside {lo}..{hi}", start + k)
        return values

    def _which(self, line: _Line) -> str:
        if len(line.words) < 2 or line.words[1][0] not in BUTTONS:
            raise line.error(f"{line.words[0][0]} needs a button: left, middle or right",
                             1 if len(line.words) > 1 else 0)
        return line.words[1][0]

    def _press(self, line: _Line, pressed: tuple[bool, ...] = (True,)) -> None:
        name = self._which(line)
        at = line.ints(2, (0, 2), "[X Y]")
        if at:
            self.mouse.x, self.mouse.y = at
        for p in pressed:
            self.button(name, p)

    def _release(self, line: _Line) -> None:
        self._press(line, (False,))

    def _click(self, line: _Line) -> None:
        self._press(line, (True, False))

    def _drag(self, line: _Line) -> None:
        name = self._which(line)
        x0, y0, x1, y1, *n = self._coords_steps(line, 2, (4, 5), "X0 Y0 X1 Y1 [STEPS]")
        steps = n[0] if n else DEFAULT_STEPS
        self.mouse.x, self.mouse.y = x0, y0
        self.button(name, True)
        self.steps_to(x1, y1, steps)
        self.button(name, False)

    def _key(self, line: _Line) -> None:
        if len(line.words) != 2:
            raise line.error("key wants one key name (a character, return, escape, ...)",
                             min(len(line.words) - 1, 2))
        name = line.words[1][0]
        self.key(name, name if len(name) == 1 else "")

    def _type(self, line: _Line) -> None:
        for ch in line.raw.lstrip()[5:]:
            self.key("space" if ch == " " else ch.lower(), ch)

    def _wait(self, line: _Line) -> None:
        (n,) = line.ints(1, (1,), "N frames", (0, MAX_FRAMES))  # "value N is outside"
        self.wait(line, n)

    _frames = _wait


def parse(text: str, where: str = "<script>", start: tuple[int, int] = (0, 0),
          mouse: MouseState | None = None) -> Script:
    """The script in ``text``; the mouse begins at ``start`` (or in state ``mouse``, which
    the script then updates)."""
    p = _Parser(where, mouse if mouse is not None else MouseState(*start))
    for no, raw in enumerate(text.splitlines(), 1):
        body = raw if raw.lstrip().startswith("type ") else raw.split("#", 1)[0]
        line = _Line(where, no, body)
        if line.words:
            p.line(line)
    if p.batch:
        p.wait(_Line(where, no, ""), 1)
    return p.script


def load(path: str | os.PathLike[str]) -> Script:
    """Read and parse a script file; unreadable or non-UTF-8 files name the file."""
    try:
        raw = Path(path).read_bytes()
    except OSError as exc:
        raise ScriptError(f"{path}: cannot read: {exc.strerror or exc}") from None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        col = exc.start - (raw.rfind(b"\n", 0, exc.start) + 1) + 1
        raise ScriptError(f"{path}:{line}:{col}: not UTF-8 text") from None
    return parse(text, os.fspath(path))


class Player:
    """Feeds a script frame by frame: ``due()`` before each display frame gives the events
    to inject then; ``finished`` once every batch has been given and waited for."""

    def __init__(self, script: Script) -> None:
        self.steps = list(script.steps)
        self.wait = 0
        self._total = len(self.steps)

    def played(self) -> int:
        """How many batches have been given (a save state's place in the script)."""
        return self._total - len(self.steps)

    def can_resume(self, played: int, wait: int) -> bool:
        """``resume(played, wait)`` fits this script (from its start)."""
        return self.played() == 0 and 0 <= played <= self._total and wait >= 0 and (
            played > 0 or wait == 0)

    def resume(self, played: int, wait: int) -> None:
        """Continue a fresh player from a saved place (``can_resume`` first)."""
        del self.steps[:played]
        self.wait = wait

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
