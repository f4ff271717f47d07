"""Cells as three-dimensional actors (thesis 8.1): the model and the actors text file.

An ``ActorSet`` gives each cell state of a rule set an ``Actor``: a colour, a Phong material,
a few solid parts (lathe, box, sphere, extrusion) in cell units, and its own motion cycles.
A state without an actor is drawn as a coloured square tile on the floor. The text format
is documented in docs/ca_actors.md; ``format_actors`` writes exactly what ``parse_actors``
reads back (floats by ``repr``, so a round trip is exact).

Pure Python + numpy; imports nothing of apps.ca (the rule set is named by its string).
"""

from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass, field

from camlab88.base.atomicfile import write_atomic
from camlab88.base.textinput import InputError, read_text

KINDS = ("lathe", "box", "sphere", "extrude")
CYCLE_KINDS = ("bob", "turn")
PHASES = ("together", "individual")
FACES = ("fixed", "glide")
MAX_STATE = 255
MAX_ACTORS = 256
MAX_PARTS = 64
MAX_POINTS = 512
MAX_COORD = 100.0  # cell units: an actor a hundred cells across is surely a typo
MAX_PERIOD = 1_000_000
MAX_FILE_BYTES = 4 * 1024 * 1024
NAME = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.+-]{0,63}\Z")
RULES = re.compile(r"[^\s#]{1,256}\Z")


class ActorFileError(InputError):
    """A bad actors file: the message is ``file:line:col: what``."""

    @classmethod
    def at(cls, source: str, line: int, col: int, what: str) -> ActorFileError:
        return cls(f"{source}:{line}:{col}: {what}", source, line, col, what)

    def __reduce__(self):  # picklable across the film's worker processes
        return (type(self), (str(self), self.name, self.line, self.column, self.reason))


@dataclass(frozen=True)
class Material:
    """Phong coefficients: I = ambient*A*c + sum(diffuse*c*N.L + specular*(R.V)^shininess)*I_l."""

    ambient: float
    diffuse: float
    specular: float
    shininess: float


DEFAULT_MATERIAL = Material(0.3, 0.8, 0.4, 24.0)


@dataclass(frozen=True)
class Part:
    """One solid, in cell units, its base centred at ``offset`` (x, y across the floor, z up).

    lathe: ``profile`` (radius, height) pairs bottom to top, revolved about the vertical axis;
    ``size`` scales x, y, z. box: ``size`` = width, depth, height. sphere: ``size[0]`` = radius
    (the sphere stands on ``offset``). extrude: ``profile`` = polygon (x, y) on the floor,
    raised ``size[2]`` high; ``size[0]``, ``size[1]`` scale x and y.
    """

    kind: str
    profile: tuple[tuple[float, float], ...] = ()
    size: tuple[float, float, float] = (1, 1, 1)
    offset: tuple[float, float, float] = (0, 0, 0)
    # An articulated part (a limb): it swings about the horizontal x axis through
    # (offset x, offset y, pivot z) by amplitude·sin(2π(n/period + phase)) degrees at the
    # actor's frame n: (pivot z, amplitude degrees, period frames, phase 0..1).
    swing: tuple[float, float, float, float] | None = None


@dataclass(frozen=True)
class Cycle:
    """The actor's own motion: "bob" (height amplitude, cell units) or "turn" (degrees per
    period); ``period`` in frames."""

    kind: str
    amount: float
    period: int


@dataclass(frozen=True)
class Actor:
    state: int
    name: str
    colour: tuple[int, int, int]
    material: Material
    parts: tuple[Part, ...]
    cycles: tuple[Cycle, ...] = ()
    # "together": every actor of the state moves in step (one clock, the film's);
    # "individual": each actor its own phase, from the cell and generation it was born in
    phase: str = "together"
    # "fixed": as modelled, whichever way it moves; "glide": it turns to face the way it
    # glides (its own -y forward) and keeps facing it while it stands
    face: str = "fixed"


@dataclass(frozen=True)
class ActorSet:
    """State number -> actor, for the rule set named ``rules``."""

    rules: str
    actors: dict[int, Actor] = field(default_factory=dict)


# ---------------------------------------------------------------- writing

def _num(x: float) -> str:
    text = repr(float(x))
    return text[:-2] if text.endswith(".0") else text


def _nums(values) -> str:
    return " ".join(_num(v) for v in values)


