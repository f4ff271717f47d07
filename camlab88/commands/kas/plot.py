"""``camlab88 kas plot``: plot every frame (HP-GL, SVG, PDF) with registration marks."""

from __future__ import annotations

import argparse
from pathlib import Path

from camlab88.runopts import check_output_dir, fail, progress

COMMAND = "camlab88 kas plot"

DESCRIPTION = """\
Each frame at the given size (default the twelve-field, 12 x 8.75 inches) with registration \
marks; HP-GL uses pen N for colour N; PDF is one multi-page sequence.pdf."""


HELP = "plot every frame (HP-GL, SVG, PDF) with registration marks"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("seq")
    p.add_argument("--hpgl", metavar="DIR")
    p.add_argument("--svg", metavar="DIR")
    p.add_argument("--pdf", metavar="DIR")
    p.add_argument("--width", default=12.0, type=float, help="inches (default 12)")
    p.add_argument("--height", default=8.75, type=float, help="inches (default 8.75)")
    p.add_argument("--margin", default=1.0, type=float, help="inches round the field")


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import files, library, plot

    targets = [(f, d) for f, d in (("hpgl", args.hpgl), ("svg", args.svg), ("pdf", args.pdf))
               if d]
    if not targets:
        return fail(COMMAND, "give --hpgl DIR, --svg DIR and/or --pdf DIR")
    for fmt, d in targets:  # the one output rule, before the work: DIR is made one level
        check_output_dir(COMMAND, Path(d), f"write the {fmt.upper()} plots to")
    try:
        if min(args.width, args.height) <= 0 or args.margin < 0:
            raise ValueError("sizes must be positive")
        seq = files.load_sequence(library.resolve(args.seq))
        size = plot.PlotSize(args.width, args.height, args.margin)
        for fmt, d in targets:
            written = plot.plot_sequence(seq, d, fmt, size, progress(f"plot {fmt}"))
            print(f"{fmt}: {len(written)} file(s) in {d}")
    except (OSError, ValueError) as exc:
        return fail(COMMAND, exc)
    return 0
