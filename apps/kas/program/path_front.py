"""The in-betweener's set-up screen on the Sigma (§3.1.2): sample path and tick marks.

Both keyframes superimposed in different colours (first cyan, second magenta), the previous
pair's path in blue (for continuity), the path being drawn in yellow and the tick marks as
small white crosses.  ``camlab88.apps.kas.path_editor.PathEditor`` is the model; F2 saves through
``on_save(path, timing)``.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from camlab88.apps.kas.events import Key, Pointer
from camlab88.apps.kas.files import SamplePath, Timing
from camlab88.apps.kas.path_editor import PathEditor
from camlab88.apps.kas.program import layout as L
from camlab88.apps.kas.program.base import Front
from camlab88.apps.kas.program.draw import Prim, chain_prims, poly, text
from camlab88.apps.kas.program.screen import FIELD_CLIP, field_marks

ROLE_COLOUR = {"first": 6, "second": 7, "previous-path": 4, "path": 5, "tick": 1}
LEGEND = ["SAMPLE PATH", "cyan  first key", "mgnta second key", "blue  previous path",
          "yellow path", "", "stylus: draw path", "t  tick marks", "p  back to path",
          "u  undo tick/path", "c  clear", "f2 save"]


class PathFront(Front):
    def __init__(self, model: PathEditor, background: str = "black",
                 on_save: Callable[[SamplePath, Timing], None] | None = None) -> None:
        super().__init__(background)
        self.model = model
        self.on_save = on_save
        self._saved: tuple = ((), ())  # the path and ticks last saved

    def prims(self) -> list[Prim]:
        out = field_marks()
        y = L.FIELD_Y1 - 4
        for line in LEGEND:
            out.append(text(L.TEXT, L.PANEL_X, y - L.CHAR_H, line))
            y -= L.CHAR_H + 1
        m = self.model
        status = (f"{m.mode.upper()}  path points {len(m.path)}  ticks {len(m.ticks)}  "
                  f"frames {len(m.ticks) + 2 if m.ticks else '-'}")
        out.append(text(L.TEXT, L.FIELD_X0, L.STATUS_Y, status))
        if m.message:
            out.append(text(L.TEXT, L.FIELD_X0, L.MESSAGE_Y, m.message[:90]))
        for role, pts, _colour in m.display_list():
            px = np.column_stack([L.CENTRE_X + np.asarray(pts)[:, 0] * L.SCALE,
                                  L.CENTRE_Y + np.asarray(pts)[:, 1] * L.SCALE])
            c = ROLE_COLOUR[role]
            if role == "tick":
                x, y0 = (round(v) for v in px[0])
                if L.FIELD_X0 + 3 <= x <= L.FIELD_X1 - 3 and L.FIELD_Y0 + 3 <= y0 <= \
                        L.FIELD_Y1 - 3:
                    out.append(poly(c, [(x - 3, y0), (x + 3, y0)]))
                    out.append(poly(c, [(x, y0 - 3), (x, y0 + 3)]))
            else:
                out += chain_prims(px, [c] * len(px), FIELD_CLIP)
        return out

    def on_pointer(self, x: float, y: float, down: bool) -> None:
        self.model.feed(Pointer(x, y, down))

    def on_key(self, key: str) -> None:
        if key == "f2":
            self.save_work()
        elif key.lower() == "escape":
            self.request_quit()
        else:
            self.model.feed(Key(key))

    def _state(self) -> tuple:
        return tuple(self.model.path), tuple(self.model.ticks)

    def unsaved(self) -> bool:
        return bool(self.model.path) and self._state() != self._saved

    def save_work(self) -> bool:
        path = self.model.sample_path()
        if path is None:
            self.model.message = "draw the path first"
            return False
        if self.on_save is not None:
            try:
                self.on_save(path, self.model.timing())
            except OSError as exc:  # keep the path on the screen: it can be saved again
                self.model.message = f"NOT saved: {exc.strerror or exc}"
                return False
            self.model.message = "saved"
        self._saved = self._state()
        return True

    def say(self, message: str) -> None:
        self.model.message = message