def _part_line(p: Part) -> str:
    size, at = tuple(p.size), tuple(p.offset)
    if p.kind == "box":
        out = f"box {_nums(size)}"
    elif p.kind == "sphere":
        out = f"sphere {_num(size[0])}" if size[0] == size[1] == size[2] else \
            f"sphere size {_nums(size)}"
    else:
        pts = "  ".join(_nums(pt) for pt in p.profile)
        out = f"{p.kind} {pts}"
        if p.kind == "extrude" and size[:2] == (1, 1):
            out += f" height {_num(size[2])}"
        elif p.kind == "extrude" or size != (1, 1, 1):
            out += f" size {_nums(size)}"
    if at != (0, 0, 0):
        out += f" at {_nums(at)}"
    if p.swing is not None:
        out += f" swing {_nums(p.swing[:2])} {int(p.swing[2])} {_num(p.swing[3])}"
    return out


def _actor_lines(a: Actor) -> list[str]:
    m = a.material
    lines = [f"actor {a.state} {a.name}",
             f"  colour {a.colour[0]} {a.colour[1]} {a.colour[2]}",
             f"  material ambient {_num(m.ambient)} diffuse {_num(m.diffuse)} "
             f"specular {_num(m.specular)} shininess {_num(m.shininess)}"]
    lines += [f"  {_part_line(p)}" for p in a.parts]
    lines += [f"  {c.kind} {_num(c.amount)} {c.period}" for c in a.cycles]
    if a.phase != "together":
        lines.append(f"  phase {a.phase}")
    if a.face != "fixed":
        lines.append(f"  face {a.face}")
    return lines + ["end"]


def format_actors(s: ActorSet) -> str:
    """The actors file for ``s`` (``parse_actors`` reads it back equal)."""
    lines = ["# camlab88 actors file (docs/ca_actors.md)", f"rules {s.rules}"]
    for state in sorted(s.actors):
        lines += [""] + _actor_lines(s.actors[state])
    return "\n".join(lines) + "\n"


def write_actors(path: str | os.PathLike[str], s: ActorSet) -> None:
    """Save atomically: the file is its old self or wholly the new one."""
    write_atomic(path, format_actors(s))


# ---------------------------------------------------------------- reading

class _Line:
    """One line's words with their 1-based columns, consumed left to right."""

    def __init__(self, source: str, no: int, raw: str) -> None:
        self.source, self.no = source, no
        body = raw.split("#", 1)[0]
        self.words = [(m.start() + 1, m.group()) for m in re.finditer(r"\S+", body)]
        self.i = 0
        self.end_col = len(body.rstrip()) + 1

    def error(self, what: str, col: int | None = None) -> ActorFileError:
        if col is None:
            col = self.words[self.i][0] if self.i < len(self.words) else self.end_col
        return ActorFileError.at(self.source, self.no, col, what)

    @property
    def key_col(self) -> int:
        """The column of the line's first word (its keyword)."""
        return self.words[0][0] if self.words else 1

    def at_key(self, what: str) -> ActorFileError:
        return self.error(what, self.key_col)

    def more(self) -> bool:
        return self.i < len(self.words)

    def peek(self) -> str | None:
        return self.words[self.i][1] if self.more() else None

    def word(self, what: str) -> str:
        if not self.more():
            raise self.error(f"expected {what}, the line ends")
        self.i += 1
        return self.words[self.i - 1][1]

    def number(self, what: str, lo: float = -MAX_COORD, hi: float = MAX_COORD) -> float:
        col = self.words[self.i][0] if self.more() else self.end_col
        tok = self.word(what)
        try:
            v = float(tok)
        except ValueError:
            raise self.error(f"{what}: {tok[:40]!r} is not a number", col) from None
        if not math.isfinite(v) or not lo <= v <= hi:
            raise self.error(f"{what} must be between {_num(lo)} and {_num(hi)}, not {tok[:40]}",
                             col)
        return v

    def integer(self, what: str, lo: int, hi: int) -> int:
        col = self.words[self.i][0] if self.more() else self.end_col
        tok = self.word(what)
        if not re.fullmatch(r"[+-]?[0-9]{1,9}", tok):
            raise self.error(f"{what}: {tok[:40]!r} is not a whole number", col)
        if not lo <= int(tok) <= hi:
            raise self.error(f"{what} must be between {lo} and {hi}, not {tok}", col)
        return int(tok)

    def done(self) -> None:
        if self.more():
            raise self.error(f"unexpected {self.peek()[:40]!r} at the end of the line")


def _triple(ln: _Line, what: str, lo: float, hi: float) -> tuple[float, float, float]:
    return (ln.number(f"{what} x", lo, hi), ln.number(f"{what} y", lo, hi),
            ln.number(f"{what} z", lo, hi))


