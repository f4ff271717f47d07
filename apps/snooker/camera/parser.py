"""CCL's parser (thesis §6.3.1's grammar, every construct).  It never stops at the first
error: a bad sub-command is reported (line, column, what was expected, the nearest keyword
for a misspelling) and parsing goes on with the next one, so a script's errors are all
reported at once.  Accepted beyond the letter of the grammar, for a non-expert: ``CUE
BALL`` for CUEBALL, ``HIT BALL`` for HITBALL, ``START``/``STOP``/``STRIKE`` for
``STARTS``/``STOPS``/``STRIKES`` (and ``ALL BALLS STOPS``), ``CENTER``/``MIDDLE`` for
``CENTRE``."""

from __future__ import annotations

from camlab88.apps.snooker.camera.cursor import (
    COLOUR_WORDS,
    PLURAL,
    SUBCOMMANDS,
    Cursor,
    Fail,
)
from camlab88.apps.snooker.camera.errors import CclError
from camlab88.apps.snooker.camera.lexer import Token, tokenize
from camlab88.apps.snooker.camera.projection import FOCAL_MAX_MM, FOCAL_MIN_MM
from camlab88.apps.snooker.camera.syntax import (
    BallRef,
    CameraDef,
    Command,
    Coord,
    CoordsDef,
    Event,
    Focal,
    Name,
    Place,
    Simple,
    Time,
)

# --- balls, events and time ----------------------------------------------------------------
_BALL_START = ("CUEBALL", "CUE", *COLOUR_WORDS, "RED", "HITBALL", "HIT")


def ball(c: Cursor) -> BallRef:
    t = c.peek()
    w = c.word()
    if w == "CUEBALL" or w == "HITBALL":
        c.take()
        return BallRef("cue" if w == "CUEBALL" else "hit", t)
    if w in ("CUE", "HIT"):
        c.take()
        c.expect("BALL")
        return BallRef("cue" if w == "CUE" else "hit", t)
    if w in COLOUR_WORDS:
        c.take()
        c.expect("BALL", what=f"BALL after {w} (or SPOT, where a position is meant)")
        return BallRef("colour", t, colour=w.lower())
    if w == "RED":
        c.take()
        n, _ = c.integer("the number of a red (RED 1 is the red nearest the top cushion)", 1)
        return BallRef("red", t, n=n)
    raise c.fail("a ball (CUEBALL, YELLOW BALL ... BLACK BALL, RED <n> or HITBALL)", _BALL_START)


_EVENT_START = ("FRAME", "CUEBALL", "ANY", "ALL", "END", *_BALL_START)


def event(c: Cursor) -> Event:
    t = c.peek()
    ev = _event_body(c, t)
    s = c.sign()
    if s is None:
        return ev
    n, _ = c.integer("a number of frames after '+' or '-'", 0)
    return Event(ev.kind, ev.tok, ev.frame, ev.ball, int(s) * n)


def _event_body(c: Cursor, t: Token) -> Event:
    if t.kind == "number":
        n, _ = c.integer("a frame number", 1)
        return Event("frame", t, frame=n)
    w = c.word()
    if w == "FRAME":
        c.take()
        n, _ = c.integer("a frame number", 1)
        return Event("frame", t, frame=n)
    if w == "END":
        c.take()
        return Event("end", t)
    if w == "ANY":
        c.take()
        c.expect("BALL")
        c.expect("STARTS")
        return Event("any_start", t)
    if w == "ALL":
        c.take()
        c.expect("BALLS", "BALL")
        c.expect("STOPS")
        return Event("all_stop", t)
    if w not in _BALL_START:
        raise c.fail("an event (a frame number, FRAME <n>, CUEBALL STRIKES, ANY BALL STARTS, "
                     "ALL BALLS STOP, <ball> STARTS, <ball> STOPS or END)", _EVENT_START)
    b = ball(c)
    verbs = ("STRIKES", "STARTS", "STOPS") if b.kind == "cue" else ("STARTS", "STOPS")
    v = c.expect(*verbs)
    kind = {"STRIKES": "strike", "STARTS": "start", "STOPS": "stop"}[_verb(v)]
    return Event(kind, t, ball=b)


