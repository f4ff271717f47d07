"""The emulator-control flags every program, device command and replay shares:

``--speed X``        pace the wall clock to virtual time X times period speed (0.1..1000)
``--video FILE``     the frames shown as an .mp4 or .gif at the program's frame rate
``--inspect``        the device inspector beside the screen in the window (F11 toggles it)
``--inspect-out DIR`` the inspector's panels as DIR/frame_NNNNN.png, one per frame shown
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from camlab88.replay_policy import KEEP, SCRATCH

if TYPE_CHECKING:  # the harness (and numpy) load when a command runs, not for its --help
    from camlab88.emulator.harness.control_options import Controls


def speed(text: str) -> float:
    """``--speed X``: a number from 0.1 to 1000 (1 = the period's speed)."""
    from camlab88.emulator.harness.control_options import SPEED_MAX, SPEED_MIN

    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not SPEED_MIN <= value <= SPEED_MAX:
        raise argparse.ArgumentTypeError(
            f"must be from {SPEED_MIN:g} to {SPEED_MAX:g} (1 = period speed), not {text}")
    return value


def video(text: str) -> Path:
    from camlab88.emulator.harness.video import FORMATS

    path = Path(text)
    if path.suffix.lower() not in FORMATS:
        raise argparse.ArgumentTypeError(f"makes .mp4 or .gif, not {text!r}")
    return path


SPEED_DEFAULT = "a window at period speed, headless flat out"


def add_control_options(p: argparse.ArgumentParser, speed_flag: bool = True,
                        speed_default: str = SPEED_DEFAULT) -> None:
    """Add --speed, --video, --inspect and --inspect-out to an action's parser; each is
    run-only, and what a replay does with it is said (the pacing and the inspector change
    nothing a replay checks; the files they write are outputs). ``speed_default`` says what
    runs without --speed (tests/controls/test_stated_speed.py)."""
    shown = []
    if speed_flag:
        shown.append((p.add_argument(
            "--speed", type=speed, metavar="X",
            help="run at X times the period's speed (0.1..1000; 1 = period speed; default: "
                 f"{speed_default})"), KEEP))
    shown += [
        (p.add_argument("--video", type=video, metavar="FILE",
                        help="write the frames shown as FILE.mp4 or FILE.gif"), SCRATCH),
        (p.add_argument("--inspect", action="store_true",
                        help="show the device inspector beside the screen (F11 toggles it)"),
         KEEP),
        (p.add_argument("--inspect-out", type=Path, metavar="DIR",
                        help="write the inspector's panel for every frame as "
                             "DIR/frame_NNNNN.png"), SCRATCH)]
    for action, kind in shown:
        action.replay, action.run_only = kind, True


def controls_from_args(args: argparse.Namespace, command: str, headless: bool) -> Controls:
    """Controls from the flags (absent flags: the defaults); outputs checked now."""
    from camlab88.emulator.harness.control_options import Controls
    from camlab88.runopts import check_output, check_output_dir

    c = Controls(speed=getattr(args, "speed", None), video=getattr(args, "video", None),
                 inspect=bool(getattr(args, "inspect", False)),
                 inspect_out=getattr(args, "inspect_out", None))
    if c.video is not None:
        check_output(command, c.video, "write the video")
    if c.inspect_out is not None:
        check_output_dir(command, Path(c.inspect_out), "write the inspector's frames to")
    if c.inspect and headless:
        print(f"{command}: --inspect shows a panel in the window; headless, "
              "--inspect-out DIR writes the panels", file=sys.stderr)
    return c
