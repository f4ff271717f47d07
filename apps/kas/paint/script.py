"""Painting scripts: the painting program's commands as text, one a line, for headless runs
and tests (docs/kas.md).  Coordinates are field inches.

    colour 5            select -2.0 0.5     fill        line        clear
    region 0.3 -1.2     touch 0.3 -1.2      rgb red +20 mix 2:1 6:3
    show preview        frame 12            autopaint
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

from camlab88.apps.kas.paint.palette import GUNS
from camlab88.apps.kas.paint.session import VIEWS, PaintSession

ARGS = {"colour": "i", "select": "ff", "fill": "", "line": "", "clear": "", "region": "ff",
        "touch": "ff", "rgb": "gi", "mix": "m", "show": "v", "frame": "i", "autopaint": ""}


class ScriptError(ValueError):
    def __init__(self, name: str, line: int, col: int, msg: str) -> None:
        super().__init__(f"{name}:{line}:{col}: {msg}")


@dataclass(frozen=True)
class Command:
    name: str
    args: tuple
    line: int


def _value(kind: str, word: str) -> object:
    if kind == "i":
        if not re.fullmatch(r"[+-]?[0-9]+", word):
            raise ValueError(f"expected a whole number, found {word!r}")
        return int(word)
    if kind == "f":
        v = float(word) if re.fullmatch(r"[0-9eE+\-.]+", word) else math.nan
        if not math.isfinite(v):
            raise ValueError(f"expected a number, found {word!r}")
        return v
    if kind == "g" and word not in GUNS:
        raise ValueError(f"expected {', '.join(GUNS)}, found {word!r}")
    if kind == "v" and word not in VIEWS:
        raise ValueError(f"expected {', '.join(VIEWS)}, found {word!r}")
    if kind == "m":
        m = re.fullmatch(r"([0-9]+):([0-9]+)", word)
        if not m:
            raise ValueError(f"expected ENTRY:AMOUNT, found {word!r}")
        return int(m.group(1)), int(m.group(2))
    return word


def parse(text: str, name: str = "<script>") -> list[Command]:
    out = []
    for n, raw in enumerate(text.splitlines(), start=1):
        words = [(m.start() + 1, m.group()) for m in re.finditer(r"\S+", raw.split("#")[0])]
        if not words:
            continue
        col, cmd = words[0]
        if cmd not in ARGS:
            raise ScriptError(name, n, col, f"unknown command {cmd!r} (one of "
                                            f"{', '.join(ARGS)})")
        kinds = ARGS[cmd]
        rest = words[1:]
        if (kinds == "m" and not rest) or (kinds != "m" and len(rest) != len(kinds)):
            raise ScriptError(name, n, col, f"'{cmd}' takes {len(kinds) or 'no'} value(s)")
        vals = []
        for i, (c, w) in enumerate(rest):
            try:
                vals.append(_value(kinds if kinds == "m" else kinds[i], w))
            except ValueError as exc:
                raise ScriptError(name, n, c, str(exc)) from None
        out.append(Command(cmd, tuple(vals), n))
    return out


def load(path: str | Path) -> list[Command]:
    return parse(Path(path).read_text(encoding="utf-8"), str(path))


def run(session: PaintSession, cmd: Command) -> bytes:
    """One command's Sigma bytes (messages go to ``session.message``)."""
    a = cmd.args
    s = session
    table = {
        "colour": lambda: s.pick(a[0]), "select": lambda: s.select_near(a[0], a[1]),
        "fill": s.fill, "line": s.colour_lines, "clear": s.clear,
        "region": lambda: s.region(a[0], a[1]), "touch": lambda: s.touch(a[0], a[1]),
        "rgb": lambda: s.rgb(a[0], a[1]), "mix": lambda: s.mix(dict(a)),
        "show": lambda: s.show(a[0]), "frame": lambda: s.goto(a[0]),
        "autopaint": lambda: _autopaint(s),
    }
    return table[cmd.name]()


def _autopaint(s: PaintSession) -> bytes:
    fails = s.autopaint()
    s.message = f"auto-paint: {len(fails)} operation(s) could not apply" + "".join(
        f"\n  {f}" for f in fails)
    return b""
