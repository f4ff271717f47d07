"""``camlab88 replay FILE``: a recorded session (``--record FILE``) run again.

The recording's command runs again in a scratch directory holding the recorded input files
(by content), with the recorded input events at their ticks (emulator.harness.replay);
``--check`` compares every stored screen hash: exit 0 when all agree, 1 naming the first
frame (and time) that differs; a damaged, truncated or newer recording is refused (exit 2).
"""

from __future__ import annotations

import argparse
import sys
from fractions import Fraction
from pathlib import Path

from camlab88.control_flags import add_control_options
from camlab88.runopts import fail, frames_dir
from camlab88.stateopts import add_state_options, seconds

COMMAND = "camlab88 replay"
SNAPSHOT_EVERY = 1  # s of virtual time between a seek's snapshots (F4 steps back by them)

DESCRIPTION = """\
Run a session recording again: its program, arguments and input files as recorded, its input \
events at their virtual times. --check compares every screen hash (exit 0: all agree; 1: \
names the first differing frame and time). --period plays at the original speed (9600 baud is \
slow: that is the point); otherwise as fast as possible, in a window too. It names every \
file and directory it writes (--frames, --screenshot, --video, --inspect-out, --save-state)."""


HELP = "replay a recorded session (--record FILE) and check it"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("recording", type=Path, metavar="FILE")
    p.add_argument("--headless", action="store_true", help="no window")
    p.add_argument("--check", action="store_true", help="compare every recorded screen hash")
    p.add_argument("--period", action="store_true",
                   help="play at the recorded speed (the same as --speed 1)")
    p.add_argument("--frames", type=frames_dir, metavar="DIR",
                   help="write every frame shown as DIR/frame_NNNNN.png")
    p.add_argument("--screenshot", type=Path, metavar="PNG", help="save the last screen")
    add_control_options(p, speed_default="flat out, in a window too (--period is --speed 1)")
    add_state_options(p)
    p.add_argument("--seek", type=seconds, metavar="T",
                   help="start showing at virtual time T: run there headless first, "
                        "keeping a state snapshot every 1 s for F4 (step back)")
    p.add_argument("--html", type=Path, metavar="OUT",
                   help="replay headless into a web page that plays the session with its "
                        "input events and (Sigma) the orders on the line, synchronised; "
                        "OUT.html: one self-contained file (the video inside), else a "
                        "directory: index.html beside the video (docs/replay-web.md)")
    p.add_argument("--html-codec", choices=["h264", "vp9"], default="h264",
                   help="the page's video: H.264 in MP4 (default: plays in every browser) or "
                        "VP9 in WebM")


def run(args: argparse.Namespace) -> int:
    from camlab88.emulator.harness import choose_headless
    from camlab88.emulator.harness.replay import Replay
    from camlab88.protocols.session import SessionFileError, read
    from camlab88.replay_policy import ReplayRefused
    from camlab88.session_replay import rerun

    try:
        rec = read(args.recording, traffic=False)  # a replay: the traffic is not kept
    except SessionFileError as exc:
        return fail(COMMAND, exc)
    if args.html is not None:
        return _html(args, rec)
    _check_outputs(args)
    headless = choose_headless(COMMAND, args.headless, "checking the screen hashes")
    ctx = Replay(rec, headless=headless, period=args.period, check=args.check,
                 frames=_abs(args.frames), screenshot=_abs(args.screenshot),
                 controls=_controls(args, headless), state=_state(args))
    try:
        if args.seek is not None:
            seeked = _seek(args, rec, ctx)
            if seeked is not None:
                return seeked
        status, said = rerun(ctx)
    except ReplayRefused as exc:  # the header (line 1) holds the command line
        return fail(COMMAND, f"{args.recording}:1: not replayed: {exc}")
    _name_written(ctx)
    return _verdict(args, ctx, status, said)


def _check_outputs(args: argparse.Namespace) -> None:
    """The one output rule (docs/exit_status.md) for the replay's own --screenshot and
    --frames, before the work: the replayed program's checks are skipped under a replay,
    and its writers make no directory but DIR itself."""
    from camlab88.runopts import check_output, check_output_dir

    if args.screenshot is not None:
        check_output(COMMAND, args.screenshot, "save the screenshot to", (".png",))
    if args.frames is not None:
        check_output_dir(COMMAND, args.frames)


def _name_written(ctx) -> None:
    """Every file and directory the replay wrote (--frames, --screenshot, --video,
    --inspect-out, --save-state, F12), one line each, as every other command names them:
    the replayed program's own lines are kept back."""
    for text in ctx.wrote:
        print(f"{COMMAND}: {text}", file=sys.stderr)


