"""``camlab88 link echo``: an echoing device on a paced line (pty, TCP or URL)."""

from __future__ import annotations

import argparse

# the options are declared beside the code that reads them (protocols.link)
from camlab88.protocols.link.cli_args import ECHO_HELP as HELP
from camlab88.protocols.link.cli_args import add_echo_arguments as add_arguments

__all__ = ["HELP", "add_arguments", "run"]


def run(args: argparse.Namespace) -> int:
    from camlab88.protocols.link.cli import echo_command

    return echo_command(args)
