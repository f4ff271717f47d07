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
with every screen hash checked, as 'camlab88 replay --check'. In a window the emulator's \
controls work as in every program: F1 the keys, F5 pause / resume, F6 one frame, F7 / F8 half / \
double speed, F11 the inspector, F12 a screenshot, Esc or closing the window stops the \
replay (exit 1: the check did not finish)."""


HELP = "replay a recorded command stream and check it"


def add_arguments(p: argparse.ArgumentParser) -> None:
    from camlab88.control_flags import add_control_options

    p.add_argument("recording", metavar="FILE")
    p.add_argument("--headless", action="store_true", help="no window")
    p.add_argument("--screenshot", metavar="PNG", help="save the last frame")
    p.add_argument("--scale", default=1, type=int, help="window scale factor")
    p.add_argument("--strict", action="store_true",
                   help="replay on the relic's video memory (for stream recordings made "
                        "with --strict; a session recording repeats its own options)")
    add_control_options(p, speed_default="a window at the Rainbow's 50 frames a second, "
                                         "headless flat out")


def run(args: argparse.Namespace) -> int:
    from camlab88.base.png import write_png
    from camlab88.control_flags import controls_from_args
    from camlab88.emulator.harness import RunOptions, choose_headless, run
    from camlab88.emulator.harness.rainbow_stream_replay import StreamReplay
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
    headless = choose_headless(COMMAND, args.headless, "checking the replies")
    target = StreamReplay(rec, strict=args.strict)
    run(target, RunOptions(headless=headless, scale=args.scale, command=COMMAND,
                           controls=controls_from_args(args, COMMAND, headless)))
    if args.screenshot:
        try:
            write_png(target.machine.frame(), args.screenshot)
        except OSError as exc:  # after the start: the work failed (status 1)
            return fail(COMMAND, exc, 1)
    result = target.result
    if result is None:
        print(f"{COMMAND}: stopped after {target.k} frames, before the end of the recording: "
              "not checked to the end", file=sys.stderr)
        return 1
    print(f"{COMMAND}: {result.commands} commands, {result.events} input events, "
          f"{target.machine.frame_count} frames, {len(result.mismatches)} mismatches")
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
    headless = choose_headless(COMMAND, args.headless, "checking the screen hashes")
    ctx = Replay(rec, headless, check=True, screenshot=shot,
                 controls=_controls(args, headless))
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


def _controls(args: argparse.Namespace, headless: bool):
    """The replay's own controls, as ``camlab88 replay``'s: paths made absolute (a session
    replay runs in a scratch directory), F12 screenshots where the replay was started."""
    from pathlib import Path

    from camlab88.control_flags import controls_from_args

    c = controls_from_args(args, COMMAND, headless)
    c.video = c.video.resolve() if c.video is not None else None
    c.inspect_out = c.inspect_out.resolve() if c.inspect_out is not None else None
    c.shots = Path.cwd()
    return c
