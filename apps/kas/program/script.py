"""Headless event scripts and the session of a front on its port to the terminal.

Script format (UTF-8 text, one event a line, ``#`` starts a comment)::

    [TIME] VERB ARGS

TIME is line time in seconds: ``2.5`` (absolute) or ``+0.1`` (after the previous event);
without it an event comes 0.02 s after the previous one.  Times never go back.  VERBs:

    move X Y     stylus moves, lifted        (X Y in screen field inches: centre origin,
    down X Y     stylus down (touch or drag)  y up; the menu row is above the field,
    up X Y       stylus lifted                y 4.525..5.125)
    menu ITEM    touch the centre of a menu box and lift (two stylus events)
    key K        a key on the terminal's keyboard: a character or a name
                 (space return backspace escape tab up down left right f2)
    type TEXT    one key per character (a space types "space")
    wait         nothing; only moves time on (e.g. ``5.0 wait`` lets the screen catch up)

Stylus events go through the tablet input layer exactly as a window's mouse does (a
position on the 768 x 512 screen), keys are struck on the emulated terminal (by the harness,
which runs the machine: the user is not the host) and travel up the serial line to the
program; the program's drawing orders travel down it.  So a script exercises the whole byte
path, on the line's virtual clock.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from fractions import Fraction
from typing import Any, Protocol

from camlab88.apps.kas.events import TIME_WORD
from camlab88.apps.kas.files import KasFileError
from camlab88.apps.kas.program import layout as L
from camlab88.apps.kas.program.base import Front
from camlab88.protocols.link.port import HostPort
from camlab88.protocols.sigma.keyboard import key_to_bytes
from camlab88.protocols.tablets.input_layer import InputLayer, MouseSample

DEFAULT_STEP = Fraction(1, 50)
MAX_TIME = 10**6  # seconds: a script time beyond this is a typing error


@dataclass(frozen=True)
class TimedEvent:
    t: Fraction
    kind: str               # "pointer" | "key" | "wait"
    x: float = 0.0
    y: float = 0.0
    down: bool = False
    key: str = ""


def _time(tok: str, prev: Fraction) -> Fraction:
    if not TIME_WORD.fullmatch(tok):  # before Fraction: see TIME_WORD
        raise ValueError
    rel = tok.startswith("+")
    v = Fraction(tok[1:] if rel else tok)
    if not 0 <= v <= MAX_TIME:
        raise ValueError
    return prev + v if rel else v


def parse_timed_script(text: str, name: str = "<script>") -> list[TimedEvent]:
    """Events of a script (format above); a bad line raises KasFileError naming the line."""
    from camlab88.apps.kas.editor import menu_layout

    boxes = {item: ((x0 + x1) / 2, (y0 + y1) / 2) for item, x0, y0, x1, y1 in menu_layout()}
    out: list[TimedEvent] = []
    prev = Fraction(0)
    for no, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        words = line.split(None, 1)
        try:
            t = prev + DEFAULT_STEP if out else prev
            first = words[0]
            if first[0] in "+0123456789.":
                t = _time(first, prev)
                words = words[1].split(None, 1) if len(words) > 1 else []
                if not words:
                    raise ValueError
            if t < prev:
                raise KasFileError(name, no, f"time {float(t):g} s goes back (previous "
                                   f"{float(prev):g} s)")
            verb, rest = words[0], (words[1].strip() if len(words) > 1 else "")
            if verb in ("move", "down", "up"):
                xs, ys = rest.split()
                x, y = float(xs), float(ys)
                if not (math.isfinite(x) and math.isfinite(y)):
                    raise ValueError
                out.append(TimedEvent(t, "pointer", x, y, verb == "down"))
            elif verb == "menu" and rest:
                if rest not in boxes:
                    raise KasFileError(name, no, f"no menu item {rest!r}")
                x, y = boxes[rest]
                out.append(TimedEvent(t, "pointer", x, y, True))
                t += DEFAULT_STEP
                out.append(TimedEvent(t, "pointer", x, y, False))
            elif verb == "key" and rest:
                key_to_bytes(rest)
                out.append(TimedEvent(t, "key", key=rest))
            elif verb == "type" and rest:
                for i, ch in enumerate(rest):
                    out.append(TimedEvent(t + i * DEFAULT_STEP, "key",
                                          key="space" if ch == " " else ch))
                    key_to_bytes(out[-1].key)
                t += (len(rest) - 1) * DEFAULT_STEP
            elif verb == "wait" and not rest:
                out.append(TimedEvent(t, "wait"))
            else:
                raise ValueError
        except KasFileError:
            raise
        except (ValueError, ZeroDivisionError, IndexError, OverflowError) as exc:
            shown = repr(line[:60]) + ("..." if len(line) > 60 else "")  # a line can be 1 MB
            detail = str(exc) if str(exc).startswith("no Sigma key") else (
                f"bad event {shown} (expected [TIME] move/down/up X Y, menu ITEM, key K, "
                "type TEXT or wait)")
            raise KasFileError(name, no, detail) from None
        prev = t
    return out


class PointerSource(Protocol):
    def poll(self, mouse: Iterable[MouseSample] = ()) -> list: ...


class Session:
    """A front on its port to the terminal (emulator.machine.SigmaMachine.host).

    Each ``step`` (one poll; whoever runs the machine then moves the line on): stylus samples
    go through the input layer to the front, key bytes that have arrived up the line go to
    the front, and if everything sent so far has arrived the front's update is sent.
    """

    def __init__(self, front: Front, port: HostPort,
                 pointer: PointerSource | None = None) -> None:
        self.front = front
        self.port = port
        self.pointer_source = pointer or InputLayer(L.TABLET_AREA, None)
        self.sent: list[tuple[Fraction, bytes]] = []
        self.updates = 0
        self._dirty = True
        self._started = False
        self._arrives = 0.0  # line time the last byte sent arrives

    @property
    def now(self) -> Fraction:
        return self.port.exact

    def send(self, data: bytes) -> None:
        if data:
            self.sent.append((self.port.exact, data))
            self._arrives = self.port.write(data)

    def begin(self) -> None:
        if not self._started:
            self._started = True
            self.send(self.front.start())
            self._dirty = False

    def step(self, mouse: Iterable[MouseSample] = ()) -> None:
        """One poll: input in, screen update out."""
        self.begin()
        events = self.pointer_source.poll(list(mouse))
        if events:
            self.front.pointer(events)
            self._dirty = True
        data = self.port.read()
        if data:
            self.front.keys(data)
            self._dirty = True
        if self._dirty and self._arrives <= self.port.now:
            self.send(self.front.update())
            self.updates += 1
            self._dirty = False

    def due(self, events: list[TimedEvent], i: int) -> tuple[list[MouseSample], list[str], int]:
        """Script events from index ``i`` that are due now, as mouse samples and keys."""
        mouse: list[MouseSample] = []
        keys: list[str] = []
        while i < len(events) and events[i].t <= self.port.exact:
            ev = events[i]
            if ev.kind == "pointer":
                mx, my = L.field_to_mouse(ev.x, ev.y)
                mouse.append(MouseSample(mx, my, 1 if ev.down else 0, (L.SCREEN_W, L.SCREEN_H)))
            elif ev.kind == "key":
                keys.append(ev.key)
            i += 1
        return mouse, keys, i

    def busy(self) -> bool:
        """The screen is not up to date, or what was sent has not all been taken (keys on
        their way up the line are the machine's to know)."""
        return bool(self._dirty or not self.port.drained())


def load_timed_script(path: Any) -> list[TimedEvent]:
    """Read and parse a script file; an unreadable or non-UTF-8 file names the file."""
    from camlab88.base.textinput import InputError, read_text

    try:  # a directory, an unreadable file or a bad byte: named with its line and column
        text = read_text(path)
    except InputError as exc:
        raise KasFileError(exc.name or str(path), exc.line, exc.reason, exc.column) from None
    return parse_timed_script(text, str(path))
