"""``camlab88 link stream REC --out FILE``: the bytes one end received, as a raw stream."""

from __future__ import annotations

import argparse


def register(actions: argparse._SubParsersAction) -> None:
    p = actions.add_parser("stream", help="write the bytes one end received as a raw stream")
    p.add_argument("recording")
    p.add_argument("--out", required=True, help="raw stream file to write")
    p.add_argument("--direction", choices=[">", "<"], default=">",
                   help="> host to device (default), < device to host")
    p.set_defaults(handler=stream)


def stream(args: argparse.Namespace) -> int:
    from protocols.link.cli import write_stream

    return write_stream(args.recording, args.out, args.direction)