def _verb(t: Token) -> str:
    return PLURAL.get(t.upper, t.upper)


def time(c: Cursor) -> Time:
    start = None
    if c.at("FROM"):
        c.take()
        start = event(c)
        c.expect("UNTIL", what="UNTIL (FROM <event> UNTIL <event>)")
    else:
        c.expect("UNTIL")
    return Time(event(c), start)


# --- coordinates ----------------------------------------------------------------------------
def simple(c: Cursor) -> Simple:
    t = c.punct("(", "a coordinate such as (1.5, -0.2, 0.8)")
    user = c.peek().kind == "punct" and c.peek().text == "#"
    if user:
        c.take()
    x, _ = c.number("the x value (a number)")
    c.punct(",", "',' between x and y")
    y, _ = c.number("the y value (a number)")
    c.punct(",", "',' between y and z")
    z, _ = c.number("the z value (a number)")
    c.punct(")", "')' to close the coordinate")
    return Simple((x, y, z), user, t)


_POCKET_START = ("BOTTOM", "TOP", "LEFT", "RIGHT")
_NAME_START = (*_BALL_START, "CAMERA", *_POCKET_START)


def name(c: Cursor) -> Name:
    t = c.peek()
    w = c.word()
    if w in COLOUR_WORDS and c.toks[c.i + 1].upper == "SPOT":
        c.take()
        c.take()
        return Name("spot", t, key=w.lower())
    if w == "CAMERA":
        c.take()
        n, _ = c.integer("a camera number", 0, 9)
        return Name("camera", t, n=n)
    if w in ("BOTTOM", "TOP"):
        c.take()
        side = c.expect("LEFT", "RIGHT")
        c.expect("POCKET")
        return Name("pocket", t, key=f"{w} {side.upper}".lower())
    if w in ("LEFT", "RIGHT"):
        c.take()
        c.expect("CENTRE")
        c.expect("POCKET")
        return Name("pocket", t, key=f"{w.lower()} centre")
    if w in _BALL_START:
        return Name("ball", t, ball=ball(c))
    raise c.fail("a coordinate: (x, y, z), (#x, y, z) or a name (a ball, <colour> SPOT, "
                 "CAMERA <n> or a pocket such as TOP LEFT POCKET)", _NAME_START)


def coordinate(c: Cursor) -> Coord:
    t = c.peek()
    if t.kind == "punct" and t.text == "(":
        return Coord(t, simple=simple(c))
    n = name(c)
    s = c.sign()
    if s is None:
        return Coord(t, name=n)
    return Coord(t, name=n, simple=simple(c), sign=s)


# --- sub-commands ---------------------------------------------------------------------------
def place(c: Cursor) -> Place:
    t = c.take()
    what = t.upper.lower()
    mode = c.expect("AT", "MOVING", "FOLLOWING")
    m = _verb(mode)
    if m == "AT":
        return Place(what, "at", t, a=coordinate(c))
    if m == "MOVING":
        c.expect("FROM")
        a = coordinate(c)
        c.expect("TO")
        return Place(what, "moving", t, a=a, b=coordinate(c))
    b = ball(c)
    s = c.sign()
    if s is None:
        return Place(what, "following", t, ball=b)
    return Place(what, "following", t, ball=b, offset=simple(c), sign=s)


def _focal_number(c: Cursor) -> float:
    f, t = c.number("a focal length in mm")
    if not FOCAL_MIN_MM <= f <= FOCAL_MAX_MM:
        raise Fail(CclError(t.line, t.col, f"a focal length of {f:g} mm is out of range: it "
                                            f"must be {FOCAL_MIN_MM:g} to {FOCAL_MAX_MM:g} mm"))
    return f


def focal(c: Cursor) -> Focal:
    t = c.take()
    c.expect("LENGTH", what="LENGTH (FOCAL LENGTH OF <mm> or FOCAL LENGTH FROM <mm> TO <mm>)")
    how = c.expect("OF", "FROM")
    a = _focal_number(c)
    if how.upper == "OF":
        return Focal(a, t)
    c.expect("TO")
    return Focal(a, t, _focal_number(c))


