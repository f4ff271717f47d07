"""``camlab88 kas superimpose``: superimpose sequences with start offsets — given on the
command line (SEQ@N, ours), or prompted for on entry on the Sigma (``--prompt``, §3.1.3)."""

from __future__ import annotations

import argparse
import re

from camlab88.commands.kas import add_front_options
from camlab88.replay_policy import KEEP, SCRATCH
from camlab88.runopts import fail

COMMAND = "camlab88 kas superimpose"
KEYS = "type each sequence's start (frames) and Return; Return alone keeps the default"

DESCRIPTION = """\
Combine sequences; SEQ@N starts N frames late (its first frame is held until then); a \
sequence that ends early holds its last frame. The same sequence may be given several times. \
With --prompt the program runs on the emulated Sigma and asks each sequence's start on entry, \
as section 3.1.3 says ('all timing information is prompted for on entry'); any @N is then the \
default shown in brackets. Without --prompt the offsets come from the command line (ours)."""


HELP = "superimpose sequences with start offsets"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("seqs", nargs="+", metavar="SEQ[@OFFSET]")
    p.add_argument("--out", required=True).replay = SCRATCH
    p.add_argument("--prompt", action="store_true",
                   help="ask the timings on the Sigma (keyboard, or --script "
                        "key events)").replay = KEEP
    add_front_options(p)


def run(args: argparse.Namespace) -> int:
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
