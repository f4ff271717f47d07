"""``camlab88 link stream REC --out FILE``: the bytes one end received, as a raw stream."""

from __future__ import annotations

import argparse

# the options are declared beside the code that reads them (protocols.link)
from camlab88.protocols.link.cli_args import STREAM_HELP as HELP
from camlab88.protocols.link.cli_args import add_stream_arguments as add_arguments

__all__ = ["HELP", "add_arguments", "run"]


def run(args: argparse.Namespace) -> int:
    from camlab88.protocols.link.cli import write_stream

    return write_stream(args.recording, args.out, args.direction)
