"""``camlab88 rainbow replay FILE``: a device recording (``rainbow run --record-stream``)
fed to a fresh Rainbow, every reply checked; a session recording goes to ``camlab88 replay``."""

from __future__ import annotations

import argparse
import sys

from camlab88.runopts import fail

COMMAND = "camlab88 rainbow replay"

DESCRIPTION = """\
Feed a recording's commands and input events (rainbow run --record-stream) to a fresh \
Rainbow; every reply must match the recorded one. A session recording (--record) is run again \
with every screen hash checked, as 'camlab88 replay --check'."""


def add_parser(actions: argparse._SubParsersAction) -> argparse.ArgumentParser:
    p = actions.add_parser("replay", help="replay a recorded command stream and check it",
                           description=DESCRIPTION)
    p.add_argument("recording", metavar="FILE")
    p.add_argument("--headless", action="store_true", help="no window")
    p.add_argument("--screenshot", metavar="PNG", help="save the last frame")
    p.add_argument("--scale", default=1, type=int, help="window scale factor")
    p.add_argument("--strict", action="store_true",
                   help="replay on the relic's video memory (for stream recordings made "
                        "with --strict; a session recording repeats its own options)")
    p.set_defaults(handler=replay)
    return p


def replay(args: argparse.Namespace) -> int:
    from camlab88.base.png import write_png
    from camlab88.emulator.machine import RainbowMachine
    from camlab88.protocols.rainbow.recording import Recording, RecordingError

    if args.screenshot:  # the one output rule, before the work (docs/exit_status.md)
        from pathlib import Path

        from camlab88.runopts import check_output

        check_output(COMMAND, Path(args.screenshot), "save the screenshot to", (".png",))
    if _is_session(args.recording):
        return _session(args)
    try:
        rec = Recording.load(args.recording)
    except (OSError, RecordingError) as exc:
        return fail(COMMAND, exc)
    window = _window(args)
    machine = RainbowMachine(strict_memory=args.strict, on_frame=_show(window))
    try:
        result = machine.replay(rec)
    finally:
        if window is not None:
            window.close()
    if args.screenshot:
        try:
            write_png(machine.frame(), args.screenshot)
        except OSError as exc:  # after the start: the work failed (status 1)
            return fail(COMMAND, exc, 1)
    print(f"{COMMAND}: {result.commands} commands, {result.events} input events, "
          f"{machine.frame_count} frames, {len(result.mismatches)} mismatches")
    for m in result.mismatches[:10]:
        print(f"  {m}", file=sys.stderr)
    return 1 if result.mismatches else 0


def _is_session(path: str) -> bool:
    try:
        with open(path, "rb") as fh:
            return fh.read(40).startswith(b'{"type":"header"')
    except OSError:
        return False


def _session(args: argparse.Namespace) -> int:
    """A session recording (``rainbow run --record``): run again and every screen hash
    checked, as ``camlab88 replay FILE --check`` does."""
    from pathlib import Path

    from camlab88.emulator.harness import choose_headless
    from camlab88.emulator.harness.replay import Replay
    from camlab88.protocols.session import SessionFileError, read
    from camlab88.replay_policy import ReplayRefused
    from camlab88.session_replay import rerun

    try:
        rec = read(args.recording, traffic=False)  # a replay: the traffic is not kept
    except SessionFileError as exc:
        return fail(COMMAND, exc)
    shot = Path(args.screenshot).resolve() if args.screenshot else None
    ctx = Replay(rec, choose_headless(COMMAND, args.headless, "checking the screen hashes"),
                 check=True, screenshot=shot)
    try:
        status, _said = rerun(ctx)
    except ReplayRefused as exc:
        return fail(COMMAND, f"{args.recording}:1: not replayed: {exc}")
    if ctx.fault is not None:  # read again as it played, the recording failed its checks
        return fail(COMMAND, ctx.fault)
    bad = ctx.mismatch is not None or status != 0
    print(f"{COMMAND}: session recording, {ctx.compared} screen hashes compared, "
          f"{int(bad)} mismatches")
    if ctx.mismatch is not None:
        print(f"  {ctx.mismatch.describe()}", file=sys.stderr)
    return 1 if bad else 0


def _window(args: argparse.Namespace):
    from camlab88.emulator.harness import choose_headless

    if choose_headless(COMMAND, args.headless, "checking the replies"):
        return None
    from camlab88.emulator.window import Window

    return Window("camlab88 Rainbow (replay)", (768, 576), scale=args.scale)


def _show(window):
    def on_frame(frame) -> None:
        if window is not None:
            window.show(frame)
            window.poll()
            window.wait_frame(50)
    return on_frame
