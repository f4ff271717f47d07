"""``camlab88 demo``: the main job — the emulated devices running the thesis's programs.

The demo is a list of *acts*, each a device showing a program at 25 frames a second of
device time:

1. ``sigma`` — a Sigma T5684 session over a 9600-baud line: a byte stream built with
   protocols.sigma.Encoder the way a host program would send it (abbreviated-mode vectors,
   dash masks, graphics text, firmware ellipses and flood fill, solid blocks, then LUT
   animation and the thesis's double buffering, §3.1.4).
2. ``kas`` — KAS on the T5684: the keyframe editor drawing a stroke, then "a line taking a
   walk" in-betweened, superimposed and played by the line-test viewer (real time, frames
   dropped as 9600 baud forces; then every frame).

3. ``snooker`` — the snooker motion-development program on the Rainbow: a break simulated
   and replayed at 25 frames a second.
4. ``ca`` — the programmable cellular automaton on the Rainbow: Life's Gosper gun in auto
   mode, panned with the four-times-mapped super pad and zoomed, by scripted mouse events.

 With a display a window shows each
act as it arrives; without one (or with --headless) the frames go to PNGs and one animated GIF
per act.
"""

from __future__ import annotations

import argparse
import math
import os
import sys
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Any

FPS = 25
GIF_EVERY = 3  # every 3rd frame in the GIF (8.3 fps) keeps it small


def register(subparsers: argparse._SubParsersAction) -> None:
    p = subparsers.add_parser("demo", help="play the demo session",
                              description="Play a Sigma T5684 demo session on the emulated "
                              "terminal over a 9600-baud line (virtual time). With a display it "
                              "opens a window; with no DISPLAY, or --headless, it writes the "
                              "frames as PNGs and an animated GIF.")
    p.add_argument("--headless", action="store_true", help="no window, write files")
    p.add_argument("--out", type=Path, default=Path("camlab88-demo"),
                   help="output directory when headless (default ./camlab88-demo)")
    p.add_argument("--scale", type=int, default=1, help="window scale")
    p.add_argument("--screenshot", type=Path, help="save the window at the end and exit")
    p.add_argument("--fast", action="store_true", help="do not pace to the wall clock")
    p.add_argument("--only", action="append", choices=[a.name for a in ACTS], metavar="ACT",
                   help="play only this act (repeatable): " + ", ".join(a.name for a in ACTS))
    p.set_defaults(handler=demo_command)


# ---------------------------------------------------------------------- the session
def sigma_demo_stream() -> bytes:
    """The whole session: the still picture, then LUT animation and double buffering."""
    return sigma_picture_stream() + _sigma_animation_stream()


def sigma_picture_stream() -> bytes:
    """The still part: vectors, dash masks, text, ellipses, flood fill, solid blocks."""
    from protocols.sigma import Encoder

    e = Encoder()
    out = bytearray()
    put = out.extend
    # power-on banner on the alpha screen, then into graphics like the RAL GKS driver does
    put(b"\r" + e.flag() + e.reset() + e.flag_anywhere() + e.sequence_length(0))
    put(e.graphics_on() + e.alpha_on() + e.alpha_mode())
    put(b"camlab88: Sigma T5684 on a 9600 baud line\r\n")
    put(b"\r" + e.flag() + e.cursor_off())
    for i, rgb in enumerate(((0, 0, 0), (15, 15, 15), (15, 3, 3), (3, 15, 3), (4, 6, 15),
                             (15, 15, 2), (15, 4, 15), (3, 15, 15))):
        put(e.lut(i, *rgb))

    # 1. a star of vectors in abbreviated mode
    cx, cy = 200, 330
    put(e.colour(7))
    for k in range(24):
        a = 2 * math.pi * k / 24
        put(e.abbreviated_polyline([(cx, cy), (cx + int(150 * math.cos(a)),
                                               cy + int(150 * math.sin(a)))]))
    put(e.colour(1) + e.move(40, 462) + e.text("VECTORS (ABBREVIATED MODE)"))

    # 2. dash masks, continuing across vectors
    y = 300
    for colour, mask in ((2, 0xF0F0), (3, 0x8888), (5, 0xFE10), (6, 0xF888)):
        put(e.colour(colour) + e.dash(mask))
        put(e.abbreviated_polyline([(400, y), (500, y + 40), (600, y), (720, y + 40)]))
        y += 35
    put(e.line_reset() + e.line_solid())
    put(e.colour(1) + e.move(400, 462) + e.text("DL DASH MASKS"))

    # 3. firmware ellipses
    for k, (x, r, ratio, solid) in enumerate(((460, 40, 1.0, False), (560, 45, 1.8, True),
                                              (670, 35, 0.6, False))):
        put(e.colour(2 + k) + e.move(x, 200) + e.ellipse(r, ratio, solid))
    put(e.colour(1) + e.move(430, 130) + e.text("JO/JM/JN ELLIPSES"))

    # 4. polygon outline + firmware flood fill from a seed
    pts = [(60, 40), (330, 60), (260, 150), (170, 110), (90, 170), (60, 40)]
    put(e.colour(5) + e.polyline(pts))
    put(e.colour(4) + e.move(120, 80) + e.fill(5))
    put(e.colour(1) + e.move(40, 15) + e.text("JK FLOOD FILL"))

    # 5. solid blocks: a colour bar
    for k in range(8):
        put(e.colour(k) + e.move(420 + 40 * k, 20) + e.block(450 + 40 * k, 60))

    return bytes(out)


