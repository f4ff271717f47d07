"""The harness's standard plugins: ``--frames DIR``, ``--screenshot PNG``, ``--record FILE``,
and, inside ``camlab88 replay``, recorded input and screen-hash checking."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from camlab88.base.png import frame_path, write_frame, write_png
from camlab88.emulator.harness.loop import Plugin, RunOptions
from camlab88.emulator.harness.written import tell_written

if TYPE_CHECKING:
    from camlab88.emulator.harness.loop import Harness


class FrameWriter(Plugin):
    """``--frames DIR``: every frame shown as ``DIR/frame_NNNNN.png``, named at the end."""

    def __init__(self, directory: Path) -> None:
        self.directory = Path(directory)
        self.count = 0

    def on_frame(self, harness: Harness, frame: np.ndarray) -> None:
        path = frame_path(self.directory, self.count)
        with _named_errors(harness, path):
            write_frame(frame, self.directory, self.count)
        self.count += 1

    def finish(self, harness: Harness) -> None:
        tell_written(harness, f"wrote {self.count} frames to {self.directory}/frame_NNNNN.png")


class Screenshot(Plugin):
    """``--screenshot PNG``: the screen when the run ends (the window's pixels if there is a
    window, else the device frame, with the inspector's panel beside it when ``--inspect``
    is on, as a window shows it), named on stderr."""

    def __init__(self, path: Path) -> None:
        self.path = Path(path)

    def finish(self, harness: Harness) -> None:
        with _named_errors(harness, self.path):
            if harness.window is not None and not harness.window.closed:
                harness.window.show(harness.screen())
                harness.window.screenshot(self.path)
            else:
                write_png(_with_panel(harness, harness.screen()), self.path)
        tell_written(harness, f"screenshot {self.path}")


def _with_panel(harness: Harness, frame: np.ndarray) -> np.ndarray:
    """The frame with the inspector's panel on its right when --inspect asks for it."""
    if not harness.options.controls.inspect:
        return frame
    from camlab88.emulator.inspect import panel_for

    panel = panel_for(harness.target)
    return frame if panel is None else np.concatenate([frame, panel(frame)], axis=1)


@contextmanager
def _named_errors(harness: Harness, path: Path) -> Iterator[None]:
    """A file that cannot be written is a one-line error naming it, not a traceback."""
    try:
        yield
    except OSError as exc:
        raise SystemExit(f"{harness.options.command}: cannot write {path}: "
                         f"{exc.strerror or exc}") from None


def standard_plugins(options: RunOptions) -> list[Plugin]:
    """The plugins ``options`` ask for, and those of an active replay (emulator.harness.replay)."""
    from camlab88.emulator.harness import replay, session_record

    plugins: list[Plugin] = []
    active = replay.active()
    if active is not None:
        active.adjust(options)
        plugins += active.plugins()
    elif options.record is not None:
        plugins.append(session_record.SessionRecorder(options))
    if options.state is not None:  # first: a loaded state is in place before others start
        from camlab88.emulator.harness.state_plugin import StatePlugin

        plugins.insert(0, StatePlugin(options.state))
    if options.frames is not None:
        plugins.append(FrameWriter(options.frames))
    if options.screenshot is not None:
        plugins.append(Screenshot(options.screenshot))
    return plugins
