"""``camlab88 link dump REC``: a link recording in readable form."""

from __future__ import annotations

import argparse


def register(actions: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    p = actions.add_parser("dump", help="print a link recording readably")
    p.add_argument("recording")
    p.set_defaults(handler=dump)


def dump(args: argparse.Namespace) -> int:
    from protocols.link.cli import dump as dump_recording

    return dump_recording(args.recording)
