"""``camlab88 rainbow run``: the Rainbow demo of pads and transparency, on the harness."""

from __future__ import annotations

import argparse
import sys

from camlab88.runopts import add_run_options, positive, run_options
from camlab88.traceopts import add_trace_options, open_trace

COMMAND = "camlab88 rainbow run"
KEYS = "middle button: the demo's menu; Esc or close the window to quit"
HEADLESS_FRAMES = 250


def register(actions: argparse._SubParsersAction) -> None:
    u = actions.add_parser("run", help="open the window with a demo of pads and transparency",
                           description="Run the Rainbow with the Appendix I transparency "
                           "example and moving double-buffered pads (headless: "
                           f"{HEADLESS_FRAMES} frames unless --stop-after N).")
    add_run_options(u)
    u.add_argument("--screenshot-frame", type=positive, metavar="N", dest="stop_after_old",
                   help="the same as --stop-after N (kept for old command lines)")
    u.add_argument("--record-stream", metavar="FILE",
                   help="record the device's command stream and input for 'rainbow replay'")
    u.add_argument("--strict", action="store_true",
                   help="the relic's video memory (64K 16-bit words)")
    u.add_argument("--demo", choices=("pads", "shelf"), default="pads",
                   help="pads: the Appendix I transparency example and double-buffered pads "
                   "(default); shelf: Appendix I's shelf unit of translucent components on "
                   "four pads sliding apart (left button pauses)")
    u.add_argument("--tablet", metavar="SOURCE",
                   help="also feed a real tablet (hid:VID:PID, serial:PORT?protocol=P, or a "
                   "pyserial URL?protocol=P) to the Rainbow's tablet input")
    add_trace_options(u, strict="--strict-protocol")
    u.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from emulator.harness import run as run_target

    opts = run_options(args, COMMAND, f"{HEADLESS_FRAMES} frames unless --stop-after N",
                       argv=getattr(args, "_argv", None))
    opts.stop_after = args.stop_after or args.stop_after_old or (
        HEADLESS_FRAMES if opts.headless else None)
    tablet = _open_tablet(args.tablet, opts.record is not None)
    if tablet is not None and tablet.live:  # a real stylus moves on the wall clock
        opts.live = True
    target = None
    try:
        with open_trace(args, COMMAND, "the command stream") as trace:
            target = _target(args, opts, tablet, trace)
            run_target(target, opts)
    finally:
        _finish(args, target, tablet)
    if trace.failed or target is None:
        return 1
    dev = target.session.device
    print(f"{COMMAND}: {dev.frame_count} frames, {dev.compiler.stats.compiles} compiles")
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
        target.session.recorder.recording.save(args.record_stream)
        print(f"{COMMAND}: recorded the command stream to {args.record_stream}")


def _target(args: argparse.Namespace, opts, tablet, trace):
    from emulator.harness.rainbow import RainbowTarget
    from emulator.rainbow import Rainbow
    from emulator.rainbow.session import in_process
    from protocols.rainbow.demo import Demo

    record = bool(args.record_stream) or opts.record is not None
    session = in_process(Rainbow(strict=args.strict), record=record)
    if trace.sink is not None:  # from the first call the demo makes
        from emulator.rainbow.trace import RainbowTracer

        session.executor.tracer = RainbowTracer(trace.sink, trace.strict)
    if getattr(args, "demo", "pads") == "shelf":
        from protocols.rainbow.shelf import ShelfDemo

        demo = ShelfDemo(session.client)
    else:
        demo = Demo(session.client)

    def step() -> bool:
        if target.tablet is not None and not target.tablet.gone:
            target.tablet = _poll_tablet(target.tablet, session)
        demo.step()
        return True  # the demo runs until the window closes or --stop-after

    target = RainbowTarget(session, step, "camlab88 Rainbow", KEYS)
    target.tablet = tablet
    return target


def _open_tablet(text: str | None, record: bool):
    """The --tablet source (on a tape with --record; from the recording's tape in a replay,
    where the device is never opened)."""
    if not text:
        return None
    from emulator.tablet_input.taped import TapedTablet
    from protocols.tablets.sources import SourceError

    try:
        return TapedTablet.open(text, record)
    except (SourceError, OSError) as exc:
        raise SystemExit(f"{COMMAND}: --tablet {text}: {exc}") from None


def _poll_tablet(tablet, session):
    """Feed new tablet reports to the device; a lost tablet is reported once and dropped."""
    from emulator.rainbow.host_input import tablet_event
    from protocols.tablets.sources import SourceLost

    try:
        for ev in tablet.read(0.0):
            session.inject(tablet_event(ev))
    except (SourceLost, OSError) as exc:
        print(f"{COMMAND}: tablet lost ({exc}); carrying on without it", file=sys.stderr)
        tablet.close()  # gone: not read again (its tape keeps what it said)
    return tablet
