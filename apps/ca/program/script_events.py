"""Scripted mouse and keyboard input for headless runs and tests (pure, no device).

A text file, one command a line, ``#`` comments::

    move X Y                 the mouse moves (buttons held stay held)
    press left|middle|right X Y
    release left|middle|right X Y
    click left|middle|right X Y        press then release
    drag left|middle|right X0 Y0 X1 Y1 [STEPS]   press, STEPS moves, release
    key NAME                 a key pressed and released (return, escape, backspace, ...)
    type TEXT                each character typed (the rest of the line, spaces kept)
    frames N                 let N frames pass (the events so far are read in the first)

Parsing gives a list of steps: a Rainbow input event, or an int (frames to run). Errors
name the file and line.
"""

from __future__ import annotations

from collections.abc import Callable

from protocols.rainbow.events import KeyEvent, MouseEvent

BUTTONS = {"left": (1, 1), "middle": (2, 2), "right": (3, 4)}  # name: (button, bit)
Step = MouseEvent | KeyEvent | int


class ScriptError(ValueError):
    pass


class MouseState:
    """Position and held buttons, carried from line to line (and between scripts)."""

    def __init__(self) -> None:
        self.x = self.y = 0
        self.held = 0

    def move(self, x: int, y: int) -> MouseEvent:
        self.x, self.y = x, y
        return MouseEvent(0, x, y, self.held)

    def button(self, name: str, x: int, y: int, pressed: bool) -> MouseEvent:
        b, bit = BUTTONS[name]
        self.held = self.held | bit if pressed else self.held & ~bit
        self.x, self.y = x, y
        return MouseEvent(0, x, y, self.held, b, pressed)


def _ints(words: list[str], n: int | tuple[int, ...], where: str) -> list[int]:
    allowed = n if isinstance(n, tuple) else (n,)
    if len(words) not in allowed:
        want = " or ".join(str(k) for k in allowed)
        raise ScriptError(f"{where}: expected {want} numbers, found {len(words)}")
    try:
        return [int(w) for w in words]
    except ValueError:
        raise ScriptError(f"{where}: expected whole numbers, found {' '.join(words)!r}") from None


def parse(text: str, source: str = "<events>", mouse: MouseState | None = None) -> list[Step]:
    steps: list[Step] = []
    mouse = mouse or MouseState()
    for n, raw in enumerate(text.splitlines(), 1):
        where = f"{source}:{n}"
        line = raw.split("#", 1)[0] if not raw.lstrip().startswith("type ") else raw
        words = line.split()
        if not words:
            continue
        cmd, args = words[0], words[1:]
        if cmd == "move":
            steps.append(mouse.move(*_ints(args, 2, where)))
        elif cmd in ("press", "release", "click", "drag"):
            if not args or args[0] not in BUTTONS:
                raise ScriptError(f"{where}: {cmd} needs a button: left, middle or right")
            name = args[0]
            if cmd == "drag":
                nums = _ints(args[1:], (4, 5), where)
                x0, y0, x1, y1 = nums[:4]
                k = nums[4] if len(nums) == 5 else 8
                if k < 1:
                    raise ScriptError(f"{where}: drag needs at least 1 step")
                steps.append(mouse.button(name, x0, y0, True))
                for i in range(1, k + 1):
                    steps.append(mouse.move(x0 + (x1 - x0) * i // k, y0 + (y1 - y0) * i // k))
                steps.append(mouse.button(name, x1, y1, False))
                continue
            x, y = _ints(args[1:], 2, where)
            if cmd in ("press", "click"):
                steps.append(mouse.button(name, x, y, True))
            if cmd in ("release", "click"):
                steps.append(mouse.button(name, x, y, False))
        elif cmd == "key":
            if len(args) != 1:
                raise ScriptError(f"{where}: key needs one key name")
            steps += [KeyEvent(0, args[0], "", True), KeyEvent(0, args[0], "", False)]
        elif cmd == "type":
            for ch in line.lstrip()[5:]:
                name = "space" if ch == " " else ch.lower()
                steps += [KeyEvent(0, name, ch, True), KeyEvent(0, name, "", False)]
        elif cmd == "frames":
            (k,) = _ints(args, 1, where)
            if k < 0:
                raise ScriptError(f"{where}: frames must be >= 0")
            steps.append(k)
        else:
            raise ScriptError(f"{where}: unknown command {cmd!r} (move, press, release, "
                              "click, drag, key, type, frames)")
    return steps


def read(path: str) -> list[Step]:
    with open(path, encoding="utf-8") as f:
        return parse(f.read(), path)


def play(steps: list[Step], inject: Callable[[MouseEvent | KeyEvent], None],
         frame: Callable[[], None], finished: Callable[[], bool] = lambda: False) -> int:
    """Inject the events, running ``frame`` where the script says; returns frames run.

    Events not followed by a ``frames`` line are still read: one frame is run at the end
    if any are left over."""
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