def _points(ln: _Line, kind: str) -> tuple[tuple[float, float], ...]:
    """A lathe's (radius, height) pairs, heights never decreasing, or a polygon's (x, y)."""
    lathe = kind == "lathe"
    first, second = ("lathe radius", "lathe height") if lathe else ("extrude x", "extrude y")
    pts: list[tuple[float, float]] = []
    while ln.more() and ln.peek() not in ("size", "height", "at"):
        if len(pts) >= MAX_POINTS:
            raise ln.error(f"more than {MAX_POINTS} points")
        a = ln.number(first, 0.0 if lathe else -MAX_COORD)
        col = ln.words[ln.i][0] if ln.more() else ln.end_col
        b = ln.number(second)
        if lathe and pts and b < pts[-1][1]:
            raise ln.error(f"a lathe profile goes bottom to top: height {_num(b)} is below "
                           f"the point before ({_num(pts[-1][1])})", col)
        pts.append((a, b))
    return tuple(pts)


def _check_profile(ln: _Line, kind: str, pts: tuple[tuple[float, float], ...]) -> None:
    if kind == "lathe":
        if len(pts) < 2:
            raise ln.at_key("a lathe profile needs at least 2 (radius, height) points")
        if max(r for r, _ in pts) <= 0:
            raise ln.at_key("a lathe profile needs a radius above 0")
    elif len(pts) < 3:
        raise ln.at_key("an extrusion needs a polygon of at least 3 (x, y) points")


def _part(ln: _Line, kind: str) -> Part:
    size: tuple[float, float, float] = (1, 1, 1)
    pts: tuple[tuple[float, float], ...] = ()
    if kind == "box":
        size = _triple(ln, "box size", 1e-6, MAX_COORD)
    elif kind == "sphere":
        if ln.peek() != "size":
            r = ln.number("sphere radius", 1e-6)
            size = (r, r, r)
    else:
        pts = _points(ln, kind)
        _check_profile(ln, kind, pts)
    if ln.peek() == "height" and kind == "extrude":
        ln.word("height")
        size = (1, 1, ln.number("extrude height", 1e-6))
    elif ln.peek() == "size" and kind != "box":
        ln.word("size")
        size = _triple(ln, "size", 1e-6, MAX_COORD)
    elif kind == "extrude":
        raise ln.error("expected 'height H' or 'size W D H' after the extrusion's polygon")
    offset: tuple[float, float, float] = (0, 0, 0)
    if ln.peek() == "at":
        ln.word("at")
        offset = _triple(ln, "at", -MAX_COORD, MAX_COORD)
    swing = None
    if ln.peek() == "swing":
        ln.word("swing")
        swing = (ln.number("swing pivot height", -MAX_COORD, MAX_COORD),
                 ln.number("swing amplitude (degrees)", -180.0, 180.0),
                 float(ln.integer("swing period (frames)", 1, MAX_PERIOD)),
                 ln.number("swing phase (0..1)", 0.0, 1.0))
    ln.done()
    return Part(kind, pts, size, offset, swing)


def _material(ln: _Line) -> Material:
    names = ("ambient", "diffuse", "specular", "shininess")
    got: dict[str, float] = {}
    while ln.more():
        col, key = ln.words[ln.i]
        if key not in names:
            raise ln.error(f"unknown material term {key[:40]!r} (expected one of "
                           f"{', '.join(names)})")
        if key in got:
            raise ln.error(f"{key} given twice")
        ln.word(key)
        got[key] = ln.number(key, 0.0, 1000.0 if key == "shininess" else 10.0)
    missing = [n for n in names if n not in got]
    if missing:
        raise ln.error(f"material lacks {', '.join(missing)}")
    return Material(*(got[n] for n in names))


@dataclass
class _Draft:
    state: int
    name: str
    line: _Line
    colour: tuple[int, int, int] | None = None
    material: Material | None = None
    parts: list[Part] = field(default_factory=list)
    cycles: list[Cycle] = field(default_factory=list)
    phase: str = "together"
    face: str = "fixed"

    def finish(self, ln: _Line) -> Actor:
        if self.colour is None:
            raise ln.at_key(f"actor {self.state} {self.name!r} has no 'colour R G B' line")
        if not self.parts:
            raise ln.error(f"actor {self.state} {self.name!r} has no parts "
                           f"({', '.join(KINDS)})", ln.key_col)
        return Actor(self.state, self.name, self.colour, self.material or DEFAULT_MATERIAL,
                     tuple(self.parts), tuple(self.cycles), self.phase, self.face)


