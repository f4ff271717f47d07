"""The operations file (thesis §3.3): plain text, editable by hand; docs/kas.md describes it.

    KAS paint 1
    palette 3                 # entries, then one line each: colour INDEX R G B (0-255)
    colour 0 0 0 0
    colour 1 255 255 255
    colour 2 220 30 30
    gap 0.05                  # gap-closing tolerance, inches
    painted 11                # the frame painted by hand (1-based)
    ops 2                     # sequence operations, front-most last
    fill 1 2 colour 2 seeds -3.9 -1.2
    region 0.5 -1.0 colour 1
    frame 5 ops 1 seeds 2     # frame 5's own operations, then its seeds
    touch 0.3 0.4 colour 2
    seeds fill 1 2 at -3.7 -1.1          # the seeds 'fill 1 2' used in frame 5
    seeds region 0.5 -1.0 at 0.6 -0.9    # ... and the region's
    end

Errors name the file, line and column; counts are declared before their records and the
file ends with ``end``, so a truncated file is always noticed.  Saves are atomic.
"""

from __future__ import annotations

import math
import os
import re
from pathlib import Path

from camlab88.apps.kas.model import AnimSequence
from camlab88.apps.kas.paint.ops import Op, OpsFile, Seeds, op_key
from camlab88.apps.kas.paint.palette import Palette
from camlab88.base.atomicfile import write_atomic
from camlab88.base.fileerror import FilePlaceError

MAGIC = "KAS paint 1"
_TOKEN = re.compile(r"\S+")


class OpsFileError(FilePlaceError):
    """A bad operations file; the message starts ``file:line:column:``."""


# ------------------------------------------------------------------------ writing

def _num(x: float) -> str:
    r = repr(float(x))
    return "0.0" if r == "-0.0" else r


def op_text(op: Op) -> str:
    if op.kind in ("fill", "line"):
        words = [op.kind, *map(str, op.chains), "colour", str(op.colour)]
        if op.seeds:
            words += ["seeds"] + [_num(v) for p in op.seeds for v in p]
        return " ".join(words)
    assert op.at is not None
    return f"{op.kind} {_num(op.at[0])} {_num(op.at[1])} colour {op.colour}"


def ops_text(f: OpsFile) -> str:
    lines = [MAGIC, f"palette {len(f.palette)}"]
    lines += [f"colour {i} {r} {g} {b}" for i, (r, g, b) in enumerate(f.palette.entries)]
    lines += [f"gap {_num(f.gap)}", f"painted {f.painted}", f"ops {len(f.ops)}"]
    lines += [op_text(o) for o in f.ops]
    for n in sorted(set(f.frame_ops) | set(f.frame_seeds)):
        own, recs = f.frame_ops.get(n, []), f.frame_seeds.get(n, [])
        lines.append(f"frame {n} ops {len(own)}" + (f" seeds {len(recs)}" if recs else ""))
        lines += [op_text(o) for o in own] + [seeds_text(r) for r in recs]
    return "\n".join(lines + ["end"]) + "\n"


def seeds_text(r: Seeds) -> str:
    kind, what = r.key
    head = " ".join(map(str, what)) if kind in ("fill", "line") else \
        f"{_num(what[0])} {_num(what[1])}"
    return " ".join([f"seeds {kind} {head} at"] + [_num(v) for p in r.seeds for v in p])


def save(path: str | os.PathLike[str], f: OpsFile) -> None:
    write_atomic(path, ops_text(f).encode("utf-8"))


# ------------------------------------------------------------------------ reading

def _show(word: str, most: int = 40) -> str:
    """A word quoted in an error, shortened: a damaged file's 'word' can be megabytes."""
    return repr(word) if len(word) <= most else repr(word[:most]) + "..."


class _Reader:
    """Lines as (number, [(column, word)]), comments and blank lines skipped."""

    def __init__(self, text: str, name: str) -> None:
        self.name = name
        self.lines: list[tuple[int, list[tuple[int, str]]]] = []
        for n, raw in enumerate(text.splitlines(), start=1):
            body = raw.split("#", 1)[0]
            words = [(m.start() + 1, m.group()) for m in _TOKEN.finditer(body)]
            if words:
                self.lines.append((n, words))
        self.i = 0
        self.last = len(text.splitlines())

    def error(self, line: int, col: int, msg: str) -> OpsFileError:
        return OpsFileError(self.name, line, col, msg)

    def next(self, what: str) -> tuple[int, list[tuple[int, str]]]:
        if self.i >= len(self.lines):
            raise self.error(self.last + 1, 1, f"file ends before {what} (truncated?)")
        self.i += 1
        return self.lines[self.i - 1]

    def keyword(self, what: str, n_args: int) -> tuple[int, list[tuple[int, str]]]:
        ln, words = self.next(f"'{what}'")
        if words[0][1] != what:
            raise self.error(ln, words[0][0], f"expected '{what}', found {_show(words[0][1])}")
        if len(words) != n_args + 1:
            raise self.error(ln, words[0][0], f"'{what}' takes {n_args} value(s)")
        return ln, words[1:]

    def int_at(self, ln: int, w: tuple[int, str], lo: int, hi: int, what: str) -> int:
        col, s = w
        if not re.fullmatch(r"[+-]?[0-9]+", s):
            raise self.error(ln, col, f"{what} must be a whole number, not {_show(s)}")
        if len(s.lstrip("+-").lstrip("0")) > 18:  # int() refuses over 4300 digits
            raise self.error(ln, col, f"{what} {s[:20]}... outside {lo}..{hi}")
        v = int(s)
        if not lo <= v <= hi:
            raise self.error(ln, col, f"{what} {v} outside {lo}..{hi}")
        return v

    def float_at(self, ln: int, w: tuple[int, str], what: str) -> float:
        col, s = w
        try:
            v = float(s)
        except ValueError:
            raise self.error(ln, col, f"{what} must be a number, not {_show(s)}") from None
        if not math.isfinite(v) or not re.fullmatch(r"[0-9eE+\-.]+", s):
            raise self.error(ln, col, f"{what} must be a finite number, not {_show(s)}")
        return v


