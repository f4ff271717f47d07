"""``camlab88 kas demo``: build 'a line taking a walk' from the library."""

from __future__ import annotations

import argparse

from camlab88.runopts import fail


def _demo(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import demo, files

    try:
        seq = demo.build()
        files.save_sequence(args.out, seq)
    except (OSError, ValueError) as exc:
        return fail("camlab88 kas demo", exc)
    print(f"{args.out}: {len(seq)} frames")
    return 0
