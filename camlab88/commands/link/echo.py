"""``camlab88 link echo``: an echoing device on a paced line (pty, TCP or URL)."""

from __future__ import annotations

import argparse


def echo(args: argparse.Namespace) -> int:
    from camlab88.protocols.link.cli import echo_command

    return echo_command(args)
