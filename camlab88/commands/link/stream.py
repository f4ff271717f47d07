"""``camlab88 link stream REC --out FILE``: the bytes one end received, as a raw stream."""

from __future__ import annotations

import argparse

from camlab88.protocols.link.cli_args import STREAM_HELP as LINK_STREAM_HELP
from camlab88.protocols.link.cli_args import add_stream_arguments


def add_parser(actions: argparse._SubParsersAction) -> argparse.ArgumentParser:
    p = actions.add_parser("stream", help=f"{LINK_STREAM_HELP}")
    add_stream_arguments(p)
    p.set_defaults(handler=stream)
    return p


def stream(args: argparse.Namespace) -> int:
    from camlab88.protocols.link.cli import write_stream

    return write_stream(args.recording, args.out, args.direction)
