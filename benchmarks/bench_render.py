"""Snooker renderer benchmarks: truecolour frame time, the period/fixed modes'
line time and wall time through the emulated T5688, and the palette table.

Run: .venv/bin/python benchmarks/bench_render.py [--quick]
(figures go to docs/perf/render.md by hand; the load average is printed beside them)
"""

from __future__ import annotations

import os
import statistics
import sys
import time

import numpy as np
from _bench import load, times

from camlab88.apps.snooker.render.metrics import score
from camlab88.apps.snooker.render.palette import adaptive_palette, fixed_palette
from camlab88.apps.snooker.render.sigma_host import SigmaHost
from camlab88.apps.snooker.render.sigma_session import SigmaSession
from camlab88.apps.snooker.render.truecolour import RenderOptions, render_frame, render_linear
from camlab88.emulator.harness.sigma_batch import t5688_link
from tests.snooker_render.helpers import break_scene, break_views


def timed(fn, repeat: int) -> tuple[float, float]:
    ts = times(fn, repeat)
    return min(ts), statistics.median(ts)


def bench_truecolour(repeat: int) -> None:
    scene, view = break_scene(), break_views()[0]
    assert scene.on_table[0].sum() == 22
    opts = RenderOptions(768, 512)
    render_frame(scene, view, opts)  # compile / load the kernels
    lo, med = timed(lambda: render_frame(scene, view, opts), repeat)
    print(f"truecolour 768x512, 22 balls, {len(scene.lights.positions)} lights, shadows, AA, "
          f"specks, wood: min {lo * 1e3:.1f} ms, median {med * 1e3:.1f} ms ({repeat} runs; "
          f"{load()})")


def bench_numba_pays(repeat: int) -> None:
    """The compiled kernels against numpy doing the same work (docs/development.md: numba
    only where measured to pay)."""
    from camlab88.apps.snooker.render.frame import frame_geometry
    from camlab88.apps.snooker.render.gamma import encode, encode_image
    from camlab88.apps.snooker.render.materials import BALL_PHONG
    from camlab88.apps.snooker.render.painter import BallItem
    from camlab88.apps.snooker.render.shading import lights_array, phong
    from camlab88.apps.snooker.render.truecolour import draw_ball

    scene, view = break_scene(), break_views()[0]
    lin = render_linear(scene, view)
    lo_np, _ = timed(lambda: encode(lin), repeat)
    lo_nb, _ = timed(lambda: encode_image(lin), repeat)
    print(f"gamma encode 768x512: numpy {lo_np * 1e3:.1f} ms, compiled {lo_nb * 1e3:.1f} ms "
          f"(min of {repeat}; {load()})")
    g = frame_geometry(scene, np.array(view.observer), np.array(view.viewpoint),
                       view.focal_mm, 1, 768, 512)
    balls = [i for i in g.items if isinstance(i, BallItem)]
    lights = lights_array(scene.lights)
    img = np.zeros((512, 768, 3))

    def compiled() -> None:
        for b in balls:
            draw_ball(img, scene, g, b, lights, True)

    def numpy_phong() -> None:  # the same normals and Phong terms, no specks, no coverage
        for b in balls:
            cx, cy = g.ball_xy[b.ball]
            r = g.ball_r_px[b.ball]
            ys, xs = np.mgrid[int(cy - r):int(cy + r) + 1, int(cx - r):int(cx + r) + 1]
            ux, uy = (xs + 0.5 - cx) / r, (cy - ys - 0.5) / r
            inside = ux ** 2 + uy ** 2 < 1
            uz = np.sqrt(1 - ux[inside] ** 2 - uy[inside] ** 2)
            n = (ux[inside, None] * g.pin.right + uy[inside, None] * g.pin.up
                 - uz[:, None] * g.pin.forward)
            phong(b.centre + scene.table.radius * n, n, g.pin.observer, scene.lights,
                  b.albedo, BALL_PHONG)

    lo_c, _ = timed(compiled, repeat)
    lo_n, _ = timed(numpy_phong, repeat)
    print(f"22 Phong balls: numpy (shading only) {lo_n * 1e3:.1f} ms, compiled (shading, "
          f"specks, coverage, blend) {lo_c * 1e3:.1f} ms (min of {repeat}; {load()})")


def bench_sigma(frames: list[int]) -> None:
    scene, views = break_scene(), break_views()
    pal = fixed_palette(scene)
    for mode in ("period", "fixed", "adapted"):
        session = SigmaSession(SigmaHost(scene, pal, mode), t5688_link())
        for f in frames:
            t = time.perf_counter()
            sent = session.show(views[f - 1])
            wall = time.perf_counter() - t
            kinds = ", ".join(f"{k} {v}" for k, v in sent.frame.bytes_by_kind.items())
            print(f"{mode} frame {f}: {len(sent.frame.data)} bytes = {sent.line_seconds:.1f} s "
                  f"at 9600 baud; wall {wall:.2f} s through the emulator; leaks {sent.leaks}, "
                  f"gaps {sent.gaps} ({kinds}; {load()})")


def bench_palette(step: int) -> None:
    scene = break_scene()
    views = break_views()[::step]
    opts = RenderOptions(768, 512, wood=False)  # the picture the Sigma modes draw
    frames = [render_linear(scene, v, opts) for v in views]
    t = time.perf_counter()
    adaptive = adaptive_palette(frames)
    choose = time.perf_counter() - t
    rows = [("fixed (period)", score(frames, [fixed_palette(scene)])),
            ("adaptive, one for the sequence", score(frames, [adaptive])),
            ("adaptive, chosen per frame", score(frames, [adaptive_palette([f])
                                                          for f in frames]))]
    print(f"palette over {len(frames)} frames of the break at 768x512 (k-means {choose:.1f} s; "
          f"{load()}):")
    print("| palette | mean dE (error) | flicker (mean dE, still pixels) |")
    print("|---|---|---|")
    for name, s in rows:
        print(f"| {name} | {s.error:.4f} | {s.flicker:.5f} |")
    print(f"adaptive / fixed error: {rows[1][1].error / rows[0][1].error:.2f}")


def main() -> None:
    quick = "--quick" in sys.argv
    if "--truecolour" in sys.argv:
        bench_truecolour(30)
        return
    print(f"numpy {np.__version__}; {os.cpu_count()} CPUs; {load()}")
    bench_truecolour(5 if quick else 30)
    bench_numba_pays(5 if quick else 20)
    bench_sigma([1, 20] if quick else [1, 12, 20, 40])
    bench_palette(8 if quick else 1)


if __name__ == "__main__":
    main()