def _palette(r: _Reader) -> Palette:
    ln, (w,) = r.keyword("palette", 1)
    n = r.int_at(ln, w, 1, 32, "palette size")
    entries = []
    for i in range(n):
        cl, args = r.keyword("colour", 4)
        r.int_at(cl, args[0], i, i, "palette entries go in order: index")
        entries.append(tuple(r.int_at(cl, a, 0, 255, g) for a, g in
                             zip(args[1:], ("red", "green", "blue"), strict=True)))
    return Palette(entries)


def _op(r: _Reader, ln: int, words: list[tuple[int, str]], n_colours: int,
        frame: int | None) -> Op:
    kind = words[0][1]
    allowed = ("fill", "line", "region") + (("touch",) if frame is not None else ())
    if kind not in allowed:
        raise r.error(ln, words[0][0], f"expected an operation ({', '.join(allowed)}), "
                                       f"found {_show(kind)}")
    names = [w for _, w in words]
    if "colour" not in names:
        raise r.error(ln, words[-1][0] + len(words[-1][1]), "missing 'colour C'")
    k = names.index("colour")
    if k + 1 >= len(words):
        raise r.error(ln, words[k][0], "'colour' needs a palette entry number")
    colour = r.int_at(ln, words[k + 1], 0, n_colours - 1, "colour (palette entry)")
    head, tail = words[1:k], words[k + 2:]
    if kind in ("region", "touch"):
        if len(head) != 2 or tail:
            raise r.error(ln, words[0][0], f"'{kind} X Y colour C' expected")
        at = (r.float_at(ln, head[0], "x"), r.float_at(ln, head[1], "y"))
        return Op(kind, colour, at=at, frame=frame, line_no=ln)
    if not head:
        raise r.error(ln, words[0][0], f"'{kind}' names at least one line-chain")
    chains = tuple(r.int_at(ln, w, 1, 10**6, "line-chain number") for w in head)
    seeds: tuple[tuple[float, float], ...] = ()
    if tail:
        if kind != "fill" or tail[0][1] != "seeds" or len(tail) % 2 == 0:
            raise r.error(ln, tail[0][0], "after the colour only 'seeds X Y ...' may follow")
        v = [r.float_at(ln, w, "seed coordinate") for w in tail[1:]]
        seeds = tuple(zip(v[0::2], v[1::2], strict=True))
    return Op(kind, colour, chains=chains, frame=frame, seeds=seeds, line_no=ln,
              cols=tuple(c for c, _ in head))


def parse(text: str, name: str = "<operations>") -> OpsFile:
    r = _Reader(text, name)
    ln, words = r.next("the 'KAS paint 1' line")
    if " ".join(w for _, w in words) != MAGIC:
        raise r.error(ln, 1, f"not a KAS operations file (expected {MAGIC!r})")
    pal = _palette(r)
    ln, (w,) = r.keyword("gap", 1)
    gap = r.float_at(ln, w, "gap")
    if gap < 0:
        raise r.error(ln, w[0], "the gap tolerance cannot be negative")
    pln, (w,) = r.keyword("painted", 1)
    painted = r.int_at(pln, w, 1, 10**6, "painted frame")
    pcol = w[0]
    ln, (w,) = r.keyword("ops", 1)
    ops = [_op(r, *r.next("an operation"), len(pal), None)
           for _ in range(r.int_at(ln, w, 0, 10**6, "operation count"))]
    out = OpsFile(pal, ops, {}, gap, painted, name, {"painted": (pln, pcol)})
    while True:
        ln, words = r.next("'end'")
        if words[0][1] == "end" and len(words) == 1:
            break
        frame, count, n_seeds = _frame_header(r, ln, words)
        if f"frame {frame}" in out.at:
            raise r.error(ln, words[1][0], f"frame {frame} has a second section")
        out.at[f"frame {frame}"] = (ln, words[1][0])
        if count:
            out.frame_ops[frame] = [_op(r, *r.next("an operation"), len(pal), frame)
                                    for _ in range(count)]
        if n_seeds:
            out.frame_seeds[frame] = [_seeds(r, *r.next("a 'seeds' line"))
                                      for _ in range(n_seeds)]
    if r.i < len(r.lines):
        ln, words = r.lines[r.i]
        raise r.error(ln, words[0][0], "text after 'end'")
    return out


