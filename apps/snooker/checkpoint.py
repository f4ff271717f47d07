"""The checkpoint file, exactly as §6.2.2 shows it:

    5000,6003            <- 22 lines: initial positions x,y, standard ball order
    ...                     (1 cue, 2 yellow, 3 green, 4 brown, 5 blue, 6 pink, 7 black, 8-22 reds)
    1 122 -119, 7 -2 1, 22 -12 13   <- one line per further time frame: `ball dx dy` for each
    1 119 -116, 22 -11 12              ball that moved since the previous frame
    -1                   <- a negative ball number ends the sequence

Positions are integers, 4096 units to the foot, x up the table from the baulk cushion face
and y across it (see table.py).  Each frame's positions are rounded first and the deltas
are differences of the rounded values, so summing them reproduces every frame exactly.
Potted balls sit outside the playing area (behind their pocket).  A frame in which no ball
moved is an empty line.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from apps.snooker.table import FOOT_M, N_BALLS
from protocols.atomicfile import write_atomic

UNITS_PER_FOOT = 4096
UNITS_PER_M = UNITS_PER_FOOT / FOOT_M


class CheckpointError(ValueError):
    def __init__(self, path: str | os.PathLike[str], line: int, message: str) -> None:
        super().__init__(f"{path}:{line}: {message}")
        self.path = str(path)
        self.line = line


def to_units(pos_m: np.ndarray) -> np.ndarray:
    """Metres -> integer file units, rounding half up."""
    return np.floor(np.asarray(pos_m, dtype=np.float64) * UNITS_PER_M + 0.5).astype(np.int64)


def to_metres(units: np.ndarray) -> np.ndarray:
    return np.asarray(units, dtype=np.float64) / UNITS_PER_M


@dataclass(frozen=True, eq=False)
class Checkpoint:
    """Ball positions for a run of consecutive time frames, in file units."""

    positions: np.ndarray  # (frames, 22, 2) int64

    @classmethod
    def from_metres(cls, frames: Sequence[np.ndarray]) -> Checkpoint:
        if not frames:
            raise ValueError("a checkpoint needs at least one frame")
        return cls(np.stack([to_units(p) for p in frames]))

    @property
    def n_frames(self) -> int:
        return int(self.positions.shape[0])

    def subset(self, first: int, last: int) -> Checkpoint:
        if not 0 <= first <= last < self.n_frames:
            raise ValueError(f"frames {first}..{last} are not within 0..{self.n_frames - 1}")
        return Checkpoint(self.positions[first : last + 1])

    def to_text(self) -> str:
        p = self.positions
        lines = [f"{x},{y}" for x, y in p[0].tolist()]
        for k in range(1, p.shape[0]):
            d = p[k] - p[k - 1]
            moved = np.nonzero(np.any(d != 0, axis=1))[0]
            lines.append(", ".join(f"{b + 1} {d[b, 0]} {d[b, 1]}" for b in moved.tolist()))
        lines.append("-1")
        return "\n".join(lines) + "\n"

    def write(self, path: str | os.PathLike[str]) -> None:
        atomic_write_text(path, self.to_text())


def atomic_write_text(path: str | os.PathLike[str], text: str) -> None:
    """Write to a temporary file in the same directory, fsync, then rename over `path`."""
    write_atomic(path, text, encoding="ascii")


def _int(path: str, line: int, token: str, what: str) -> int:
    try:
        return int(token)
    except ValueError:
        raise CheckpointError(path, line, f"{what} {token!r} is not an integer") from None


def parse(text: str, path: str = "<checkpoint>") -> Checkpoint:
    lines = text.splitlines()
    if len(lines) < N_BALLS:
        raise CheckpointError(path, len(lines) + 1,
                              f"expected {N_BALLS} initial position lines, found {len(lines)}")
    first = np.zeros((N_BALLS, 2), dtype=np.int64)
    for i in range(N_BALLS):
        parts = lines[i].split(",")
        if len(parts) != 2:
            raise CheckpointError(path, i + 1, f"expected 'x,y' for ball {i + 1}, got {lines[i]!r}")
        first[i] = (_int(path, i + 1, parts[0].strip(), "x"),
                    _int(path, i + 1, parts[1].strip(), "y"))
    frames = [first]
    ended = False
    lineno = N_BALLS
    for lineno in range(N_BALLS + 1, len(lines) + 1):
        raw = lines[lineno - 1]
        if ended:
            if raw.strip():
                raise CheckpointError(path, lineno, "text after the end of the sequence")
            continue
        cur = frames[-1].copy()
        seen: set[int] = set()
        entries = [e for e in raw.split(",")] if raw.strip() else []
        for e in entries:
            toks = e.split()
            if not toks:
                raise CheckpointError(path, lineno, "empty entry between commas")
            ball = _int(path, lineno, toks[0], "ball number")
            if ball < 0:
                if len(toks) != 1:
                    raise CheckpointError(path, lineno, "the end marker takes no deltas")
                ended = True
                break
            if len(toks) != 3:
                raise CheckpointError(path, lineno, f"expected 'ball dx dy', got {e.strip()!r}")
            if not 1 <= ball <= N_BALLS:
                raise CheckpointError(path, lineno, f"ball number {ball} is not in 1..{N_BALLS}")
            if ball in seen:
                raise CheckpointError(path, lineno, f"ball {ball} appears twice in one frame")
            seen.add(ball)
            cur[ball - 1, 0] += _int(path, lineno, toks[1], "dx")
            cur[ball - 1, 1] += _int(path, lineno, toks[2], "dy")
        if ended and not seen:
            continue  # "-1" alone: no further frame
        frames.append(cur)
    if not ended:
        raise CheckpointError(path, lineno + 1, "missing the negative ball number that ends it")
    return Checkpoint(np.stack(frames))


def read(path: str | os.PathLike[str]) -> Checkpoint:
    try:
        raw = Path(path).read_bytes()
    except OSError as exc:
        raise CheckpointError(path, 0, f"cannot read: {exc.strerror}") from None
    try:
        text = raw.decode("ascii")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        raise CheckpointError(path, line, f"non-ASCII byte at offset {exc.start}") from None
    return parse(text, str(path))
