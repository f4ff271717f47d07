"""``camlab88 snooker ccl SCRIPT CHECKPOINT|SESSION --out VIEWS``: interpret a camera script
(thesis §6.3.1) over a shot, writing the view file."""

from __future__ import annotations

import argparse
import sys

from camlab88.runopts import fail

COMMAND = "camlab88 snooker ccl"

DESCRIPTION = """\
Interpret a camera control language script (thesis §6.3.1) over the ball positions of a \
checkpoint file or a session file, and write the view file: 'frame ox oy oz vx vy vz focal' \
for every frame (metres from the table's centre, focal length in mm). Every error of the \
script is reported, with its line and column. See docs/snooker.md for the language."""


HELP = "interpret a camera script over a shot; write the view file"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("script", metavar="SCRIPT", help="the camera script")
    p.add_argument("motion", metavar="CHECKPOINT|SESSION",
                   help="the motion program's checkpoint file, or its session file (whose "
                        "collision events then give CUEBALL STRIKES and HITBALL)")
    p.add_argument("--out", required=True, metavar="VIEWS", help="the view file to write")


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.snooker.camera import ccl as language
    from camlab88.apps.snooker.camera import motion
    from camlab88.apps.snooker.camera.errors import CclErrors
    from camlab88.apps.snooker.camera.views import write_views
    from camlab88.apps.snooker.checkpoint import CheckpointError
    from camlab88.apps.snooker.session import SessionError

    try:
        text = language.read_script(args.script)
        shot = motion.load(args.motion)
        result = language.compile_script(text, shot, args.script)
        write_views(args.out, result.views(),
                    [f"camlab88 snooker ccl {args.script} {args.motion}",
                     f"{shot.n_frames} frames, {len(result.periods)} commands"])
    except CclErrors as exc:
        print(exc, file=sys.stderr)
        n = len(exc.errors)
        return fail(COMMAND, f"{n} error{'s' if n > 1 else ''}; no view file written")
    except (CheckpointError, SessionError, OSError) as exc:
        return fail(COMMAND, exc)
    periods = ", ".join(f"line {ln}: {a}-{b}" for ln, a, b in result.periods)
    print(f"{COMMAND}: wrote {shot.n_frames} frames to {args.out} ({periods or 'defaults'})")
    return 0