def _html(args: argparse.Namespace, rec) -> int:
    """``--html OUT``: the session replayed headless into a web page."""
    from camlab88.replay_page.make import form_of, make_page
    from camlab88.replay_policy import ReplayRefused
    from camlab88.runopts import check_output, check_output_dir

    others = [flag for flag, given in (("--seek", args.seek), ("--save-state", args.save_state),
              ("--load-state", args.load_state), ("--frames", args.frames),
              ("--screenshot", args.screenshot), ("--period", args.period or None),
              ("--video", args.video), ("--inspect-out", args.inspect_out)) if given]
    if others:
        return fail(COMMAND, f"--html makes the whole session's page on its own; "
                    f"it does not take {', '.join(others)}")
    out = args.html.resolve()
    if out.suffix.lower() in (".html", ".htm"):
        check_output(COMMAND, out, "write the page to")
    elif out.exists() and not out.is_dir():
        return fail(COMMAND, f"cannot write the page to {args.html}: it is a file in the way, "
                    "not a directory (name a .html file for a single page)")
    else:  # the one output rule: DIR is made one level, in a directory that exists
        check_output_dir(COMMAND, out, "write the page to")
    try:
        made = make_page(rec, args.recording, out, args.html_codec, check=args.check)
    except ReplayRefused as exc:
        return fail(COMMAND, f"{args.recording}:1: not replayed: {exc}")
    except OSError as exc:
        return fail(COMMAND, f"cannot write the page to {args.html}: {exc.strerror or exc}")
    status = _verdict(args, made.ctx, made.status, made.said)
    if status == 0:
        size = sum(f.stat().st_size for f in made.files)
        print(f"{COMMAND}: web page {made.files[0]} ({size / 1e6:.2f} MB; "
              f"{form_of(args.html)}; {len(made.capture.frames)} frames, "
              f"{len(made.capture.events)} input events, {len(made.capture.orders)} orders)",
              file=sys.stderr)
    return status


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
def _state(args: argparse.Namespace):
    """The replay's own StateOptions (paths made absolute: the replay runs elsewhere)."""
    from camlab88 import __version__
    from camlab88.emulator.harness.program_state import StateOptions
    from camlab88.runopts import check_output

    if args.at is not None and args.save_state is None:
        raise SystemExit(f"{COMMAND}: --at needs --save-state FILE")
    if args.save_state is not None:
        check_output(COMMAND, args.save_state, "save a state to")
    if args.load_state is not None and not args.load_state.is_file():
        raise SystemExit(f"{COMMAND}: cannot read {args.load_state}: no such file")
    return StateOptions(save=_abs(args.save_state), at=args.at, load=_abs(args.load_state),
                        version=__version__, key_dir=Path.cwd())


def _seek(args: argparse.Namespace, rec, ctx) -> int | None:
    """The first run of a seek: headless and unshown to T, keeping snapshots (and checking
    the hashes on the way with --check); then ``ctx`` starts from the state at T.
    Returns an exit status when the seek cannot go on."""
    from dataclasses import replace

    from camlab88.emulator.harness.replay import Replay
    from camlab88.session_replay import rerun

    first = replace(ctx.state, seek_to=args.seek, snapshots=[],
                    snapshot_every=Fraction(SNAPSHOT_EVERY), save=None, at=None)
    ahead = Replay(rec, headless=True, check=args.check, state=first, seeking=True)
    status, said = rerun(ahead)
    if ahead.mismatch is not None or status != 0 or ahead.runs == 0 or ahead.fault:
        return _verdict(args, ahead, status, said)
    if first.seek_state is None:
        end = float(rec.end.time) if rec.end is not None else 0.0
        return fail(COMMAND, f"{args.recording}: --seek {float(args.seek):g}: the recording "
                    f"ends at {end:g} s")
    ctx.state.load_data, ctx.state.snapshots = first.seek_state, first.snapshots
    ctx.compared = ahead.compared
    return None


def _abs(path: Path | None) -> Path | None:
    return None if path is None else path.resolve()


def _verdict(args: argparse.Namespace, ctx, status: int, said: str) -> int:
    name = args.recording
    if ctx.fault is not None:  # read again as it played, the recording failed its checks
        return fail(COMMAND, ctx.fault if ctx.fault.startswith(str(name)) else
                    f"{name}: {ctx.fault}")
    if ctx.runs == 0:
        return fail(COMMAND, f"{name}: the recorded command ran no program "
                    f"({' '.join(ctx.rec.argv)}; exit status {status}){_said(said)}")
    if ctx.mismatch is not None:  # and why, when the program failed
        return fail(COMMAND, f"{name}: {ctx.mismatch.describe()}"
                    f"{_said(said) if status != 0 else ''}", 1)
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
