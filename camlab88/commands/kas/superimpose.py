"""``camlab88 kas superimpose``: superimpose sequences with start offsets — given on the
command line (SEQ@N, ours), or prompted for on entry on the Sigma (``--prompt``, §3.1.3)."""

from __future__ import annotations

import argparse
import re

from camlab88.commandspec import keys_of
from camlab88.runopts import fail

COMMAND = "camlab88 kas superimpose"
KEYS = keys_of(__name__)


def _superimpose(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import files
    from camlab88.apps.kas.superimpose import superimpose

    try:
        parts = _parts(args.seqs)
        if args.prompt:
            seq = _prompted(args, parts)
            if seq is None:
                return 0  # a screenshot run, or the window closed before every answer
        else:
            seq = superimpose([(s, off) for _n, s, off in parts])
            files.save_sequence(args.out, seq)
    except (OSError, ValueError) as exc:
        return fail(COMMAND, exc)
    print(f"{args.out}: {len(seq)} frames")
    return 0


def _parts(specs: list[str]) -> list:
    from camlab88.apps.kas import files, library

    parts = []
    cache: dict[str, object] = {}
    for spec in specs:
        # SEQ@N: only a last '@' followed by a whole number is an offset, so file
        # names may contain '@' ('a@b.kas', 'take@2.kas@5')
        m = re.fullmatch(r"(.+)@([+-]?\d+)", spec)
        name, offset = (m[1], int(m[2])) if m else (spec, 0)
        if name not in cache:
            cache[name] = files.load_sequence(library.resolve(name))
        parts.append((name, cache[name], offset))
    return parts


def _prompted(args: argparse.Namespace, parts: list):
    """The superimposer on the Sigma; the composite, saved, or None if not every start was
    answered (an error when a headless script leaves some unanswered)."""
    from camlab88.apps.kas import files
    from camlab88.apps.kas.program.superimpose_front import SuperimposeFront
    from camlab88.commands.kas import run_front

    def save(seq, _starts) -> None:
        if args.screenshot is None:  # a screenshot run never touches the user's files
            files.save_sequence(args.out, seq)

    front = SuperimposeFront(parts, args.background, save)
    run_front(front, args, COMMAND, KEYS)
    if front.result is None and args.script is not None and args.screenshot is None:
        raise ValueError(f"{args.script}: the script answers {len(front.starts)} of "
                         f"{len(parts)} start prompts")
    return None if args.screenshot is not None else front.result
