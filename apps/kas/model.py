"""The KAS picture data: points joined into coloured line-chains, grouped into sections.

A drawing (a keyframe or one frame of a sequence) is an ordered list of chains; the order is
the order of drawing, which is how the in-betweener matches chains between keyframes
(thesis §3.1.2).  Each point carries the colour of the segment drawn *to* it, so the colour
of a single segment can be changed (§3.1.1); point 0's colour is the chain's pen colour.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

import numpy as np

# The twelve-field (thesis §2.2.1): 12" x 8.75"; the nine-field is the central 9" x 6.5625".
FIELD_W = 12.0
FIELD_H = 8.75
NINE_W = 9.0
NINE_H = 6.5625
# The working area is "many times larger than the area visible on-screen" (§3.1.1):
# reconstructed as eight twelve-fields each way.
WORK_X = 8 * FIELD_W / 2
WORK_Y = 8 * FIELD_H / 2

# Pen colours (index -> name, RGB).  Index 0 is the background and never a pen.  Eight pens,
# because the paint pots share the menu row with the command boxes and a plotter carousel
# holds eight pens.
PALETTE: dict[int, tuple[str, tuple[int, int, int]]] = {
    1: ("white", (255, 255, 255)),
    2: ("red", (255, 0, 0)),
    3: ("green", (0, 255, 0)),
    4: ("blue", (0, 96, 255)),
    5: ("yellow", (255, 255, 0)),
    6: ("cyan", (0, 255, 255)),
    7: ("magenta", (255, 0, 255)),
    8: ("orange", (255, 160, 0)),
}
PENS = tuple(PALETTE)

_uids = itertools.count(1)


def new_uid() -> int:
    """A process-unique chain identity (not saved): lets the editor see which chains moved."""
    return next(_uids)


@dataclass
class Chain:
    """A line-chain: ``points`` (n, 2) float64 inches; ``colours`` (n,) pen per point."""

    points: np.ndarray
    colours: np.ndarray
    section: int = 0
    uid: int = field(default_factory=new_uid, compare=False)

    @classmethod
    def raw(cls, points: np.ndarray, colours: np.ndarray, section: int) -> Chain:
        """Trusted fast path for the in-betweener: arrays already float64 (n, 2) / int16."""
        c = cls.__new__(cls)
        c.points, c.colours, c.section, c.uid = points, colours, section, new_uid()
        return c

    def __post_init__(self) -> None:
        self.points = np.asarray(self.points, dtype=np.float64).reshape(-1, 2)
        self.colours = np.asarray(self.colours, dtype=np.int16).reshape(-1)
        if len(self.colours) != len(self.points):
            raise ValueError("a chain needs one colour per point")

    @classmethod
    def from_points(cls, pts: Iterable[Sequence[float]], colour: int = 1,
                    section: int = 0) -> Chain:
        arr = np.asarray(list(pts), dtype=np.float64).reshape(-1, 2)
        return cls(arr, np.full(len(arr), colour, dtype=np.int16), section)

    @property
    def colour(self) -> int:
        return int(self.colours[0]) if len(self.colours) else 1

    def __len__(self) -> int:
        return len(self.points)

    def copy(self, keep_uid: bool = True) -> Chain:
        c = Chain(self.points.copy(), self.colours.copy(), self.section)
        if keep_uid:
            c.uid = self.uid
        return c

    def same_shape(self, other: Chain) -> bool:
        return self.points.shape == other.points.shape and bool(
            np.array_equal(self.points, other.points)
        )

    def length(self) -> float:
        if len(self.points) < 2:
            return 0.0
        return float(np.hypot(*np.diff(self.points, axis=0).T).sum())

    def centre(self) -> np.ndarray:
        """Geometric centre: mean of the vertices (the "centre point" of §3.1.2)."""
        return self.points.mean(axis=0) if len(self.points) else np.zeros(2)


@dataclass
class Drawing:
    """A keyframe or a frame: chains in drawing order."""

    chains: list[Chain] = field(default_factory=list)

    def copy(self, keep_uid: bool = True) -> Drawing:
        return Drawing([c.copy(keep_uid) for c in self.chains])

    @property
    def n_points(self) -> int:
        return sum(len(c) for c in self.chains)

    def sections(self) -> list[int]:
        return sorted({c.section for c in self.chains})

    def all_points(self) -> np.ndarray:
        if not self.chains:
            return np.zeros((0, 2))
        return np.concatenate([c.points for c in self.chains])

    def equals(self, other: Drawing, tol: float = 0.0) -> bool:
        if len(self.chains) != len(other.chains):
            return False
        for a, b in zip(self.chains, other.chains):
            if a.points.shape != b.points.shape or a.section != b.section:
                return False
            if not np.array_equal(a.colours, b.colours):
                return False
            if not np.allclose(a.points, b.points, atol=tol, rtol=0):
                return False
        return True


@dataclass
class AnimSequence:
    """An animated sequence: frames in order, ``fps`` frames per second (25 for video)."""

    frames: list[Drawing] = field(default_factory=list)
    fps: float = 25.0

    def __len__(self) -> int:
        return len(self.frames)


def drop_collinear(points: np.ndarray, colours: np.ndarray,
                   tol: float = 1e-9) -> tuple[np.ndarray, np.ndarray]:
    """Remove redundant points (§3.1.2): the middle of three collinear points going the
    same way when the colour does not change there, and repeats of the previous point."""
    keep = redundant_mask(points[None], colours[None], tol)[0]
    return points[keep], colours[keep]


def redundant_mask(points: np.ndarray, colours: np.ndarray, tol: float = 1e-9,
                   bounds: np.ndarray | None = None) -> np.ndarray:
    """Vectorised over frames: ``points`` (F, n, 2) -> (F, n) bool, True = keep.

    ``bounds`` (C + 1,) splits the n points into chains (default: one chain); chain ends
    are always kept and nothing is compared across a chain boundary."""
    f, n = points.shape[:2]
    keep = np.ones((f, n), dtype=bool)
    if n < 2:
        return keep
    d = np.diff(points, axis=1)                                   # (F, n-1, 2)
    n2 = d[..., 0] * d[..., 0] + d[..., 1] * d[..., 1]            # squared segment lengths
    if n >= 3:
        d1, d2 = d[:, :-1], d[:, 1:]
        cross = d1[..., 0] * d2[..., 1] - d1[..., 1] * d2[..., 0]
        dot = d1[..., 0] * d2[..., 0] + d1[..., 1] * d2[..., 1]
        l1, l2 = n2[:, :-1], n2[:, 1:]
        # Middle of three collinear points going the same way; both segments non-empty, so
        # a repeated corner point is never mistaken for a straight run.
        straight = (l1 > 0) & (l2 > 0) & (cross * cross <= (tol * tol) * l1 * l2) & (dot > 0)
        straight &= colours[:, 1:-1] == colours[:, 2:]
        keep[:, 1:-1] = ~straight
    # A repeat of the previous point draws nothing.
    keep[:, 1:] &= n2 > 0
    if bounds is not None:
        starts = np.asarray(bounds[:-1])
        ends = np.asarray(bounds[1:]) - 1
        keep[:, starts] = True
        # An end is kept unless it repeats its own predecessor (tests above may have looked
        # across the boundary into the next chain).
        multi = ends > starts
        keep[:, ends[multi]] = n2[:, ends[multi] - 1] > 0
    return keep
