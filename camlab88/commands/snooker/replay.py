"""``camlab88 snooker replay CHECKPOINT``: a checkpoint file played on the Rainbow."""

from __future__ import annotations

import argparse

from camlab88.replay_policy import KEEP
from camlab88.runopts import add_run_options, fail, run_options

COMMAND = "camlab88 snooker replay"
OUTPUT_HINT = "give --frames DIR or --screenshot PNG to write what it plays"

DESCRIPTION = """\
Play a §6.2.2 checkpoint file on the emulated Rainbow at 25 frames/s (real time in a window, \
virtual time headless)."""


HELP = "play a checkpoint file on the Rainbow at 25 fps"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("checkpoint", metavar="CHECKPOINT")
    p.add_argument("--first", default=0, type=int, help="first frame (default 0)").replay = KEEP
    p.add_argument("--last", type=int, help="last frame (default: the last)").replay = KEEP
    add_run_options(p)


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.snooker.checkpoint import CheckpointError, read, to_metres
    from camlab88.apps.snooker.table import Table

    try:
        cp = read(args.checkpoint)
        last = cp.n_frames - 1 if args.last is None else args.last
        cp = cp.subset(args.first, last)
    except (CheckpointError, ValueError) as exc:
        return fail(COMMAND, exc)
    writes = args.frames or args.screenshot or args.record
    opts = run_options(args, COMMAND, "playing the checkpoint to its end" if writes else None,
                       f"{OUTPUT_HINT} (or --headless to only count the frames)",
                       argv=getattr(args, "_argv", None))
    table = Table()
    pos = [to_metres(p) for p in cp.positions]
    on = [[table.on_playing_area(x, y) for x, y in p] for p in pos]
    h = _run(pos, on, opts)
    print(f"{COMMAND}: {min(h.ticks, len(pos))} frames at 25 frames/s "
          f"({h.target.machine.frame_count} display frames, {len(pos) / 25:.2f} s)")
    if opts.headless and not writes:  # headless play leaves nothing to see: say how
        print(f"{COMMAND}: headless, so nothing was shown or written; {OUTPUT_HINT}")
    return 0


def _run(pos, on, opts):
    from camlab88.apps.snooker.program.program import PositionReplay, Program
    from camlab88.emulator.harness import run
    from camlab88.emulator.harness.rainbow import RainbowTarget
    from camlab88.emulator.machine import RainbowMachine

    rb = RainbowMachine(record=opts.record is not None)
    replay = PositionReplay(Program(rb.client), pos, on)
    target = RainbowTarget(rb, replay.step, "camlab88 snooker replay",
                           "Esc or close the window to quit", program=replay)
    return run(target, opts)
