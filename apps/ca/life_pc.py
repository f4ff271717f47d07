"""Alan Hensel's PC Life formats, Life 1.05 and 1.06 (``.lif``, ``.life``), read as Golly does.

Golly's ``readpclife`` (readpattern.cpp) is the reference: one pass over the lines, where

* ``#P x y`` starts a block of rows at (x, y) (a number it cannot read leaves that
  coordinate where it was: ``#P`` alone in acorn.lif starts at (0, 0));
* ``#N`` means Conway's Life, ``#R rule`` names the rule (1.05 writes it S/B, ``#R 23/3``);
  any other ``#`` line (``#Life``, ``#D``, ``#L``) is a comment;
* a line starting with ``.`` or ``*`` is a row of a block: ``*`` live, anything else dead;
  the next row is one lower, back at the block's x;
* a line starting with a digit or ``-`` is a Life 1.06 cell ``x y``.

Cells are relative to Golly's origin, which becomes the pattern's reference point.  Golly
skips what it cannot read; here a 1.06 line without two numbers is an error naming the line,
since silently dropping a cell would change the pattern.
"""

from __future__ import annotations

import re

HEADERS = ("#Life 1.05", "#Life 1.06")
_INT = re.compile(r"\s*([+-]?[0-9]{1,12})(?![0-9])")  # longer numbers: not coordinates
LIMIT = 1 << 30  # a coordinate further than this from the origin is not a plane position


class LifeTextError(ValueError):
    def __init__(self, line: int, column: int, message: str) -> None:
        super().__init__(message)
        self.line, self.column, self.message = line, column, message


def _ints(text: str, n: int) -> list[int]:
    """Up to ``n`` leading integers, as sscanf(" %d %d") reads them."""
    out: list[int] = []
    pos = 0
    while len(out) < n:
        m = _INT.match(text, pos)
        if m is None:
            break
        out.append(int(m.group(1)))
        pos = m.end()
    return out


def parse_life_pc(text: str) -> tuple[list[tuple[int, int]], str, list[str]]:
    """(live cells relative to Golly's origin, rule, comments) of a Life 1.05/1.06 text."""
    lines = text.splitlines()
    first = lines[0].rstrip() if lines else ""
    if not first.startswith(HEADERS):
        raise LifeTextError(1, 1, "expected '#Life 1.05' or '#Life 1.06' on the first line, "
                                  f"found {first[:40]!r}")
    x = y = left = 0
    rule = ""
    comments: list[str] = []
    cells: list[tuple[int, int]] = []
    for lineno, line in enumerate(lines, start=1):
        if line.startswith("#"):
            tag = line[1:2]
            if tag == "P":
                got = _ints(line[2:], 2)
                x, y = (got + [x, y][len(got):])[:2]
                left = x
            elif tag == "N":
                rule = "B3/S23"
            elif tag == "R":
                words = line[2:].split()
                rule = words[0].rstrip(",") if words else rule
            elif tag in ("D", "C"):
                comments.append(line[2:].strip())
        elif line[:1] == "-" or line[:1].isdigit():
            got = _ints(line, 2)
            if len(got) < 2:
                raise LifeTextError(lineno, 1, "a Life 1.06 cell is two integers 'x y', "
                                               f"found {line[:40]!r}")
            x, y = got
            cells.append((x, y))
        elif line[:1] in (".", "*"):
            cells.extend((x + k, y) for k, c in enumerate(line) if c == "*")
            x = left
            y += 1
        else:
            continue  # blank lines and anything else: Golly skips them too
        if abs(x) > LIMIT or abs(y) > LIMIT:
            raise LifeTextError(lineno, 1, f"position ({x}, {y}) is beyond any plane")
    return cells, rule, comments