def _frame_header(r: _Reader, ln: int,
                  words: list[tuple[int, str]]) -> tuple[int, int, int]:
    names = [w for _, w in words]
    if (len(words) not in (4, 6) or names[0] != "frame" or names[2] != "ops"
            or (len(words) == 6 and names[4] != "seeds")):
        raise r.error(ln, words[0][0], f"expected 'frame N ops K [seeds M]' or 'end', found "
                                       f"{_show(' '.join(names))}")
    n_seeds = r.int_at(ln, words[5], 0, 10**6, "seeds count") if len(words) == 6 else 0
    return (r.int_at(ln, words[1], 1, 10**6, "frame number"),
            r.int_at(ln, words[3], 0, 10**6, "operation count"), n_seeds)


def _seeds(r: _Reader, ln: int, words: list[tuple[int, str]]) -> Seeds:
    """``seeds fill|line C ... at X Y ...`` or ``seeds region X Y at X Y ...``."""
    names = [w for _, w in words]
    if names[0] != "seeds" or len(words) < 3 or names[1] not in ("fill", "region"):
        raise r.error(ln, words[0][0], "expected 'seeds fill C ... at X Y ...' or "
                                       "'seeds region X Y at X Y ...'")
    if "at" not in names:
        raise r.error(ln, words[-1][0] + len(words[-1][1]), "missing 'at X Y ...'")
    k = names.index("at")
    head, tail = words[2:k], words[k + 1:]
    if len(tail) % 2:
        raise r.error(ln, tail[-1][0], "seed coordinates come in pairs (x y)")
    if names[1] == "fill":
        if not head:
            raise r.error(ln, words[1][0], "'seeds fill' names at least one line-chain")
        what: tuple[object, ...] = tuple(r.int_at(ln, w, 1, 10**6, "line-chain number")
                                         for w in head)
    else:
        if len(head) != 2:
            raise r.error(ln, words[1][0], "'seeds region X Y at ...' expected")
        what = (r.float_at(ln, head[0], "x"), r.float_at(ln, head[1], "y"))
    v = [r.float_at(ln, w, "seed coordinate") for w in tail]
    return Seeds((names[1], what), tuple(zip(v[0::2], v[1::2], strict=True)), ln,
                 words[1][0])


def load(path: str | os.PathLike[str]) -> OpsFile:
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        raise OpsFileError(str(p), 1, 1, f"not UTF-8 text ({exc.reason})") from None
    return parse(text, str(p))


def check(f: OpsFile, seq: AnimSequence) -> None:
    """Refuse, before anything is painted, a file that names a frame or chain the sequence
    does not have (file:line:column of the offending number)."""
    n = len(seq.frames)
    most = max((len(fr.chains) for fr in seq.frames), default=0)
    if not 1 <= f.painted <= n:
        raise OpsFileError(f.name, *f.at.get("painted", (0, 0)),
                           f"painted frame {f.painted} outside 1..{n}")
    _check_seeds(f, n)
    for frame, ops in [(None, f.ops)] + sorted(f.frame_ops.items()):
        if frame is not None and not 1 <= frame <= n:
            raise OpsFileError(f.name, *f.at.get(f"frame {frame}", (0, 0)),
                               f"frame {frame} outside 1..{n} (the sequence's frames)")
        have = most if frame is None else len(seq.frames[frame - 1].chains)
        for op in ops:
            for c, col in zip(op.chains, op.cols or (0,) * len(op.chains), strict=True):
                if c > have:
                    raise OpsFileError(f.name, op.line_no, col,
                                       f"line-chain {c} does not exist (at most {have})")


def _check_seeds(f: OpsFile, n: int) -> None:
    """Each frame's seed records belong to a sequence operation (as many as there are)."""
    for frame, recs in sorted(f.frame_seeds.items()):
        if not 1 <= frame <= n:
            raise OpsFileError(f.name, *f.at.get(f"frame {frame}", (0, 0)),
                               f"frame {frame} outside 1..{n} (the sequence's frames)")
        for i, r in enumerate(recs):
            have = sum(op_key(o) == r.key for o in f.ops)
            mine = sum(q.key == r.key for q in recs[:i + 1])
            if mine > have:
                raise OpsFileError(f.name, r.line_no, r.col,
                                   f"seeds for '{seeds_text(r).split(' at')[0][6:]}' but "
                                   f"{'only ' + str(have) if have else 'no'} such sequence "
                                   f"operation")