def _sigma_animation_stream() -> bytes:
    from protocols.sigma import Encoder

    e = Encoder()
    out = bytearray()
    put = out.extend
    # 6. LUT animation: concentric rings in entries 8..15, cycled by JG only
    for k in range(8):
        put(e.colour(8 + k) + e.move(200, 330) + e.ellipse(60 - 7 * k, 1.0, True))
    ramp = [(15, 2 * k, 0) for k in range(8)]
    for step in range(32):
        for k in range(8):
            put(e.lut(8 + k, *ramp[(k + step) % 8]))
    put(e.alpha_mode() + b"LUT animation done; now double buffering (thesis 3.1.4)\r\n")
    put(b"\r" + e.flag())

    # 7. double buffering: planes 0-1 = buffer A, planes 2-3 = buffer B
    put(e.erase())
    lut_show_a = [(0, 0, 0), (15, 15, 15), (15, 8, 0), (0, 10, 15)]
    for idx in range(16):  # show buffer A (empty) while B is drawn
        put(e.lut(idx, *lut_show_a[idx & 3]))
    for frame in range(24):
        draw_b = frame % 2 == 0  # draw into the hidden buffer
        shift = 2 if draw_b else 0
        put(e.write_mask(0b11 << shift) + e.erase())
        put(e.colour(1 << shift))
        a = 2 * math.pi * frame / 24
        square = [(384 + int(120 * math.cos(a + q * math.pi / 2)),
                   256 + int(120 * math.sin(a + q * math.pi / 2))) for q in range(5)]
        put(e.abbreviated_polyline(square))
        put(e.colour(2 << shift) + e.move(384, 256) + e.ellipse(20 + 2 * frame, 1.0, True))
        # swap: make the LUT show the buffer just drawn (index bits of that buffer only)
        for idx in range(16):
            v = (idx >> shift) & 3
            put(e.lut(idx, *lut_show_a[v]))
    put(e.write_mask(15) + e.alpha_mode() + b"end of demo\r\n")
    return bytes(out)


# ---------------------------------------------------------------------- the acts
@dataclass(frozen=True)
class Act:
    name: str
    title: str
    size: tuple[int, int]                 # device pixels (w, h)
    frames: Callable[[], Iterator[Any]]   # yields (h, w, 3) uint8 frames at 25 per second


def sigma_frames() -> Iterator[Any]:
    """The Sigma showcase: the screen after each 1/25 s of line time at 9600 baud."""
    from emulator.sigma import Terminal
    from protocols.link import LineSettings, chunks_by_period

    term = Terminal("t5684")
    for _k, chunk in chunks_by_period(sigma_demo_stream(), LineSettings(baud=9600),
                                      Fraction(1, FPS)):
        term.feed(chunk)
        yield term.frame()


def kas_frames() -> Iterator[Any]:
    """KAS on the T5684: the host's chunks written to a 9600-baud line at their times."""
    from apps.kas.front import demo_session
    from emulator.sigma import Terminal

    term = Terminal("t5684")
    session = demo_session()
    for _k, data in session.arrivals(Fraction(1, FPS)):
        term.feed(data)
        yield term.frame()


