"""``tablet monitor``: one line per decoded report from a real or emulated tablet, as a
program on the harness (headless for a real tablet, whose reads pace the ticks; a window for
the emulated tablet the mouse drives).  A real tablet that is lost (unplugged, cable out) is
reopened until it comes back; ``--seconds`` counts on the wall clock."""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
from typing import Any

from camlab88.emulator.tablet_input.program import TabletProgram

SILENT_HINT = 5.0  # s without a single report before the monitor says what to check
READ_TIMEOUT = 0.02  # s one tick waits for the tablet
DRAIN_TICKS = 20  # ticks read after a scripted stroke ends (its last bytes on the pty)
SHOT_FRAMES = 30  # --screenshot after so many frames
KEYS = "the mouse is the pen (o: out of proximity, e: eraser); close it to quit"


class Held:
    """The real tablet being monitored: lost (unplugged, cable out) it is reopened every
    RETRY s until it comes back; the monitor keeps running meanwhile."""

    RETRY = 0.5

    def __init__(self, source: Any, spec: Any, on_raw: Any,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.source, self.spec, self.on_raw, self.clock = source, spec, on_raw, clock
        self._next_try = 0.0
        self._opened_at = clock()
        self._hinted = False

    def hint_if_silent(self, count: int) -> None:
        """Said once: nothing at all for SILENT_HINT s (a tablet without a start-up query
        cannot be told from an empty port any sooner)."""
        if count or self._hinted or self.clock() - self._opened_at < SILENT_HINT:
            return
        self._hinted = True
        heard = getattr(self.source, "heard", 0)
        what = ("bytes came but no report decoded: check the protocol and the baud" if heard
                else "nothing at all came: put the pen on the tablet; if still nothing, check "
                "the cable, that the tablet is switched on, the port, the protocol and the baud")
        print(f"camlab88 tablet: {self.spec.text}: no report in {SILENT_HINT:g} s; {what} "
              "(still listening)", file=sys.stderr, flush=True)

    def read(self, timeout: float) -> list:
        from camlab88.protocols.tablets.sources import SourceLost, open_source

        if self.source is None:
            if self.clock() < self._next_try:
                time.sleep(timeout)
                return []
            self._next_try = self.clock() + self.RETRY
            try:
                self.source = open_source(self.spec, on_raw=self.on_raw)
            except SourceLost:
                return []
            print(f"camlab88 tablet: {self.spec.text}: back", file=sys.stderr, flush=True)
        try:
            return self.source.read(timeout=timeout)
        except SourceLost as exc:
            self.source.close()
            self.source = None
            self._next_try = self.clock() + self.RETRY
            print(f"camlab88 tablet: lost {exc}; waiting for it to come back (Ctrl-C stops)",
                  file=sys.stderr, flush=True)
            return []

    def close(self) -> None:
        if self.source is not None:
            self.source.close()


class MonitorProgram(TabletProgram):
    """Each tick: the emulated tablet's stroke a step on, one read, a line per report."""

    def __init__(self, held: Held, emu: Any, count: int | None, seconds: float | None,
                 clock: Callable[[], float] = time.monotonic) -> None:
        super().__init__(emu, KEYS)
        self.held, self.count, self.seconds, self.clock = held, count, seconds, clock
        self.printed = self.idle = 0
        self.start = clock()

    def step(self) -> bool:
        from camlab88.protocols.tablets.sources import SourceLost

        if self.seconds is not None and self.clock() - self.start >= self.seconds:
            return False
        emu = self.emu
        if emu is not None and not emu.step():
            self.idle += 1
            if self.idle > DRAIN_TICKS:
                return False  # the scripted stroke finished and drained
        try:  # the emulated tablet does not come back
            events = self.held.source.read(timeout=READ_TIMEOUT) if emu is not None \
                else self.held.read(READ_TIMEOUT)
        except SourceLost as exc:
            print(f"camlab88 tablet: {exc}", file=sys.stderr)
            self.exit_status = 1
            return False
        for e in events[: None if self.count is None else self.count - self.printed]:
            print(e.describe(), flush=True)
            self.printed += 1
        self.held.hint_if_silent(self.printed)
        if emu is not None:
            emu.show(events)
        return self.count is None or self.printed < self.count


def refuse_without_display(command: str, source_text: str) -> None:
    """A mouse-driven emulated tablet needs a window: without a display refuse before its
    pty is opened and announced (a newcomer saw the pty's path, then the refusal)."""
    from camlab88.emulator.harness import choose_headless
    from camlab88.emulator.tablet_input.emulated_source import needs_window

    if needs_window(source_text):
        choose_headless(command, False, None, "use SOURCE?drive=demo, or a real tablet")


def _windowed(command: str, emu: Any, screenshot: str | None) -> bool:
    """The emulated tablet's window: needed for the mouse (the one display rule)."""
    from camlab88.emulator.harness import choose_headless

    if emu is None or not (emu.drive == "mouse" or screenshot):
        return False
    can = None if emu.drive == "mouse" else "the scripted stroke, no window"
    return not choose_headless(command, False, can, "use SOURCE?drive=demo, or a real tablet")


def monitor_tablet(command: str, source_text: str, raw: bool, count: int | None,
                   seconds: float | None, screenshot: str | None) -> int:
    """Open SOURCE, print its header and then one line per report until ``count`` reports,
    ``seconds``, the end of a scripted stroke, or the window closes."""
    from pathlib import Path

    from camlab88.emulator.harness import RunOptions, run
    from camlab88.emulator.tablet import demo_path
    from camlab88.emulator.tablet_input.emulated_source import open_tablet

    def on_raw(data: bytes) -> None:
        print("raw " + data.hex(" "), flush=True)

    refuse_without_display(command, source_text)
    source, emu, spec = open_tablet(source_text, on_raw if raw else None, demo_path())
    held = Held(source, spec, on_raw if raw else None)
    try:
        windowed = _windowed(command, emu, screenshot)
        if windowed:
            emu.with_view()
        for note in getattr(source, "size_notes", ()):  # a size reply we could not trust
            print(f"camlab88 tablet: {note}", file=sys.stderr)
        print(f"# {source.name}: {source.model.name}, 0..{source.model.max_x} x "
              f"0..{source.model.max_y}, {source.model.lines_per_inch:g} lpi", flush=True)
        for note in getattr(source, "header_notes", ()):
            print(f"# {note}", flush=True)
        program = MonitorProgram(held, emu, count, seconds)
        shot = screenshot is not None and windowed
        run(program, RunOptions(headless=not windowed, command=command,
                                screenshot=Path(screenshot) if shot else None,
                                stop_after=SHOT_FRAMES if shot else None))
    finally:
        (emu if emu is not None else held).close()
    return program.exit_status
