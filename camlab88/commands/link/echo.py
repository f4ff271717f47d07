"""``camlab88 link echo``: an echoing device on a paced line (pty, TCP or URL)."""

from __future__ import annotations

import argparse

from camlab88.areas import delegated_action
from camlab88.protocols.link.cli_args import ECHO_HELP, add_echo_arguments


def add_parser(actions: argparse._SubParsersAction) -> argparse.ArgumentParser:
    return delegated_action(actions, "echo", ECHO_HELP, add_echo_arguments, echo)


def echo(args: argparse.Namespace) -> int:
    from camlab88.protocols.link.cli import echo_command

    return echo_command(args)
