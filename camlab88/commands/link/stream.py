"""``camlab88 link stream REC --out FILE``: the bytes one end received, as a raw stream."""

from __future__ import annotations

import argparse


def stream(args: argparse.Namespace) -> int:
    from camlab88.protocols.link.cli import write_stream

    return write_stream(args.recording, args.out, args.direction)
