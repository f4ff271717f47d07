"""``camlab88 kas paint SEQ``: the painting program of thesis §3.3 on an emulated T5688."""

from __future__ import annotations

import argparse
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

from camlab88.replay_policy import KEEP, SCRATCH
from camlab88.runopts import add_run_options, fail, run_options, unattended

COMMAND = "camlab88 kas paint"
FLAT_OUT = "flat out, not at the line's speed"  # headless time is virtual: nothing paces it

DESCRIPTION = """\
Paint SEQ on an emulated Sigma T5688 over a 9600-baud line (thesis 3.3). Interactive (a \
window, or --headless with --script): select chains, fill, colour, edit the palette; the \
operations are recorded (--save). With --replay, or --ops with --frames/--gif/--mp4: every \
frame painted from the operations file, double-buffered in the two spare quarters, each \
painted frame written as DIR/frame_NNNNN.png (from 1)."""


HELP = "paint a sequence on the emulated Sigma T5688"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("seq", help="the sequence (.kas; library names work)")
    p.add_argument("--ops", type=Path, help="operations file to start from / replay").replay = KEEP
    p.add_argument("--save", type=Path,
                   help="write the operations file here at the end, with the seed points "
                        "each frame used (default: --ops when interactive)").replay = SCRATCH
    p.add_argument("--script", type=Path, help="painting script (docs/kas.md)").replay = KEEP
    p.add_argument("--replay", action="store_true",
                   help="paint every frame and play it").replay = KEEP
    p.add_argument("--gif", type=Path, help="the painted sequence as a GIF").replay = SCRATCH
    p.add_argument("--mp4", type=Path, help="the painted sequence as an MP4").replay = SCRATCH
    p.add_argument("--baud", default=9600, type=int).replay = KEEP
    add_run_options(p)


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import files, library
    from camlab88.apps.kas.paint import opsfile
    from camlab88.apps.kas.paint.ops import OpsFile

    try:
        seq = files.load_sequence(library.resolve(args.seq))
        ops = opsfile.load(args.ops) if args.ops else OpsFile(painted=(len(seq) + 1) // 2)
        opsfile.check(ops, seq)
        if args.replay or (args.ops and (args.frames or args.gif or args.mp4)):
            return _replay(seq, ops, args)
        return _interactive(seq, ops, args)
    except (OSError, ValueError) as exc:
        return fail(COMMAND, exc)


def _machine(baud: int):
    """The T5688 on its line (no XON/XOFF: the painting orders are binary)."""
    from camlab88.emulator.machine import SigmaMachine
    from camlab88.protocols.link import LineSettings

    return SigmaMachine("t5688", LineSettings(baud=baud), xonxoff=False)


def _replay(seq: Any, ops: Any, args: argparse.Namespace) -> int:
    from camlab88.apps.kas.paint.host import ReplayFrames
    from camlab88.apps.kas.paint.program import PaintProgram
    from camlab88.emulator.harness import run
    from camlab88.emulator.harness.sigma_host import SigmaHostTarget

    opts = run_options(args, COMMAND, f"painting every frame {FLAT_OUT}; a window plays at it",
                       argv=getattr(args, "_argv", None))
    machine, shown = _machine(args.baud), []
    replay = ReplayFrames(PaintProgram(seq, ops), machine.host)
    # one tick = one painted frame: every tick's picture is shown (fps 1000; ticks are
    # >= 0.1 s of line time apart)
    target = SigmaHostTarget(machine, replay, f"{COMMAND} - Sigma T5688 (replay)",
                             "Esc or close the window to stop", dt=None, fps=1000,
                             on_tick=shown.append if (args.gif or args.mp4 or args.frames)
                             else None)
    # --frames here means the painted frames, numbered from 1 (not every harness tick)
    started = time.monotonic()
    run(target, replace(opts, frames=None))
    _replay_report(args, seq, ops, replay.host, shown, float(target.time()),
                   time.monotonic() - started if opts.headless else None)
    return 0


def _replay_report(args: argparse.Namespace, seq: Any, ops: Any, host: Any, shown: list,
                   line_time: float, wall: float | None) -> None:
    from camlab88.apps.kas.paint.replay import write_frames, write_movie

    if args.frames:
        write_frames(shown, args.frames)
    for movie in (args.gif, args.mp4):
        if movie is not None and shown:
            print(f"wrote {write_movie(shown, movie, seq.fps)}")
    if args.frames:
        print(f"wrote {host.shown} frames to {args.frames}/frame_00001.png .. "
              f"frame_{host.shown:05d}.png")
    print(f"{host.shown} frames painted: {host.chars} characters, "
          f"{line_time:.1f} s of line time at {args.baud} baud"
          + (f"; headless: painted in {wall:.1f} s, {FLAT_OUT}" if wall is not None else ""))
    for f in host.failures:
        print(f"  {f}")
    if args.save is not None:
        from camlab88.apps.kas.paint import opsfile

        host.program.painter.record(host.plans)
        opsfile.save(args.save, ops)
        print(f"saved {args.save}: the seed points of {len(ops.frame_seeds) + 1} frame(s)")


def _interactive(seq: Any, ops: Any, args: argparse.Namespace) -> int:
    from camlab88.apps.kas.paint import opsfile, script
    from camlab88.apps.kas.paint.host import KEYS, PaintHost
    from camlab88.apps.kas.paint.session import PaintSession
    from camlab88.emulator.harness import run
    from camlab88.emulator.harness.sigma_host import SigmaHostTarget

    if args.headless and args.script is None:
        raise ValueError("--headless needs --script (or --replay)")
    commands = script.load(args.script) if args.script else []
    opts = run_options(args, COMMAND, "playing the --script" if commands else None,
                       "give --headless with --script FILE", getattr(args, "_argv", None))
    session = PaintSession(seq, ops)
    machine = _machine(args.baud)
    host = PaintHost(session, machine.host, commands,
                     end=unattended(opts))
    # one tick = 1/25 s of line time
    run(SigmaHostTarget(machine, host, f"{COMMAND} - Sigma T5688", KEYS), opts)
    for m in host.messages:
        print(f"kas paint: {m}")
    save = args.save or args.ops
    if save is not None and opts.screenshot is None:
        opsfile.save(save, session.ops)
        print(f"saved {save}: {len(session.ops.ops)} operation(s)")
    return 0
