"""The one parser of each link tool, shared by ``python -m camlab88.protocols.link`` and ``camlab88
link``; argparse only, so a command registers it without loading the line."""

from __future__ import annotations

import argparse

STREAM_HELP = "write the bytes one end received as a raw stream"
ECHO_HELP = "an echoing device on a paced line (pty, TCP or URL)"


def add_stream_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("recording")
    p.add_argument("--out", required=True, help="raw stream file to write")
    p.add_argument("--direction", choices=[">", "<"], default=">",
                   help="> host to device (default), < device to host")


def add_echo_arguments(p: argparse.ArgumentParser) -> None:
    where = p.add_mutually_exclusive_group()
    where.add_argument("--pty", action="store_true", help="a pseudo-terminal (the default)")
    where.add_argument("--listen", type=int, metavar="PORT", help="TCP on 127.0.0.1 (0 = any)")
    where.add_argument("--url", help="any pyserial URL, e.g. /dev/ttyUSB0 or loop://")
    p.add_argument("--baud", type=int, default=9600)
    p.add_argument("--framing", default="8N1", help="data bits, parity, stop bits (8N1)")
    p.add_argument("--no-xonxoff", action="store_true", help="pass DC1/DC3 as data")
    p.add_argument("--record", metavar="REC",
                   help="record the line to this link recording (link dump reads it)")
    p.add_argument("--seconds", type=float, help="stop after this much line time")
    p.add_argument("--speed", type=float, default=1.0, help="times real time; 0 = flat out")