def camera(c: Cursor) -> CameraDef:
    t = c.take()
    n, _ = c.integer("a camera number", 0, 9)
    c.expect("AT")
    return CameraDef(n, coordinate(c), t)


def coords(c: Cursor) -> CoordsDef:
    t = c.take()
    origin = coordinate(c)
    if origin.simple is not None and origin.simple.user:
        s = origin.simple.tok
        raise Fail(CclError(s.line, s.col, "the COORDS origin is in the default space (metres "
                                            "from the table's centre), so it cannot use '#'"))
    factors = []
    for axis in "xyz":
        f, ft = c.number(f"the number of user units per metre in {axis}")
        if f == 0:
            raise Fail(CclError(ft.line, ft.col, f"user units per metre in {axis} cannot be 0"))
        factors.append(f)
    return CoordsDef(origin, (factors[0], factors[1], factors[2]), t)


_SUBCOMMAND_HELP = ("a sub-command (FROM, UNTIL, OBSERVER, VIEWPOINT, FOCAL LENGTH, CAMERA "
                    "or COORDS)")


def _subcommand(c: Cursor, cmd: Command) -> None:
    w = c.word()
    t = c.peek()
    if w in ("FROM", "UNTIL"):
        _set_once(cmd, "time", time(c), t, "time period (FROM/UNTIL)")
    elif w in ("OBSERVER", "VIEWPOINT"):
        _set_once(cmd, w.lower(), place(c), t, w)
    elif w == "FOCAL":
        _set_once(cmd, "focal", focal(c), t, "FOCAL LENGTH")
    elif w == "CAMERA":
        cmd.definitions.append(camera(c))
    elif w == "COORDS":
        cmd.definitions.append(coords(c))
    else:
        raise c.fail(_SUBCOMMAND_HELP, SUBCOMMANDS)
    end = c.peek()
    if end.kind != "end" and not (end.kind == "punct" and end.text in ":;"):
        raise Fail(CclError(end.line, end.col, f"unexpected {end.describe()} after a complete "
                                                "sub-command (is a ';' missing before it?)"))


def _set_once(cmd: Command, attr: str, value: object, t: Token, what: str) -> None:
    if getattr(cmd, attr) is not None:
        raise Fail(CclError(t.line, t.col, f"a second {what} in one command (each command "
                                            "has at most one; start a new command with ':')"))
    setattr(cmd, attr, value)


def _split(tokens: list[Token], ch: str) -> list[list[Token]]:
    """Runs of tokens, each ending with its delimiter `ch` (the last with the end token)."""
    out, run = [], []
    for t in tokens:
        run.append(t)
        if t.kind == "end" or (t.kind == "punct" and t.text == ch):
            out.append(run)
            run = []
    return out


def parse_tokens(tokens: list[Token]) -> tuple[list[Command], list[CclError]]:
    commands: list[Command] = []
    errors: list[CclError] = []
    for run in _split(tokens[1:] if tokens and tokens[0].text == ":" else tokens, ":"):
        cmd = Command(run[0])
        for sub in _split(run[:-1] + [_as_end(run[-1])], ";"):
            if len(sub) == 1:
                continue  # an empty sub-command (";;", or a command ending with ';')
            try:
                _subcommand(Cursor(sub), cmd)
            except Fail as f:
                errors.append(f.error)
        if cmd.time or cmd.sets_view or cmd.definitions:
            commands.append(cmd)
    return commands, errors


def _as_end(t: Token) -> Token:
    """A command's closing ':' ends its last sub-command."""
    return Token("end", t.text, t.line, t.col) if t.kind == "punct" else t


def parse(text: str) -> tuple[list[Command], list[CclError]]:
    """Script text -> (commands, every lexical and syntax error)."""
    tokens, errors = tokenize(text)
    commands, more = parse_tokens(tokens)
    return commands, errors + more
