"""``camlab88 link echo``: an echoing device on a paced line (pty, TCP or URL)."""

from __future__ import annotations

import argparse

from protocols.link.cli_args import ECHO_HELP, add_echo_arguments


def register(actions: argparse._SubParsersAction) -> None:
    p = actions.add_parser("echo", help=ECHO_HELP)
    add_echo_arguments(p)
    p.set_defaults(handler=echo)


def echo(args: argparse.Namespace) -> int:
    from protocols.link.cli import echo_command

    return echo_command(args)
