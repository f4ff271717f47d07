"""``camlab88 link stream REC --out FILE``: the bytes one end received, as a raw stream."""

from __future__ import annotations

import argparse

from camlab88.areas import delegated_action
from camlab88.protocols.link.cli_args import STREAM_HELP, add_stream_arguments


def add_parser(actions: argparse._SubParsersAction) -> argparse.ArgumentParser:
    return delegated_action(actions, "stream", STREAM_HELP, add_stream_arguments, stream)


def stream(args: argparse.Namespace) -> int:
    from camlab88.protocols.link.cli import write_stream

    return write_stream(args.recording, args.out, args.direction)
