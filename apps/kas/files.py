"""KAS file formats: keyframes, sequences, sample paths and timings (docs/kas.md).

Plain text, one record a line, with a versioned magic first line (``KAS keyframe 1``) and an
``end`` line so a truncated file is always noticed.  Every count is declared before its
records.  Errors name the file and line.  Saves are atomic (temp file in the same directory,
fsync, rename), so a failed save never loses what was saved before.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from camlab88.apps.kas.model import AnimSequence, Chain, Drawing
from camlab88.base import budget
from camlab88.base.atomicfile import write_atomic
from camlab88.base.textinput import InputError, parse_int, quote, read_text

VERSION = 1
KINDS = ("keyframe", "sequence", "path", "timing")


MAX_FPS = 1000  # film runs at 24 or 25; no sequence means more than this


class KasFileError(ValueError):
    """A bad KAS file; the message starts ``file:line:``."""

    def __init__(self, path: str | os.PathLike[str], line: int, message: str,
                 column: int = 0) -> None:
        where = f"{path}:{line}:{column}" if column else f"{path}:{line}" if line else f"{path}"
        super().__init__(f"{where}: {message}")  # line 0: the file as a whole
        self.path = str(path)
        self.line = line


@dataclass
class SamplePath:
    """A hand-drawn interpolation path (§3.1.2): a polyline in inches."""

    points: np.ndarray

    def __post_init__(self) -> None:
        self.points = np.asarray(self.points, dtype=np.float64).reshape(-1, 2)


@dataclass
class Timing:
    """Timing between two keyframes.

    ``kind == "ticks"``: ``values`` are the fractions of the path length at the in-between
    frames' tick marks (the thesis's method; fixes the frame count).
    ``kind == "curve"``: ``values`` is (k, 2) samples (fraction of time, fraction of distance),
    piecewise linear, independent of the frame count (the improvement asked for in §3.2).
    """

    kind: str
    values: np.ndarray
    name: str = ""

    def __post_init__(self) -> None:
        if self.kind not in ("ticks", "curve"):
            raise ValueError(f"timing kind must be ticks or curve, not {self.kind!r}")
        v = np.asarray(self.values, dtype=np.float64)
        self.values = v.reshape(-1) if self.kind == "ticks" else v.reshape(-1, 2)


# ---------------------------------------------------------------- writing

def _num(x: float) -> str:
    r = repr(float(x))
    return "0.0" if r == "-0.0" else r


def _xy_lines(points: np.ndarray) -> list[str]:
    """'x y' per point with exact shortest float text; repr of a whole list runs in C."""
    if not len(points):
        return []
    return [xy.replace(",", "") for xy in repr(points.tolist())[2:-2].split("], [")]


def _chain_lines(c: Chain) -> Iterator[str]:
    yield f"chain section={c.section} points={len(c)}"
    if not len(c):
        return
    if (c.colours == c.colours[0]).all():
        # One colour: build the whole block with C-level string operations.
        col = f" {int(c.colours[0])}"
        yield repr(c.points.tolist())[2:-2].replace("], [", col + "\n").replace(",", "") + col
        return
    yield from (f"{xy} {col}" for xy, col in zip(_xy_lines(c.points), c.colours.tolist()))


def _drawing_lines(d: Drawing) -> Iterator[str]:
    yield f"chains {len(d.chains)}"
    for c in d.chains:
        yield from _chain_lines(c)


def keyframe_text(d: Drawing) -> str:
    lines = [f"KAS keyframe {VERSION}", *_drawing_lines(d), "end"]
    return "\n".join(lines) + "\n"


def sequence_text(s: AnimSequence) -> str:
    lines = [f"KAS sequence {VERSION}", f"fps {_num(s.fps)}", f"frames {len(s.frames)}"]
    for i, f in enumerate(s.frames):
        lines.append(f"frame {i}")
        lines.extend(_drawing_lines(f))
    lines.append("end")
    return "\n".join(lines) + "\n"


def path_text(p: SamplePath) -> str:
    lines = [f"KAS path {VERSION}", f"points {len(p.points)}"]
    lines += _xy_lines(p.points)
    return "\n".join([*lines, "end"]) + "\n"


def timing_text(t: Timing) -> str:
    lines = [f"KAS timing {VERSION}", f"kind {t.kind}"]
    if t.name:
        lines.append(f"name {t.name}")
    lines.append(f"samples {len(t.values)}")
    if t.kind == "ticks":
        lines += [_num(v) for v in t.values.tolist()]
    else:
        lines += [f"{_num(a)} {_num(b)}" for a, b in t.values.tolist()]
    return "\n".join([*lines, "end"]) + "\n"


def save_keyframe(path: str | os.PathLike[str], d: Drawing) -> None:
    write_atomic(path, keyframe_text(d))


def save_sequence(path: str | os.PathLike[str], s: AnimSequence) -> None:
    write_atomic(path, sequence_text(s))


def save_path(path: str | os.PathLike[str], p: SamplePath) -> None:
    write_atomic(path, path_text(p))


def save_timing(path: str | os.PathLike[str], t: Timing) -> None:
    write_atomic(path, timing_text(t))


# ---------------------------------------------------------------- reading

# One data line: cols fields, optional surrounding blanks (checked for a whole table at once).
_LAYOUT = {c: re.compile(r"(?:[ \t]*\S+" + r"[ \t]+\S+" * (c - 1) + r"[ \t]*\n)*[ \t]*\S+"
                         + r"[ \t]+\S+" * (c - 1) + r"[ \t]*") for c in (1, 2, 3)}


# What reading a line costs, measured on a keyframe of 10^6 points: ~550 bytes (its string,
# its numbers as Python values on the way to the array)
LINE_BYTES = 600


class _Reader:
    """Line cursor over the raw lines, skipping blanks and ``#`` comments between records.

    Numeric tables take the fast path when their lines are contiguous and well formed; any
    irregularity falls back to a record-by-record read that names the bad line."""

    def __init__(self, text: str, name: str) -> None:
        self.name = name
        lines = text.count("\n") + 1
        budget.check(name, lines * LINE_BYTES, f"reading its {lines:,} lines")
        self.raw = text.splitlines()
        self.pos = 0                      # index of the next raw line
        self.last_line = len(self.raw)
        self.rows: list[int] | range = []  # file line numbers of the last table's rows

    def _skip(self) -> None:
        raw = self.raw
        while self.pos < len(raw):
            t = raw[self.pos].strip()
            if t and t[0] != "#":
                return
            self.pos += 1

    def at_end(self) -> bool:
        self._skip()
        return self.pos >= len(self.raw)

    def peek(self) -> str | None:
        self._skip()
        return self.raw[self.pos].strip() if self.pos < len(self.raw) else None

    def line_no(self) -> int:
        self._skip()
        return self.pos + 1 if self.pos < len(self.raw) else self.last_line

    def error(self, msg: str, line: int | None = None) -> KasFileError:
        return KasFileError(self.name, self.line_no() if line is None else line, msg)

    def next(self, what: str) -> tuple[int, str]:
        if self.at_end():
            raise self.error(f"file ends early: expected {what}")
        self.pos += 1
        return self.pos, self.raw[self.pos - 1].strip()

    def keyword(self, word: str) -> tuple[int, list[str]]:
        no, text = self.next(f"'{word}'")
        parts = text.split()
        if parts[0] != word:
            raise KasFileError(self.name, no, f"expected '{word}', found {quote(parts[0])}")
        return no, parts[1:]

    def count(self, word: str) -> int:
        no, rest = self.keyword(word)
        if len(rest) != 1 or not (rest[0].isascii() and rest[0].isdigit()):
            raise KasFileError(self.name, no, f"'{word}' needs one non-negative integer")
        if len(rest[0]) > len(str(len(self.raw))) + 1 or int(rest[0]) > len(self.raw):
            # every counted item takes at least a line: more than the file has is damage
            raise KasFileError(self.name, no, f"'{word} {quote(rest[0], 24)}' counts more "
                               f"than the file's {len(self.raw)} lines could hold")
        return int(rest[0])

    def number(self, word: str) -> float:
        no, rest = self.keyword(word)
        try:
            (v,) = rest
            x = float(v)
        except ValueError:
            raise KasFileError(self.name, no, f"'{word}' needs one number") from None
        if not np.isfinite(x):
            raise KasFileError(self.name, no, f"'{word}' must be finite")
        return x

    def table(self, n: int, cols: int, what: str) -> np.ndarray:
        """``n`` records of ``cols`` finite numbers each."""
        if n == 0:
            self.rows = []
            return np.zeros((0, cols))
        self._skip()
        first = self.pos
        chunk = "\n".join(self.raw[first:first + n])
        if first + n <= len(self.raw) and _LAYOUT[cols].fullmatch(chunk):
            try:
                flat = np.array(list(map(float, chunk.split())), dtype=np.float64)
            except ValueError:
                flat = None
            if flat is not None and np.isfinite(flat).all():
                self.pos = first + n
                self.rows = range(first + 1, first + n + 1)
                return flat.reshape(n, cols)
        rows, nos = [], []
        for _ in range(n):
            if self.at_end():
                raise self.error(f"file ends early: expected {n} {what} lines")
            no, t = self.next(what)
            parts = t.split()
            try:
                vals = [float(p) for p in parts]
            except ValueError:
                vals = []
            if len(parts) != cols or len(vals) != cols or not np.isfinite(vals).all():
                raise KasFileError(self.name, no, f"expected {cols} finite numbers "
                                   f"for a {what}, found {quote(t)}")
            rows.append(vals)
            nos.append(no)
        self.rows = nos
        return np.array(rows, dtype=np.float64).reshape(n, cols)

    def finish(self) -> None:
        no, text = self.next("'end'")
        if text != "end":
            raise KasFileError(self.name, no, f"expected 'end', found {quote(text)}")
        if not self.at_end():
            raise self.error("unexpected text after 'end'")


def _header(r: _Reader, kind: str) -> None:
    if r.at_end():
        raise KasFileError(r.name, 1, f"empty file: expected 'KAS {kind} {VERSION}'")
    no, text = r.next("header")
    parts = text.split()
    if len(parts) != 3 or parts[0] != "KAS" or parts[1] not in KINDS:
        raise KasFileError(r.name, no, f"not a KAS file: expected 'KAS {kind} {VERSION}'")
    if parts[1] != kind:
        raise KasFileError(r.name, no, f"this is a KAS {parts[1]} file, not a {kind} file")
    if parts[2] != str(VERSION):
        raise KasFileError(r.name, no, f"unsupported {kind} file version {quote(parts[2])} "
                           f"(this program reads version {VERSION})")


def _read_drawing(r: _Reader) -> Drawing:
    n_chains = r.count("chains")
    chains = []
    for _ in range(n_chains):
        no, rest = r.keyword("chain")
        fields = dict(p.split("=", 1) for p in rest if "=" in p)
        try:
            section = parse_int(fields["section"], "", -(1 << 15), (1 << 15) - 1)
            npts = parse_int(fields["points"], "", 0, len(r.raw))
            if len(fields) != len(rest):
                raise ValueError
        except (KeyError, ValueError):
            raise KasFileError(r.name, no, "expected 'chain section=S points=N'") from None
        tab = r.table(npts, 3, "point (x y colour)")
        cols = tab[:, 2]
        if npts and (np.any(cols != np.round(cols)) or cols.min() < 1 or cols.max() > 255):
            bad = int(np.argmax((cols != np.round(cols)) | (cols < 1) | (cols > 255)))
            line = r.rows[bad]
            raise KasFileError(r.name, line, "colour must be an integer pen 1..255")
        chains.append(Chain(tab[:, :2].copy(), cols.astype(np.int16), section))
    return Drawing(chains)


def _source(src: str | os.PathLike[str]) -> tuple[str, str]:
    """The file's text; a directory, missing file or bad byte raises KasFileError (a bad
    byte at its line and column)."""
    try:
        return read_text(src), str(src)
    except InputError as exc:
        raise KasFileError(src, exc.line or 1, exc.reason, exc.column) from None


def parse_keyframe(text: str, name: str = "<keyframe>") -> Drawing:
    r = _Reader(text, name)
    _header(r, "keyframe")
    d = _read_drawing(r)
    r.finish()
    return d


def parse_sequence(text: str, name: str = "<sequence>") -> AnimSequence:
    r = _Reader(text, name)
    _header(r, "sequence")
    fps_line = r.line_no()
    fps = r.number("fps")
    if not 0 < fps <= MAX_FPS:
        raise r.error(f"fps must be above 0 and at most {MAX_FPS}", fps_line)
    n = r.count("frames")
    frames = []
    for i in range(n):
        no, rest = r.keyword("frame")
        if rest != [str(i)]:
            raise KasFileError(r.name, no, f"expected 'frame {i}'")
        frames.append(_read_drawing(r))
    r.finish()
    return AnimSequence(frames, fps)


def parse_path(text: str, name: str = "<path>") -> SamplePath:
    r = _Reader(text, name)
    _header(r, "path")
    n = r.count("points")
    pts = r.table(n, 2, "path point (x y)")
    r.finish()
    return SamplePath(pts)


def parse_timing(text: str, name: str = "<timing>") -> Timing:
    r = _Reader(text, name)
    _header(r, "timing")
    no, rest = r.keyword("kind")
    if rest not in (["ticks"], ["curve"]):
        raise KasFileError(r.name, no, "kind must be 'ticks' or 'curve'")
    kind = rest[0]
    label = ""
    nxt = r.peek()
    if nxt is not None and nxt.split()[0] == "name":
        label = r.next("name")[1][4:].strip()
    n = r.count("samples")
    no = r.line_no()
    vals = r.table(n, 1 if kind == "ticks" else 2, f"{kind} sample")
    r.finish()
    try:
        t = Timing(kind, vals, label)
        validate_timing(t)
    except ValueError as exc:
        raise KasFileError(name, no, str(exc)) from None
    return t


def validate_timing(t: Timing) -> None:
    """Ticks are path fractions in 0..1 in order along the path (equal ticks hold a frame);
    a curve's time fractions run from 0 to 1, increasing."""
    if t.kind == "ticks":
        v = t.values
        bad = np.flatnonzero((v < 0) | (v > 1) | ~np.isfinite(v))
        if len(bad):
            i = int(bad[0])
            raise ValueError(f"tick {i + 1} ({v[i]:g}) is not a fraction of the path "
                             "between 0 and 1")
        back = np.flatnonzero(np.diff(v) < 0)
        if len(back):
            i = int(back[0]) + 1
            raise ValueError(f"tick {i + 1} ({v[i]:g}) comes before tick {i} ({v[i - 1]:g}) "
                             "along the path: ticks must be in order")
        return
    v = t.values
    if len(v) < 2:
        raise ValueError("a timing curve needs at least two samples")
    if v[0, 0] != 0.0 or v[-1, 0] != 1.0:
        raise ValueError("a timing curve's time fractions must run from 0 to 1")
    if np.any(np.diff(v[:, 0]) <= 0):
        raise ValueError("a timing curve's time fractions must increase")


def load_keyframe(path: str | os.PathLike[str]) -> Drawing:
    return parse_keyframe(*_source(path))


def load_sequence(path: str | os.PathLike[str]) -> AnimSequence:
    return parse_sequence(*_source(path))


def load_path(path: str | os.PathLike[str]) -> SamplePath:
    return parse_path(*_source(path))


def load_timing(path: str | os.PathLike[str]) -> Timing:
    return parse_timing(*_source(path))


def load_drawing_or_frame(path: str | os.PathLike[str]) -> Drawing:
    """A keyframe file, or the last frame of a sequence file (to continue from it)."""
    text, name = _source(path)
    if text.lstrip().startswith("KAS sequence"):
        seq = parse_sequence(text, name)
        if not seq.frames:
            raise KasFileError(name, 1, "sequence has no frames")
        return seq.frames[-1]
    return parse_keyframe(text, name)
