"""``camlab88 ca convert``: a pattern converted between native, RLE, .cells and Golly's
macrocell (.mc)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from camlab88.runopts import check_output, fail

COMMAND = "camlab88 ca convert"

DESCRIPTION = """\
Read a pattern and write it in the format given by the output file's extension (.rle, .cells, \
.mc Golly's macrocell, anything else native)."""


HELP = "convert a pattern between native, RLE, .cells and .mc"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("source", help="pattern file or library name")
    p.add_argument("dest", help="output file")


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.ca import library
    from camlab88.apps.ca.patterns import PatternError, check_write, read_pattern, write_pattern

    # the one output rule (docs/exit_status.md): the extension names the format written
    check_output(COMMAND, Path(args.dest), "write", library.PATTERN_SUFFIXES)
    try:
        pattern = read_pattern(library.pattern_path(args.source))
        check_write(args.dest, pattern, args.source)  # named by the input that costs it
    except (FileNotFoundError, PatternError, ValueError) as exc:
        print(f"{COMMAND}: {exc}", file=sys.stderr)
        return 2
    try:
        write_pattern(args.dest, pattern)
    except ValueError as exc:  # a format that cannot hold this pattern (RLE past 255 states)
        return fail(COMMAND, exc)
    except OSError as exc:  # checked at the start: a fault while writing is the work failing
        return fail(COMMAND, f"cannot write {args.dest}: {exc.strerror or exc}", 1)
    print(f"wrote {args.dest}")
    return 0
