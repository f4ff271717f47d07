"""Camera benchmarks: the CCL interpreter, the visualiser on the emulated Rainbow
and the camera tool's edit-to-view time.

    .venv/bin/python benchmarks/bench_camera.py

Targets: interpreting a 1000-frame script <= 20 ms; the visualiser, compile and scan-out
included, >= 100 frames/s with a static view and >= 50 frames/s with a moving one (thesis
§6.3.2: 12 and 3); a script edit to the updated view <= 100 ms.  Each figure is the min and
median of several runs, printed with the load average (the machine may be shared).
"""

from __future__ import annotations

import os
import shutil
import statistics
import tempfile
import time
from pathlib import Path

import numpy as np

from camlab88.apps.snooker.camera import ccl, motion
from camlab88.apps.snooker.camera.motion import Motion
from camlab88.apps.snooker.camera.views import View
from camlab88.apps.snooker.camera_tool.tool import CameraTool
from camlab88.apps.snooker.visualiser.program import Visualiser
from camlab88.emulator.machine import RainbowMachine
from camlab88.protocols.rainbow.events import KeyEvent

DATA = Path(__file__).resolve().parents[1] / "tests" / "data" / "snooker_camera"
SCRIPT_1000 = """A 1000-frame script, the example of the thesis and then more of everything
:
from frame 1 until frame 33; observer at camera 1; viewpoint at (0,0,0); focal length of 50
:
camera 3 at (7.3, -4.5, 1.2);
from frame 34 until cueball strikes;
observer moving from camera 3 - (0,1,0) to camera 3;
focal length from 30 to 135;
viewpoint at pink spot
:
until pink ball stops - 10; viewpoint following pink ball
:
until pink ball stops; observer following pink ball + (0.1, -0.1, 0.05);
viewpoint at top left pocket; focal length of 28
:
coords top left pocket 39.37 39.37 39.37; camera 6 at (#-20, -10, 40)
:
until frame 300; observer moving from camera 6 to camera 2; viewpoint following cueball;
focal length from 28 to 200
:
until frame 600; observer at black ball + (0, 0, 2); viewpoint at black spot
:
until end; observer moving from camera 0 to camera 8; focal length from 200 to 35;
viewpoint following black ball
:
"""


def load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def stats(times: list[float]) -> str:
    return f"min {min(times):.2f} ms, median {statistics.median(times):.2f} ms"


def long_motion(n: int = 1000) -> Motion:
    """The pink shot, then the balls at rest until frame n."""
    m = motion.load(DATA / "pink_shot.checkpoint")
    pad = np.repeat(m.centres[-1:], n - m.n_frames, axis=0)
    on = np.repeat(m.on_table[-1:], n - m.n_frames, axis=0)
    return Motion(m.table, np.concatenate([m.centres, pad]), np.concatenate([m.on_table, on]),
                  m.strikes)


def bench_interpreter() -> None:
    m = long_motion()
    ccl.compile_script(SCRIPT_1000, m)  # warm up
    times = []
    for _ in range(30):
        t0 = time.perf_counter()
        ccl.compile_script(SCRIPT_1000, m)
        times.append((time.perf_counter() - t0) * 1e3)
    print(f"CCL, 1000-frame script, parse + interpret: {stats(times)}  (load {load()})")


def bench_visualiser(views: list[View], m: Motion, what: str, device_frames: int) -> None:
    fps, cpu = [], []
    for _ in range(3):
        rb = RainbowMachine()
        vis = Visualiser(rb.client, m, views)
        vis.draw()
        rb.client.wait_frame()  # first picture (and any compilation) outside the timing
        t0, c0 = time.perf_counter(), time.process_time()
        for i in range(1, len(views)):
            vis.index = i
            vis.draw()
            for _ in range(device_frames):
                rb.client.wait_frame()
        fps.append((len(views) - 1) / (time.perf_counter() - t0))
        cpu.append((len(views) - 1) / (time.process_time() - c0))
    print(f"visualiser, {what}, {device_frames} scan-out(s) per frame: wall min {min(fps):.0f}"
          f", median {statistics.median(fps):.0f} frames/s; by CPU time min {min(cpu):.0f}, "
          f"median {statistics.median(cpu):.0f} frames/s; table redrawn "
          f"{vis.display.table_redraws} times  (load {load()})")


def bench_edit() -> None:
    m = motion.load(DATA / "pink_shot.checkpoint")
    with tempfile.TemporaryDirectory() as tmp:
        script = Path(tmp) / "cam.ccl"
        shutil.copy(DATA / "thesis_example.ccl", script)
        rb = RainbowMachine()
        tool = CameraTool(rb.client, m, script)
        tool.step()
        tool.buf.place(4, 16)  # "focal length of 50": edit the 50
        first, both = [], []
        for k in range(20):
            rb.post(KeyEvent(0, "backspace", "", True))
            rb.post(KeyEvent(0, str(k % 10), str(k % 10), True))
            t0 = time.perf_counter()
            for e in rb.client.poll_events():
                tool.handle(e)
            tool.reinterpret()
            tool.show()
            rb.client.wait_frame()  # the updated view is on the screen now
            first.append((time.perf_counter() - t0) * 1e3)
            rb.client.wait_frame()
            both.append((time.perf_counter() - t0) * 1e3)
    print(f"camera tool, key press -> updated view on screen: {stats(first)}; "
          f"with the second scan-out of the 25 frames/s step: {stats(both)}  (load {load()})")


def main() -> None:
    bench_interpreter()
    m = motion.load(DATA / "pink_shot.checkpoint")
    r = ccl.compile_script((DATA / "thesis_example.ccl").read_text(), m)
    static = [View(v.frame, (-5.5, 0.0, 2.5), (0.0, 0.0, 0.0), 50.0) for v in r.views()]
    moving = [View(v.frame, (-5.5 + 0.02 * v.frame, -0.01 * v.frame, 2.5), (0.0, 0.0, 0.0),
                   50.0) for v in r.views()]
    for n in (1, 2):
        bench_visualiser(static, m, "static view, 75 frames of the pink shot", n)
        bench_visualiser(moving, m, "moving view (every frame)", n)
    bench_edit()


if __name__ == "__main__":
    main()
