"""``--inspect-out DIR``: the inspector's panel for every frame shown, as
DIR/frame_NNNNN.png (headless or not)."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from camlab88.base.png import frame_path, write_frame
from camlab88.emulator.harness.loop import Plugin
from camlab88.emulator.harness.written import tell_written

if TYPE_CHECKING:
    from camlab88.emulator.harness.loop import Harness


class InspectOut(Plugin):
    def __init__(self, directory: Path) -> None:
        self.directory = Path(directory)
        self.count = 0
        self._panel: Any = None

    def start(self, harness: Harness) -> None:
        from camlab88.emulator.inspect import panel_for

        self._panel = panel_for(harness.target)
        if self._panel is None:
            raise SystemExit(f"{harness.options.command}: --inspect-out: this program's "
                             "device has no inspector")

    def on_frame(self, harness: Harness, frame: np.ndarray) -> None:
        path = frame_path(self.directory, self.count)
        try:
            write_frame(self._panel(frame), self.directory, self.count)
        except OSError as exc:
            raise SystemExit(f"{harness.options.command}: cannot write {path}: "
                             f"{exc.strerror or exc}") from None
        self.count += 1

    def finish(self, harness: Harness) -> None:
        if self.count:
            tell_written(harness, f"wrote {self.count} inspector panels to "
                         f"{self.directory}/frame_NNNNN.png")
