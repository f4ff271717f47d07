"""The checkpoint file, exactly as §6.2.2 shows it:

    5000,6003            <- 22 lines: initial positions x,y, standard ball order
    ...                     (1 cue, 2 yellow, 3 green, 4 brown, 5 blue, 6 pink, 7 black, 8-22 reds)
    1 122 -119, 7 -2 1, 22 -12 13   <- one line per further time frame: `ball dx dy` for each
    1 119 -116, 22 -11 12              ball that moved since the previous frame
    -1                   <- a negative ball number ends the sequence

Positions are integers, 4096 units to the foot, x up the table from the baulk cushion face
and y across it (see table.py).  Each frame's positions are rounded first and the deltas
are differences of the rounded values, so summing them reproduces every frame exactly.
A frame in which no ball moved is an empty line.

Every stored position is in 0..65535 on both axes: "ball positions can be packed into a
single 32 bit computer word (16 bits for each of x and y)" (§6.2.2); a file whose
coordinates leave that range is refused at the line that takes them out. The table is
49152 by 25088 units, so the packing leaves room beyond the top and left cushions: a potted
ball's drop point behind its pocket is stored as it is when it lies in range, and otherwise
(the right and baulk pockets drop below 0) parked at y = 65535, x clamped into range —
outside the playing area either way, which is all a replay needs to know it is off the table.
"""

from __future__ import annotations

import os
import re
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from camlab88.apps.snooker.table import FOOT_M, N_BALLS
from camlab88.base.atomicfile import write_atomic
from camlab88.base.textinput import InputError, quote, read_bytes

UNITS_PER_FOOT = 4096
UNITS_PER_M = UNITS_PER_FOOT / FOOT_M
PACK_MAX = (1 << 16) - 1  # 16 bits for each of x and y (§6.2.2)
PARK_Y = PACK_MAX  # where a potted ball out of the packing's range is stored


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
    def from_metres(cls, frames: Sequence[np.ndarray],
                    table_m: tuple[float, float] | None = None) -> Checkpoint:
        """Frames of (22, 2) positions in metres; ``table_m`` (length, width) checks that the
        playing area fits the 16-bit packing (a giant table may not)."""
        if not frames:
            raise ValueError("a checkpoint needs at least one frame")
        if table_m is not None and max(to_units(np.asarray(table_m))) > PARK_Y - 1:
            raise ValueError(f"a {table_m[0]:.2f} x {table_m[1]:.2f} m table does not fit the "
                             f"checkpoint's 16-bit coordinates (0..{PACK_MAX} units, §6.2.2)")
        return cls(np.stack([park(to_units(p)) for p in frames]))

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
        _check_range("<checkpoint being written>", self.positions.reshape(-1, 2), 0)
        write_atomic(path, self.to_text(), encoding="ascii")


def park(units: np.ndarray) -> np.ndarray:
    """Positions in file units with every out-of-range (so off-table, potted) ball moved to
    its parking place in range: x clamped to 0..65535, y = 65535 (see the module docstring)."""
    out = np.array(units, dtype=np.int64)
    bad = np.any((out < 0) | (out > PACK_MAX), axis=1)
    out[bad, 0] = np.clip(out[bad, 0], 0, PACK_MAX)
    out[bad, 1] = PARK_Y
    return out


_NUMBER = re.compile(r"[+-]?[0-9]{1,6}")


def _int(path: str, line: int, token: str, what: str, lo: int, hi: int) -> int:
    if not _NUMBER.fullmatch(token):
        if re.fullmatch(r"[+-]?[0-9]+", token):
            raise CheckpointError(path, line, f"{what} {quote(token, 24)} is outside {lo}..{hi}")
        raise CheckpointError(path, line, f"{what} {quote(token, 24)} is not an integer")
    value = int(token)
    if not lo <= value <= hi:
        raise CheckpointError(path, line, f"{what} {value} is outside {lo}..{hi}")
    return value


def _check_range(path: str, cur: np.ndarray, lineno: int) -> None:
    bad = np.flatnonzero(np.any((cur < 0) | (cur > PACK_MAX), axis=1))
    if bad.size:
        b = int(bad[0])
        raise CheckpointError(path, lineno, f"ball {b + 1} moves to {tuple(cur[b].tolist())}, "
                              f"outside the 16-bit packing 0..{PACK_MAX} (§6.2.2)")


def parse(text: str, path: str = "<checkpoint>") -> Checkpoint:
    lines = text.splitlines()
    if len(lines) < N_BALLS:
        raise CheckpointError(path, len(lines) + 1,
                              f"expected {N_BALLS} initial position lines, found {len(lines)}")
    first = np.zeros((N_BALLS, 2), dtype=np.int64)
    for i in range(N_BALLS):
        parts = lines[i].split(",")
        if len(parts) != 2:
            raise CheckpointError(path, i + 1,
                                  f"expected 'x,y' for ball {i + 1}, got {quote(lines[i])}")
        first[i] = (_int(path, i + 1, parts[0].strip(), "x", 0, PACK_MAX),
                    _int(path, i + 1, parts[1].strip(), "y", 0, PACK_MAX))
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
            ball = _int(path, lineno, toks[0], "ball number", -PACK_MAX, PACK_MAX)
            if ball < 0:
                if len(toks) != 1:
                    raise CheckpointError(path, lineno, "the end marker takes no deltas")
                ended = True
                break
            if len(toks) != 3:
                raise CheckpointError(path, lineno,
                                      f"expected 'ball dx dy', got {quote(e.strip())}")
            if not 1 <= ball <= N_BALLS:
                raise CheckpointError(path, lineno, f"ball number {ball} is not in 1..{N_BALLS}")
            if ball in seen:
                raise CheckpointError(path, lineno, f"ball {ball} appears twice in one frame")
            seen.add(ball)
            cur[ball - 1, 0] += _int(path, lineno, toks[1], "dx", -PACK_MAX, PACK_MAX)
            cur[ball - 1, 1] += _int(path, lineno, toks[2], "dy", -PACK_MAX, PACK_MAX)
        _check_range(path, cur, lineno)
        if ended and not seen:
            continue  # "-1" alone: no further frame
        frames.append(cur)
    if not ended:
        raise CheckpointError(path, lineno + 1, "missing the negative ball number that ends it")
    return Checkpoint(np.stack(frames))


def _read_error(message: str) -> CheckpointError:
    path, _, why = message.partition(": ")
    return CheckpointError(path, 0, why)


# 22 balls x ~20 bytes a frame: 64 MB is hours of 25 frames/s
MAX_CHECKPOINT_BYTES = 64 * 1024 * 1024


def read(path: str | os.PathLike[str]) -> Checkpoint:
    try:
        raw = read_bytes(path, MAX_CHECKPOINT_BYTES)
    except InputError as exc:
        raise _read_error(str(exc)) from None
    try:
        text = raw.decode("ascii")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        raise CheckpointError(path, line, f"non-ASCII byte at offset {exc.start}") from None
    return parse(text, str(path))
