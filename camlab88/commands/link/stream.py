"""``camlab88 link stream REC --out FILE``: the bytes one end received, as a raw stream."""

from __future__ import annotations

import argparse

from protocols.link.cli_args import STREAM_HELP, add_stream_arguments


def register(actions: argparse._SubParsersAction) -> None:
    p = actions.add_parser("stream", help=STREAM_HELP)
    add_stream_arguments(p)
    p.set_defaults(handler=stream)


def stream(args: argparse.Namespace) -> int:
    from protocols.link.cli import write_stream

    return write_stream(args.recording, args.out, args.direction)
