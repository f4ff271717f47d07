"""``camlab88 link echo``: an echoing device on a paced line (pty, TCP or URL)."""

from __future__ import annotations

import argparse


def register(actions: argparse._SubParsersAction) -> None:
    p = actions.add_parser("echo", help="an echoing device on a paced line (pty, TCP or URL)")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--pty", action="store_true", help="a pseudo-terminal (the default)")
    where.add_argument("--listen", type=int, metavar="PORT", help="TCP on 127.0.0.1 (0 = any)")
    where.add_argument("--url", help="any pyserial URL, e.g. /dev/ttyUSB0 or loop://")
    p.add_argument("--baud", type=int, default=9600)
    p.add_argument("--framing", default="8N1", help="data bits, parity, stop bits (8N1)")
    p.add_argument("--no-xonxoff", action="store_true", help="pass DC1/DC3 as data")
    p.add_argument("--record", metavar="REC", help="record the line to this link recording")
    p.add_argument("--seconds", type=float, help="stop after this much line time")
    p.add_argument("--speed", type=float, default=1.0, help="times real time; 0 = flat out")
    p.set_defaults(handler=echo)


def echo(args: argparse.Namespace) -> int:
    from protocols.link import cli

    return int(cli._echo(args) or 0)  # the echo device's own loop (protocols.link.cli)
