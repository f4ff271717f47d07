"""``camlab88 kas superimpose``: superimpose sequences with start offsets."""

from __future__ import annotations

import argparse
import re

from camlab88.runopts import fail


def register(actions: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    p = actions.add_parser("superimpose", help="superimpose sequences with start offsets",
                        description="Combine sequences; SEQ@N starts N frames late (its first "
                        "frame is held until then); a sequence that ends early holds its "
                        "last frame. The same sequence may be given several times.")
    p.add_argument("seqs", nargs="+", metavar="SEQ[@OFFSET]")
    p.add_argument("--out", required=True)
    p.set_defaults(handler=_superimpose)


def _superimpose(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.superimpose import superimpose

    try:
        parts = []
        cache: dict[str, object] = {}
        for spec in args.seqs:
            # SEQ@N: only a last '@' followed by a whole number is an offset, so file
            # names may contain '@' ('a@b.kas', 'take@2.kas@5')
            m = re.fullmatch(r"(.+)@([+-]?\d+)", spec)
            name, offset = (m[1], int(m[2])) if m else (spec, 0)
            if name not in cache:
                cache[name] = files.load_sequence(library.resolve(name))
            parts.append((cache[name], offset))
        seq = superimpose(parts)
        files.save_sequence(args.out, seq)
    except (OSError, ValueError) as exc:
        return fail("camlab88 kas superimpose", exc)
    print(f"{args.out}: {len(seq)} frames")
    return 0
