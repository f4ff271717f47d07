"""``camlab88 rainbow run``: the Rainbow demo of pads and transparency, on the harness."""

from __future__ import annotations

import argparse

from camlab88.commands.rainbow import add_relic_memory_options
from camlab88.rainbow_tablet import add_tablet_option, feed_tablet, open_tablet
from camlab88.replay_policy import DROP, KEEP
from camlab88.runopts import add_run_options, positive, run_options
from camlab88.traceopts import add_trace_options, open_trace

COMMAND = "camlab88 rainbow run"
KEYS = "middle button: the demo's menu; Esc or close the window to quit"
HEADLESS_FRAMES = 250

DESCRIPTION = """\
Run the Rainbow with the Appendix I transparency example and moving double-buffered pads \
(headless: 250 frames unless --stop-after N)."""


HELP = "open the window with a demo of pads and transparency"


def add_arguments(p: argparse.ArgumentParser) -> None:
    add_run_options(p)
    p.add_argument("--screenshot-frame", dest="stop_after_old", type=positive, metavar="N",
                   help="the same as --stop-after N (kept for old command lines)").replay = KEEP
    p.add_argument("--record-stream", metavar="FILE",
                   help="record the device's command stream and input for "
                        "'rainbow replay'").replay = DROP
    add_relic_memory_options(p)
    p.add_argument("--demo", default="pads", choices=["pads", "shelf"],
                   help="pads: the Appendix I transparency example and double-buffered "
                        "pads (default); shelf: Appendix I's shelf unit of translucent "
                        "components on four pads sliding apart (left button pauses)").replay = KEEP
    add_tablet_option(p, what="feed", where=" to the Rainbow's tablet input")
    add_trace_options(p, strict="--strict-protocol")


def run(args: argparse.Namespace) -> int:
    from camlab88.emulator.harness import run as run_target

    opts = run_options(args, COMMAND, f"{HEADLESS_FRAMES} frames unless --stop-after N",
                       argv=getattr(args, "_argv", None))
    opts.stop_after = args.stop_after or args.stop_after_old or (
        HEADLESS_FRAMES if opts.headless else None)
    tablet = open_tablet(COMMAND, args.tablet, opts)
    target = None
    try:
        with open_trace(args, COMMAND, "the command stream") as trace:
            target = _target(args, opts, tablet, trace)
            run_target(target, opts)
    finally:
        _finish(args, target, tablet)
    if trace.failed or target is None:
        return 1
    machine = target.machine
    print(f"{COMMAND}: {machine.frame_count} frames, {machine.compiles} compiles")
    return 0


def _finish(args: argparse.Namespace, target, tablet) -> None:
    """Close the tablet (if still open) and save --record-stream, however the run ended."""
    if target is None:
        if tablet is not None:
            tablet.close()
        return
    if target.tablet is not None:
        target.tablet.close()
    if args.record_stream:
        target.machine.recording.save(args.record_stream)
        print(f"{COMMAND}: recorded the command stream to {args.record_stream}")


def _target(args: argparse.Namespace, opts, tablet, trace):
    from camlab88.emulator.harness.rainbow import RainbowTarget
    from camlab88.emulator.machine import RainbowMachine
    from camlab88.protocols.rainbow.demo import Demo

    record = bool(args.record_stream) or opts.record is not None
    machine = RainbowMachine(strict_memory=args.strict, record=record)
    if trace.sink is not None:  # from the first call the demo makes
        machine.trace(trace.sink, trace.strict)
    if getattr(args, "demo", "pads") == "shelf":
        from camlab88.protocols.rainbow.shelf import ShelfDemo

        demo = ShelfDemo(machine.client)
    else:
        demo = Demo(machine.client)

    def step() -> bool:
        if target.tablet is not None and not target.tablet.gone:
            feed_tablet(COMMAND, target.tablet, machine)
        demo.step()
        return True  # the demo runs until the window closes or --stop-after

    target = RainbowTarget(machine, step, "camlab88 Rainbow", KEYS, program=demo)
    target.tablet = tablet
    return target
