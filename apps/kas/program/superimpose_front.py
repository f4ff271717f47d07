"""The superimposer on the Sigma (§3.1.3): "all timing information is prompted for on entry".

The sequences named on the command line are listed in the panel; the message line asks, for
each in turn, how many frames after the start of the composite it begins (digits, Backspace,
Return; Return alone keeps the default shown in brackets).  When every start is answered the
composite is made (apps.kas.superimpose) and handed to ``on_done``; its last frame is shown.
The prompt and its keys are the editor's number prompts (apps.kas.editor ``_ask``) reused.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from camlab88.apps.kas.model import AnimSequence
from camlab88.apps.kas.program import layout as L
from camlab88.apps.kas.program.base import Front
from camlab88.apps.kas.program.draw import Prim, chain_prims, text
from camlab88.apps.kas.program.screen import FIELD_CLIP, field_marks
from camlab88.apps.kas.superimpose import superimpose


class SuperimposeFront(Front):
    """Ask each sequence's start on entry, then superimpose."""

    def __init__(self, parts: Sequence[tuple[str, AnimSequence, int]], background: str = "black",
                 on_done: Callable[[AnimSequence, list[int]], None] | None = None) -> None:
        super().__init__(background)
        self.parts = list(parts)  # (name, sequence, default start)
        self.starts: list[int] = []
        self.typed = ""
        self.on_done = on_done
        self.result: AnimSequence | None = None
        self.message = self._question()

    def _question(self) -> str:
        name, seq, default = self.parts[len(self.starts)]
        return (f"start of {_short(name)} ({len(seq)} frames), frames after the start "
                f"[{default}]: {self.typed}")

    def prims(self) -> list[Prim]:
        out = field_marks()
        y = L.FIELD_Y1 - 4
        for i, (name, seq, _d) in enumerate(self.parts):
            start = str(self.starts[i]) if i < len(self.starts) else "?"
            line = f"{_short(name)[:12]} {len(seq)}f @{start}"
            out.append(text(L.TEXT, L.PANEL_X, y - L.CHAR_H, line[:21]))
            y -= L.CHAR_H + 1
        status = f"SUPERIMPOSE  sequences {len(self.parts)}"
        if self.result is not None:
            status += f"  composite {len(self.result)} frames"
            out += self._last_frame()
        out.append(text(L.TEXT, L.FIELD_X0, L.STATUS_Y, status))
        out.append(text(L.TEXT, L.FIELD_X0, L.MESSAGE_Y, self.message[:90]))
        return out

    def _last_frame(self) -> list[Prim]:
        assert self.result is not None
        out: list[Prim] = []
        for c in self.result.frames[-1].chains:
            pts = np.asarray(c.points, float)
            px = np.column_stack([L.CENTRE_X + pts[:, 0] * L.SCALE,
                                  L.CENTRE_Y + pts[:, 1] * L.SCALE])
            out += chain_prims(px, [int(v) for v in c.colours], FIELD_CLIP)
        return out

    def on_pointer(self, x: float, y: float, down: bool) -> None:
        """The stylus has nothing to do here: the superimposer asks only numbers."""

    def on_key(self, key: str) -> None:
        if self.result is not None:
            return
        if len(key) == 1 and key.isdigit():
            self.typed += key
        elif key == "backspace":
            self.typed = self.typed[:-1]
        elif key == "return":
            self.starts.append(int(self.typed) if self.typed else self.parts[len(self.starts)][2])
            self.typed = ""
            if len(self.starts) == len(self.parts):
                self._finish()
                return
        self.message = self._question()

    def _finish(self) -> None:
        try:
            self.result = superimpose([(seq, s) for (_n, seq, _d), s in
                                       zip(self.parts, self.starts, strict=True)])
            if self.on_done is not None:
                self.on_done(self.result, self.starts)
        except (OSError, ValueError) as exc:
            self.result = None
            self.starts, self.typed = [], ""
            self.message = f"NOT saved: {exc}; " + self._question()
            return
        self.message = f"composite of {len(self.result)} frames made"
        self.done = True


def _short(name: str) -> str:
    """A sequence's name without its directory (the panel is 21 characters wide)."""
    return name.replace("\\", "/").rsplit("/", 1)[-1]
