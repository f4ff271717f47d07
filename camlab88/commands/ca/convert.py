"""``camlab88 ca convert``: a pattern converted between native, RLE, .cells and Golly's
macrocell (.mc)."""

from __future__ import annotations

import argparse
import sys


def _convert(args: argparse.Namespace) -> int:
    from camlab88.apps.ca import library
    from camlab88.apps.ca.patterns import PatternError, check_write, read_pattern, write_pattern

    try:
        pattern = read_pattern(library.pattern_path(args.source))
        check_write(args.dest, pattern, args.source)  # named by the input that costs it
        write_pattern(args.dest, pattern)
    except (FileNotFoundError, PatternError, ValueError) as exc:
        print(f"camlab88 ca convert: {exc}", file=sys.stderr)
        return 2
    except OSError as exc:  # the destination: no directory there, read-only, disk full
        print(f"camlab88 ca convert: cannot write {args.dest}: {exc.strerror or exc}",
              file=sys.stderr)
        return 2
    print(f"wrote {args.dest}")
    return 0
