"""``camlab88 kas demo``: build 'a line taking a walk' from the library."""

from __future__ import annotations

import argparse

from camlab88.runopts import fail

HELP = "build 'a line taking a walk' from the library"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--out", required=True, help="sequence file to write")


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import demo, files

    try:
        seq = demo.build()
        files.save_sequence(args.out, seq)
    except (OSError, ValueError) as exc:
        return fail("camlab88 kas demo", exc)
    print(f"{args.out}: {len(seq)} frames")
    return 0