def _choice(ln: _Line, key: str, words: tuple[str, ...]) -> str:
    """The line's one word after ``key``, one of ``words`` (an error points at it)."""
    col = ln.words[ln.i][0] if ln.more() else ln.end_col
    word = ln.word(" or ".join(repr(w) for w in words))
    if word not in words:
        raise ln.error(f"{key} {word[:40]!r}: expected {' or '.join(words)}", col)
    ln.done()
    return word


def _actor_line(d: _Draft, ln: _Line, key: str) -> None:
    if key in ("colour", "color"):
        d.colour = (ln.integer("red", 0, 255), ln.integer("green", 0, 255),
                    ln.integer("blue", 0, 255))
        ln.done()
    elif key == "material":
        d.material = _material(ln)
    elif key in KINDS:
        if len(d.parts) >= MAX_PARTS:
            raise ln.at_key(f"more than {MAX_PARTS} parts in one actor")
        d.parts.append(_part(ln, key))
    elif key in CYCLE_KINDS:
        lim = 3600.0 if key == "turn" else MAX_COORD
        d.cycles.append(Cycle(key, ln.number(f"{key} amount", -lim, lim),
                              ln.integer(f"{key} period (frames)", 1, MAX_PERIOD)))
        ln.done()
    elif key == "phase":
        d.phase = _choice(ln, key, PHASES)
    elif key == "face":
        d.face = _choice(ln, key, FACES)
    else:
        raise ln.error(f"unknown keyword {key[:40]!r} in an actor (expected colour, material, "
                       f"{', '.join(KINDS)}, {', '.join(CYCLE_KINDS)}, phase, face or end)",
                       ln.key_col)


def _header(ln: _Line, actors: dict[int, Actor]) -> _Draft:
    state = ln.integer("cell state", 0, MAX_STATE)
    if state in actors:
        raise ln.error(f"state {state} already has an actor", ln.words[1][0])
    if len(actors) >= MAX_ACTORS:
        raise ln.at_key(f"more than {MAX_ACTORS} actors")
    col = ln.words[ln.i][0] if ln.more() else ln.end_col
    name = ln.word("the actor's name")
    if not NAME.match(name):
        raise ln.error(f"{name[:40]!r} is not a name (letters, digits, _ . + -; at most 64)",
                       col)
    ln.done()
    return _Draft(state, name, ln)


def parse_actors(text: str, source: str) -> ActorSet:
    """Parse an actors file; a bad one raises ActorFileError at ``source:line:col``."""
    rules: str | None = None
    actors: dict[int, Actor] = {}
    draft: _Draft | None = None
    last = _Line(source, 1, "")
    for no, raw in enumerate(text.split("\n"), start=1):
        ln = last = _Line(source, no, raw.rstrip("\r"))
        if not ln.more():
            continue
        key = ln.word("a keyword")
        if key == "rules":
            if rules is not None or draft is not None or actors:
                raise ln.at_key("'rules' comes once, before the first actor")
            rules = ln.word("the rule set's name")
            if not RULES.match(rules):
                raise ln.error("the rule set's name is too long", ln.words[1][0])
            ln.done()
        elif rules is None:
            raise ln.at_key("the file must start with 'rules NAME'")
        elif key == "actor":
            if draft is not None:
                raise ln.at_key(f"actor {draft.state} (line {draft.line.no}) lacks its 'end'")
            draft = _header(ln, actors)
        elif draft is None:
            raise ln.at_key(f"{key[:40]!r} outside an actor (expected 'actor STATE NAME')")
        elif key == "end":
            ln.done()
            actors[draft.state] = draft.finish(ln)
            draft = None
        else:
            _actor_line(draft, ln, key)
    if rules is None:
        raise last.at_key("the file must start with 'rules NAME'")
    if draft is not None:
        raise draft.line.at_key(f"actor {draft.state} is not closed by 'end'")
    return ActorSet(rules, actors)


def read_actor_text(path: str | os.PathLike[str]) -> str:
    """An actors file's text (UTF-8, at most MAX_FILE_BYTES): ActorFileError otherwise."""
    return read_text(path, MAX_FILE_BYTES, ActorFileError)


def read_actors(path: str | os.PathLike[str]) -> ActorSet:
    """Read and parse an actors file (UTF-8); every refusal is an ActorFileError."""
    return parse_actors(read_actor_text(path), str(path))
