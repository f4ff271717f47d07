"""``camlab88 snooker ccl SCRIPT CHECKPOINT|SESSION --out VIEWS``: interpret a camera script
(thesis §6.3.1) over a shot, writing the view file."""

from __future__ import annotations

import argparse
import sys

from camlab88.runopts import fail

COMMAND = "camlab88 snooker ccl"


def ccl(args: argparse.Namespace) -> int:
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
