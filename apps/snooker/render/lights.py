"""Point lights close to the table (thesis 6.4.1: "four light bulbs in a canopy above it",
no lights at infinity), and the lights file.

Lights file (UTF-8 text; ``#`` starts a comment; one light a line, table-frame metres)::

    x y z [intensity | r g b]     # e.g.  0.9 0.4 1.0 0.3

``ambient A`` on a line of its own sets the ambient light. A bad line raises LightsError
naming ``path:line:column``.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from camlab88.base import budget

DEFAULT_AMBIENT = 0.22
DEFAULT_INTENSITY = 0.32
CANOPY_HEIGHT_M = 1.0  # bulbs above the baize (reconstructed)
CANOPY_X_M, CANOPY_Y_M = 0.9, 0.4


class LightsError(ValueError):
    def __init__(self, path: str, line: int, col: int, message: str) -> None:
        super().__init__(f"{path}:{line}:{col}: {message}")


@dataclass(frozen=True, eq=False)
class Lights:
    """Positions (n, 3) in the table frame, colours (n, 3) linear, ambient (3,)."""

    positions: np.ndarray
    colours: np.ndarray
    ambient: np.ndarray


def canopy() -> Lights:
    """Four bulbs in a canopy above the table, 2 x 2 (the thesis's default set-up)."""
    pos = np.array([(sx * CANOPY_X_M, sy * CANOPY_Y_M, CANOPY_HEIGHT_M)
                    for sx in (-1, 1) for sy in (-1, 1)], dtype=np.float64)
    return Lights(pos, np.full((4, 3), DEFAULT_INTENSITY), np.full(3, DEFAULT_AMBIENT))


def _number(path: str, no: int, col: int, token: str) -> float:
    try:
        v = float(token)
    except ValueError:
        raise LightsError(path, no, col, f"{token!r} is not a number") from None
    if not math.isfinite(v):
        raise LightsError(path, no, col, f"{token!r} is not a finite number")
    return v


def _columns(raw: str) -> list[tuple[int, str]]:
    out, col = [], 0
    for tok in raw.split():
        col = raw.index(tok, col)
        out.append((col + 1, tok))
        col += len(tok)
    return out


def parse_lights(text: str, path: str = "<lights>") -> Lights:
    pos, rgb = [], []
    ambient = np.full(3, DEFAULT_AMBIENT)
    for no, line in enumerate(text.splitlines(), start=1):
        toks = _columns(line.split("#", 1)[0])
        if not toks:
            continue
        if toks[0][1].lower() == "ambient":
            if len(toks) != 2:
                raise LightsError(path, no, toks[0][0], "expected 'ambient A'")
            ambient = np.full(3, _number(path, no, toks[1][0], toks[1][1]))
            continue
        if len(toks) not in (3, 4, 6):
            raise LightsError(path, no, toks[0][0],
                              f"expected 'x y z [intensity | r g b]', got {len(toks)} numbers")
        v = [_number(path, no, c, t) for c, t in toks]
        if v[2] <= 0:
            raise LightsError(path, no, toks[2][0], "a light must be above the baize (z > 0)")
        if any(x < 0 for x in v[3:]):
            raise LightsError(path, no, toks[3][0], "intensities must not be negative")
        pos.append(v[:3])
        rgb.append(v[3:] * 3 if len(v) == 4 else (v[3:] or [DEFAULT_INTENSITY] * 3))
    if not pos:
        raise LightsError(path, max(1, len(text.splitlines())), 1, "no lights in the file")
    return Lights(np.array(pos, dtype=np.float64), np.array(rgb, dtype=np.float64), ambient)


# A light's cost in a frame: its terms at every pixel (a float64 each; 5,000 lights at
# 160x120 took 34 s a frame) or, for a renderer with shadow maps, its map
LIGHT_PIXEL_BYTES = 8


def read_lights(path: str | os.PathLike[str], light_bytes: int = 0, what: str = "") -> Lights:
    """The lights file; with ``light_bytes`` (what one light costs the frame it lights) a
    file of more lights than the memory budget allows is refused before it is parsed
    (base.budget): each line may be a light."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except OSError as exc:
        raise LightsError(str(path), 0, 0, f"cannot read: {exc.strerror}") from None
    except UnicodeDecodeError as exc:
        raise LightsError(str(path), 1, exc.start + 1, "not UTF-8 text") from None
    if light_bytes:
        lines = text.count("\n") + 1
        budget.check(str(path), lines * light_bytes, f"up to {lines:,} lights {what}".rstrip())
    return parse_lights(text, str(path))
