"""``camlab88 kas view SEQ``: the line test, a sequence played on the emulated Sigma."""

from __future__ import annotations

import argparse

from camlab88.commands.kas import add_background_options
from camlab88.replay_policy import KEEP
from camlab88.runopts import add_run_options, fail, run_options

COMMAND = "camlab88 kas view"

DESCRIPTION = """\
Play SEQ on an emulated Sigma T5684 over the line, double buffered in two 2-bit buffers (four \
colours). --realtime (default) keeps period-line time and drops the frames the line cannot \
carry; --every shows every frame however long it takes."""


HELP = "the line test: play a sequence on the emulated Sigma"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("seq")
    either = p.add_mutually_exclusive_group()
    either.add_argument("--realtime", dest="mode", action="store_const", const="realtime",
                        default="realtime").replay = KEEP
    either.add_argument("--every", dest="mode", action="store_const", const="every",
                        default="realtime").replay = KEEP
    p.add_argument("--baud", default=9600, type=int).replay = KEEP
    p.add_argument("--fps", type=float, help="default: the sequence's").replay = KEEP
    p.add_argument("--swap", default="lut", choices=["lut", "mask"],
                   help="buffer switch: rewrite the LUT (default) or the "
                        "display mask").replay = KEEP
    add_background_options(p)
    add_run_options(p, stop_after=False)
    p.set_defaults(mode="realtime")


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import files, library
    from camlab88.apps.kas.program.viewer import LineTest, ViewerHost
    from camlab88.emulator.harness import run
    from camlab88.emulator.harness.sigma import PeriodTarget
    from camlab88.emulator.harness.sigma_batch import host_periods
    from camlab88.emulator.machine import SigmaMachine
    from camlab88.protocols.link import LineSettings

    opts = run_options(args, COMMAND, "playing the line test to its end",
                       argv=getattr(args, "_argv", None))
    try:
        seq = files.load_sequence(library.resolve(args.seq))
        test = LineTest(seq, args.swap, args.background)
        settings = LineSettings(baud=args.baud)
        fps = args.fps or seq.fps

        def build():  # a fresh machine and the viewer's periods over it (again to load a state)
            machine = SigmaMachine("t5684", settings)
            host = ViewerHost(test, args.mode, machine.host, settings, args.fps)
            return machine, host_periods(machine, host, host.period)

        h = run(PeriodTarget(*build(), fps, f"{COMMAND} - Sigma T5684", build), opts)
    except (OSError, ValueError) as exc:
        return fail(COMMAND, exc)
    rep = h.target.result
    if rep is None:
        print("kas view: window closed")
        return 0
    print(rep.summary())
    print("shown:", " ".join(map(str, rep.shown_frames)))
    print("dropped:", " ".join(map(str, rep.dropped)) or "-")
    return 0