def ca_frames() -> Iterator[Any]:
    """The cellular automaton on the Rainbow: the Gosper gun in auto mode, panned and zoomed,
    driven by the program's own scripted mouse events."""
    from apps.ca.program import script_events
    from apps.ca.program.demo import demo_events
    from apps.ca.program.program import CAProgram, Options
    from emulator.rainbow.session import in_process

    session = in_process()
    program = CAProgram(session.client, Options(rules="life", pattern="gosper_gun"))
    frames: list[Any] = []

    def frame() -> None:
        program.frame()
        frames.append(session.executor.last_frame.copy())

    steps = script_events.parse(demo_events(60), "<ca demo>")
    script_events.play(steps, session.inject, frame, lambda: program.finished)
    yield from frames


def snooker_frames() -> Iterator[Any]:
    """The snooker program's replay on the Rainbow: a break simulated and shown at 25
    frames a second (ball pads double-buffered over the table pad by LUT transparency)."""
    from camlab88.commands.snooker import rainbow_demo

    frames: list[Any] = []
    rainbow_demo(on_frame=lambda f: frames.append(f.copy()), seconds=4.0)
    yield from frames


ACTS: tuple[Act, ...] = (
    Act("sigma", "Sigma T5684 on a 9600-baud line", (768, 512), sigma_frames),
    Act("kas", "KAS keyframe editor and line test on the T5684", (768, 512), kas_frames),
    Act("snooker", "snooker motion development on the Rainbow", (768, 576), snooker_frames),
    Act("ca", "the programmable cellular automaton on the Rainbow", (768, 576), ca_frames),
)


# ---------------------------------------------------------------------- playing it
def demo_command(args: argparse.Namespace) -> int:
    acts = [a for a in ACTS if not args.only or a.name in args.only]
    headless = args.headless or not os.environ.get("DISPLAY")
    if headless:
        return _headless(acts, args.out)
    return _windowed(acts, args)


def _headless(acts: list[Act], out: Path) -> int:
    from camlab88.commands.sigma import write_png_atomic

    out.mkdir(parents=True, exist_ok=True)
    for act in acts:
        frames = []
        for k, f in enumerate(act.frames()):
            write_png_atomic(f, out / f"{act.name}_{k:04d}.png")
            if k % GIF_EVERY == 0:
                frames.append(f)
            last = f
        frames.append(last)
        gif = out / f"{act.name}_demo.gif"
        _write_gif(frames, gif)
        n = k + 1
        print(f"camlab88 demo: {act.title}: {n} frames "
              f"written to {out}/{act.name}_*.png and {gif}")
    return 0

def _write_gif(frames: list, path: Path) -> None:
    from PIL import Image

    from protocols.atomicfile import atomic_output

    images = [Image.fromarray(f).convert("P", palette=Image.Palette.ADAPTIVE, colors=64)
              for f in frames]
    with atomic_output(path) as fh:
        images[0].save(fh, format="GIF", save_all=True, append_images=images[1:],
                       duration=int(1000 * GIF_EVERY / FPS), loop=0)


def _windowed(acts: list[Act], args: argparse.Namespace) -> int:
    from emulator.host_input import KeyDown, Quit
    from emulator.window import Window

    frame = None
    win = None
    try:
        for act in acts:
            if win is not None:
                win.close()
            win = Window(f"camlab88 demo - {act.title}", act.size, scale=args.scale)
            for frame in act.frames():
                win.show(frame)
                for ev in win.poll():
                    if isinstance(ev, Quit):
                        return 0
                    if isinstance(ev, KeyDown) and ev.key == "escape":
                        return 0
                    if isinstance(ev, KeyDown) and ev.key == "space":
                        break  # on to the next act
                else:
                    if not args.fast and args.screenshot is None:
                        win.wait_frame(FPS)
                    continue
                break
        if win is None:
            return 0
        if args.screenshot is not None:
            win.screenshot(args.screenshot)
            print(f"camlab88 demo: screenshot {args.screenshot}")
            return 0
        print("camlab88 demo: finished; close the window or press a key", file=sys.stderr)
        while True:
            for ev in win.poll():
                if isinstance(ev, Quit) or isinstance(ev, KeyDown):
                    return 0
            win.wait_frame(10)
    finally:
        if win is not None:
            win.close()
