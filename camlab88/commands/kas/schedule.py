"""``camlab88 kas schedule``: which frames the real-time viewer shows and drops."""

from __future__ import annotations

import argparse
from pathlib import Path

from camlab88.runopts import fail

DESCRIPTION = """\
Given each frame's size in characters on the line, compute the real-time line test of §3.1.4: \
the frame due now is sent after each swap; frames passed over are dropped."""


HELP = "which frames the real-time viewer shows and drops"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("sizes",
                   help="comma-separated characters per frame, or @FILE with one number a "
                        "line")
    p.add_argument("--fps", default=25.0, type=float)
    p.add_argument("--baud", default=9600, type=float)
    p.add_argument("--bits-per-char", default=10.0, type=float, help="10 for 8N1")
    p.add_argument("--clock", default="first-shown", choices=["first-shown", "first-sent"],
                   help="time runs from the first frame displayed (§3.1.4, default) or "
                        "from its first character sent (the earlier model)")


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import viewer_schedule as vs

    try:
        text = args.sizes
        if text.startswith("@"):
            text = ",".join(Path(text[1:]).read_text().split())
        sizes = [int(s) for s in text.split(",") if s.strip()]
        if any(s < 0 for s in sizes):
            raise ValueError("sizes must not be negative")
        sched = vs.realtime(sizes, args.fps, args.baud, args.bits_per_char, args.clock)
    except (OSError, ValueError) as exc:
        return fail("camlab88 kas schedule", exc)
    print(f"{len(sched.shown)} shown, {len(sched.dropped)} dropped, {sched.end:.3f} s")
    print("shown:", " ".join(map(str, sched.shown_frames)))
    print("dropped:", " ".join(map(str, sched.dropped)))
    return 0
