"""``camlab88 kas demo``: build 'a line taking a walk' from the library."""

from __future__ import annotations

import argparse

from camlab88.runopts import fail


def add_parser(actions: argparse._SubParsersAction) -> argparse.ArgumentParser:
    p = actions.add_parser("demo", help="build 'a line taking a walk' from the library")
    p.add_argument("--out", required=True, help="sequence file to write")
    p.set_defaults(handler=_demo)
    return p


def _demo(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import demo, files

    try:
        seq = demo.build()
        files.save_sequence(args.out, seq)
    except (OSError, ValueError) as exc:
        return fail("camlab88 kas demo", exc)
    print(f"{args.out}: {len(seq)} frames")
    return 0
