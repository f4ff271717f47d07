"""``camlab88 snooker visualise CHECKPOINT VIEWS``: the perspective view of every frame on
the Rainbow (thesis §6.3.2), at 25 frames/s; ``--frames DIR`` writes frame_NNNNN.png
numbered as the checkpoint's frames (from 1)."""

from __future__ import annotations

import argparse
import sys

from camlab88.runopts import add_run_options, fail, run_options, unattended

COMMAND = "camlab88 snooker visualise"
KEYS = """\
space play/pause, left/right step, page up/down 25 frames, home/end, drag with the left \
button to scrub, escape quits"""

DESCRIPTION = f"""\
Play a view file (from 'snooker ccl') over a checkpoint or session on the emulated Rainbow at \
25 frames/s. Keys: {KEYS}. Headless it plays every frame once; --frames DIR writes \
DIR/frame_NNNNN.png numbered as the checkpoint's frames."""


HELP = "the perspective view of every frame on the Rainbow (§6.3.2)"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("motion", metavar="CHECKPOINT|SESSION")
    p.add_argument("views", metavar="VIEWS", help="the view file")
    add_run_options(p)


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.snooker.camera import motion
    from camlab88.apps.snooker.camera.views import ViewFileError, read_views
    from camlab88.apps.snooker.checkpoint import CheckpointError
    from camlab88.apps.snooker.session import SessionError
    from camlab88.apps.snooker.visualiser.program import ViewsError

    try:
        shot = motion.load(args.motion)
        views = read_views(args.views)
        frames_dir, args.frames = args.frames, None  # written here, numbered by frame
        opts = run_options(args, COMMAND, "playing every frame once",
                           argv=getattr(args, "_argv", None))
        h, vis, n_written = _run(shot, views, opts, frames_dir)
    except (CheckpointError, SessionError, ViewFileError, ViewsError, OSError) as exc:
        return fail(COMMAND, exc)
    d = vis.display
    wrote = (f"; wrote {n_written} frames to {frames_dir}/frame_NNNNN.png"
             if frames_dir is not None else "")
    print(f"{COMMAND}: {h.frames_shown} frames shown ({len(views)} in the view file, "
          f"frames {views[0].frame}-{views[-1].frame}); table redrawn {d.table_redraws} "
          f"times{wrote}", file=sys.stderr)
    return 0


def status(vis, target) -> str:
    """The window's title bar: the checkpoint frame shown, the virtual time, the keys."""
    return (f"frame {vis.frame} ({vis.index + 1} of {len(vis.views)}), "
            f"t = {float(target.time()):.2f} s | {KEYS}")


def _run(shot, views, opts, frames_dir):
    from camlab88.apps.snooker.visualiser.program import Visualiser
    from camlab88.base.png import write_frame
    from camlab88.emulator.harness import run
    from camlab88.emulator.harness.loop import Plugin
    from camlab88.emulator.harness.rainbow import RainbowTarget
    from camlab88.emulator.machine import RainbowMachine

    rb = RainbowMachine(record=opts.record is not None)
    vis = Visualiser(rb.client, shot, views)
    once = unattended(opts)

    def step() -> bool:
        last = vis.index == len(vis.views) - 1
        vis.step()
        return not vis.done and not (once and last)

    class Frames(Plugin):
        """Each newly drawn frame as DIR/frame_NNNNN.png, NNNNN its checkpoint frame."""

        written: int | None = None
        count = 0

        def on_frame(self, harness, frame) -> None:
            if frames_dir is not None and vis.drawn is not None and vis.drawn != self.written:
                write_frame(frame, frames_dir, vis.views[vis.drawn].frame)
                self.written = vis.drawn
                self.count += 1  # named in the closing line

    target = RainbowTarget(rb, step, COMMAND, KEYS, status=lambda: status(vis, target),
                           program=vis)
    target.escape_is_a_key = True  # the visualiser's own Esc / q: done
    frames = Frames()
    return run(target, opts, [frames]), vis, frames.count
