"""The keyframe editor on the Sigma (§3.1.1): ``camlab88.apps.kas.editor.Editor`` behind a screen.

Stylus events become ``Pointer`` events in screen field inches (a touch in the menu row picks
a menu item, as the model already knows); keyboard bytes become ``Key`` events; F2 saves
through ``on_save``.  The display is redrawn incrementally (apps.kas.program.draw).
"""

from __future__ import annotations

from collections.abc import Callable

from camlab88.apps.kas.editor import Editor
from camlab88.apps.kas.events import Key, Pointer
from camlab88.apps.kas.model import Drawing
from camlab88.apps.kas.program import layout as L
from camlab88.apps.kas.program.base import Front
from camlab88.apps.kas.program.draw import Prim
from camlab88.apps.kas.program.screen import dim_pens, editor_prims


class EditorFront(Front):
    def __init__(self, editor: Editor | None = None, background: str = "black",
                 on_save: Callable[[Drawing], None] | None = None) -> None:
        super().__init__(background)
        self.editor = editor if editor is not None else Editor()
        if on_save is not None:
            self.editor.on_save = on_save

    def prims(self) -> list[Prim]:
        return editor_prims(self.editor, dim_pens(self.editor))

    def current_lut(self) -> list[tuple[int, int, int]]:
        """Edit mode with the background shown: entries 11-13 hold the dim pens (§3.1.1)."""
        ed = self.editor
        if ed.mode != "edit" or not ed.background:
            return self.lut
        return L.dim_lut(self.lut, dim_pens(ed), self.background)

    def on_pointer(self, x: float, y: float, down: bool) -> None:
        self.editor.feed(Pointer(x, y, down))

    def on_key(self, key: str) -> None:
        if key.lower() == "escape" and self.editor.pending is None:
            self.request_quit()  # Esc cancels a command first; with none it quits
            return
        self.editor.feed(Key(key))

    def unsaved(self) -> bool:
        return self.editor.dirty

    def save_work(self) -> bool:
        return self.editor.save()

    def say(self, message: str) -> None:
        self.editor.message = message
