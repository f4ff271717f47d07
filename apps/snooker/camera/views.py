"""The view file: the CCL interpreter's output and the visualiser's input (thesis §6.3.1:
"a file containing a list of viewing parameters specifying the observer position,
viewpoint and focal length for each frame").

Format (text, ASCII): lines starting with ``#`` are comments (allowed anywhere, as are blank
lines); every other line is one frame::

    frame ox oy oz vx vy vz focal

`frame` is the checkpoint's frame number (its initial positions are frame 1), the observer
and viewpoint are in default-space metres, `focal` in mm (8 to 2000).  Frames are
consecutive and increasing.  Numbers are written as Python's shortest round-trip repr, so
reading a written file gives back bit-identical values.
"""

from __future__ import annotations

import math
import os
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

from camlab88.apps.snooker.camera.projection import FOCAL_MAX_MM, FOCAL_MIN_MM, Camera
from camlab88.base.atomicfile import write_atomic
from camlab88.base.fileerror import FilePlaceError

Vec3 = tuple[float, float, float]
_TOKEN = re.compile(r"\S+")
_NUMBER = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?", re.ASCII)
_FIELDS = ("frame", "ox", "oy", "oz", "vx", "vy", "vz", "focal")


class ViewFileError(FilePlaceError):
    """A bad view file (``path:line:col: what``)."""


@dataclass(frozen=True)
class View:
    """One frame's viewing parameters."""

    frame: int
    observer: Vec3
    viewpoint: Vec3
    focal_mm: float

    def camera(self) -> Camera:
        return Camera(self.observer, self.viewpoint, self.focal_mm)

    def to_line(self) -> str:
        nums = (*self.observer, *self.viewpoint, self.focal_mm)
        return " ".join([str(self.frame), *(repr(float(x)) for x in nums)])


def _number(path: str, line: int, col: int, field: str, tok: str) -> float:
    x = float(tok) if _NUMBER.fullmatch(tok) else math.nan  # not "1_000", "inf" or "nan"
    if not math.isfinite(x):
        raise ViewFileError(path, line, col, f"{field} {tok!r} is not a finite number")
    return x


def _frame_number(path: str, line: int, col: int, tok: str, want: int | None) -> int:
    if not (tok.isascii() and tok.isdigit()) or int(tok) < 1:
        raise ViewFileError(path, line, col, f"frame number {tok!r} is not an integer >= 1")
    n = int(tok)
    if want is not None and n != want:
        raise ViewFileError(path, line, col, f"frame {n} where frame {want} was expected "
                            "(frames are consecutive)")
    return n


def _parse_line(path: str, lineno: int, raw: str, want: int | None) -> View:
    toks = list(_TOKEN.finditer(raw))
    if len(toks) != len(_FIELDS):
        col = toks[min(len(toks), len(_FIELDS)) - 1].end() + 1 if toks else 1
        raise ViewFileError(path, lineno, col, f"expected 8 fields ({' '.join(_FIELDS)}), "
                            f"found {len(toks)}")
    frame = _frame_number(path, lineno, toks[0].start() + 1, toks[0].group(), want)
    v = [_number(path, lineno, t.start() + 1, f, t.group()) for f, t in zip(_FIELDS[1:], toks[1:])]
    if not FOCAL_MIN_MM <= v[6] <= FOCAL_MAX_MM:
        raise ViewFileError(path, lineno, toks[7].start() + 1,
                            f"focal length {v[6]:g} mm is outside {FOCAL_MIN_MM:g} to "
                            f"{FOCAL_MAX_MM:g}")
    if v[0:3] == v[3:6]:
        raise ViewFileError(path, lineno, toks[1].start() + 1,
                            "observer and viewpoint are the same point")
    return View(frame, (v[0], v[1], v[2]), (v[3], v[4], v[5]), v[6])


def parse_views(text: str, path: str = "<views>") -> list[View]:
    views: list[View] = []
    for lineno, raw in enumerate(text.splitlines(), start=1):
        if not raw.strip() or raw.lstrip().startswith("#"):
            continue
        want = views[-1].frame + 1 if views else None
        views.append(_parse_line(path, lineno, raw, want))
    if not views:
        raise ViewFileError(path, max(1, text.count("\n") + 1), 1, "no frames in the view file")
    return views


def read_views(path: str | os.PathLike[str]) -> list[View]:
    try:
        raw = Path(path).read_bytes()
    except OSError as exc:
        raise ViewFileError(str(path), 0, 0, f"cannot read: {exc.strerror}") from None
    try:
        text = raw.decode("ascii")
    except UnicodeDecodeError as exc:
        before = raw[: exc.start]
        line = before.count(b"\n") + 1
        col = exc.start - (before.rfind(b"\n") + 1) + 1
        raise ViewFileError(str(path), line, col, "non-ASCII byte") from None
    return parse_views(text, str(path))


def views_text(views: Sequence[View], comments: Iterable[str] = ()) -> str:
    head = [f"# {' '.join(c.split())}" for c in comments]  # one line each
    head.append("# " + " ".join(_FIELDS) + "  (metres in the table frame; focal in mm)")
    return "\n".join([*head, *(v.to_line() for v in views)]) + "\n"


def write_views(path: str | os.PathLike[str], views: Sequence[View],
                comments: Iterable[str] = ()) -> None:
    """Write atomically: `path` is either its old self or the whole new file."""
    write_atomic(path, views_text(views, comments), encoding="ascii")
