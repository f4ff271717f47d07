"""``camlab88 kas plot``: plot every frame (HP-GL, SVG, PDF) with registration marks."""

from __future__ import annotations

import argparse

from camlab88.runopts import fail, progress


def _plot(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import files, library, plot

    targets = [(f, d) for f, d in (("hpgl", args.hpgl), ("svg", args.svg), ("pdf", args.pdf))
               if d]
    if not targets:
        return fail("camlab88 kas plot", "give --hpgl DIR, --svg DIR and/or --pdf DIR")
    try:
        if min(args.width, args.height) <= 0 or args.margin < 0:
            raise ValueError("sizes must be positive")
        seq = files.load_sequence(library.resolve(args.seq))
        size = plot.PlotSize(args.width, args.height, args.margin)
        for fmt, d in targets:
            written = plot.plot_sequence(seq, d, fmt, size, progress(f"plot {fmt}"))
            print(f"{fmt}: {len(written)} file(s) in {d}")
    except (OSError, ValueError) as exc:
        return fail("camlab88 kas plot", exc)
    return 0
