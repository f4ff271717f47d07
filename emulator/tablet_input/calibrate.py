"""``tablet calibrate``: touch the top-left then the bottom-right corner; the two corners are
saved per device.  A program on the harness, like monitor (emulator.tablet_input.monitor):
headless for a real tablet, a window for the emulated tablet the mouse drives."""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
from typing import Any

from camlab88.emulator.tablet_input.monitor import READ_TIMEOUT, refuse_without_display
from camlab88.emulator.tablet_input.program import TabletProgram

# the scripted stroke of an emulated ?drive=demo tablet: a tap near each corner
TAPS = ([(0.1, 0.1, 0)] * 3 + [(0.1, 0.1, 1)] * 3 + [(0.1, 0.1, 0)] * 3
        + [(0.9, 0.9, 0)] * 3 + [(0.9, 0.9, 1)] * 3 + [(0.9, 0.9, 0)] * 3)
KEYS = "the mouse is the pen: press at the top-left, then at the bottom-right; close it to quit"


class CalibrateProgram(TabletProgram):
    """Each tick: the emulated tablet's taps a step on, one read, the corners found."""

    def __init__(self, session: Any, source: Any, emu: Any, seconds: float,
                 clock: Callable[[], float] = time.monotonic) -> None:
        super().__init__(emu, KEYS)
        self.session, self.source, self.seconds, self.clock = session, source, seconds, clock
        self.seen = 0
        self.start = clock()
        self.exit_status = 1  # until both corners are touched

    def step(self) -> bool:
        from camlab88.protocols.tablets.sources import SourceLost

        if self.clock() - self.start > self.seconds:
            print(f"camlab88 tablet: {self.source.name}: calibration gave up after "
                  f"{self.seconds:g} s: {_hint(self.source, self.seen)}", file=sys.stderr)
            return False
        if self.emu is not None:
            self.emu.step()
        try:
            events = self.source.read(timeout=READ_TIMEOUT)
        except SourceLost as exc:
            print(f"camlab88 tablet: {exc}", file=sys.stderr)
            return False
        self.seen += len(events)
        if self.emu is not None:
            self.emu.show(events)
        for e in events:
            if self.session.feed(e):
                print(f"corner at x={e.x} y={e.y}", flush=True)
                if self.session.prompt:
                    print(self.session.prompt, flush=True)
        if self.session.done:
            self.exit_status = 0
        return not self.session.done


def _hint(source: Any, seen: int) -> str:
    """What to check when no corner came: nothing at all from the device, or no press."""
    if seen:
        return (f"{seen} reports came but no corner was pressed: touch each corner with the "
                "tip (or press the first puck button) and lift it again")
    if getattr(source, "heard", 0):
        return ("bytes came but none decoded as a report: check the protocol "
                "(?protocol=...) and the line speed (?baud=N)")
    return ("nothing came from the tablet: check the cable and that the tablet is switched "
            "on, the port, the protocol and the baud ('camlab88 tablet monitor SOURCE' shows "
            "every report)")


def calibrate_tablet(command: str, source_text: str, seconds: float) -> int:
    """Prompt for the two corners, read them, save the calibration; 1 on a timeout, a lost
    tablet, a closed window or corners that make no working area."""
    from camlab88.emulator.harness import RunOptions, run
    from camlab88.emulator.tablet_input.emulated_source import open_tablet
    from camlab88.protocols.tablets.calibration import CalibrationSession, save_calibration

    refuse_without_display(command, source_text)
    source, emu, spec = open_tablet(source_text, script=TAPS)
    try:
        windowed = emu is not None and emu.drive == "mouse"
        if windowed:
            emu.with_view()
        session = CalibrationSession(spec.device_key)
        print(session.prompt, flush=True)
        program = CalibrateProgram(session, source, emu, seconds)
        harness = run(program, RunOptions(headless=not windowed, command=command))
    finally:
        (emu or source).close()
    if program.exit_status:
        if harness.quit:
            print(f"{command}: the window was closed before both corners were touched",
                  file=sys.stderr)
        return program.exit_status
    try:
        cal = session.result()
        path = save_calibration(cal)
    except (ValueError, OSError) as exc:
        print(f"camlab88 tablet: {exc}", file=sys.stderr)
        return 1
    print(f"saved {spec.device_key}: top-left {cal.top_left}, bottom-right "
          f"{cal.bottom_right} -> {path}")
    return 0
