"""``camlab88 kas view SEQ``: the line test, a sequence played on the emulated Sigma."""

from __future__ import annotations

import argparse

from camlab88.runopts import fail, run_options

COMMAND = "camlab88 kas view"


def view(args: argparse.Namespace) -> int:
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
