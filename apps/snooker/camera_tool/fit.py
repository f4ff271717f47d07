"""Text fitted to a pane's width and height with nothing lost silently: a line wider than
the pane scrolls sideways with ``<`` / ``>`` where text is hidden, a message too long for
one row is elided in the middle (``...``) or wrapped, rows past the pane's bottom are
counted on its last row."""

from __future__ import annotations

import textwrap
from collections.abc import Sequence

MORE_LEFT, MORE_RIGHT, ELIDED = "<", ">", "..."


def window(text: str, left: int, cols: int) -> str:
    """Columns ``left`` .. ``left + cols`` of ``text``; an end with hidden text shows a marker."""
    shown = text[left:left + cols]
    if left + cols < len(text):
        shown = shown[:-1] + MORE_RIGHT
    if left > 0 and text[:left].strip():
        shown = MORE_LEFT + shown[1:]
    return shown


def scroll_left(left: int, col: int, cols: int) -> int:
    """The first column shown so the cursor column ``col`` stays in view (a margin of one
    for the markers)."""
    if col < left + 1:
        return max(0, col - 1)
    if col > left + cols - 2:
        return col - cols + 2
    return left


def elide(text: str, cols: int) -> str:
    """``text`` in ``cols`` columns, its middle replaced by ``...`` when it is too long."""
    if len(text) <= cols:
        return text
    head = (cols - len(ELIDED)) // 2
    return text[:head] + ELIDED + text[len(text) - (cols - len(ELIDED) - head):]


def wrap_rows(rows: Sequence[tuple[str, int]], cols: int,
              n_rows: int) -> list[tuple[str, int]]:
    """(text, value) rows wrapped to ``cols`` (continuations indented) and cut to ``n_rows``,
    the last row then saying how many more there were."""
    out: list[tuple[str, int]] = []
    for text, value in rows:
        wrapped = (textwrap.wrap(text, cols, subsequent_indent="    ")
                   if len(text) > cols else [text])
        out += [(w, value) for w in wrapped]
    if len(out) > n_rows:
        more = len(out) - n_rows + 1
        out = out[:n_rows - 1] + [(f"... {more} more rows", out[n_rows - 1][1])]
    return out
