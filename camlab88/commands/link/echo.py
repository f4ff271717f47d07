"""``camlab88 link echo``: an echoing device on a paced line (pty, TCP or URL)."""

from __future__ import annotations

import argparse

from camlab88.protocols.link.cli_args import ECHO_HELP as LINK_ECHO_HELP
from camlab88.protocols.link.cli_args import add_echo_arguments


def add_parser(actions: argparse._SubParsersAction) -> argparse.ArgumentParser:
    p = actions.add_parser("echo", help=f"{LINK_ECHO_HELP}")
    add_echo_arguments(p)
    p.set_defaults(handler=echo)
    return p


def echo(args: argparse.Namespace) -> int:
    from camlab88.protocols.link.cli import echo_command

    return echo_command(args)
