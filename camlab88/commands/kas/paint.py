"""``camlab88 kas paint SEQ``: the painting program of thesis §3.3 on an emulated T5688."""

from __future__ import annotations

import argparse
import time
from dataclasses import replace
from fractions import Fraction
from pathlib import Path
from typing import Any

from camlab88.runopts import add_run_options, fail, run_options

COMMAND = "camlab88 kas paint"
KEYS = ("click: select chain / pick swatch; f fill, l colour lines, r region, t touch at the "
        "pointer, c clear; r/g/b (+shift) RGB steps; w painting, m mixing, p preview; , . "
        "frames; a auto-paint (saved at the end)")
TICK = Fraction(1, 25)
FLAT_OUT = "flat out, not at the line's speed"  # headless time is virtual: nothing paces it


def register(actions: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    p = actions.add_parser("paint", help="paint a sequence on the emulated Sigma T5688",
                           description="Paint SEQ on an emulated Sigma T5688 over a 9600-baud "
                           "line (thesis 3.3). Interactive (a window, or --headless with "
                           "--script): select chains, fill, colour, edit the palette; the "
                           "operations are recorded (--save). With --replay, or --ops with "
                           "--frames/--gif/--mp4: every frame painted from the operations "
                           "file, double-buffered in the two spare quarters, each painted "
                           "frame written as DIR/frame_NNNNN.png (from 1).")
    p.add_argument("seq", help="the sequence (.kas; library names work)")
    p.add_argument("--ops", type=Path, help="operations file to start from / replay")
    p.add_argument("--save", type=Path, help="write the operations file here at the end, "
                   "with the seed points each frame used (default: --ops when interactive)")
    p.add_argument("--script", type=Path, help="painting script (docs/kas.md)")
    p.add_argument("--replay", action="store_true", help="paint every frame and play it")
    p.add_argument("--gif", type=Path, help="the painted sequence as a GIF")
    p.add_argument("--mp4", type=Path, help="the painted sequence as an MP4")
    p.add_argument("--baud", type=int, default=9600)
    add_run_options(p)
    p.set_defaults(handler=paint)


def paint(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.paint import opsfile
    from apps.kas.paint.ops import OpsFile

    try:
        seq = files.load_sequence(library.resolve(args.seq))
        ops = opsfile.load(args.ops) if args.ops else OpsFile(painted=(len(seq) + 1) // 2)
        opsfile.check(ops, seq)
        if args.replay or (args.ops and (args.frames or args.gif or args.mp4)):
            return _replay(seq, ops, args)
        return _interactive(seq, ops, args)
    except (OSError, ValueError) as exc:
        return fail(COMMAND, exc)


class ReplayTarget:
    """One tick = one painted frame, drawn into the hidden buffer and then shown; the
    harness's time is the line's, so a window plays at the speed of the 9600-baud line."""

    fps = 1000  # every tick's picture is shown (ticks are >= 0.1 s of line time apart)
    keys = "Esc or close the window to stop"
    size = (768, 512)

    def __init__(self, program: Any, term: Any, baud: int, keep: bool) -> None:
        from apps.kas.paint.program import Line

        self.program, self.term, self.keep = program, term, keep
        self.title = f"{COMMAND} - Sigma T5688 (replay)"
        self.line = Line(term, baud)
        self.line.send(program.setup())
        self.n, self.shown, self.failures, self.chars = 0, [], [], 0
        self.plans: list = []

    def handle_events(self, events: list) -> None:
        """Replay takes no input."""

    def tick(self) -> bool:
        from apps.kas.paint.areas import BUFFERS

        if self.n >= len(self.program.seq.frames):
            return False
        self.n += 1
        buf = BUFFERS[(self.n - 1) % 2]
        data, plan = self.program.frame(self.n, buf)
        self.line.send(data + self.program.show(buf.view))
        self.chars += len(data)
        self.failures += plan.failures
        self.plans.append(plan)
        if self.keep:
            self.shown.append(self.term.frame())
        return True

    def frame(self) -> Any:
        return self.term.frame()

    def time(self) -> Fraction:
        return Fraction(self.line.clock.exact)

    def status(self) -> str:
        """The window's title bar: the frame painted, the line time, the keys."""
        return (f"frame {self.n} of {len(self.program.seq.frames)}, "
                f"line time {float(self.time()):.1f} s | {self.keys}")


def _replay(seq: Any, ops: Any, args: argparse.Namespace) -> int:
    from apps.kas.paint.program import PaintProgram
    from apps.kas.paint.replay import write_frames, write_movie
    from emulator.harness import run
    from emulator.sigma import Terminal

    opts = run_options(args, COMMAND, f"painting every frame {FLAT_OUT}; a window plays at it",
                       argv=getattr(args, "_argv", None))
    target = ReplayTarget(PaintProgram(seq, ops), Terminal("t5688"), args.baud,
                          keep=bool(args.gif or args.mp4 or args.frames))
    # --frames here means the painted frames, numbered from 1 (not every harness tick)
    started = time.monotonic()
    run(target, replace(opts, frames=None))
    wall = time.monotonic() - started
    if args.frames:
        write_frames(target.shown, args.frames)
    for movie in (args.gif, args.mp4):
        if movie is not None and target.shown:
            print(f"wrote {write_movie(target.shown, movie, seq.fps)}")
    if args.frames:
        print(f"wrote {target.n} frames to {args.frames}/frame_00001.png .. "
              f"frame_{target.n:05d}.png")
    print(f"{target.n} frames painted: {target.chars} characters, "
          f"{float(target.time()):.1f} s of line time at {args.baud} baud"
          + (f"; headless: painted in {wall:.1f} s, {FLAT_OUT}" if opts.headless else ""))
    for f in target.failures:
        print(f"  {f}")
    if args.save is not None:
        from apps.kas.paint import opsfile

        target.program.painter.record(target.plans)
        opsfile.save(args.save, ops)
        print(f"saved {args.save}: the seed points of {len(ops.frame_seeds) + 1} frame(s)")
    return 0


def _interactive(seq: Any, ops: Any, args: argparse.Namespace) -> int:
    from apps.kas.paint import opsfile, script
    from apps.kas.paint.session import PaintSession
    from emulator.harness import run
    from emulator.sigma import Terminal

    if args.headless and args.script is None:
        raise ValueError("--headless needs --script (or --replay)")
    commands = script.load(args.script) if args.script else []
    opts = run_options(args, COMMAND, "playing the --script" if commands else None,
                       "give --headless with --script FILE", getattr(args, "_argv", None))
    session = PaintSession(seq, ops)
    target = PaintTarget(session, Terminal("t5688"), args.baud, commands,
                         end=opts.headless or opts.screenshot is not None)
    run(target, opts)
    for m in target.messages:
        print(f"kas paint: {m}")
    save = args.save or args.ops
    if save is not None and opts.screenshot is None:
        opsfile.save(save, session.ops)
        print(f"saved {save}: {len(session.ops.ops)} operation(s)")
    return 0


class PaintTarget:
    """The painting session on a T5688 over the line: one tick = 1/25 s of line time; the
    next script command (or the window's input) is taken when the line has drained."""

    fps = 25
    keys = KEYS
    size = (768, 512)

    def __init__(self, session: Any, term: Any, baud: int, commands: list, end: bool) -> None:
        from protocols.link import LineSettings, SerialLine, VirtualClock

        self.session, self.term, self.commands, self.end = session, term, list(commands), end
        self.title = f"{COMMAND} - Sigma T5688"
        self.clock = VirtualClock()
        self.line = SerialLine(LineSettings(baud=baud), self.clock, xonxoff=False)
        self.messages: list[str] = []
        self.pointer = (0, 0)
        self._send(session.start())

    def _send(self, data: bytes) -> None:
        if data:
            self.line.host.write(data)

    def _busy(self) -> bool:
        return self.line.host.drain_time_exact() > self.clock.exact

    def handle_events(self, events: list) -> None:
        from emulator.host_input import KeyDown, PointerButton, PointerMove

        for ev in events:
            if isinstance(ev, (PointerMove, PointerButton)):
                self.pointer = (ev.x, 511 - ev.y)
            if isinstance(ev, PointerButton) and ev.pressed and ev.button == 1:
                self._do(self._click)
            elif isinstance(ev, KeyDown):
                self._do(lambda k=ev: self._key(k.key, "shift" in k.mods))

    def _do(self, fn: Any) -> None:
        try:
            self._send(fn())
        except ValueError as exc:
            self.session.message = str(exc)
        if self.session.message:
            self.messages.append(self.session.message)
            self.session.message = ""

    def _click(self) -> bytes:
        s = self.session
        k = s.swatch_at(*self.pointer)
        if k is not None:
            return s.pick(k)
        at = s.area_point(*self.pointer)
        return s.select_near(*at) if at else b""

    def _key(self, key: str, shift: bool) -> bytes:
        s = self.session
        at = s.area_point(*self.pointer)
        guns = {"r": "red", "g": "green", "b": "blue"}
        acts = {"f": s.fill, "l": s.colour_lines, "c": s.clear,
                "w": lambda: s.show("painting"), "m": lambda: s.show("mixing"),
                "p": lambda: s.show("preview"), "a": lambda: self._auto(),
                ",": lambda: s.goto(max(s.n - 1, 1)),
                ".": lambda: s.goto(min(s.n + 1, len(s.seq.frames)))}
        if key in guns and s.view != 1:
            return s.rgb(guns[key], -8 if shift else 8)
        if key in ("r", "t") and at:
            return s.region(*at) if key == "r" else s.touch(*at)
        return acts[key]() if key in acts else b""

    def _auto(self) -> bytes:
        fails = self.session.autopaint()
        self.session.message = f"auto-paint: {len(fails)} operation(s) could not apply"
        self.messages += [str(f) for f in fails]
        return b""

    def tick(self) -> bool:
        from apps.kas.paint import script

        if not self._busy() and self.commands:
            cmd = self.commands.pop(0)
            self._do(lambda: script.run(self.session, cmd))
        self.clock.advance(TICK)
        self.term.feed(self.line.device.read())
        return not (self.end and not self.commands and not self._busy())

    def frame(self) -> Any:
        return self.term.frame()

    def time(self) -> Fraction:
        return self.clock.exact

    def status(self) -> str:
        """The window's title bar: the frame painted on, the line time, the keys."""
        s = self.session
        return (f"frame {s.n} of {len(s.seq.frames)}, line time {float(self.time()):.1f} s"
                f" | {self.keys}")

