"""``camlab88 kas demo``: build 'a line taking a walk' from the library."""

from __future__ import annotations

import argparse

from camlab88.runopts import fail


def register(actions: argparse._SubParsersAction) -> None:
    p = actions.add_parser("demo", help="build 'a line taking a walk' from the library")
    p.add_argument("--out", required=True, help="sequence file to write")
    p.set_defaults(handler=_demo)


def _demo(args: argparse.Namespace) -> int:
    from apps.kas import demo, files

    try:
        seq = demo.build()
        files.save_sequence(args.out, seq)
    except (OSError, ValueError) as exc:
        return fail("camlab88 kas demo", exc)
    print(f"{args.out}: {len(seq)} frames")
    return 0
