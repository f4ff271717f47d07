"""``tablet emulate``: an emulated tablet on a pty for an outside program, driven by the
window's mouse or a scripted stroke, as a program on the harness."""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

from camlab88.emulator.tablet_input.program import TabletProgram

DEMO_FRAMES = 300  # a scripted stroke keeps the pty open this long (a client reads it all)
SHOT_FRAMES = {True: 270, False: 30}  # --screenshot after so many frames (demo, mouse)


class EmulateProgram(TabletProgram):
    """The view decodes the bytes as they are sent (the pty is the outside program's)."""

    def __init__(self, emu: Any, demo: bool, seconds: float | None,
                 clock: Callable[[], float] = time.monotonic) -> None:
        super().__init__(emu, "the mouse is the pen; close it to quit")
        self.demo, self.seconds, self.clock = demo, seconds, clock
        self.start = clock()

    def step(self) -> bool:
        emu = self.emu
        if not (emu.step() or (self.demo and emu.frames < DEMO_FRAMES)):
            return False
        if self.seconds is not None and self.clock() - self.start >= self.seconds:
            return False
        emu.show(emu.take_local())
        return True


def emulate_tablet(command: str, protocol: str, demo: bool, seconds: float | None,
                   screenshot: str | None) -> int:
    """Open the emulated tablet, print its pty, run it until the stroke ends, the window
    closes or ``seconds`` pass (wall clock, paced: a client on the pty reads in real time)."""
    from pathlib import Path

    from camlab88.emulator.harness import RunOptions, choose_headless, run
    from camlab88.emulator.tablet import demo_path
    from camlab88.emulator.tablet_input.emulated_source import EmulatedSource
    from camlab88.protocols.tablets.sources import parse_source

    can = "the scripted stroke, no window" if demo and not screenshot else None
    headless = choose_headless(command, False, can, "it is driven by the mouse; try --demo")
    spec = parse_source(f"emulated:{protocol}" + ("?drive=demo" if demo else ""))
    emu = EmulatedSource(spec, script=demo_path() if demo else None, reader=False)
    try:
        if not headless:
            emu.with_view()
        print(f"serial port: {emu.tablet.slave_path}  (open it with pyserial; "
              f"{emu.tablet.line.describe()})", flush=True)
        program = EmulateProgram(emu, demo, seconds)
        shot = screenshot is not None and not headless
        run(program, RunOptions(headless=headless, live=True, command=command,
                                screenshot=Path(screenshot) if shot else None,
                                stop_after=SHOT_FRAMES[demo] if shot else None))
    finally:
        emu.close()
    return program.exit_status
