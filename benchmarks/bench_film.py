"""Film benchmarks: a 250-frame truecolour sequence at 768x512 rendered in one
process, on the local pool (one process per core) and on a LocalCluster of two workers;
the speed-up, and the per-frame costs a reader needs to extrapolate to N machines.

Run: .venv/bin/python benchmarks/bench_film.py [--quick] [--repeat N]
(figures go to docs/perf/film.md by hand; the load average is printed beside each)
"""

from __future__ import annotations

import os
import shutil
import statistics
import sys
import tempfile
import time
from pathlib import Path

from _bench import load

from camlab88.apps.snooker.camera.views import View
from camlab88.apps.snooker.film.backends import DaskCluster, InProcess, LocalPool
from camlab88.apps.snooker.film.schedule import render_film
from camlab88.apps.snooker.film.task import FrameTask, render_png, scene_digest
from camlab88.apps.snooker.render.scene import Scene
from camlab88.base.atomicfile import write_atomic


def long_break(frames: int) -> Scene:
    """The opening break simulated for ``frames`` frames by the motion program's model."""
    import math

    from camlab88.apps.snooker.session import Session
    from camlab88.apps.snooker.table import CUE

    s = Session.new_game()
    red, cue = s.balls.pos[7], s.balls.pos[CUE]
    s.strike(CUE, 6.0, math.degrees(math.atan2(red[1] - cue[1], red[0] - cue[0])))
    for _ in range(frames - 1):
        s.simulate_frame()
    import numpy as np

    shot = Scene.from_checkpoint(s.checkpoint(0, min(frames, s.frame_number + 1) - 1))
    pad = frames - shot.n_frames  # the balls came to rest: the last frame held
    return Scene(shot.table, np.concatenate([shot.centres] + [shot.centres[-1:]] * pad),
                 np.concatenate([shot.on_table] + [shot.on_table[-1:]] * pad), shot.lights)


def tasks_for(scene: Scene, size: tuple[int, int]) -> list[FrameTask]:
    """A camera behind baulk tracking slowly down the table."""
    n = scene.n_frames
    return [FrameTask(f, View(f, (-2.6, 0.6 - 0.4 * f / n, 1.0), (-0.6 + f / n, 0.0, 0.0),
                              32.0), size[0], size[1]) for f in range(1, n + 1)]


def run(backend, scene: Scene, tasks: list[FrameTask]) -> float:
    out = Path(tempfile.mkdtemp(prefix="bench-film-"))
    try:
        t = time.perf_counter()
        render_film(tasks, out, backend, scene_digest(scene))
        return time.perf_counter() - t
    finally:
        shutil.rmtree(out, ignore_errors=True)


def figures(name: str, times: list[float], frames: int, base: float | None) -> float:
    lo, med = min(times), statistics.median(times)
    speed = f", speed-up {base / lo:.2f}x (min/min)" if base else ""
    print(f"{name:34s} min {lo:6.2f} s  median {med:6.2f} s  {frames / lo:5.1f} frames/s"
          f"{speed}   [{load()}]", flush=True)
    return lo


def main_process_cost(scene: Scene, task: FrameTask, repeat: int = 20) -> None:
    """What the scheduling process does per frame whatever the cluster: check the PNG
    decodes at its size, write it atomically (fsync) — the ceiling on frames/s."""
    from camlab88.apps.snooker.film.pngcheck import png_size

    data = render_png(scene, task)
    out = Path(tempfile.mkdtemp(prefix="bench-film-"))
    t = time.perf_counter()
    for _ in range(repeat):
        png_size(data)
    check = (time.perf_counter() - t) / repeat
    t = time.perf_counter()
    for k in range(repeat):
        write_atomic(out / f"frame_{k:05d}.png", data)
    write = (time.perf_counter() - t) / repeat
    shutil.rmtree(out, ignore_errors=True)
    per = check + write
    print(f"per frame in the scheduling process ({len(data)} B PNG): decode check "
          f"{check * 1000:.1f} ms + atomic write {write * 1000:.1f} ms -> at most "
          f"{1 / per:.0f} frames/s   [{load()}]")


def round_trip(backend, scene: Scene, repeat: int = 60) -> None:
    """A tiny (8x8) frame's wall time per frame through the backend: its fixed overhead."""
    tiny = [FrameTask(1 + k % scene.n_frames, t.view, 8, 8)
            for k, t in enumerate(tasks_for(scene, (8, 8))[:repeat])]
    tiny = [FrameTask(k + 1, t.view, 8, 8) for k, t in enumerate(tiny)]
    wall = run(backend, scene, tiny)
    print(f"{backend.name}: 8x8 frames, {wall / len(tiny) * 1000:.1f} ms a frame of wall "
          f"time over {backend.workers} workers   [{load()}]")


def main() -> None:
    quick = "--quick" in sys.argv
    repeat = int(sys.argv[sys.argv.index("--repeat") + 1]) if "--repeat" in sys.argv else 3
    frames = 60 if quick else 250
    scene = long_break(frames)
    tasks = tasks_for(scene, (768, 512))
    print(f"{frames} truecolour frames at 768x512, 22 balls, 4 lights; cpus {os.cpu_count()}")
    one = InProcess(scene)
    render_png(scene, tasks[0])  # compile / load the kernels outside the timing
    base = figures("one process", [run(one, scene, tasks) for _ in range(repeat)], frames,
                   None)
    main_process_cost(scene, tasks[0])
    for make in (lambda: LocalPool(scene, 2), lambda: DaskCluster(scene, "local", 2)):
        b = make()
        try:
            run(b, scene, tasks[:4])  # warm the workers (imports, numba cache)
            figures(b.name, [run(b, scene, tasks) for _ in range(repeat)], frames, base)
            round_trip(b, scene)
        finally:
            b.close()
    round_trip(one, scene)


if __name__ == "__main__":
    main()
