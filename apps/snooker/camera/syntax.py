"""The parsed form of a camera script (thesis §6.3.1's grammar).  Every node keeps the
token it started at, so the interpreter's errors can name a line and column."""

from __future__ import annotations

from dataclasses import dataclass, field

from camlab88.apps.snooker.camera.lexer import Token

Vec = tuple[float, float, float]


@dataclass(frozen=True)
class BallRef:
    """CUEBALL, <colour> BALL, RED <n> or HITBALL."""

    kind: str  # "cue", "colour", "red" or "hit"
    tok: Token
    colour: str = ""
    n: int = 0

    def describe(self) -> str:
        return {"cue": "the cue ball", "colour": f"the {self.colour} ball",
                "red": f"red {self.n}", "hit": "the hit ball"}[self.kind]


@dataclass(frozen=True)
class Event:
    """<event> [+/- <offset>]; kind: frame, strike, any_start, all_stop, start, stop, end."""

    kind: str
    tok: Token
    frame: int = 0
    ball: BallRef | None = None
    offset: int = 0


@dataclass(frozen=True)
class Time:
    until: Event
    start: Event | None = None  # FROM; None: the frame after the previous command


@dataclass(frozen=True)
class Simple:
    """(x, y, z) in metres, or (#x, y, z) in user units."""

    xyz: Vec
    user: bool
    tok: Token


@dataclass(frozen=True)
class Name:
    kind: str  # "ball", "spot", "camera" or "pocket"
    tok: Token
    ball: BallRef | None = None
    key: str = ""  # spot colour or pocket name ("top left")
    n: int = 0  # camera number


@dataclass(frozen=True)
class Coord:
    """<simple> | <name> | <name> +/- <simple>."""

    tok: Token
    name: Name | None = None
    simple: Simple | None = None
    sign: float = 1.0


@dataclass(frozen=True)
class Place:
    """OBSERVER/VIEWPOINT AT, MOVING FROM .. TO, or FOLLOWING <ball> [+/- <simple>]."""

    what: str  # "observer" or "viewpoint"
    mode: str  # "at", "moving" or "following"
    tok: Token
    a: Coord | None = None
    b: Coord | None = None
    ball: BallRef | None = None
    offset: Simple | None = None
    sign: float = 1.0


@dataclass(frozen=True)
class Focal:
    """FOCAL LENGTH OF a (b is None) or FOCAL LENGTH FROM a TO b, in mm."""

    a: float
    tok: Token
    b: float | None = None


@dataclass(frozen=True)
class CameraDef:
    n: int
    at: Coord
    tok: Token


@dataclass(frozen=True)
class CoordsDef:
    origin: Coord
    factors: Vec
    tok: Token


@dataclass
class Command:
    """One colon-delimited command; its sub-commands may come in any order."""

    tok: Token
    time: Time | None = None
    observer: Place | None = None
    viewpoint: Place | None = None
    focal: Focal | None = None
    definitions: list[CameraDef | CoordsDef] = field(default_factory=list)

    @property
    def sets_view(self) -> bool:
        return any(x is not None for x in (self.observer, self.viewpoint, self.focal))
