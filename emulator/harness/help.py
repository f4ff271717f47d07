"""The F1 help overlay: every key the window answers — the harness's controls, each
plugin's ``keys`` and the program's own hint — drawn over the screen in the ROM font."""

from __future__ import annotations

import textwrap
from collections.abc import Iterable
from typing import TYPE_CHECKING

import numpy as np

from camlab88.emulator.inspect import draw

if TYPE_CHECKING:
    from camlab88.emulator.harness.loop import Harness

KeyList = list[tuple[str, str]]


def key_lines(harness: Harness) -> list[tuple[str, KeyList]]:
    """(heading, [(key, what)]) for the harness's plugins that have ``keys``, then the
    program's own hint (its one-line ``keys``, split at ';')."""
    groups: list[tuple[str, KeyList]] = []
    for p in harness.plugins:
        keys = getattr(p, "keys", None)
        if keys:
            groups.append((getattr(p, "keys_title", type(p).__name__), list(keys)))
    hint = str(getattr(harness.target, "keys", "") or "")
    program = [("", part.strip()) for part in hint.split(";") if part.strip()]
    if program:
        groups.append(("The program", program))
    return groups


def overlay(frame: np.ndarray, groups: Iterable[tuple[str, KeyList]]) -> np.ndarray:
    """``frame`` with the key list drawn over a darkened box."""
    out = frame.copy()
    h, w = out.shape[:2]
    cw, ch = draw.cell()
    cols = max(20, (w - 4 * cw) // cw)
    rows: list[tuple[str, draw.Colour]] = [("Keys (F1 closes this)", draw.ACCENT)]
    for title, keys in groups:
        rows.append(("", draw.INK))
        rows.append((title, draw.ACCENT))
        for key, what in keys:
            label = f"{key:<12}" if key else ""
            for i, part in enumerate(textwrap.wrap(what, cols - len(label)) or [""]):
                rows.append(((label if i == 0 else " " * len(label)) + part, draw.INK))
    box_h = min(h, (len(rows) + 2) * ch)
    draw.shade(out, 0, 0, w, box_h, 0.2)
    for i, (line, colour) in enumerate(rows):
        draw.text(out, 2 * cw, ch + i * ch, line, colour)
    return out
