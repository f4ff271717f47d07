"""``camlab88 replay FILE``: a recorded session (``--record FILE``) run again.

The recording's command runs again in a scratch directory holding the recorded input files
(by content), with the recorded input events at their ticks (emulator.harness.replay);
``--check`` compares every stored screen hash: exit 0 when all agree, 1 naming the first
frame (and time) that differs; a damaged, truncated or newer recording is refused (exit 2).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from camlab88.control_flags import add_control_options
from camlab88.runopts import fail, frames_dir

COMMAND = "camlab88 replay"


def register(subparsers: argparse._SubParsersAction) -> None:
    p = subparsers.add_parser(
        "replay", help="replay a recorded session (--record FILE) and check it",
        description="Run a session recording again: its program, arguments and input files "
        "as recorded, its input events at their virtual times. --check compares every screen "
        "hash (exit 0: all agree; 1: names the first differing frame and time). --period "
        "plays at the original speed (9600 baud is slow: that is the point); otherwise as "
        "fast as possible.")
    p.add_argument("recording", type=Path, metavar="FILE")
    p.add_argument("--headless", action="store_true", help="no window")
    p.add_argument("--check", action="store_true", help="compare every recorded screen hash")
    p.add_argument("--period", action="store_true", help="play at the recorded speed "
                   "(the same as --speed 1)")
    p.add_argument("--frames", type=frames_dir, metavar="DIR",
                   help="write every frame shown as DIR/frame_NNNNN.png")
    p.add_argument("--screenshot", type=Path, metavar="PNG", help="save the last screen")
    add_control_options(p)
    p.set_defaults(handler=replay)


def replay(args: argparse.Namespace) -> int:
    from camlab88.replay_policy import ReplayRefused
    from camlab88.session_replay import rerun
    from emulator.harness import choose_headless
    from emulator.harness.replay import Replay
    from protocols.session import SessionFileError, read

    try:
        rec = read(args.recording)
    except SessionFileError as exc:
        return fail(COMMAND, exc)
    headless = choose_headless(COMMAND, args.headless, "checking the screen hashes")
    ctx = Replay(rec, headless=headless, period=args.period, check=args.check,
                 frames=_abs(args.frames), screenshot=_abs(args.screenshot),
                 controls=_controls(args, headless))
    try:
        status, said = rerun(ctx)
    except ReplayRefused as exc:  # the header (line 1) holds the command line
        return fail(COMMAND, f"{args.recording}:1: not replayed: {exc}")
    return _verdict(args, ctx, status, said)


def _controls(args: argparse.Namespace, headless: bool):
    """The replay's own controls; paths made absolute (the replay runs in a scratch
    directory), --period is --speed 1, F12 screenshots land where the replay was started."""
    from camlab88.control_flags import controls_from_args

    c = controls_from_args(args, COMMAND, headless)
    if args.period and c.speed is None:
        c.speed = 1.0
    c.video, c.inspect_out = _abs(c.video), _abs(c.inspect_out)
    c.shots = Path.cwd()
    return c


def _abs(path: Path | None) -> Path | None:
    return None if path is None else path.resolve()


def _verdict(args: argparse.Namespace, ctx, status: int, said: str) -> int:
    name = args.recording
    if ctx.runs == 0:
        return fail(COMMAND, f"{name}: the recorded command ran no program "
                    f"({' '.join(ctx.rec.argv)}; exit status {status}){_said(said)}")
    if ctx.mismatch is not None:
        return fail(COMMAND, f"{name}: {ctx.mismatch.describe()}", 1)
    if status != 0:
        return fail(COMMAND, f"{name}: the program ended with exit status {status}"
                    f"{_said(said)}", 1)
    if args.check:
        print(f"{COMMAND}: {name}: all {ctx.compared} screen hashes agree "
              f"({' '.join(ctx.rec.argv[:2])}, {ctx.ended.frame if ctx.ended else 0} frames)")
    return 0


def _said(text: str) -> str:
    """The last lines the failed program printed (its own messages are kept back)."""
    lines = text.strip().splitlines()[-3:]
    return "".join(f"\n  the replayed program said: {line}" for line in lines)
