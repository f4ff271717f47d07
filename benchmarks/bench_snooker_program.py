"""Display-loop speed of the snooker program on the emulated Rainbow (target >= 50
frames/s; the thesis's program managed 12).

Each figure is display frames per wall-clock second through the whole path: program logic,
the pad-library calls over the in-process command stream, band-structure compile and the
video processor's scan-out of 768 x 576 through the LUT. Run: python
benchmarks/bench_snooker_program.py
"""

from __future__ import annotations

import platform
import statistics
import time

from camlab88.apps.snooker.layout import break_off_direction
from camlab88.apps.snooker.program.demo import break_session
from camlab88.apps.snooker.program.program import Program
from camlab88.apps.snooker.table import CUE
from camlab88.emulator.machine import RainbowMachine
from camlab88.protocols.rainbow.events import MouseEvent

REPEATS = 5


def _fps(setup, frames: int) -> float:
    rates = []
    for _ in range(REPEATS):
        run = setup()
        t = time.perf_counter()
        run(frames)
        rates.append(frames / (time.perf_counter() - t))
    return statistics.median(rates)


def simulating_break():
    """The break simulated live: a time frame every second display frame, balls redrawn."""
    rb = RainbowMachine()
    p = Program(rb.client)
    ux, uy = break_off_direction(p.session.table, p.session.balls)
    p.session.set_velocity(CUE, 7 * ux, 7 * uy)
    p.right_button()
    p.step()
    return lambda n: [p.step() for _ in range(n)]


def stepping_frames():
    """Alter a different frame: a new frame every display frame, velocity arrows drawn."""
    rb = RainbowMachine()
    p = Program(rb.client, break_session(7.0))
    p.session.goto_time_frame(0)
    p.mode = "alter"

    def run(n: int) -> None:
        for _ in range(n):
            p.session.step(1, "frame")
            p.step()
    return run


def replaying():
    """Replay: every time frame shown for two display frames."""
    rb = RainbowMachine()
    s = break_session(7.0)
    p = Program(rb.client, s)
    frames = s.timeline.time_frames

    def run(n: int) -> None:
        k = (n + 1) // 2
        sel = [frames[i % len(frames)] for i in range(k)]
        p.play_positions([f.balls.pos for f in sel], [f.balls.on_table for f in sel])
    return run


def cursor_moving():
    """Idle, the mouse moving every frame over the table (cursor pad moves, selection)."""
    rb = RainbowMachine()
    p = Program(rb.client)

    def run(n: int) -> None:
        for i in range(n):
            rb.post(MouseEvent(0, 100 + (i * 7) % 560, 150 + (i * 3) % 300, 0))
            p.step()
    return run


def main() -> None:
    simulating_break()(50)  # warm the numba kernels and the compiler
    print(f"python {platform.python_version()}, {platform.machine()}")
    print("| display loop | frames/s |")
    print("|---|---|")
    for name, setup, n in (("break simulated live (25 time frames/s)", simulating_break, 300),
                           ("alter a different frame: stepping, arrows on", stepping_frames,
                            200),
                           ("replay at 25 frames/s (virtual time)", replaying, 300),
                           ("idle, cursor moving", cursor_moving, 300)):
        print(f"| {name} | {_fps(setup, n):.0f} |")


if __name__ == "__main__":
    main()
