"""``camlab88 kas schedule``: which frames the real-time viewer shows and drops."""

from __future__ import annotations

import argparse
from pathlib import Path

from camlab88.runopts import fail


def register(actions: argparse._SubParsersAction) -> None:
    p = actions.add_parser("schedule", help="which frames the real-time viewer shows and drops",
                        description="Given each frame's size in characters on the line, "
                        "compute the real-time line test of §3.1.4: the frame due now is "
                        "sent after each swap; frames passed over are dropped.")
    p.add_argument("sizes", help="comma-separated characters per frame, or @FILE with one "
                    "number a line")
    p.add_argument("--fps", type=float, default=25.0)
    p.add_argument("--baud", type=float, default=9600)
    p.add_argument("--bits-per-char", type=float, default=10.0, help="10 for 8N1")
    p.add_argument("--clock", choices=("first-shown", "first-sent"), default="first-shown",
                   help="time runs from the first frame displayed (§3.1.4, default) or from "
                   "its first character sent (the earlier model)")
    p.set_defaults(handler=_schedule)


def _schedule(args: argparse.Namespace) -> int:
    from apps.kas import viewer_schedule as vs

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
