"""``camlab88 kas schedule``: which frames the real-time viewer shows and drops."""

from __future__ import annotations

import argparse
from pathlib import Path

from camlab88.runopts import fail


def _schedule(args: argparse.Namespace) -> int:
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
