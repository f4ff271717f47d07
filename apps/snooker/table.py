"""The table: every constant that characterises it (§6.2: "sensible default values, but they
may be altered by the animator"), the derived geometry (cushion faces, jaws, pocket mouths,
spots, the D) and the ball set.

Units are SI inside the model (metres, seconds, m/s); the checkpoint file converts to the
thesis's 4096 units per foot at its boundary.  Coordinates: x runs up the table from the
face of the baulk cushion (x = 0) to the face of the top cushion (x = length); y runs across
it.  Seen by a player standing at the baulk end looking up the table, +y is to the LEFT, so
the y = 0 cushion is the "right" cushion and y = width the "left" one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import cached_property

FOOT_M = 0.3048  # exact
INCH_M = FOOT_M / 12.0

# Ball numbering: the thesis's standard checkpoint order, 1-based in files, 0-based here.
BALL_NAMES: tuple[str, ...] = (
    "cue", "yellow", "green", "brown", "blue", "pink", "black",
    *(f"red{n}" for n in range(1, 16)),
)
N_BALLS = 22
CUE = 0
YELLOW, GREEN, BROWN, BLUE, PINK, BLACK = 1, 2, 3, 4, 5, 6
COLOURS: tuple[int, ...] = (YELLOW, GREEN, BROWN, BLUE, PINK, BLACK)  # also the end-game order
REDS: tuple[int, ...] = tuple(range(7, 22))
BALL_VALUES: tuple[int, ...] = (0, 2, 3, 4, 5, 6, 7, *(1,) * 15)


def is_red(ball: int) -> bool:
    return ball >= 7


def ball_index(name_or_number: str) -> int:
    """'cue', 'black', 'red3' or a 1-based checkpoint number '1'..'22' -> 0-based index."""
    text = name_or_number.strip().lower()
    if text.isascii() and text.isdigit():  # ('²'.isdigit() is True; int() refuses it)
        n = int(text)
        if 1 <= n <= N_BALLS:
            return n - 1
        raise ValueError(f"ball number {n} is not in 1..{N_BALLS}")
    if text == "white":
        text = "cue"
    if text == "red":
        text = "red1"
    if text in BALL_NAMES:
        return BALL_NAMES.index(text)
    raise ValueError(f"unknown ball {name_or_number!r} (use 1..22 or a name: cue, pink, red3 ...)")


@dataclass(frozen=True)
class Segment:
    """A straight cushion face: the ball touches it when its centre is `radius` from the line."""

    name: str  # "right-baulk", "top", ...
    side: str  # "baulk", "top", "left" or "right"
    ax: float
    ay: float
    bx: float
    by: float

    @property
    def length(self) -> float:
        return math.hypot(self.bx - self.ax, self.by - self.ay)

    @property
    def tangent(self) -> tuple[float, float]:
        n = self.length
        return ((self.bx - self.ax) / n, (self.by - self.ay) / n)

    @property
    def normal(self) -> tuple[float, float]:
        """Unit normal pointing into the playing area (segments run anticlockwise)."""
        tx, ty = self.tangent
        return (-ty, tx)


@dataclass(frozen=True)
class Pocket:
    """A pocket mouth: the line between its two jaw points.  A ball whose centre crosses this
    line outwards has dropped; it is then parked at `drop` (outside the playing area)."""

    name: str
    ax: float
    ay: float
    bx: float
    by: float
    drop: tuple[float, float]

    @property
    def centre(self) -> tuple[float, float]:
        return ((self.ax + self.bx) / 2.0, (self.ay + self.by) / 2.0)

    @property
    def width(self) -> float:
        return math.hypot(self.bx - self.ax, self.by - self.ay)

    @property
    def outward(self) -> tuple[float, float]:
        tx, ty = (self.bx - self.ax) / self.width, (self.by - self.ay) / self.width
        return (ty, -tx)  # mouths run anticlockwise too, so the right-hand normal is outwards


# lengths a table's constants may have: beyond these the geometry degenerates in floating
# point (a 1e20 m table's middle pocket mouth rounds to zero width)
MIN_LENGTH_M, MAX_LENGTH_M = 1e-3, 1e3
_LENGTHS = ("length_m", "width_m", "ball_diameter_m", "corner_mouth_m", "middle_mouth_m")


@dataclass(frozen=True)
class Table:
    """All editable constants (§6.1.1 sizes, §6.2 friction/restitution).  Values above 1 for
    `cushion_restitution` and giant balls are allowed, as the thesis suggests."""

    length_m: float = 12.0 * FOOT_M
    width_m: float = 6.125 * FOOT_M  # six feet one and a half inches
    ball_diameter_m: float = 2.0625 * INCH_M  # 2 1/16 in
    corner_mouth_m: float = 3.5 * INCH_M  # jaw-to-jaw, reconstructed (see docs/fidelity)
    middle_mouth_m: float = 4.25 * INCH_M
    cushion_restitution: float = 0.8
    ball_restitution: float = 1.0  # the thesis's formula is the perfectly elastic one
    deceleration_m_s2: float = 0.25  # initial speed / time to rest on the speed curve
    spin_deceleration_m_s2: float = 1.5  # spin decays linearly and faster (§6.1.2)
    speed_curve: str = "pullen1987-observed"
    baulk_line_m: float = 29.0 * INCH_M  # from the baulk cushion face
    d_radius_m: float = 11.5 * INCH_M
    black_spot_m: float = 12.75 * INCH_M  # from the top cushion face
    frame_rate: int = 25
    max_speed_m_s: float = 30.0  # cushions with restitution > 1 cannot push a ball past this

    def __post_init__(self) -> None:
        checks = {
            "length_m": self.length_m > 0,
            "width_m": self.width_m > 0,
            "ball_diameter_m": self.ball_diameter_m > 0,
            "corner_mouth_m": self.corner_mouth_m > 0,
            "middle_mouth_m": self.middle_mouth_m > 0,
            "cushion_restitution": self.cushion_restitution >= 0,
            "ball_restitution": 0 <= self.ball_restitution <= 1,
            "deceleration_m_s2": self.deceleration_m_s2 > 0,
            "spin_deceleration_m_s2": self.spin_deceleration_m_s2 > 0,
            "frame_rate": self.frame_rate > 0,
            "max_speed_m_s": self.max_speed_m_s > 0,
        }
        for name, ok in checks.items():
            value = getattr(self, name)
            if not (ok and math.isfinite(value)):
                raise ValueError(f"table constant {name}={value!r} is out of range")
        for name in _LENGTHS:  # giant balls yes, but a pocket must still have a width in floats
            value = getattr(self, name)
            if not MIN_LENGTH_M <= value <= MAX_LENGTH_M:
                raise ValueError(f"table constant {name}={value!r} is out of range "
                                 f"({MIN_LENGTH_M:g}..{MAX_LENGTH_M:g} m)")
        corner_leg = self.corner_mouth_m / math.sqrt(2.0)
        if 2 * corner_leg >= self.width_m or 2 * corner_leg + self.middle_mouth_m >= self.length_m:
            raise ValueError("pockets are wider than the cushions that hold them")

    def with_changes(self, **changes: float | str | int) -> Table:
        return replace(self, **changes)

    # --- derived geometry -------------------------------------------------------------
    @property
    def radius(self) -> float:
        return self.ball_diameter_m / 2.0

    @property
    def frame_dt(self) -> float:
        return 1.0 / self.frame_rate

    @cached_property
    def segments(self) -> tuple[Segment, ...]:
        L, W = self.length_m, self.width_m
        c = self.corner_mouth_m / math.sqrt(2.0)
        m = self.middle_mouth_m / 2.0
        # Anticlockwise round the table, so each segment's left normal points inwards.
        return (
            Segment("right-baulk", "right", c, 0.0, L / 2 - m, 0.0),
            Segment("right-top", "right", L / 2 + m, 0.0, L - c, 0.0),
            Segment("top", "top", L, c, L, W - c),
            Segment("left-top", "left", L - c, W, L / 2 + m, W),
            Segment("left-baulk", "left", L / 2 - m, W, c, W),
            Segment("baulk", "baulk", 0.0, W - c, 0.0, c),
        )

    @cached_property
    def jaws(self) -> tuple[tuple[float, float], ...]:
        """The cushion noses beside the pockets (segment ends), modelled as rounded points."""
        pts: list[tuple[float, float]] = []
        for s in self.segments:
            pts.append((s.ax, s.ay))
            pts.append((s.bx, s.by))
        return tuple(pts)

    @cached_property
    def pockets(self) -> tuple[Pocket, ...]:
        L, W, r = self.length_m, self.width_m, self.radius
        c = self.corner_mouth_m / math.sqrt(2.0)
        m = self.middle_mouth_m / 2.0
        mouths = (  # anticlockwise, from the jaw ending one segment to the next one's start
            ("baulk-right", 0.0, c, c, 0.0),
            ("middle-right", L / 2 - m, 0.0, L / 2 + m, 0.0),
            ("top-right", L - c, 0.0, L, c),
            ("top-left", L, W - c, L - c, W),
            ("middle-left", L / 2 + m, W, L / 2 - m, W),
            ("baulk-left", c, W, 0.0, W - c),
        )
        out = []
        for name, ax, ay, bx, by in mouths:
            w = math.hypot(bx - ax, by - ay)
            ox, oy = (by - ay) / w, -(bx - ax) / w
            mx, my = (ax + bx) / 2, (ay + by) / 2
            out.append(Pocket(name, ax, ay, bx, by, (mx + ox * 2.5 * r, my + oy * 2.5 * r)))
        return tuple(out)

    def pocket_index(self, name: str) -> int:
        for i, p in enumerate(self.pockets):
            if p.name == name:
                return i
        raise ValueError(f"unknown pocket {name!r}; pockets are "
                         + ", ".join(p.name for p in self.pockets))

    @cached_property
    def spots(self) -> dict[int, tuple[float, float]]:
        L, W = self.length_m, self.width_m
        cy = W / 2.0
        return {
            YELLOW: (self.baulk_line_m, cy - self.d_radius_m),  # right of the D from baulk
            GREEN: (self.baulk_line_m, cy + self.d_radius_m),
            BROWN: (self.baulk_line_m, cy),
            BLUE: (L / 2.0, cy),
            PINK: (0.75 * L, cy),
            BLACK: (L - self.black_spot_m, cy),
        }

    def in_d(self, x: float, y: float) -> bool:
        """Inside the D (on or behind the baulk line, within the semicircle)."""
        bx, by = self.spots[BROWN]
        return x <= bx and math.hypot(x - bx, y - by) <= self.d_radius_m

    def on_playing_area(self, x: float, y: float) -> bool:
        return 0.0 <= x <= self.length_m and 0.0 <= y <= self.width_m


def cushion_sides() -> tuple[str, ...]:
    return ("baulk", "top", "left", "right")
